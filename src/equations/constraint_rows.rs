//! The constraint rows (closures, contacts, prescribed motion, a friction site's sticking)
//! at the acceleration level, as equations every method's system takes as given.

use crate::mechanics::{ConstraintRow, MechanicsError};
use crate::plan::{Equation, Groups, Sum};
use crate::symbolic::{Expr, Symbol};

/// The constraint rows at the acceleration level, as equations.
pub(super) fn constraint_equations<'r>(
    rows: impl Iterator<Item = &'r ConstraintRow>,
    unknowns: &[Symbol],
) -> Result<Vec<Equation>, MechanicsError> {
    rows.map(|row| {
        let expression = row.acceleration()?;
        Ok(Equation {
            free_body: Vec::new(),
            sum: Sum::Constraint {
                name: row.name.clone(),
            },
            direction: None,
            unknowns: crate::plan::unknowns_in(&expression, unknowns),
            groups: Groups {
                contact: expression.clone(),
                distance: Expr::zero(),
                inertia_force: Expr::zero(),
                inertia_torque: Expr::zero(),
            },
            expression,
        })
    })
    .collect()
}
