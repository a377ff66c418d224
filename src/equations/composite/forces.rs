//! What Kane's rows hold besides the q'': the generalized active forces and the inertia
//! forces without the q'', from resultants carried in from the leaves, as the recursive
//! Newton–Euler algorithm's backward pass carries them.
//!
//! For a speed `r` of joint `i` the row's rest is `Q_r + u_r · F_i + ω_r · M_i` (see
//! [`super`]), with `Q_r` the joint loads' generalized force, and `F_i` and `M_i` the
//! resultant and the moment about the joint's point of every force and couple on the bodies
//! outboard of `i`, the inertia forces and torques without the q'' included (weights
//! included, see [`super::kinematics`]). Each joint's are its child's own plus those of the
//! joints the child carries, carried in: n work, where the rows dot every body's forces with
//! every speed's partial velocities.

use super::kinematics::BodyMotion;
use super::tree::{
    carried_by, carried_in, leaves_first, named_components, named_vector, sum, SpeedMotion,
};
use crate::mechanics::{apply, cross3, Components, Model, Vector};
use crate::plan::{is_joint_load, joint_load_generalized_forces, Action, ActionKind, Source};
use crate::symbolic::{add, Expr};

/// The forces on the bodies outboard of a joint: their resultant and their moment about the
/// joint's point with the couples, in its child's unit vectors (and its parent's, where a
/// force was given in those).
#[derive(Clone)]
pub struct Resultant {
    /// The resultant.
    pub force: Vector,
    /// The moment about the joint's point.
    pub moment: Vector,
}

/// Every joint's resultant, from the leaves in, on the bodies' `motions` (indexed by
/// joint); `None` when an action is one these resultants do not take (a reaction outside
/// the tree's joints).
pub fn resultants(
    model: &Model,
    actions: &[Action],
    motions: &[BodyMotion],
) -> Option<Vec<Resultant>> {
    let problem = model.problem;
    let mut resultants: Vec<Option<Resultant>> = vec![None; problem.joints.len()];
    for j in leaves_first(model) {
        resultants[j] = Some(resultant(model, actions, &motions[j], j, &resultants)?);
    }
    resultants.into_iter().collect()
}

/// The rest of each of Kane's rows (what the row holds besides the q''), indexed by speed.
pub fn rests(model: &Model, resultants: &[Resultant], speeds: &[Vec<SpeedMotion>]) -> Vec<Expr> {
    let mut rows = joint_load_generalized_forces(model);
    for (j, own) in speeds.iter().enumerate() {
        let body = model.problem.joints[j].child;
        let Resultant { force, moment } = &resultants[j];
        for r in own {
            rows[r.speed] = add([rows[r.speed].clone(), r.dot(model, body, (force, moment))]);
        }
    }
    rows
}

/// The resultant of joint `j`: the actions on its child and the child's inertia force and
/// torque without the q'' (from its `motion`), and the resultants of the joints the child
/// carries (`outer`).
fn resultant(
    model: &Model,
    actions: &[Action],
    motion: &BodyMotion,
    j: usize,
    outer: &[Option<Resultant>],
) -> Option<Resultant> {
    let problem = model.problem;
    let child = problem.joints[j].child;
    let point = &model.joints[j].child_at;
    let (mut forces, mut moments) = applied(model, actions, j)?;
    let (force, moment) = inertia(model, j, motion);
    forces.push(Vector::new(child, force));
    moments.push(Vector::new(child, moment));
    for c in carried_by(model, child) {
        let Some(carried) = &outer[c] else {
            continue;
        };
        let (force, moment) = carried_in(model, c, point, (&carried.force, &carried.moment));
        forces.push(Vector::new(child, force));
        moments.push(Vector::new(child, moment));
    }
    let name = model.frames.name(child);
    let what = |kind: &str| format!("{kind} on {name} and the bodies it carries, without the q''");
    Some(Resultant {
        force: named_vector(
            model,
            child,
            ("F", "F", &what("resultant of the forces")),
            &Vector::sum(forces),
        ),
        moment: named_vector(
            model,
            child,
            ("M", "M", &what("moment about its joint of the forces")),
            &Vector::sum(moments),
        ),
    })
}

/// The inertia force of joint `j`'s child without the q'' (its weight included), and its
/// moment about the joint's point with the inertia torque: `f = −m ã*` with
/// `ã* = ã_O + α̃ × ρ + ω × (ω × ρ)`, and `ρ × f − (I α̃ + ω × I ω)`, `ρ` the mass centre from
/// the joint's point.
fn inertia(model: &Model, j: usize, motion: &BodyMotion) -> (Components, Components) {
    let child = model.problem.joints[j].child;
    let state = &model.bodies[child.0];
    let point = &model.joints[j].child_at;
    let rho: Components = std::array::from_fn(|i| &state.center_offset[i] - &point[i]);
    let (w, alpha) = (&motion.omega, &motion.alpha);
    let center = [
        &motion.joint_point,
        &cross3(alpha, &rho),
        &cross3(w, &cross3(w, &rho)),
    ]
    .into_iter()
    .fold(crate::mechanics::zero3(), |total, part| sum(&total, part));
    let name = model.frames.name(child);
    let what = format!("acceleration of {name}* with −g, without the q''");
    let center = named_components(model, child, ("ac", "\\tilde{a}^{*}", &what), center);
    let force: Components = std::array::from_fn(|i| -(&state.mass * &center[i]));
    let spin = sum(
        &apply(&state.inertia, alpha),
        &cross3(w, &apply(&state.inertia, w)),
    );
    let moment = std::array::from_fn(|i| &cross3(&rho, &force)[i] - &spin[i]);
    (force, moment)
}

/// The forces that act on joint `j`'s child and do work with the speeds, and their moments
/// about the joint's point with the couples. Weights are in the inertia forces, joint loads
/// in `Q_r`; reactions at the tree's joints do no work. `None` for a reaction elsewhere.
fn applied(model: &Model, actions: &[Action], j: usize) -> Option<(Vec<Vector>, Vec<Vector>)> {
    let joints = model.problem.joints.len();
    let on_child = actions
        .iter()
        .filter(|a| a.body == model.problem.joints[j].child);
    let mut working = Vec::new();
    for action in on_child {
        match action.source {
            Source::Gravity => continue,
            Source::Reaction(site) if site < joints => continue,
            Source::Reaction(_) => return None,
            _ if is_joint_load(model, action) => continue,
            _ => working.push(action),
        }
    }
    Some(moments_about_joint(model, j, working))
}

/// The forces of `actions` on joint `j`'s child, each part in the child's unit vectors or
/// its parent's, and their moments about the joint's point with the couples.
pub(super) fn moments_about_joint<'a>(
    model: &Model,
    j: usize,
    actions: impl IntoIterator<Item = &'a Action>,
) -> (Vec<Vector>, Vec<Vector>) {
    let frames = &model.frames;
    let joint = &model.problem.joints[j];
    let point = &model.joints[j].child_at;
    let near = |v: &Vector| -> Vector {
        let parts = v.parts().iter().map(|(frame, c)| match *frame {
            f if f == joint.child || f == joint.parent => Vector::new(f, c.clone()),
            f => Vector::new(joint.child, frames.express(c, f, joint.child)),
        });
        Vector::sum(parts)
    };
    let (mut forces, mut moments) = (Vec::new(), Vec::new());
    for action in actions {
        match &action.kind {
            ActionKind::Force { offset, force } => {
                let force = near(force);
                let arm: Components = std::array::from_fn(|i| &offset[i] - &point[i]);
                moments.push(Vector::new(joint.child, arm).cross(&force, frames));
                forces.push(force);
            }
            ActionKind::Couple { torque } => moments.push(near(torque)),
        }
    }
    (forces, moments)
}
