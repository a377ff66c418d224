//! Numbers: evaluation, the linear solve, integration and the confirmation checks
//! (steps 5 and 6).

pub mod format;

use std::fmt;

/// The equations could not be solved at some state.
#[derive(Clone, Debug, PartialEq)]
pub enum SolveError {
    /// The system matrix is singular at the state described.
    SingularSystem {
        /// The state, e.g. `t = 0, q1 = 0.3, q1' = 0`.
        state: String,
        /// Which unknowns are involved, when known.
        detail: String,
    },
    /// A value came out NaN or infinite.
    NotFinite {
        /// The state.
        state: String,
        /// What was not finite.
        what: String,
    },
}

impl fmt::Display for SolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolveError::SingularSystem { state, detail } => {
                write!(f, "the equations are singular at {state}: {detail}")
            }
            SolveError::NotFinite { state, what } => write!(f, "{what} is not finite at {state}"),
        }
    }
}

impl std::error::Error for SolveError {}
