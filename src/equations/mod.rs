//! Step 5: Newton-Euler, the Motion Law and Kane's method -> a linear system in the q''
//! and the reactions.

pub mod energy;
pub mod kane;
pub mod newton_euler;
pub mod rows;
pub mod system;

pub use system::{derive, Derivation, LinearSystem, Method};
