//! The contracts of the problem format, the constraints and the command line driven on
//! problems the bundled set does not hold (`tests/fresh_problems/*.json`): a bar under
//! sideways gravity, a block on a tilted guide, a body sliding and turning on a skew shaft,
//! a pendulum on a universal joint, an unsymmetrical body on a ball joint, a bead on a
//! parabolic wire, a ladder on a smooth wall, a hoop on a rough incline, a pendulum on a
//! cart kept at a set speed, a rod bouncing on a smooth floor, a ball striking a rough
//! floor, a rolling hoop struck and twisted, a crate pushed high (slip or tip) and an arm
//! held at an angle. Every number is checked against a closed form or a
//! derivation by hand written in the test (Lagrange's equations, worked with sympy for the
//! universal joint), by every method. Eleven more hold Version 4's questions: `in` frames,
//! `show`, `period`, `slips`, `tips` (with no equilibrium near, and with a contact lost),
//! `impending`, a held motor, a collision with friction, Lagrange's multipliers and
//! `grade` (`version_four`, `at_rest_four`, `grading_four`). Six more hold a block on a
//! wedge tied by a spring, an elastic pendulum, a ladder climbed on a rough floor, a rod
//! swinging into a stop, a bead on a spun hoop and a toggle held against a load
//! (`springs_and_stops`); `handout_lines` checks lines of the handouts on them.

mod at_rest_four;
mod errors;
mod grading_four;
mod handout_lines;
mod handouts_four;
mod motion;
mod motion_3d;
mod rest_and_impact;
mod springs_and_stops;
mod version_four;

use crate::support::{method_json, METHODS};
use serde_json::Value;
use std::path::PathBuf;

/// The path of `tests/fresh_problems/NAME.json`.
fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("fresh_problems")
        .join(format!("{name}.json"))
}

/// `mbd-tutor COMMAND tests/fresh_problems/NAME.json --format json --method M EXTRA…`.
fn command(cmd: &str, name: &str, method: &str, extra: &[&str]) -> Value {
    method_json(cmd, &fixture(name), method, extra)
}

/// `grade` of tests/fresh_problems/NAME.json by `method`, the submission written to a
/// scratch file.
fn graded(name: &str, submission: &Value, method: &str) -> Value {
    let dir = std::env::temp_dir().join(format!("mbd-fresh-grade-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("folder");
    let path = dir.join(format!("{method}.json"));
    std::fs::write(&path, submission.to_string()).expect("write");
    command(
        "grade",
        name,
        method,
        &[path.to_str().expect("a UTF-8 path")],
    )
}

/// `solve` by every method, each checked to say its method.
fn solve_each(name: &str, extra: &[&str]) -> Vec<Value> {
    METHODS
        .iter()
        .map(|m| {
            let s = command("solve", name, m, extra);
            assert_eq!(s["method"], *m, "{name}: the method is named");
            s
        })
        .collect()
}

/// A number of a JSON object, by a path of keys.
fn at(value: &Value, keys: &[&str]) -> f64 {
    keys.iter()
        .fold(value, |v, k| &v[*k])
        .as_f64()
        .unwrap_or_else(|| panic!("no number at {keys:?} in {value}"))
}

/// A JSON array of three numbers.
fn triple(value: &Value) -> [f64; 3] {
    let items = value
        .as_array()
        .unwrap_or_else(|| panic!("not a vector: {value}"));
    assert_eq!(items.len(), 3, "a vector has three components: {value}");
    std::array::from_fn(|k| items[k].as_f64().expect("a number"))
}

/// Asserts `|got − want| ≤ 1e-6 · max(|want|, 1)` with a description.
#[track_caller]
fn close(got: f64, want: f64, what: &str) {
    crate::support::assert_close(got, want, 1e-6, 1.0, what);
}
