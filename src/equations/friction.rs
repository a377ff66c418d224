//! Coulomb friction in the equations: every method solves for the friction and normal
//! forces of each friction site, and is formed with the site sticking (rolling). The rows
//! that say so are named after the site's tangential components, so that the numbers can
//! exchange them for the sliding law where the site slips ([`crate::numeric::friction`]).

use super::rows::Equation;
use crate::mechanics::{MechanicsError, Model};
use crate::symbolic::linear::linear_split;
use crate::symbolic::{Expr, Symbol};

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

/// Adds to `q`, one generalized force per coordinate, the friction of each rough prismatic
/// joint of the tree: its force `F` along the axis, whose stick row is the slip velocity
/// `±q'`, gives `F ∂(±q')/∂q'` (Kane's rows leave the rest of a tree joint's reaction out,
/// as it does no work).
pub fn add_slider_forces(model: &Model, q: &mut [Expr]) {
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    for f in &model.constraints.friction {
        if f.site >= problem.joints.len() {
            continue;
        }
        for row in &f.stick {
            let Ok((coefficients, _)) = linear_split(&row.velocity, &rates) else {
                continue;
            };
            for (c, coefficient) in coefficients.iter().enumerate() {
                if !coefficient.is_zero() {
                    q[c] = &q[c] + &(coefficient * &Expr::sym(row.unknown.clone()));
                }
            }
        }
    }
}

/// Whether `unknown` is the friction force of a rough prismatic joint `j` of the tree.
pub fn is_slider_friction(model: &Model, j: usize, unknown: &Symbol) -> bool {
    j < model.problem.joints.len()
        && model
            .constraints
            .friction
            .iter()
            .any(|f| f.site == j && f.stick.iter().any(|r| r.unknown == *unknown))
}
