//! A student's submission read from JSON: every section optional, each entry kept as
//! written so that one unparsable expression is graded invalid and the rest still graded.

use crate::SubmissionError;
use serde_json::Value;

/// A list of named entries in the order written.
pub type Named<T> = Vec<(String, T)>;

/// A student's work, as written.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Submission {
    /// Who wrote it.
    pub student: Option<String>,
    /// The variant file it answers (`variant-07.json`), for a batch.
    pub variant: Option<String>,
    /// Question index → a number, or `{ "x", "y", "z", "frame", "moment" }`.
    pub answers: Option<Named<Value>>,
    /// Coordinate → its q'' as an expression.
    pub accelerations: Option<Named<Value>>,
    /// Equations of motion, `LHS = RHS` or an expression equal to zero.
    pub equations: Option<Vec<Value>>,
    /// Point or body → quantity (`velocity`, `acceleration`, `angular_velocity`, …) → vector.
    pub kinematics: Option<Named<Named<Value>>>,
    /// Point or body → one vector per generalized speed.
    pub partial_velocities: Option<Named<Vec<Value>>>,
    /// `active` and `inertia` → one expression per generalized speed.
    pub generalized_forces: Option<Named<Vec<Value>>>,
}

const KEYS: [&str; 8] = [
    "student",
    "variant",
    "answers",
    "accelerations",
    "equations",
    "kinematics",
    "partial_velocities",
    "generalized_forces",
];

/// Reads a submission from its JSON text.
///
/// # Errors
/// Text that is not a JSON object, a section of the wrong type, or an unknown key.
pub fn read(text: &str) -> Result<Submission, SubmissionError> {
    let value: Value = serde_json::from_str(text).map_err(|e| {
        SubmissionError::new(
            "",
            format!("not JSON: {e}"),
            "a submission is one JSON object, e.g. { \"student\": \"s017\", \"equations\": [\"…\"] }",
        )
    })?;
    let Value::Object(map) = value else {
        return Err(SubmissionError::new(
            "",
            "a submission is a JSON object",
            "write { \"student\": …, \"answers\": { … }, \"equations\": [ … ] }",
        ));
    };
    for key in map.keys() {
        if !KEYS.contains(&key.as_str()) {
            let hint = crate::symbolic::closest(key, KEYS)
                .map(|k| format!("did you mean `{k}`?"))
                .unwrap_or_else(|| format!("the sections are {}", KEYS.join(", ")));
            return Err(SubmissionError::new(
                key,
                format!("unknown key `{key}`"),
                hint,
            ));
        }
    }
    let field = |key: &str| map.get(key).filter(|v| !v.is_null());
    Ok(Submission {
        student: field("student")
            .map(|v| text_of(v, "student"))
            .transpose()?,
        variant: field("variant")
            .map(|v| text_of(v, "variant"))
            .transpose()?,
        answers: field("answers").map(|v| object(v, "answers")).transpose()?,
        accelerations: field("accelerations")
            .map(|v| object(v, "accelerations"))
            .transpose()?,
        equations: field("equations")
            .map(|v| array(v, "equations"))
            .transpose()?,
        kinematics: field("kinematics")
            .map(|v| nested(v, "kinematics", object))
            .transpose()?,
        partial_velocities: field("partial_velocities")
            .map(|v| nested(v, "partial_velocities", array))
            .transpose()?,
        generalized_forces: field("generalized_forces").map(generalized).transpose()?,
    })
}

fn text_of(value: &Value, path: &str) -> Result<String, SubmissionError> {
    match value {
        Value::String(s) => Ok(s.clone()),
        Value::Number(n) => Ok(n.to_string()),
        _ => Err(SubmissionError::new(
            path,
            "expected a string",
            format!("write \"{path}\": \"…\""),
        )),
    }
}

fn object(value: &Value, path: &str) -> Result<Named<Value>, SubmissionError> {
    match value {
        Value::Object(map) => Ok(map.iter().map(|(k, v)| (k.clone(), v.clone())).collect()),
        _ => Err(SubmissionError::new(
            path,
            "expected an object",
            format!("write \"{path}\": {{ \"name\": … }}"),
        )),
    }
}

fn array(value: &Value, path: &str) -> Result<Vec<Value>, SubmissionError> {
    match value {
        Value::Array(items) => Ok(items.clone()),
        Value::String(_) => Ok(vec![value.clone()]),
        _ => Err(SubmissionError::new(
            path,
            "expected a list",
            format!("write \"{path}\": [ \"…\", \"…\" ]"),
        )),
    }
}

fn nested<T>(
    value: &Value,
    path: &str,
    inner: fn(&Value, &str) -> Result<T, SubmissionError>,
) -> Result<Named<T>, SubmissionError> {
    object(value, path)?
        .into_iter()
        .map(|(k, v)| {
            let at = format!("{path}.{k}");
            inner(&v, &at).map(|t| (k, t))
        })
        .collect()
}

fn generalized(value: &Value) -> Result<Named<Vec<Value>>, SubmissionError> {
    let entries = nested(value, "generalized_forces", array)?;
    for (key, _) in &entries {
        if key != "active" && key != "inertia" {
            return Err(SubmissionError::new(
                &format!("generalized_forces.{key}"),
                format!("unknown key `{key}`"),
                "the generalized forces are `active` and `inertia`, each a list by speed",
            ));
        }
    }
    Ok(entries)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_section_is_optional_and_unknown_keys_are_refused() {
        assert_eq!(read("{}").unwrap(), Submission::default());
        let e = read(r#"{ "equation": [] }"#).unwrap_err();
        assert_eq!(e.path, "equation");
        assert!(e.hint.unwrap().contains("equations"));
        let e = read(r#"{ "equations": 3 }"#).unwrap_err();
        assert_eq!(e.path, "equations");
        assert!(read("[1]").is_err());
    }
}
