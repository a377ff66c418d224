//! Two-force members: a particle hung on a light rod from its joint, with every other force
//! on it acting at the particle, takes its joint's force along the rod (the moment of that
//! force about the particle is zero: the particle has no rotational inertia and every other
//! force passes through it). Kane's method then writes that force as one unknown, the rod's
//! tension, as a textbook does, instead of its components.

use super::joints::ReactionComponent;
use super::site::SiteKind;
use super::vector::{zero3, Components, Vector};
use super::Model;
use crate::problem::{BodyId, ForcePoint, LoadKind, PointRef, Problem};
use crate::symbolic::{eval, Axis, ComponentKind, Expr};

/// Gives every joint whose child is a two-force member one force unknown along the member
/// (its tension, `T^O`) in place of its force components; returns the joints' names.
pub fn along_members(model: &mut Model) -> Vec<String> {
    let mut changed = Vec::new();
    for s in 0..model.sites.len() {
        let Some(direction) = member_direction(model, s) else {
            continue;
        };
        let site = &mut model.sites[s];
        site.reactions = vec![ReactionComponent {
            kind: ComponentKind::Force,
            axis: Axis::Member,
            direction,
        }];
        changed.push(site.name.clone());
    }
    changed
}

/// The unit vector from the particle toward the joint of site `s`, when the site's child
/// is a two-force member and its reaction is a force alone.
fn member_direction(model: &Model, s: usize) -> Option<Vector> {
    let problem = model.problem;
    let site = &model.sites[s];
    let SiteKind::Joint(j) = site.kind else {
        return None;
    };
    let body = site.child;
    let state = &model.bodies[body.0];
    let is_particle = state.inertia.iter().flatten().all(Expr::is_zero);
    let forces_only = site
        .reactions
        .iter()
        .all(|r| r.kind == ComponentKind::Force);
    let plain = problem.closures.is_empty()
        && problem.constraints.is_empty()
        && problem.joints[j]
            .coordinates
            .iter()
            .all(|&c| problem.coordinates[c].motion.is_none());
    if !is_particle || state.mass.is_zero() || !forces_only || !plain || loaded(problem, body, j) {
        return None;
    }
    let values = &model.values;
    let number = |e: &Expr| eval(e, values);
    // Every other joint of the body holds a child at the particle.
    let at_particle = model.sites.iter().all(|other| {
        other.parent != body
            || (0..3)
                .all(|k| number(&(&other.parent_offset[k] - &state.center_offset[k])).abs() < 1e-12)
    });
    if !at_particle {
        return None;
    }
    // Along one unit vector of the body, from the particle to the joint.
    let reach: [f64; 3] =
        std::array::from_fn(|k| number(&(&site.child_offset[k] - &state.center_offset[k])));
    unit_along(body, reach)
}

/// The unit vector of `body` that `reach` (in its unit vectors) points along, when it
/// points along one.
pub(crate) fn unit_along(body: BodyId, reach: [f64; 3]) -> Option<Vector> {
    let along: Vec<usize> = (0..3).filter(|&k| reach[k].abs() > 1e-12).collect();
    let [k] = along[..] else {
        return None;
    };
    let mut unit: Components = zero3();
    unit[k] = Expr::int(if reach[k] > 0.0 { 1 } else { -1 });
    Some(Vector::new(body, unit))
}

/// Whether a load acts on `body` or on joint `j` (then more than the member's forces act).
pub(crate) fn loaded(problem: &Problem, body: BodyId, j: usize) -> bool {
    let on_body = |p: &PointRef| match *p {
        PointRef::Named(i) => problem.points[i].on == body,
        PointRef::MassCenter(b) | PointRef::Origin(b) => b == body,
        PointRef::Joint(i) => problem.joints[i].child == body,
    };
    problem.loads.iter().any(|load| match &load.kind {
        LoadKind::Force { on, at, .. } => {
            *on == body || matches!(at, ForcePoint::Point(p) if on_body(p))
        }
        LoadKind::Torque {
            on, reaction_on, ..
        } => *on == body || *reaction_on == Some(body),
        LoadKind::Spring { between, .. } | LoadKind::Damper { between, .. } => {
            between.iter().any(on_body)
        }
        LoadKind::JointSpring { joint, .. }
        | LoadKind::JointDamper { joint, .. }
        | LoadKind::JointActuator { joint, .. } => {
            *joint == j || problem.joints[*joint].parent == body
        }
    })
}
