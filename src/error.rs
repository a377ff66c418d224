//! The one top-level error that wraps each stage's own, and the two errors that belong to
//! no one stage: a batch of problems of which some failed, and a submission to `grade`
//! that cannot be read (defined here so that this file imports no stage above it).

use std::fmt;
use std::path::PathBuf;

/// Everything that can stop a command.
#[derive(Debug)]
pub enum Error {
    /// The command line is wrong (exit status 2).
    Usage(String),
    /// A file could not be read or written.
    Io {
        /// The file.
        path: PathBuf,
        /// The system's reason.
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
    /// The symbolic work passed its limit (`--max-work`): the problem is too large.
    TooMuchWork {
        /// Where and at what limit.
        overrun: crate::symbolic::budget::Overrun,
        /// The method that was deriving.
        method: crate::equations::Method,
    },
    /// A submission to `grade` cannot be read: its JSON path and a hint.
    Submission(SubmissionError),
    /// Some problems of a directory failed (`explain DIR`); the others were written.
    Batch(BatchError),
}

impl Error {
    /// The message followed by each of its causes ([`std::error::Error::source`]), on one
    /// line: `a: b: c`.
    pub fn one_line(&self) -> String {
        std::iter::successors(Some(self as &dyn std::error::Error), |e| e.source())
            .map(|e| e.to_string().trim_end().to_string())
            .collect::<Vec<_>>()
            .join(": ")
    }

    /// Whether the reader of the output went away (`mbd-tutor simulate … | head`): not a
    /// failure, so the command ends quietly with exit status 0, as `yes | head` does.
    pub fn is_closed_output(&self) -> bool {
        matches!(self, Error::Io { source, .. } if source.kind() == std::io::ErrorKind::BrokenPipe)
    }

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
            // The system's message is the cause (`source`), printed after this.
            Error::Io { path, .. } => write!(f, "{}", path.display()),
            Error::Problem(e) => write!(f, "{e}"),
            Error::Mechanics(e) => write!(f, "{e}"),
            Error::Solve(e) => write!(f, "{e}"),
            Error::Render(e) => write!(f, "{e}"),
            Error::Batch(e) => write!(f, "{e}"),
            Error::Submission(e) => write!(f, "{e}"),
            Error::TooMuchWork { overrun, method } => {
                let raise = format!(
                    "raise the limit with --max-work {}",
                    (overrun.limit / 250_000).max(1)
                );
                match method {
                    crate::equations::Method::NewtonEuler => write!(f, "{overrun}\n  hint: {raise}"),
                    _ => write!(
                        f,
                        "{overrun}\n  hint: try --method newton-euler, whose rows are the smallest, or {raise}"
                    ),
                }
            }
        }
    }
}

/// Each stage's error is shown as it is, with its own causes after it: `Error` adds no
/// words of its own except for a file, whose system error is the cause.
impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Usage(_) => None,
            Error::Io { source, .. } => Some(source),
            Error::Problem(e) => e.source(),
            Error::Mechanics(e) => e.source(),
            Error::Solve(e) => e.source(),
            Error::Render(e) => e.source(),
            Error::Batch(e) => e.source(),
            Error::Submission(_) => None,
            Error::TooMuchWork { .. } => None,
        }
    }
}

impl From<crate::problem::LoadError> for Error {
    fn from(error: crate::problem::LoadError) -> Self {
        match error {
            crate::problem::LoadError::Io { path, source } => Error::Io { path, source },
            crate::problem::LoadError::Invalid(errors) => Error::Problem(errors),
        }
    }
}

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

#[cfg(test)]
mod tests {
    use super::Error;
    use std::error::Error as _;

    /// A file's error names the file and has the system's reason as its cause; a stage's
    /// error is passed through with its own causes.
    #[test]
    fn causes_follow_the_message() {
        let io = Error::Io {
            path: "problems/none.json".into(),
            source: std::io::Error::new(std::io::ErrorKind::NotFound, "no such file"),
        };
        assert_eq!(io.to_string(), "problems/none.json");
        assert_eq!(
            io.source().map(|e| e.to_string()).as_deref(),
            Some("no such file")
        );
        assert_eq!(io.one_line(), "problems/none.json: no such file");

        let mut tera = tera::Tera::default();
        tera.add_raw_template("t", "{{ nothing_here }}").unwrap();
        let cause = tera.render("t", &tera::Context::new()).unwrap_err();
        let render = Error::from(crate::render::RenderError {
            template: "t".into(),
            message: cause.to_string(),
            cause: Some(cause),
        });
        assert!(render
            .to_string()
            .starts_with("template `t`: Failed to render"));
        let why = render.source().expect("Tera's reason").to_string();
        assert!(why.contains("nothing_here"), "{why}");
        assert!(render.one_line().ends_with(&why), "{}", render.one_line());

        let usage = Error::Usage("no".into());
        assert!(usage.source().is_none());
        assert_eq!(usage.one_line(), "no");
    }
}

/// Some problems of a directory failed; the others were written.
#[derive(Debug)]
pub struct BatchError {
    /// The problem files that failed, with their errors.
    pub failures: Vec<(PathBuf, String)>,
    /// How many problems there were.
    pub total: usize,
}

impl fmt::Display for BatchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} of {} problems failed:",
            self.failures.len(),
            self.total
        )?;
        for (path, error) in &self.failures {
            write!(
                f,
                "\n  {}: {}",
                path.display(),
                error.replace('\n', "\n    ")
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for BatchError {}

/// A submission whose JSON cannot be graded at all: not JSON, not an object, a section of
/// the wrong type or an unknown key.
#[derive(Clone, Debug, PartialEq)]
pub struct SubmissionError {
    /// The JSON path of the offending value, e.g. `equations`; empty for the whole file.
    pub path: String,
    /// What is wrong.
    pub message: String,
    /// What to do about it.
    pub hint: Option<String>,
}

impl SubmissionError {
    pub(crate) fn new(
        path: &str,
        message: impl Into<String>,
        hint: impl Into<String>,
    ) -> SubmissionError {
        SubmissionError {
            path: path.to_string(),
            message: message.into(),
            hint: Some(hint.into()),
        }
    }
}

impl fmt::Display for SubmissionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.path.is_empty() {
            write!(f, "submission at {}: ", self.path)?;
        } else {
            write!(f, "submission: ")?;
        }
        write!(f, "{}", self.message)?;
        if let Some(hint) = &self.hint {
            write!(f, "\n  hint: {hint}")?;
        }
        Ok(())
    }
}

impl std::error::Error for SubmissionError {}
