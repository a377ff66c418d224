//! The one top-level error that wraps each stage's own.

use std::fmt;
use std::path::PathBuf;

/// Everything that can stop a command.
#[derive(Debug)]
pub enum Error {
    /// The command line is wrong (exit status 2).
    Usage(String),
    /// A file could not be read or written.
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// The problem is invalid: every error found, each with its JSON path.
    Problem(crate::problem::ProblemErrors),
    /// The problem is valid JSON but describes a system that cannot be built or solved.
    Mechanics(crate::mechanics::MechanicsError),
    /// The equations could not be solved.
    Solve(crate::numeric::SolveError),
    /// A template failed to render.
    Render(crate::render::RenderError),
    /// Some problems of a directory failed (`explain DIR`); the others were written.
    Batch(crate::cmd::explain::BatchError),
}

impl Error {
    /// The process exit status: 2 for usage errors, 1 otherwise.
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Usage(_) => 2,
            _ => 1,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Usage(message) => write!(f, "{message}"),
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Problem(e) => write!(f, "{e}"),
            Error::Mechanics(e) => write!(f, "{e}"),
            Error::Solve(e) => write!(f, "{e}"),
            Error::Render(e) => write!(f, "{e}"),
            Error::Batch(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {}

impl From<crate::problem::ProblemErrors> for Error {
    fn from(e: crate::problem::ProblemErrors) -> Self {
        Error::Problem(e)
    }
}
impl From<crate::mechanics::MechanicsError> for Error {
    fn from(e: crate::mechanics::MechanicsError) -> Self {
        Error::Mechanics(e)
    }
}
impl From<crate::numeric::SolveError> for Error {
    fn from(e: crate::numeric::SolveError) -> Self {
        Error::Solve(e)
    }
}
impl From<crate::render::RenderError> for Error {
    fn from(e: crate::render::RenderError) -> Self {
        Error::Render(e)
    }
}
