//! Step 0: JSON -> a validated [`Problem`](model::Problem).
//!
//! [`load`] reads the text into a JSON value (noting repeated keys), declares every name,
//! then reads each section, collecting every error with its JSON path, the column inside
//! an expression and a hint. A problem comes back only when there is no error at all.
//!
//! Conventions beyond the format page, documented here because they are choices:
//! - in a 2D problem a revolute joint without an `axis` turns about `N.z`;
//! - a body without `inertia` has zero central inertia; a `points` entry without `at`
//!   is the body's origin;
//! - `gravity` uses constants only, and is written in unit vectors that do not turn
//!   relative to `N`;
//! - a position (`center`, `at`, `child_at`, a point's `at`) is written in unit vectors
//!   that do not turn relative to its body (the body's own, or those of bodies joined to
//!   it by prismatic and weld joints only), and an axis likewise relative to the parent;
//! - in 2D, positions, forces and gravity have no z component, and torques only one;
//! - a force names a point fixed on the body it acts on;
//! - keys that do not apply to a joint's type (`axis` on a spherical joint) are errors.

mod bodies;
mod constraints;
mod expressions;
mod friction;
mod gear;
mod graph;
mod initial;
mod joints;
mod json;
mod loads;
pub mod model;
mod names;
mod questions;
mod read;
pub mod schema;
mod settings;
mod shapes;
mod speeds;
mod validate;
pub mod variant;
pub mod vary;

pub use model::*;
pub use questions::{Question, QuestionAt, QuestionKind, StateEntry};

use std::fmt;
use std::path::Path;

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

/// Reads and validates a problem from its JSON text.
///
/// # Errors
/// Every error in the problem, in the order of the file: a text that is not JSON gives
/// one error without a path; otherwise each error names its JSON path.
pub fn load(text: &str) -> Result<Problem, ProblemErrors> {
    let mut diag = json::Diagnostics::default();
    let value = json::parse(text, &mut diag)
        .map_err(|message| ProblemErrors(vec![ProblemError::file(message)]))?;
    let mut errors = diag.errors;
    match read::read(&value) {
        Ok(problem) if errors.is_empty() => return Ok(problem),
        Ok(_) => {}
        Err(more) => errors.extend(more),
    }
    name_joints(&mut errors, &value);
    let order = json::FileOrder::new(&value);
    // A stable sort keeps the errors of one value in the order they were found.
    errors.sort_by_key(|e| order.position(&e.path));
    Err(ProblemErrors(errors))
}

/// Puts the joint's name before every error under `joints[i]` that does not already name
/// it: the path alone says `joints[1].coordinates`, and a student looks for `P`.
fn name_joints(errors: &mut [ProblemError], value: &serde_json::Value) {
    let Some(joints) = value.get("joints").and_then(|j| j.as_array()) else {
        return;
    };
    for error in errors {
        let Some(rest) = error.path.strip_prefix("joints[") else {
            continue;
        };
        let Some((index, after)) = rest.split_once(']') else {
            continue;
        };
        if !(after.is_empty() || after.starts_with(['.', '['])) {
            continue;
        }
        let name = index
            .parse::<usize>()
            .ok()
            .and_then(|i| joints.get(i))
            .and_then(|joint| joint.get("name"))
            .and_then(|name| name.as_str())
            .filter(|name| !name.is_empty());
        if let Some(name) = name {
            if !error.message.contains(&format!("`{name}`")) {
                error.message = format!("joint `{name}`: {}", error.message);
            }
        }
    }
}

/// Why a problem file could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    /// The file could not be read.
    Io {
        path: std::path::PathBuf,
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

/// Reads and validates the problem in the file at `path`.
///
/// # Errors
/// [`LoadError::Io`] when the file cannot be read; [`LoadError::Invalid`] when it is not
/// UTF-8 text, not JSON, or not a valid problem.
pub fn load_file(path: &Path) -> Result<Problem, LoadError> {
    let bytes = std::fs::read(path).map_err(|source| LoadError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        ProblemErrors(vec![ProblemError::file(format!(
            "the file is not UTF-8 text: the byte at offset {offset} is not valid UTF-8"
        ))])
    })?;
    // Some editors start UTF-8 files with a byte-order mark; it is not part of the JSON.
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    Ok(load(text)?)
}

/// The constants' values of `problem`, as the value checks use them.
fn constant_values(problem: &Problem) -> expressions::ConstantValues {
    let mut values = expressions::ConstantValues::default();
    for constant in &problem.constants {
        values.set(&constant.name, constant.value);
    }
    values
}

/// Overrides constants (`--set NAME=VALUE`), then repeats the checks that depend on
/// their values (masses positive, inertias physical, axes not zero, nothing infinite).
/// On error `problem` is left as it was.
///
/// # Errors
/// An unknown name (with a suggestion), a value that is not finite, or a check that
/// fails with the new values.
pub fn apply_overrides(problem: &mut Problem, set: &[(String, f64)]) -> Result<(), ProblemErrors> {
    let mut updated = problem.clone();
    let mut errors = Vec::new();
    for (name, value) in set {
        let path = format!("--set {name}");
        match updated.constants.iter_mut().find(|c| c.name == *name) {
            Some(constant) if value.is_finite() => constant.value = *value,
            Some(_) => errors
                .push(ProblemError::file(format!("`{name}`: the value must be finite")).at(&path)),
            None => {
                let known: Vec<&str> = updated.constants.iter().map(|c| c.name.as_str()).collect();
                let is_coordinate = updated.coordinates.iter().any(|c| c.name == *name);
                let hint = if is_coordinate {
                    format!("`{name}` is a coordinate; `--set` changes constants, and `solve --state` sets coordinates")
                } else {
                    names::suggest(name, &known, "constants")
                };
                let mut error = ProblemError::file(format!("unknown constant `{name}`")).at(&path);
                error.hint = Some(hint);
                errors.push(error);
            }
        }
    }
    let values = constant_values(&updated);
    initial::evaluate(&mut updated, &values);
    errors.extend(validate::values(&updated, &values));
    if !errors.is_empty() {
        return Err(ProblemErrors(errors));
    }
    *problem = updated;
    Ok(())
}

impl ProblemError {
    fn at(mut self, path: &str) -> ProblemError {
        self.path = path.to_string();
        self
    }
}

#[cfg(test)]
mod tests;
