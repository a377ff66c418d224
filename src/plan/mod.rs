//! Steps 2 and 3: the free bodies and the planner's table of equations.
//!
//! Entry: [`free_bodies`] (step 2) and [`choose`] / [`candidates`], the Motion Law's
//! planner (step 3), with the rows' types ([`Equation`], [`Sum`], [`Direction`]). The
//! modules are private; what other stages use is re-exported here.

mod choose;
mod forces;
mod planner;
mod rejection;
mod rows;
mod span;

pub use choose::blocks;
pub use forces::{
    constraint_generalized_forces, is_joint_load, joint_load_generalized_forces, joint_load_value,
    load_generalized_forces, Action, ActionKind, Category, Source,
};
pub use planner::{candidates, choose, coefficient_rows, Choice};
pub use rejection::{highlights, Reason, Rejected, SpecialState, SHOWN};
pub use rows::{
    action_terms, inertia_terms, is_external, resultant, unit_direction, unknowns_in, Direction,
    Equation, Groups, Inertia, LazyInertia, Sum,
};

use crate::mechanics::{Form, MechanicsError, Model};

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
