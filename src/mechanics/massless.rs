//! Massless bodies (`mass: 0`): a light link, collar or pulley carries no weight and no
//! inertia, so a coordinate that moves only massless bodies, with nothing else to fix it,
//! leaves its q'' undetermined. The structural case is caught while building the model
//! (so `check` reports it too); the derivation names the body when its equations fall
//! short for the same reason.

use super::error::MechanicsError;
use super::model::Model;
use crate::problem::{BodyId, ConstraintKind};
use crate::symbolic::eval;

/// `q3'' is undetermined: body C has no mass and nothing else fixes it`.
pub fn undetermined(coordinate: &str, body: &str) -> String {
    format!("`{coordinate}''` is undetermined: body {body} has no mass and nothing else fixes it")
}

/// Whether `body` has mass 0 with the constants' values.
pub fn is_massless(model: &Model, body: BodyId) -> bool {
    body != BodyId::GROUND && eval(&model.problem.body(body).mass, &model.values) == 0.0
}

/// Whether a body is a particle: no central moment of inertia, so no inertia torque and
/// no partial angular velocity worth printing.
pub fn is_particle(model: &Model, body: BodyId) -> bool {
    model.bodies[body.0]
        .inertia
        .iter()
        .flatten()
        .all(crate::symbolic::Expr::is_zero)
}

/// Whether a body is named as a particle, a point: a particle that no joint, closure or
/// contact holds against turning. A body without moment of inertia that carries a reaction
/// couple (a rack or a cart on its guide) is a translating body of some extent, named by
/// its mass centre as any other body.
pub fn is_point_particle(model: &Model, body: BodyId) -> bool {
    let held = model.sites.iter().any(|site| {
        site.parent != site.child
            && (site.child == body || site.parent == body)
            && (site.reactions.iter()).any(|c| c.kind == super::ComponentKind::Moment)
    });
    is_particle(model, body) && !held
}

/// A massless body that coordinate `i` moves (its joint's child or a body outboard of it).
pub fn massless_body_moved_by(model: &Model, i: usize) -> Option<BodyId> {
    let j = model
        .problem
        .joints
        .iter()
        .position(|joint| joint.coordinates.contains(&i))?;
    model
        .subtree(j)
        .into_iter()
        .find(|&b| is_massless(model, b))
}

/// A joint coordinate whose joint carries only massless bodies, touched by no closure,
/// rolling contact or constraint and not prescribed: nothing determines its q''.
///
/// # Errors
/// The first such coordinate, named with its body, at the body's mass.
pub fn check(model: &Model) -> Result<(), MechanicsError> {
    let problem = model.problem;
    if problem.constraints.iter().any(|c| {
        matches!(
            c.kind,
            ConstraintKind::Position { .. } | ConstraintKind::Velocity { .. }
        )
    }) {
        // A general constraint may fix any coordinate: the derivation judges those.
        return Ok(());
    }
    for (j, joint) in problem.joints.iter().enumerate() {
        let subtree = model.subtree(j);
        if !subtree.iter().all(|&b| is_massless(model, b)) {
            continue;
        }
        let touched = problem
            .closures
            .iter()
            .any(|c| subtree.contains(&c.parent) || subtree.contains(&c.child))
            || problem.constraints.iter().any(|c| match &c.kind {
                ConstraintKind::Rolling { body, on, .. } => {
                    subtree.contains(body) || subtree.contains(on)
                }
                _ => true,
            });
        if touched {
            continue;
        }
        let free = joint
            .coordinates
            .iter()
            .find(|&&i| problem.coordinates[i].motion.is_none());
        if let Some(&i) = free {
            let body = problem.body(joint.child);
            return Err(MechanicsError {
                path: format!("{}.mass", body.path),
                message: undetermined(&problem.coordinates[i].name, &body.name),
                hint: Some(format!(
                    "give body {} a mass, or connect it (a closure, a rolling contact) so that the rest of the system fixes `{}`",
                    body.name, problem.coordinates[i].name
                )),
            });
        }
    }
    Ok(())
}
