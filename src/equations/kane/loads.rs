//! The generalized active forces of the loads alone: `Q_r = Σ F · ∂v/∂q̇_r + T · ∂ω/∂q̇_r`
//! over the springs, dampers, applied forces and torques, plus the joint loads' generalized
//! forces. Kane's `F_r` without gravity and reactions, for a tree whose speeds are the
//! coordinates' rates: the joint forces τ the articulated-body algorithm takes
//! ([`crate::numeric::recursive`]), where gravity is the ground's acceleration instead.

use super::partials;
use crate::mechanics::{Model, Vector};
use crate::plan::{is_joint_load, load_generalized_forces, Action, ActionKind, Source};
use crate::problem::BodyId;
use crate::symbolic::{add, Expr, Symbol};

/// `Q_r` for every coordinate's rate, in coordinate order: functions of the constants, the
/// coordinates, their rates and `t`. Zero where no load does work with a rate.
pub fn generalized_forces(model: &Model, actions: &[Action]) -> Vec<Expr> {
    let problem = model.problem;
    let frames = &model.frames;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    // Partial velocities of a body's origin and partial angular velocities, per rate; only
    // for the bodies a load acts on.
    let mut partial: Vec<Option<(Vec<Vector>, Vec<Vector>)>> = vec![None; model.bodies.len()];
    let mut terms: Vec<Vec<Expr>> = load_generalized_forces(model)
        .into_iter()
        .map(|q| vec![q])
        .collect();
    let loads = actions
        .iter()
        .filter(|a| matches!(a.source, Source::Load(_)) && !is_joint_load(model, a));
    for action in loads {
        let body: BodyId = action.body;
        let (origin, omega) = partial[body.0].get_or_insert_with(|| {
            let state = &model.bodies[body.0];
            (
                partials(&state.origin.velocity, &rates),
                partials(&state.omega, &rates),
            )
        });
        for (r, row) in terms.iter_mut().enumerate() {
            let term = match &action.kind {
                ActionKind::Force { offset, force } => {
                    let arm = Vector::new(body, offset.clone());
                    let velocity = origin[r].plus(&omega[r].cross(&arm, frames));
                    force.dot(&velocity, frames)
                }
                ActionKind::Couple { torque } => torque.dot(&omega[r], frames),
            };
            if !term.is_zero() {
                row.push(term);
            }
        }
    }
    terms.into_iter().map(add).collect()
}
