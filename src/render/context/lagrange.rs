//! Lagrange's equations in the worked solution as plain data: step 2's energies and the
//! generalized forces of the loads without a potential, and the multipliers of step 5.

use crate::render::text::{MarkupLine, Math};
use serde::Serialize;

/// Step 2 by Lagrange's equations.
#[derive(Clone, Debug, Default, Serialize)]
pub struct LagrangeView {
    /// The kinetic energy of each body, then `T`, `V` and `L = T − V`, one equation each.
    pub energy_tex: Vec<Math>,
    /// The generalized forces by virtual work, one line per load and coordinate it does
    /// work with.
    pub forces: Vec<GeneralizedForceRow>,
    /// What the table holds or why it is empty.
    pub forces_note: MarkupLine,
    /// The multipliers and the reaction components they are (empty without constraints).
    pub multipliers_note: MarkupLine,
}

/// One line of the table of generalized forces: `load | point | ∂v/∂q̇_r | Q_r`.
#[derive(Clone, Debug, Default, Serialize)]
pub struct GeneralizedForceRow {
    /// The load, on its first line; empty on the others.
    pub load: MarkupLine,
    /// Where it acts, e.g. `\text{at } B^*`, or for a couple `\text{anywhere on } B`.
    pub point_tex: Math,
    /// Its partial velocity (or partial angular velocity), e.g.
    /// `\partial \mathbf{v}^{B^*} / \partial \dot{q}_{1} = L \hat{\mathbf{a}}_{x}`.
    pub partial_tex: Math,
    /// Its share of `Q_r`, e.g. `Q_{1} \mathrel{+}= F L c_{1}`.
    pub q_tex: Math,
}
