//! A chain body's accelerations built on its parent's named parts, as Kane and Levinson
//! build a chain: each part is the parent's carried into this frame plus the joint's own, a
//! few terms, where written out from `N` it grows with the body's depth.
//!
//! Both accelerations are split as `Σ c_r q̈_r + rest` (see [`super::compact`]):
//! - angular: `ω^k_r = C ω^p_r + the joint's axis`, and
//!   `α̃^k = C α̃^p + (the joint's ω' without the q'') + ω^k × ω_rel`;
//! - mass centre: `v^{k*}_r = C(v^{p*}_r + ω^p_r × r + ḋ_r) + ω^k_r × r'`, and
//!   `ã^{k*} = C(ã^{p*} + α̃^p × r + ω^p × (ω^p × r) + 2 ω^p × ḋ + d̈ without the q'')
//!   + α̃^k × r' + ω^k × (ω^k × r')`,
//!
//! with `r` from the parent's mass centre to the joint, `d` the joint's sliding and `r'` from
//! the joint to this body's mass centre.

use crate::mechanics::compact::{Built, AXES, MAX_EXPANDED_TERMS};
use crate::mechanics::frames::apply;
use crate::mechanics::vector::{cross3, Components};
use crate::mechanics::{Model, Vector};
use crate::problem::BodyId;
use crate::symbolic::{add, latex_name, linear_split, simplify, time_derivative, Expr, Symbol};

/// The angular acceleration of `body` from its parent's as `alphas` names them (in each
/// body's own unit vectors). `None` as for `parent_in_chain`.
pub fn angular(model: &Model, body: BodyId, alphas: &[Components]) -> Option<Built> {
    let parent = parent_in_chain(model, body)?;
    let (accelerations, rates) = symbols(model);
    let relative = model.frames.relative_angular_velocity(body).ok()?;
    let (own, _) = split(&relative, &rates)?;
    let (_, own_rest) = split(&derivative(&relative)?, &accelerations)?;
    let (from_parent, parent_rest) = split(&alphas[parent.0], &accelerations)?;
    let into_body = model.frames.dcm(body, parent);
    let partials = (0..accelerations.len())
        .map(|r| {
            let carried = apply(&into_body, &from_parent[r]);
            simplified(sum(&[&carried, &own[r]]))
        })
        .collect();
    // The joint's relative angular velocity, differentiated in N: in this frame, plus ω × it.
    let omega = own_omega(model, body);
    let turning = cross3(&omega, &relative);
    let carried = apply(&into_body, &parent_rest);
    let rest = simplified(sum(&[&carried, &own_rest, &turning]));
    Some(Built { partials, rest })
}

/// The acceleration of `body`'s mass centre from its parent's as `centers` names it, and
/// the angular accelerations as `alphas` names them. `None` where [`angular`] is.
pub fn center(
    model: &Model,
    body: BodyId,
    centers: &[Vector],
    alphas: &[Components],
) -> Option<Built> {
    let parent = parent_in_chain(model, body)?;
    let j = model.problem.joint_of(body)?;
    let joint = &model.joints[j];
    let (accelerations, rates) = symbols(model);
    let frames = &model.frames;
    let (parent_center, parent_center_rest) = split(
        &centers[parent.0].components_in(parent, frames),
        &accelerations,
    )?;
    let (parent_alpha, parent_alpha_rest) = split(&alphas[parent.0], &accelerations)?;
    let (own_alpha, own_alpha_rest) = split(&alphas[body.0], &accelerations)?;
    let d = &joint.motion.translation;
    let slide_rate = derivative(d)?;
    let (slide, _) = split(&slide_rate, &rates)?;
    let (_, slide_rest) = split(&derivative(&slide_rate)?, &accelerations)?;
    let parent_offset = &model.bodies[parent.0].center_offset;
    let to_joint: Components = std::array::from_fn(|i| &(&joint.at[i] + &d[i]) - &parent_offset[i]);
    let own_offset = &model.bodies[body.0].center_offset;
    let to_center: Components = std::array::from_fn(|i| &own_offset[i] - &joint.child_at[i]);
    let into_body = frames.dcm(body, parent);
    let partials = (0..accelerations.len())
        .map(|r| {
            let across = cross3(&parent_alpha[r], &to_joint);
            let at_joint = sum(&[&parent_center[r], &across, &slide[r]]);
            let carried = apply(&into_body, &at_joint);
            let turning = cross3(&own_alpha[r], &to_center);
            simplified(sum(&[&carried, &turning]))
        })
        .collect();
    let parent_omega = own_omega(model, parent);
    let omega = own_omega(model, body);
    let across = cross3(&parent_alpha_rest, &to_joint);
    let centripetal = cross3(&parent_omega, &cross3(&parent_omega, &to_joint));
    let coriolis = cross3(&parent_omega, &slide_rate).map(|c| &Expr::int(2) * &c);
    let at_joint = sum(&[
        &parent_center_rest,
        &across,
        &centripetal,
        &coriolis,
        &slide_rest,
    ]);
    let joint_name = &model.problem.joints[j].name;
    let at_joint = joint_point_names(joint_name, frames.name(parent), simplified(at_joint));
    let carried = apply(&into_body, &at_joint);
    let turning = cross3(&own_alpha_rest, &to_center);
    let centripetal = cross3(&omega, &cross3(&omega, &to_center));
    let rest = simplified(sum(&[&carried, &turning, &centripetal]));
    Some(Built { partials, rest })
}

/// The joint point's acceleration without the q'' (in the parent's unit vectors), each long
/// component a named quantity: carried into the child's frame, the direction cosines then
/// multiply three names, not every term of the parent's motion.
fn joint_point_names(joint: &str, parent: &str, at_joint: Components) -> Components {
    if at_joint
        .iter()
        .all(|c| c.terms().len() <= MAX_EXPANDED_TERMS)
    {
        return at_joint;
    }
    std::array::from_fn(|axis| {
        let (value, axis) = (&at_joint[axis], AXES[axis]);
        if value.terms().len() < 2 {
            return value.clone();
        }
        Expr::named(
            &format!("{joint}.a.{axis}"),
            &format!("\\tilde{{a}}^{{{}}}_{{{axis}}}", latex_name(joint)),
            &format!(
                "acceleration of the joint point {joint} along {parent}.{axis} without the q''"
            ),
            value.clone(),
        )
    })
}

/// The parent whose named parts a body's are built on: `None` for a child of `N`, or with
/// declared speeds, whose kinematic equations mix the rates.
fn parent_in_chain(model: &Model, body: BodyId) -> Option<BodyId> {
    let parent = model.frames.info(body).parent?;
    // A body written in a frame that does not spin is written from that frame's turning.
    let own_frame = model.bodies[body.0].frame == body;
    let built = parent != BodyId::GROUND && model.speeds.is_none() && own_frame;
    built.then_some(parent)
}

/// The q̈ and the q̇ of the problem.
fn symbols(model: &Model) -> (Vec<Symbol>, Vec<Symbol>) {
    (
        model.problem.speed_symbols(2),
        model.problem.speed_symbols(1),
    )
}

/// The angular velocity of `body` in its own unit vectors, long components by name.
fn own_omega(model: &Model, body: BodyId) -> Components {
    model.bodies[body.0]
        .omega_named
        .components_in(body, &model.frames)
}

/// The sum of `parts`, component by component.
pub(super) fn sum(parts: &[&Components]) -> Components {
    std::array::from_fn(|i| add(parts.iter().map(|p| p[i].clone())))
}

/// Each component simplified.
pub(super) fn simplified(c: Components) -> Components {
    c.map(|e| simplify(&e))
}

/// d/dt of each component.
fn derivative(c: &Components) -> Option<Components> {
    Some([
        time_derivative(&c[0]).ok()?,
        time_derivative(&c[1]).ok()?,
        time_derivative(&c[2]).ok()?,
    ])
}

/// For every unknown its coefficient in each component, and what is left.
pub fn split(c: &Components, unknowns: &[Symbol]) -> Option<(Vec<Components>, Components)> {
    let mut by_unknown: Vec<Components> =
        vec![std::array::from_fn(|_| Expr::zero()); unknowns.len()];
    let mut rest: Components = std::array::from_fn(|_| Expr::zero());
    for axis in 0..3 {
        let (coefficients, left) = linear_split(&c[axis], unknowns).ok()?;
        for (r, coefficient) in coefficients.into_iter().enumerate() {
            by_unknown[r][axis] = coefficient;
        }
        rest[axis] = left;
    }
    Some((by_unknown, rest))
}
