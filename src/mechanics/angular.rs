//! A body's angular velocity and acceleration (step 4): in the plane, or with declared
//! speeds, multiplied out; in space, built on its parent's, the partial angular velocities
//! named where long.
//!
//! Multiplied out in the body's own unit vectors, the angular velocity of the k-th body of
//! a spatial chain carries every direction cosine across the chain: 3^k-fold trig products.
//! Built as Kane and Levinson build it, it stays a few terms per link:
//! - `ω^k = Σ_r ω^k_r q̇_r + ω̃^k`, with the partial angular velocities `ω^k_r = C ω^p_r +`
//!   the joint's axis for `q_r`, and `ω̃^k` what a driven coordinate adds;
//! - `α^k = Σ_r ω^k_r q̈_r + α̃^k`, with `α̃^k = C α̃^p + (the joint's ω' without the q'')
//!   + ω^p × ω_rel`, where `C` takes the parent's unit vectors to the body's.

use super::compact::{name_part, Kind, Quantity, AXES, MAX_EXPANDED_TERMS};
use super::error::MechanicsError;
use super::frames::{apply, Frames};
use super::model::Form;
use super::model::{dt_components, BodyState};
use super::on_parent::{simplified, split, sum};
use super::speeds::Speeds;
use super::vector::{cross3, Components};
use super::Vector;
use crate::problem::{BodyId, Problem};
use crate::symbolic::{add, latex_name, time_derivative, Expr, Symbol};

/// In spatial problems, an angular velocity component with more terms than this is kept
/// whole in velocity products; shorter ones are multiplied out (see `omega_named`).
const MAX_EXPANDED_OMEGA_TERMS: usize = 3;

/// A body's angular velocity, the same with long components named, and its angular
/// acceleration, each in the body's own unit vectors.
pub struct Angular {
    /// See [`BodyState::omega`].
    pub omega: Vector,
    /// See [`BodyState::omega_named`].
    pub omega_named: Vector,
    /// See [`BodyState::alpha`].
    pub alpha: Vector,
}

/// The angular velocity as the parent's carried into this frame plus the joint's own,
/// multiplied out, and its derivative. In the plane these are sums of rates; with declared
/// speeds the kinematic equations mix the rates, so nothing is built on the parent's parts.
pub(super) fn multiplied_out(
    problem: &Problem,
    frames: &Frames,
    parent_state: &BodyState,
    (body, path): (BodyId, &str),
    relative: &Components,
    speeds: Option<&Speeds>,
) -> Result<Angular, MechanicsError> {
    let to_speeds = |e: &Expr| match speeds {
        Some(s) => s.to_speeds(e),
        None => e.clone(),
    };
    let carried = |parent_omega: &Vector| {
        parent_omega
            .expressed_in(body, frames)
            .plus(&Vector::new(body, relative.clone()))
            .map(crate::symbolic::simplify)
            .map(to_speeds)
    };
    let omega = carried(&parent_state.omega);
    let omega_components = omega.components_in(body, frames);
    let name = &problem.body(body).name;
    let planar = problem.dimension == crate::problem::Dimension::Two;
    // The same built on the parent's named components: ω_k = C ω_(k-1) + its joint's rates,
    // a few terms where multiplied out it has many. (In the plane there is nothing to build.)
    let recursive = if planar {
        omega_components.clone()
    } else {
        carried(&parent_state.omega_named).components_in(body, frames)
    };
    let omega_named = Vector::new(
        body,
        std::array::from_fn(|axis| {
            let component = &omega_components[axis];
            let label = format!("{name}.w.{}", AXES[axis]);
            // Planar: (q1' + q2')^2 as a student writes it.
            if planar {
                Expr::defined(&label, component.clone())
            } else {
                let shorter = if recursive[axis].terms().len() < component.terms().len() {
                    &recursive[axis]
                } else {
                    component
                };
                omega_component_named(name, axis, component.terms().len(), shorter)
            }
        }),
    );
    let alpha = Vector::new(body, dt_components(&omega_components, path, speeds)?);
    Ok(Angular {
        omega,
        omega_named,
        alpha,
    })
}

/// A spatial angular velocity component for velocity products, `value` being its shortest
/// form and `length` the terms of its longest: short ones multiplied out, so that
/// sin^2 + cos^2 = 1 can simplify them; long ones named, so that the products print as
/// products of three letters.
pub fn omega_component_named(body: &str, axis: usize, length: usize, value: &Expr) -> Expr {
    if length <= MAX_EXPANDED_OMEGA_TERMS {
        return value.clone();
    }
    let axis_name = AXES[axis];
    let tex = format!("\\omega^{{{}}}_{{{axis_name}}}", latex_name(body));
    let note = format!("angular velocity of {body} along {body}.{axis_name}");
    Expr::named(&format!("{body}.w.{axis_name}"), &tex, &note, value.clone())
}

/// The angular velocity and acceleration of `body` from those of `parent` (`parent_state`)
/// and the joint's `relative` angular velocity (body's unit vectors).
///
/// # Errors
/// When the joint's angular velocity is not linear in the rates or cannot be differentiated.
pub fn built(
    problem: &Problem,
    frames: &Frames,
    parent_state: &BodyState,
    (body, parent, form): (BodyId, BodyId, Form),
    relative: &Components,
) -> Result<Angular, String> {
    let rates = problem.speed_symbols(1);
    let accelerations = problem.speed_symbols(2);
    let name = &problem.body(body).name;
    let into_body = frames.dcm(body, parent);
    let not_linear = || "its angular velocity is not linear in the rates".to_string();
    let parent_omega = parent_state.omega.components_in(parent, frames);
    let (from_parent, parent_rest) = split(&parent_omega, &rates).ok_or_else(not_linear)?;
    let (own, own_rest) = split(relative, &rates).ok_or_else(not_linear)?;
    let plain: Vec<Components> = (0..rates.len())
        .map(|r| simplified(sum(&[&apply(&into_body, &from_parent[r]), &own[r]])))
        .collect();
    let rest = simplified(sum(&[&apply(&into_body, &parent_rest), &own_rest]));
    // As in the inertia forces (see `compact`): the coefficients of a long component are
    // named, so that the next body's are built on three names, not on their terms. Once a
    // parent's are named, a child's are long whatever they look like: written on names,
    // their terms no longer count what they would multiply out to. One long axis names all
    // three, so that a child's partials are the same rule for every speed of this body's
    // (ω^c_r = C ω^k_r), written once in the handout. For numbers alone, naming every
    // multi-term partial past the first body is cheapest.
    let numeric_chain = form == Form::Numeric && parent != BodyId::GROUND;
    let parent_by_names = parent_omega.iter().any(|c| c.any_symbol(&is_name));
    let long = numeric_chain
        || parent_by_names
        || (0..3).any(|axis| {
            let terms = plain.iter().filter(|w| !w[axis].is_zero());
            let terms = terms.map(|w| w[axis].terms().len()).sum::<usize>();
            terms + usize::from(!rest[axis].is_zero()) > MAX_EXPANDED_TERMS
        });
    let quantity = Quantity {
        body: name,
        kind: Kind::AngularAcceleration,
    };
    let partials: Vec<Components> = plain
        .iter()
        .zip(&accelerations)
        .map(|(w, acceleration)| {
            std::array::from_fn(|axis| match long {
                true => name_part(&w[axis], &quantity, axis, Some(acceleration)),
                false => w[axis].clone(),
            })
        })
        .collect();
    let by_partials = |derivatives: &[Symbol], rest: &Components| -> Components {
        std::array::from_fn(|axis| {
            let terms = partials
                .iter()
                .zip(derivatives)
                .map(|(w, s)| &w[axis] * &Expr::sym(s.clone()));
            add(terms.chain([rest[axis].clone()]))
        })
    };
    let omega = by_partials(&rates, &rest);
    // The parent's ω, long components by name, carried here.
    let parent_carried = apply(
        &into_body,
        &parent_state.omega_named.components_in(parent, frames),
    );
    let recursive = sum(&[&parent_carried, relative]);
    let omega_named: Components = std::array::from_fn(|axis| {
        // Σ ω_r q̇_r has as many terms as multiplied out when the partials are written
        // whole; by names, it has fewer, and either form counts.
        let forms = [&recursive[axis], &omega[axis]];
        let by_names = partials
            .iter()
            .any(|w| w[axis].as_symbol().is_some_and(is_name));
        let length = match by_names {
            true => forms.iter().map(|c| c.terms().len()).max().unwrap_or(0),
            false => omega[axis].terms().len(),
        };
        let shorter = forms.into_iter().min_by_key(|c| c.terms().len());
        omega_component_named(name, axis, length, shorter.unwrap_or(&omega[axis]))
    });
    let turning = [&parent_carried, &omega_named].map(|w| cross3(w, relative));
    let alpha_rest = alpha_rest(
        problem,
        frames,
        parent_state,
        (body, parent),
        relative,
        &turning,
    )?;
    let alpha_rest = std::array::from_fn(|axis| {
        match long || alpha_rest[axis].terms().len() > MAX_EXPANDED_TERMS {
            true => name_part(&alpha_rest[axis], &quantity, axis, None),
            false => alpha_rest[axis].clone(),
        }
    });
    Ok(Angular {
        omega: Vector::new(body, omega),
        omega_named: Vector::new(body, omega_named),
        alpha: Vector::new(body, by_partials(&accelerations, &alpha_rest)),
    })
}

/// Whether a symbol is a named quantity (a definition).
fn is_name(s: &Symbol) -> bool {
    matches!(s, Symbol::Defined(_))
}

/// `α̃^k = C α̃^p + (the joint's ω' without the q'') + ω^k × ω_rel`, where the last term,
/// which equals `ω^p × ω_rel`, is whichever of `turning` makes the rest shorter.
fn alpha_rest(
    problem: &Problem,
    frames: &Frames,
    parent_state: &BodyState,
    (body, parent): (BodyId, BodyId),
    relative: &Components,
    turning: &[Components; 2],
) -> Result<Components, String> {
    let accelerations = problem.speed_symbols(2);
    let not_linear = || "its angular acceleration is not linear in the q''".to_string();
    let parent_alpha = parent_state.alpha.components_in(parent, frames);
    let (_, parent_rest) = split(&parent_alpha, &accelerations).ok_or_else(not_linear)?;
    let d = |e: &Expr| time_derivative(e).map_err(|e| e.to_string());
    let relative_rate = [d(&relative[0])?, d(&relative[1])?, d(&relative[2])?];
    let (_, own_rest) = split(&relative_rate, &accelerations).ok_or_else(not_linear)?;
    let carried = apply(&frames.dcm(body, parent), &parent_rest);
    let size = |c: &Components| c.iter().map(|e| e.terms().len()).sum::<usize>();
    let [a, b] = turning
        .clone()
        .map(|t| simplified(sum(&[&carried, &own_rest, &t])));
    Ok(if size(&b) < size(&a) { b } else { a })
}
