//! Step 0: JSON -> a validated [`Problem`](model::Problem).

pub mod model;

pub use model::*;

use std::fmt;

/// One thing wrong with a problem file.
#[derive(Clone, Debug, PartialEq)]
pub struct ProblemError {
    /// The JSON path of the offending value, e.g. `joints[1].axis`.
    pub path: String,
    /// The 1-based column inside an expression, when the value is one.
    pub column: Option<usize>,
    /// What is wrong.
    pub message: String,
    /// What to do about it.
    pub hint: Option<String>,
}

impl fmt::Display for ProblemError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.path)?;
        if let Some(column) = self.column {
            write!(f, ", column {column}")?;
        }
        write!(f, ": {}", self.message)?;
        if let Some(hint) = &self.hint {
            write!(f, " (hint: {hint})")?;
        }
        Ok(())
    }
}

/// Every error found in a problem file, in the order of the file.
#[derive(Clone, Debug, PartialEq)]
pub struct ProblemErrors(pub Vec<ProblemError>);

impl fmt::Display for ProblemErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let count = self.0.len();
        writeln!(f, "the problem has {count} error{}:", if count == 1 { "" } else { "s" })?;
        for e in &self.0 {
            writeln!(f, "  {e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ProblemErrors {}
