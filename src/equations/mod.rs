//! Step 5: Newton-Euler, the Motion Law, Kane's method and Lagrange's equations -> a linear system in the q''
//! and the reactions.

pub mod composite;
mod constraint_rows;
mod derive;
pub mod energy;
pub mod friction;
pub mod kane;
pub mod lagrange;
mod motion_law;
pub mod newton_euler;
mod on_motion;
/// The rows of equations, which the planner writes out in step 3 (see [`crate::plan::rows`]).
pub use crate::plan::rows;
pub mod system;
mod unknowns;
mod write;

pub use derive::derive;
pub use system::{Derivation, LinearSystem, Method, Request, Rows, State};
