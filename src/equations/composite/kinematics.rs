//! Each body's motion without the q'', built on its parent's from the root out, as the
//! recursive Newton–Euler algorithm's forward pass builds it: the angular velocity, the
//! angular acceleration and the acceleration of the child's point at its joint, each in
//! the body's own unit vectors and named, so that every body costs the same few products
//! however deep it sits.
//!
//! With `C` the joint's direction cosines (body <- parent), `ω_rel` the joint's relative
//! angular velocity, `d` its sliding (parent's unit vectors) and `r` the joint's point from
//! the parent's joint point:
//!
//! ```text
//! ω   = C ω_p + ω_rel
//! α̃   = C α̃_p + (d/dt ω_rel in the body, without the q'') + (C ω_p) × ω_rel
//! ã_O = C (ã_Op + α̃_p × r + ω_p × (ω_p × r) + 2 ω_p × ḋ + d̈ without the q'')
//! ```
//!
//! Gravity enters as an acceleration `−g` of the ground: every body's inertia force then
//! carries its weight, `−m (a − g)`, and no body needs `g` in its own unit vectors.

use super::tree::{apply, derivative, named_components, named_dcm, sum};
use crate::mechanics::{cross3, split, zero3, Components, Model};
use crate::problem::BodyId;
use crate::symbolic::Expr;

/// One body's motion without the q'', in its own unit vectors.
#[derive(Clone)]
pub struct BodyMotion {
    /// The angular velocity (all of it: it holds no q'').
    pub omega: Components,
    /// The angular acceleration without the q''.
    pub alpha: Components,
    /// The acceleration of the body's point at its joint without the q'', gravity's `−g`
    /// included.
    pub joint_point: Components,
}

/// The motion of the child of every joint, indexed like the problem's joints; `None` when
/// a joint's motion cannot be differentiated.
pub fn body_motions(model: &Model) -> Option<Vec<BodyMotion>> {
    let problem = model.problem;
    let mut motions: Vec<Option<BodyMotion>> = vec![None; problem.joints.len()];
    let gravity = match &problem.gravity {
        Some(g) => crate::mechanics::vector_of(g)
            .components_in(BodyId::GROUND, &model.frames)
            .map(|c| -c),
        None => zero3(),
    };
    for &body in &model.order {
        let Some(k) = problem.joint_of(body) else {
            continue;
        };
        let parent = problem.joints[k].parent;
        let inner = match problem.joint_of(parent) {
            Some(p) => {
                let motion = motions[p].clone()?;
                Some((p, motion))
            }
            None => None,
        };
        motions[k] = Some(body_motion(model, k, inner.as_ref(), &gravity)?);
    }
    motions.into_iter().collect()
}

/// The motion of joint `k`'s child from its parent's (`inner`: the parent's joint and
/// motion, `None` for the ground, whose acceleration is `ground`).
fn body_motion(
    model: &Model,
    k: usize,
    inner: Option<&(usize, BodyMotion)>,
    ground: &Components,
) -> Option<BodyMotion> {
    let problem = model.problem;
    let joint = &problem.joints[k];
    let (body, parent) = (joint.child, joint.parent);
    let accelerations = problem.speed_symbols(2);
    let turn = named_dcm(model, body, parent);
    // The joint's own turning and sliding, from its coordinates alone.
    let relative = model.frames.relative_angular_velocity(body).ok()?;
    let (_, turning_rate) = split(&derivative(&relative)?, &accelerations)?;
    let sliding = &model.joints[k].motion.translation;
    let sliding_rate = derivative(sliding)?;
    let (_, sliding_acceleration) = split(&derivative(&sliding_rate)?, &accelerations)?;
    let (omega, alpha, joint_point) = match inner {
        None => {
            let at_joint = sum(ground, &sliding_acceleration);
            (relative, turning_rate, apply(&turn, &at_joint))
        }
        Some((p, from)) => {
            let carried = apply(&turn, &from.omega);
            let omega = sum(&carried, &relative);
            let alpha = sum(
                &sum(&apply(&turn, &from.alpha), &turning_rate),
                &cross3(&carried, &relative),
            );
            let r = super::tree::joint_offset(model, k, &model.joints[*p].child_at);
            let w = &from.omega;
            let coriolis = cross3(w, &sliding_rate).map(|c| &Expr::int(2) * &c);
            let at_joint = [
                &from.joint_point,
                &cross3(&from.alpha, &r),
                &cross3(w, &cross3(w, &r)),
                &coriolis,
                &sliding_acceleration,
            ]
            .into_iter()
            .fold(zero3(), |total, part| sum(&total, part));
            (omega, alpha, apply(&turn, &at_joint))
        }
    };
    let what =
        |quantity: &str| format!("{quantity} of {}, without the q''", model.frames.name(body));
    Some(BodyMotion {
        omega: named_components(
            model,
            body,
            ("w", "\\omega", &what("angular velocity")),
            omega,
        ),
        alpha: named_components(
            model,
            body,
            ("alpha", "\\tilde{\\alpha}", &what("angular acceleration")),
            alpha,
        ),
        joint_point: named_components(
            model,
            body,
            (
                "a",
                "\\tilde{a}",
                &what("acceleration of the joint point, with −g,"),
            ),
            joint_point,
        ),
    })
}
