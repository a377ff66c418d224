//! `find`, `simulate`, the top level, text that is not JSON, overrides and the report.

use super::*;

/// `t = 0` and each coordinate's `initial` and `rate` as written (a rate not written is
/// zero), in the problem's coordinate order.
#[test]
fn the_initial_state_is_the_one_written() {
    let mut written = base();
    written["coordinates"] = json!({
        "x": { "initial": 0.5 },
        "q": { "initial": -0.25, "rate": 2.0 }
    });
    let problem = load(&written.to_string()).unwrap();
    let state = problem.initial_state();
    assert_eq!((state.t, state.q.len(), state.rates.len()), (0.0, 2, 2));
    for (name, q, rate) in [("x", 0.5, 0.0), ("q", -0.25, 2.0)] {
        let i = (problem.coordinates.iter())
            .position(|c| c.name == name)
            .unwrap();
        assert_eq!((state.q[i], state.rates[i]), (q, rate), "{name}");
    }
    assert_eq!(problem.initial_coordinates(), state.q);
}

#[test]
fn find_simulate_and_the_top_level() {
    rejects(
        base(),
        |p| p["find"] = json!({"reactions": ["P"]}),
        "find.reactions[0]",
        "not a joint",
    );
    rejects(
        base(),
        |p| p["find"] = json!({"reactions": ["Q"]}),
        "find.reactions[0]",
        "unknown joint",
    );
    rejects(
        base(),
        |p| p["simulate"] = json!({"duration": -1, "output_step": 0.001}),
        "simulate.duration",
        "positive",
    );
    rejects(
        base(),
        |p| p["simulate"] = json!({"duration": 1, "output_step": 2}),
        "simulate.output_step",
        "longer than the duration",
    );
    rejects(base(), |p| p["dimension"] = json!(4), "dimension", "2 or 3");
    rejects(
        base(),
        |p| p["format"] = json!(2),
        "format",
        "not supported",
    );
    rejects(
        base(),
        |p| p["constants"]["m"] = json!("1"),
        "constants.m",
        "expected a number or an object",
    );
}

#[test]
fn not_json() {
    for (text, words) in [
        ("", "empty"),
        ("{", "not valid JSON"),
        ("[1, 2]", "expected an object"),
    ] {
        let errors = load(text).unwrap_err().0;
        assert!(errors[0].message.contains(words), "{text:?}: {errors:?}");
    }
}

#[test]
fn overrides_are_checked_again() {
    let mut p = load(DOUBLE_PENDULUM).unwrap();
    apply_overrides(&mut p, &[("m".into(), 2.0)]).unwrap();
    assert_eq!(p.constants[0].value, 2.0);
    let e = apply_overrides(&mut p, &[("m".into(), -1.0)])
        .unwrap_err()
        .0;
    // Both masses, and both inertias m*L^2/12, are now negative.
    let paths: Vec<&str> = e.iter().map(|e| e.path.as_str()).collect();
    assert_eq!(
        paths,
        [
            "bodies.A.mass",
            "bodies.A.inertia",
            "bodies.B.mass",
            "bodies.B.inertia"
        ]
    );
    assert_eq!(
        p.constants[0].value, 2.0,
        "a failed override leaves the problem as it was"
    );
    let e = apply_overrides(&mut p, &[("mm".into(), 1.0)])
        .unwrap_err()
        .0;
    assert_eq!(e[0].hint.as_deref(), Some("did you mean `m`?"));
    let e = apply_overrides(&mut p, &[("q1".into(), 1.0)])
        .unwrap_err()
        .0;
    assert!(e[0].hint.as_deref().unwrap().contains("coordinate"));
}

#[test]
fn display_lists_every_error_with_its_hint() {
    let errors = ProblemErrors(vec![
        ProblemError {
            path: "joints[1].axis".into(),
            column: Some(3),
            message: "bad".into(),
            hint: Some("fix it".into()),
        },
        ProblemError::file("the file is empty"),
    ]);
    assert_eq!(
        errors.to_string(),
        "the problem has 2 errors:\n  joints[1].axis, column 3: bad\n    hint: fix it\n  the file is empty"
    );
}
