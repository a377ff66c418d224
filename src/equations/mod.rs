//! Steps 3 and 5: Newton–Euler, the Motion Law, Kane's method and Lagrange's equations ->
//! a linear system in the q'' and the reactions.
//!
//! The entry is [`derive()`]`(problem, method, `[`Request`]`)` -> [`Derivation`]. Each method
//! is a module behind one signature (its view of the model, then its rows and their
//! unknowns): `newton_euler`, `motion_law` (which calls the planner of [`crate::plan`]),
//! `kane`, `lagrange`; the unknowns common to all and the assembly of `A x = b` are
//! written once for them.

mod composite;
mod constraint_rows;
mod derive;
mod energy;
mod friction;
mod kane;
mod lagrange;
mod load_potential;
mod method;
mod motion_law;
mod newton_euler;
mod on_motion;
mod system;
mod unknowns;
mod write;

pub use composite::SMALL_PROGRAM;
pub use derive::derive;
pub use energy::{kinetic, potential};
pub use friction::{friction_forces, normal_forces};
pub use kane::loads::generalized_forces as kane_generalized_forces;
pub use kane::{equations as kane_equations, partials};
pub use lagrange::coordinate_terms;
pub use lagrange::energy::{
    bodies as energy_terms, derivative as energy_derivative, potential as lagrange_potential,
};
pub use lagrange::forces::{
    generalized_forces as lagrange_generalized_forces, joint_generalized_forces,
    partial_velocities, role, virtual_work, Role,
};
pub use lagrange::kinetic::inertia_terms;
pub use load_potential::{force_potential, has_potential};
pub use method::Method;
pub use system::{Derivation, LinearSystem, Request, Rows};
