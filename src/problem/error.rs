//! The problem stage's errors: one per fault, each with its JSON path, column and hint,
//! and all of them together.

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
        self.fmt_location(f)?;
        write!(f, "{}", self.message)?;
        if let Some(hint) = &self.hint {
            write!(f, " (hint: {hint})")?;
        }
        Ok(())
    }
}

impl ProblemError {
    /// An error about the file as a whole, which has no JSON path.
    pub fn file(message: impl Into<String>) -> ProblemError {
        ProblemError {
            path: String::new(),
            column: None,
            message: message.into(),
            hint: None,
        }
    }

    fn fmt_location(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.path.is_empty() {
            write!(f, "{}", self.path)?;
            if let Some(column) = self.column {
                write!(f, ", column {column}")?;
            }
            write!(f, ": ")?;
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
        write!(
            f,
            "the problem has {count} error{}:",
            if count == 1 { "" } else { "s" }
        )?;
        for e in &self.0 {
            write!(f, "\n  ")?;
            e.fmt_location(f)?;
            write!(f, "{}", e.message)?;
            if let Some(hint) = &e.hint {
                write!(f, "\n    hint: {hint}")?;
            }
        }
        Ok(())
    }
}

impl std::error::Error for ProblemErrors {}

impl ProblemError {
    pub(super) fn at(mut self, path: &str) -> ProblemError {
        self.path = path.to_string();
        self
    }
}

/// Why a problem file could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    /// The file could not be read.
    Io {
        /// The file.
        path: std::path::PathBuf,
        /// The system's reason.
        source: std::io::Error,
    },
    /// The file is not UTF-8 text, not JSON, or not a valid problem.
    Invalid(ProblemErrors),
}

impl std::fmt::Display for LoadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LoadError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            LoadError::Invalid(errors) => write!(f, "{errors}"),
        }
    }
}

impl std::error::Error for LoadError {}

impl From<ProblemErrors> for LoadError {
    fn from(errors: ProblemErrors) -> Self {
        LoadError::Invalid(errors)
    }
}
