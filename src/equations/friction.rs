//! Coulomb friction in the equations: every method solves for the friction and normal
//! forces of each friction site, and is formed with the site sticking (rolling). The rows
//! that say so are named after the site's tangential components, so that the numbers can
//! exchange them for the sliding law where the site slips ([`crate::numeric::friction`]).

use super::rows::Equation;
use crate::mechanics::{MechanicsError, Model};
use crate::symbolic::Symbol;

/// Adds every friction site to the sites whose reactions are unknowns: friction is
/// proportional to the normal force, so no method may leave it out.
pub fn require_sites(model: &Model, reaction_sites: &mut Vec<usize>) {
    for f in &model.constraints.friction {
        if !reaction_sites.contains(&f.site) {
            reaction_sites.push(f.site);
        }
    }
}

/// The rows that hold while each friction site sticks, at the acceleration level.
///
/// # Errors
/// When a row cannot be differentiated.
pub fn stick_equations(
    model: &Model,
    unknowns: &[Symbol],
) -> Result<Vec<Equation>, MechanicsError> {
    let rows = model.constraints.friction.iter().flat_map(|f| &f.stick);
    super::constraint_rows::constraint_equations(rows, unknowns)
}
