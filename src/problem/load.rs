//! Loading a problem: the text read into JSON, every section read and checked, the
//! errors ordered as the file has them; and the constants overridden by `--set`, then
//! checked again.

use super::error::{LoadError, ProblemError, ProblemErrors};
use super::expressions::ConstantValues;
use super::json::{self, key_path, Diagnostics};
use super::model::LoadKind;
use super::validated::Problem;
use super::{initial, names, read, validate};
use crate::symbolic::Expr;
use std::path::Path;

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

/// Reads and validates the problem in the file at `path`.
///
/// # Errors
/// [`LoadError::Io`] when the file cannot be read, is not a regular file or is longer than
/// [`crate::input::MAX_PROBLEM_BYTES`]; [`LoadError::Invalid`] when it is not UTF-8 text,
/// not JSON, or not a valid problem.
pub fn load_file(path: &Path) -> Result<Problem, LoadError> {
    let bytes =
        crate::input::read_bounded(path, crate::input::MAX_PROBLEM_BYTES).map_err(|source| {
            LoadError::Io {
                path: path.to_path_buf(),
                source,
            }
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
fn constant_values(problem: &Problem) -> ConstantValues {
    let mut values = ConstantValues::default();
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
    errors.extend(recheck(&updated, &values));
    if !errors.is_empty() {
        return Err(ProblemErrors(errors));
    }
    *problem = updated;
    Ok(())
}

/// Every value-dependent check over a whole problem, with `values` for the constants.
fn recheck(problem: &Problem, values: &ConstantValues) -> Vec<ProblemError> {
    let mut diag = Diagnostics::default();
    for constant in &problem.constants {
        if !constant.value.is_finite() {
            diag.error(
                &key_path("constants", &constant.name),
                "the value is not a finite number",
            );
        }
    }
    for (path, e) in super::initial::expressions(problem) {
        validate::finite(e, values, &path, &mut diag);
    }
    if let Some(gravity) = &problem.gravity {
        validate::vector(gravity, values, "gravity", &mut diag);
    }
    for body in &problem.bodies {
        validate::mass(&body.mass, values, &key_path(&body.path, "mass"), &mut diag);
        validate::vector(
            &body.center,
            values,
            &key_path(&body.path, "center"),
            &mut diag,
        );
        validate::inertia(
            &body.inertia,
            values,
            &key_path(&body.path, "inertia"),
            &mut diag,
        );
        validate::massless_inertia(
            &body.mass,
            &body.inertia,
            values,
            &key_path(&body.path, "inertia"),
            &mut diag,
        );
    }
    for joint in &problem.joints {
        if let Some(a) = &joint.axis {
            validate::axis(a, values, &key_path(&joint.path, "axis"), &mut diag);
        }
        validate::vector(&joint.at, values, &key_path(&joint.path, "at"), &mut diag);
        validate::vector(
            &joint.child_at,
            values,
            &key_path(&joint.path, "child_at"),
            &mut diag,
        );
    }
    for point in &problem.points {
        validate::vector(
            &point.at,
            values,
            &key_path(&key_path("points", &point.name), "at"),
            &mut diag,
        );
    }
    let coefficients = (problem.constraints.iter().map(|c| (&c.friction, &c.path)))
        .chain(problem.joints.iter().map(|j| (&j.friction, &j.path)))
        .chain(problem.closures.iter().map(|j| (&j.friction, &j.path)));
    for (friction, path) in coefficients {
        if let Some(mu) = friction {
            let path = key_path(path, "friction");
            super::friction::coefficient(mu, values, &path, &mut diag);
        }
    }
    for load in &problem.loads {
        for (key, e) in load_scalars(&load.kind) {
            // Only loads that hold constants alone can be judged before the motion.
            if e.is_constant() {
                validate::finite(e, values, &key_path(&load.path, key), &mut diag);
            }
        }
    }
    diag.errors
}

/// The scalar expressions of a load with their keys.
fn load_scalars(kind: &LoadKind) -> Vec<(&'static str, &Expr)> {
    match kind {
        LoadKind::Force { vector, .. } | LoadKind::Torque { vector, .. } => {
            vector.terms.iter().map(|(_, _, c)| ("vector", c)).collect()
        }
        LoadKind::Spring {
            stiffness,
            free_length,
            ..
        } => vec![("stiffness", stiffness), ("free_length", free_length)],
        LoadKind::Damper { coefficient, .. } | LoadKind::JointDamper { coefficient, .. } => {
            vec![("coefficient", coefficient)]
        }
        LoadKind::JointSpring {
            stiffness, rest, ..
        } => vec![("stiffness", stiffness), ("rest", rest)],
        LoadKind::JointActuator { value, .. } => vec![("value", value)],
    }
}
