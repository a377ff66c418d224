//! The generalized forces of Lagrange's equations by virtual work,
//! `Q_r = Σ F·∂v/∂q̇_r + Σ T·∂ω/∂q̇_r`: the loads without a potential (applied forces and
//! torques, dampers, joint dampers and actuators, friction), and apart from them the
//! constraint forces' share, which brings in the multipliers.

use super::energy::rates_of;
use crate::equations::kane::partials;
use crate::mechanics::{Model, Vector};
use crate::plan::{
    constraint_generalized_forces, is_joint_load, joint_load_value, Action, ActionKind, Source,
};
use crate::problem::{BodyId, LoadKind};
use crate::symbolic::{add, Expr, Symbol};

/// What an action is to Lagrange's equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Has a potential, in `V` (gravity, a spring).
    Potential,
    /// A load without a potential: in `Q_r`.
    Load,
    /// A constraint force whose components are multipliers (a closure, a contact).
    Multiplier,
    /// Does no work with the coordinates (a tree joint's reaction), or is taken per
    /// coordinate instead (a joint load, what enforces a row without a site).
    Left,
}

/// The role of `action`.
pub fn role(model: &Model, action: &Action) -> Role {
    if is_joint_load(model, action) {
        return Role::Left;
    }
    match action.source {
        Source::Gravity => Role::Potential,
        Source::Load(i) => match model.problem.loads[i].kind {
            LoadKind::Spring { .. } => Role::Potential,
            LoadKind::Force { .. } if crate::equations::has_potential(model, i) => Role::Potential,
            _ => Role::Load,
        },
        Source::Reaction(j) if j < model.problem.joints.len() => Role::Left,
        Source::Reaction(_) => Role::Multiplier,
        Source::Constraint(_) => Role::Left,
    }
}

/// The partial velocity of the point of `action` (or partial angular velocity of its body,
/// for a couple) for each coordinate's rate.
pub fn partial_velocities(model: &Model, action: &Action) -> Vec<Vector> {
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    let in_rates = rates_of(model);
    let body: BodyId = action.body;
    let state = &model.bodies[body.0];
    let omega = partials(&state.omega.map(&in_rates), &rates);
    match &action.kind {
        ActionKind::Force { offset, .. } => {
            let origin = partials(&state.origin.velocity.map(&in_rates), &rates);
            let arm = Vector::new(body, offset.clone());
            origin
                .iter()
                .zip(&omega)
                .map(|(o, w)| o.plus(&w.cross(&arm, &model.frames)))
                .collect()
        }
        ActionKind::Couple { .. } => omega,
    }
}

/// The virtual work of `action` per coordinate: `F·∂v/∂q̇_r` or `T·∂ω/∂q̇_r`.
pub fn virtual_work(model: &Model, action: &Action) -> Vec<Expr> {
    let vector = match &action.kind {
        ActionKind::Force { force, .. } => force,
        ActionKind::Couple { torque } => torque,
    };
    partial_velocities(model, action)
        .iter()
        .map(|p| vector.dot(p, &model.frames))
        .collect()
}

/// The generalized forces on the coordinates directly: the joint loads but the joint
/// springs (in `V`), and the friction of rough sliders.
pub fn joint_generalized_forces(model: &Model) -> Vec<Expr> {
    let problem = model.problem;
    let mut q = vec![Expr::zero(); problem.coordinates.len()];
    for load in &problem.loads {
        if matches!(load.kind, LoadKind::JointSpring { .. }) {
            continue;
        }
        if let Some((_, c, value)) = joint_load_value(problem, &load.kind) {
            q[c] = &q[c] + &value;
        }
    }
    crate::equations::friction::add_friction_forces(model, &mut q, true);
    q
}

/// Per coordinate, `(Q_r, multipliers' share)`: the loads without a potential, and the
/// constraint forces (`λ ∂f/∂q̇_r` for a row without a site, a closure's or contact's
/// reaction components along the partial velocity of its point).
pub fn generalized_forces(model: &Model, actions: &[Action]) -> Vec<(Expr, Expr)> {
    let n = model.problem.coordinates.len();
    let mut loads: Vec<Vec<Expr>> = joint_generalized_forces(model)
        .into_iter()
        .map(|q| vec![q])
        .collect();
    let mut multipliers: Vec<Vec<Expr>> = vec![Vec::new(); n];
    for (coordinates, values) in constraint_generalized_forces(model) {
        for (c, value) in coordinates.into_iter().zip(values) {
            multipliers[c].push(value);
        }
    }
    for action in actions {
        let target = match role(model, action) {
            Role::Load => &mut loads,
            Role::Multiplier => &mut multipliers,
            Role::Potential | Role::Left => continue,
        };
        for (r, term) in virtual_work(model, action).into_iter().enumerate() {
            if !term.is_zero() {
                target[r].push(term);
            }
        }
    }
    loads
        .into_iter()
        .zip(multipliers)
        .map(|(q, m)| (add(q), add(m)))
        .collect()
}
