//! Steps 3 and 5: Newton–Euler, the Motion Law, Kane's method and Lagrange's equations ->
//! a linear system in the q'' and the reactions.
//!
//! The entry is [`derive()`]`(problem, method, `[`Request`]`)` -> [`Derivation`]. Each method
//! is a module behind one signature (its view of the model, then its rows and their
//! unknowns): `newton_euler`, `motion_law` (which calls the planner of [`crate::plan`]),
//! `kane`, `lagrange`; the unknowns common to all and the assembly of `A x = b` are
//! written once for them.

pub mod composite;
mod constraint_rows;
mod derive;
pub mod energy;
mod friction;
pub mod kane;
pub mod lagrange;
mod motion_law;
mod newton_euler;
mod on_motion;
mod system;
mod unknowns;
mod write;

pub use derive::derive;
pub use friction::{friction_forces, normal_forces};
pub use system::{Derivation, LinearSystem, Method, Request, Rows, State};
