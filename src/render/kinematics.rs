//! Step 4's vectors: each body's angular velocity and acceleration and its mass centre's
//! velocity and acceleration, in the shortest of their multiplied-out and named forms.

use super::context::Kinematics;
use super::derived::{component_term, shortest_tex, vector_tex_by};
use crate::equations::Derivation;
use crate::mechanics::model::{same_at, sample_states};
use crate::mechanics::{Model, Vector};
use crate::problem::BodyId;
use crate::symbolic::collect::{factored, pull_common_factor};
use crate::symbolic::linear::linear_split;
use crate::symbolic::print::latex_name;
use crate::symbolic::simplify::simplify;
use crate::symbolic::{add, Expr};

pub(super) fn kinematics(derivation: &Derivation) -> Vec<Kinematics> {
    let model = &derivation.model;
    let inertia = &derivation.inertia;
    // The shorter of the vector multiplied out and as the equations use it (named parts).
    let shorter = |expanded: &Vector, named: &Vector, body: BodyId| {
        let b = shortest_tex(model, named, body);
        // Multiplied out to many times the named form's size, a vector cannot come out the
        // shorter, and simplifying it (in three frames) is most of a large handout's time.
        if expanded.operation_count() > 4 * named.operation_count().max(100) {
            return b;
        }
        let a = shortest_tex(model, expanded, body);
        if b.len() < a.len() {
            b
        } else {
            a
        }
    };
    model
        .order
        .iter()
        .map(|&body| {
            let state = &model.bodies[body.0];
            let name = model.problem.body_name(body);
            let symbol = latex_name(name);
            let direct_velocity =
                match by_partial_velocities(model, &inertia.acceleration[body.0], body) {
                    Some(named) => shorter(&state.center.velocity, &named, body),
                    None => shortest_tex(model, &state.center.velocity, body),
                };
            let direct_acceleration = shorter(
                &state.center.acceleration,
                &inertia.acceleration[body.0],
                body,
            );
            let (omega_tex, alpha_tex) = one_line_if_short(
                format!(
                    "{{}}^{{N}}\\boldsymbol{{\\omega}}^{{{symbol}}} = {}",
                    shorter(&state.omega, &state.omega_named, body)
                ),
                format!(
                    "{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{{symbol}}} = {}",
                    shorter(&state.alpha, &inertia.alpha[body.0], body)
                ),
            );
            let (velocity_tex, acceleration_tex) = one_line_if_short(
                format!(
                    "{{}}^{{N}}\\mathbf{{v}}^{{{symbol}^*}} = {}",
                    from_parent(model, body, Motion::Velocity, direct_velocity)
                ),
                format!(
                    "{{}}^{{N}}\\mathbf{{a}}^{{{symbol}^*}} = {}",
                    from_parent(model, body, Motion::Acceleration, direct_acceleration)
                ),
            );
            Kinematics {
                body: name.to_string(),
                omega_tex,
                alpha_tex,
                velocity_tex,
                acceleration_tex,
            }
        })
        .collect()
}

/// A pair such as ω and α, or v* and a*, in one display, `ω = …, α = …`, when together they
/// fit most of a line, as a textbook sets a pair of short results; else each in its own
/// (the second's then empty here).
fn one_line_if_short(first: String, second: String) -> (String, String) {
    const MOST_OF_A_LINE: usize = 60;
    if super::math_width::printed_width(&first) + super::math_width::printed_width(&second)
        <= MOST_OF_A_LINE
    {
        (format!("{first}, \\qquad {second}"), String::new())
    } else {
        (first, second)
    }
}

/// The mass centre's velocity as `Σ v_r q̇_r`, with the partial velocities named in its
/// acceleration `Σ v_r q̈_r + ã` (∂a/∂q̈_r = ∂v/∂q̇_r), or `None` when the velocity has a part
/// the rates do not carry (a driven coordinate's time) or a coefficient differs.
fn by_partial_velocities(model: &Model, acceleration: &Vector, body: BodyId) -> Option<Vector> {
    let rates = model.problem.speed_symbols(1);
    let accelerations = model.problem.speed_symbols(2);
    let velocity = model.bodies[body.0]
        .center
        .velocity
        .components_in(body, &model.frames);
    let named = acceleration.components_in(body, &model.frames);
    let states = sample_states(model);
    let mut components = Vec::with_capacity(3);
    for (v, a) in velocity.iter().zip(&named) {
        let (by_rate, rest) = linear_split(&simplify(v), &rates).ok()?;
        let (partials, _) = linear_split(a, &accelerations).ok()?;
        if !rest.is_zero() {
            return None;
        }
        let mut terms = Vec::with_capacity(rates.len());
        for ((partial, expanded), rate) in partials.iter().zip(&by_rate).zip(&rates) {
            // The named partial may be built on its parent's: compared by value at the
            // planner's sample states, where an identity holds and a slip would not.
            if !same_at(partial, expanded, &states) {
                return None;
            }
            terms.push(partial * &Expr::sym(rate.clone()));
        }
        components.push(add(terms));
    }
    let components: [Expr; 3] = components.try_into().ok()?;
    Some(Vector::new(body, components))
}

/// The mass centre's velocity or acceleration.
#[derive(Clone, Copy)]
enum Motion {
    Velocity,
    Acceleration,
}

/// `direct`, or, when shorter, the same vector as the parent's mass centre's plus the
/// difference, each part in its own unit vectors: down a chain, `v^{k*} = v^{(k-1)*} + …` is
/// a few terms where the vector written out grows with k.
fn from_parent(model: &Model, body: BodyId, motion: Motion, direct: String) -> String {
    let Some(parent) = model
        .frames
        .info(body)
        .parent
        .filter(|p| *p != BodyId::GROUND)
    else {
        return direct;
    };
    let of = |b: BodyId| {
        let center = &model.bodies[b.0].center;
        match motion {
            Motion::Velocity => &center.velocity,
            Motion::Acceleration => &center.acceleration,
        }
    };
    let difference = of(body).minus(of(parent));
    let (letter, parent_name) = (
        match motion {
            Motion::Velocity => "v",
            Motion::Acceleration => "a",
        },
        latex_name(model.problem.body_name(parent)),
    );
    let mut text = format!("{{}}^{{N}}\\mathbf{{{letter}}}^{{{parent_name}^*}}");
    if !difference.is_zero() {
        // (L/2)(q̇1 + … + q̇6) as a textbook writes it.
        let rest = vector_tex_by(model, &difference, |c, unit| {
            let (common, inner) = pull_common_factor(c);
            if c.terms().len() > 1 && !common.is_one() {
                factored(&common, &inner, unit)
            } else {
                component_term(c, unit)
            }
        });
        match rest.strip_prefix('-') {
            Some(negative) => text.push_str(&format!(" - {negative}")),
            None => text.push_str(&format!(" + {rest}")),
        }
    }
    if text.len() < direct.len() {
        text
    } else {
        direct
    }
}
