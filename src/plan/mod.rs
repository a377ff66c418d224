//! Steps 2 and 3: the free bodies and the planner's table of equations.

pub mod choose;
pub mod forces;
pub mod planner;
pub mod rejection;
pub mod rows;
mod span;

use crate::mechanics::{Form, MechanicsError, Model};
use forces::Action;
use rows::LazyInertia;

/// Step 2: what the free-body diagrams show, every force and couple on every body
/// (reactions included), and what the kinetic diagrams show, their inertia forces and
/// torques.
#[derive(Debug)]
pub struct FreeBodies {
    /// Every force and couple.
    pub actions: Vec<Action>,
    /// The inertia forces and torques, written when first read.
    pub inertia: LazyInertia,
}

/// Step 2 for `model`, its expressions in `form`.
///
/// # Errors
/// A load whose expression cannot be written on the model.
pub fn free_bodies(model: &Model, form: Form) -> Result<FreeBodies, MechanicsError> {
    Ok(FreeBodies {
        actions: forces::actions(model)?,
        inertia: LazyInertia::new(form),
    })
}
