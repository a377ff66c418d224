//! Steps 1 and 4: frames, unit vectors, dyadics and joints -> the kinematics of every body.

use std::fmt;

/// A problem that is valid JSON but cannot be built into a mechanical model.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanicsError {
    /// The JSON path of the value at fault.
    pub path: String,
    /// What is wrong.
    pub message: String,
    /// What to do about it.
    pub hint: Option<String>,
}

impl fmt::Display for MechanicsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)?;
        if let Some(hint) = &self.hint {
            write!(f, " (hint: {hint})")?;
        }
        Ok(())
    }
}

impl std::error::Error for MechanicsError {}

/// Who reads the equations: how much of the kinematics is named depends on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// A student, in the worked solution: a planar acceleration is written whole, and a
    /// spatial one named where it is long.
    Handout,
    /// The compiled program only: every long acceleration gets named parts, and every
    /// partial angular velocity past the first body, the fewest operations.
    Numeric,
}

pub mod angular;
pub mod build;
pub mod compact;
pub mod components;
pub mod constraint_rows;
pub mod constraints;
pub mod dependent;
pub mod dot_sum;
pub mod frames;
pub mod friction;
pub mod gear;
pub mod joints;
pub mod massless;
pub mod model;
pub mod on_parent;
pub mod point;
pub mod site;
pub mod sites;
pub mod speeds;
pub mod vector;

pub use model::{BodyState, JointModel, Model};
pub use point::PointMotion;
pub use vector::Vector;
