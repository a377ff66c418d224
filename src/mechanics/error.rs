//! The mechanics stage's error: a valid problem that cannot be built into a model.

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
