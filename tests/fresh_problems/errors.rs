//! A student's derivation graded right and wrong, and bad input: exit status 1, the JSON
//! path, a hint, never a panic, and an output file left as it was.

use super::fixture;
use crate::support::run;
use serde_json::{json, Value};
use std::path::PathBuf;

/// A scratch copy of a fixture, changed by `edit`, written under the system's temp folder.
pub(super) fn scratch(name: &str, tag: &str, edit: impl FnOnce(&mut Value)) -> PathBuf {
    let text = std::fs::read_to_string(fixture(name)).expect("fixture");
    let mut problem: Value = serde_json::from_str(&text).expect("JSON");
    edit(&mut problem);
    let dir = std::env::temp_dir().join(format!("mbd-fresh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch folder");
    let path = dir.join(format!("{name}-{tag}.json"));
    std::fs::write(&path, serde_json::to_string_pretty(&problem).expect("JSON")).expect("write");
    path
}

/// Runs `COMMAND PATH ARGS…`, asserts exit status 1 and returns standard error.
pub(super) fn refused(command: &str, path: &PathBuf, args: &[&str]) -> String {
    let mut all = vec![std::ffi::OsStr::new(command), path.as_os_str()];
    all.extend(args.iter().map(std::ffi::OsStr::new));
    let out = run(&all);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(
        out.status.code(),
        Some(1),
        "{command} {path:?}: exit 1, got {err}"
    );
    assert!(!err.contains("panicked"), "no panic: {err}");
    err
}

#[track_caller]
pub(super) fn names(err: &str, path: &str) {
    assert!(err.contains(path), "the error names `{path}`:\n{err}");
    assert!(err.contains("hint"), "the error gives a hint:\n{err}");
}

#[test]
fn bad_keys_values_and_expressions_name_their_json_paths() {
    let p = scratch("bar-under-sideways-gravity", "key", |p| {
        p["bodies"]["bar"]["masss"] = json!(1);
    });
    names(&refused("check", &p, &[]), "bodies.bar.masss");
    let p = scratch("bar-under-sideways-gravity", "expr", |p| {
        p["bodies"]["bar"]["inertia"] = json!("m*L^^2/12");
    });
    let err = refused("solve", &p, &[]);
    names(&err, "bodies.bar.inertia");
    assert!(
        err.contains("column"),
        "an expression's error gives the column:\n{err}"
    );
    let p = scratch("bar-under-sideways-gravity", "frame", |p| {
        p["find"]["questions"][0]["in"] = json!("Q");
    });
    names(&refused("answer", &p, &[]), "find.questions[0].in");
    let p = scratch("arm-held-with-slider", "held", |p| {
        p["coordinates"]["theta"]["motion"] = json!("0.5 + t");
    });
    names(&refused("check", &p, &[]), "coordinates.theta");
}

#[test]
fn a_collision_that_does_not_approach_or_bounces_too_much_is_refused() {
    let p = scratch("tilted-rod-drops-on-floor", "leaving", |p| {
        p["coordinates"]["y"]["rate"] = json!(3);
    });
    names(&refused("impact", &p, &[]), "impact.collision");
    let p = scratch("tilted-rod-drops-on-floor", "e", |p| {
        p["constants"]["e"] = json!(1.5);
    });
    names(&refused("impact", &p, &[]), "impact.collision");
}

#[test]
fn a_failed_run_leaves_the_output_file_as_it_was() {
    let p = scratch("bead-on-parabola", "broken", |p| {
        p["constraints"][0]["expression"] = json!("y - p*x^");
    });
    let out = std::env::temp_dir().join(format!("mbd-fresh-out-{}.json", std::process::id()));
    std::fs::write(&out, "kept").expect("write");
    for command in [
        "solve", "simulate", "statics", "impact", "answer", "explain",
    ] {
        let o = out.to_string_lossy().into_owned();
        let err = refused(command, &p, &["-o", &o]);
        names(&err, "constraints[0].expression");
        let kept = std::fs::read_to_string(&out).expect("read");
        assert_eq!(kept, "kept", "{command}: the output file is untouched");
    }
}

/// The bar's equation of motion as a student writes it, right, and with the moment of
/// inertia about the centre instead of the pin (m L²/12 for m L²/3).
#[test]
fn grade_knows_a_right_derivation_from_one_with_the_wrong_moment_of_inertia() {
    let submission = json!({
        "student": "s1",
        "answers": { "3": 0.0 },
        "accelerations": { "theta": "3*(m*g*L/2*cos(theta) + tau)/(m*L^2)" },
        "equations": [
            "m*L^2/3*theta'' = m*g*L/2*cos(theta) + tau",
            "m*L^2/12*theta'' = m*g*L/2*cos(theta) + tau"
        ]
    });
    let (m, l, g, tau, theta) = (1.5f64, 0.8, 9.81, 2.0, 0.4f64);
    let mut sub = submission.clone();
    sub["answers"]["3"] = json!((m * g * l / 2.0 * theta.cos() + tau) / (m * l * l / 3.0));
    for method in crate::support::METHODS {
        let g = super::graded("bar-under-sideways-gravity", &sub, method);
        assert_eq!(g["student"], "s1");
        let items = g["items"].as_array().expect("items");
        let item = |name: &str| {
            items
                .iter()
                .find(|i| i["item"] == name)
                .unwrap_or_else(|| panic!("{method}: no item {name} in {g}"))
        };
        assert_eq!(item("answers.3")["verdict"], "right", "{method}: {g}");
        assert_eq!(
            item("accelerations.theta")["verdict"],
            "right",
            "{method}: {g}"
        );
        assert_eq!(item("equations[0]")["verdict"], "right", "{method}: {g}");
        let wrong = item("equations[1]");
        assert_eq!(wrong["verdict"], "wrong", "{method}: {g}");
        assert_eq!(wrong["score"].as_f64(), Some(0.0));
        let why = wrong["diagnosis"].as_str().expect("diagnosis");
        assert!(
            why.contains("theta''"),
            "{method}: the diagnosis names the term: {why}"
        );
        let score = g["score"].as_f64().expect("score");
        let out_of = g["out_of"].as_f64().expect("out_of");
        assert!(out_of >= 4.0 && score <= out_of - 1.0, "{method}: {g}");
    }
}

/// A rough rolling contact's no-slip row holds only while it sticks, so it makes no rate
/// dependent: marking the hoop's turning rate `dependent_rate` is refused, and the hint
/// says why by the site's name.
#[test]
fn a_rate_marked_dependent_on_a_rough_contact_is_refused_with_the_reason() {
    let p = scratch("hoop-on-rough-incline", "marked", |p| {
        p["coordinates"]["theta"]["dependent_rate"] = json!(true);
    });
    let err = refused("check", &p, &[]);
    names(&err, "coordinates");
    assert!(err.contains("`slope`") && err.contains("sticks"), "{err}");
}
