//! Lagrange's equations as a course teaches them: the kinetic energy of every body, the
//! potential energy and the Lagrangian; the generalized forces of the loads without a
//! potential by virtual work; then per coordinate ∂L/∂q̇_r, its time derivative and ∂L/∂q_r
//! before the collected equation, and the multipliers with the reactions they are.

use crate::equations::Derivation;

/// The plan's note: what the rows are and where the reactions come from.
pub fn plan_note(derivation: &Derivation) -> String {
    let model = &derivation.model;
    let mut note = "One equation per coordinate, d/dt(∂L/∂q̇_r) − ∂L/∂q_r = Q_r, with L = T − V and Q_r the generalized forces of the loads without a potential.".to_string();
    if !model.constraints.rows.is_empty() {
        note.push_str(" Each constraint row brings a multiplier λ_k into every coordinate's equation (Σ_k λ_k ∂f_k/∂q_r, or λ_k times the row's coefficient of q̇_r); a multiplier is the reaction component along the row, and the constraint rows, differentiated, close the system.");
    }
    if derivation
        .reaction_joints
        .iter()
        .any(|&j| j < model.problem.joints.len())
    {
        note.push_str(" A reaction at a joint of the tree does no work: the joint is relaxed along each component asked for (an auxiliary coordinate, zero in the motion), and that coordinate's equation gives the component.");
    }
    note
}
