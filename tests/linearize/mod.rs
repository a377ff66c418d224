//! `linearize`: small motions against closed forms derived by hand, and the JSON contract.

use crate::support::{problem, run, run_json};
use serde_json::Value;
use std::f64::consts::TAU;
use std::path::PathBuf;

/// Writes `text` to a problem file of its own in the temporary directory.
fn temporary_problem(name: &str, text: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!(
        "mbd-tutor-linearize-{}-{name}.json",
        std::process::id()
    ));
    std::fs::write(&path, text).expect("the temporary directory is writable");
    path
}

fn linearize(args: &[&str]) -> Value {
    let mut all = vec!["linearize"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--format", "json"]);
    run_json(&all)
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The eigenvalues as (re, im).
fn eigenvalues(l: &Value) -> Vec<(f64, f64)> {
    l["eigenvalues"]
        .as_array()
        .expect("eigenvalues is an array")
        .iter()
        .map(|e| (number(&e["re"]), number(&e["im"])))
        .collect()
}

fn matrix(v: &Value) -> Vec<Vec<f64>> {
    v.as_array()
        .expect("a matrix is an array of rows")
        .iter()
        .map(|row| row.as_array().expect("a row").iter().map(number).collect())
        .collect()
}

fn natural_frequencies(l: &Value) -> Vec<f64> {
    l["modes"]
        .as_array()
        .expect("modes is an array")
        .iter()
        .map(|m| number(&m["natural_frequency_hz"]))
        .collect()
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * a.abs().max(b.abs()).max(1.0)
}

/// A sleeping top spinning at the constant `w`, for linearizing and sweeping.
const TOP: &str = r#"{
  "title": "Sleeping top", "dimension": 3,
  "constants": { "m": 0.5, "l": 0.04, "I3": 4.0e-4, "It": 2.5e-4, "g": 9.81, "w": 100 },
  "coordinates": { "a3": { "rate": "w" } },
  "gravity": "-g*N.z",
  "bodies": { "top": { "mass": "m", "center": "l*top.z", "inertia": { "xx": "It", "yy": "It", "zz": "I3" } } },
  "joints": [ { "name": "tip", "type": "spherical", "parent": "N", "child": "top", "sequence": "xyz", "coordinates": ["a1", "a2", "a3"] } ]
}"#;

mod closed_forms;
mod contract;
