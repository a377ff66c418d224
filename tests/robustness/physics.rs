//! Problems that are valid JSON but invalid in physics: each gets exit status 1 and a
//! message that names what is wrong, in the student's terms. The problem files are
//! beside this file.

use super::beside;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Runs the command, expects exit status 1 with nothing on standard output, and returns
/// standard error.
fn fails(args: &[&str]) -> String {
    let output = run(args);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert_eq!(output.status.code(), Some(1), "{args:?}: {stderr}");
    assert!(
        output.stdout.is_empty(),
        "{args:?}: output on standard output"
    );
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    stderr
}

fn file(name: &str) -> String {
    beside(name).display().to_string()
}

#[test]
fn a_coordinate_that_moves_nothing_with_mass_is_named() {
    // The particle on the pin sits on the pin's axis and has no inertia: turning it moves
    // nothing, so the column of phi'' in the mass matrix is zero. Newton-Euler and Kane
    // find it when they solve; the Motion Law's planner already finds too few rows.
    let problem = file("massless-coordinate.json");
    for method in ["motion-law", "newton-euler", "kane"] {
        let stderr = fails(&["solve", &problem, "--method", method]);
        assert!(
            stderr.contains(
                "the coordinate `phi` moves nothing with mass or inertia, so `phi''` is undetermined"
            ),
            "{method}: {stderr}"
        );
        assert!(!stderr.contains("`x` moves nothing"), "{method}: {stderr}");
        // simulate writes what it computed before the stop (at most the header), then fails.
        let output = run(&[
            "simulate",
            &problem,
            "--duration",
            "0.1",
            "--method",
            method,
        ]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{method}: {stderr}");
        assert!(
            stderr.contains("`phi` moves nothing with mass"),
            "{method}: {stderr}"
        );
    }
}

#[test]
fn an_inertia_that_breaks_the_triangle_inequality_is_rejected_by_check() {
    // Principal moments 1, 1, 3: 3 > 1 + 1, which no distribution of mass gives.
    let stderr = fails(&["check", &file("inertia-triangle.json")]);
    assert!(stderr.contains("bodies.plate.inertia"), "{stderr}");
    assert!(stderr.contains("triangle inequality"), "{stderr}");
    assert!(stderr.contains("3 > 1 + 1"), "{stderr}");
    // solve reads the problem the same way and stops there.
    let stderr = fails(&["solve", &file("inertia-triangle.json")]);
    assert!(stderr.contains("triangle inequality"), "{stderr}");
}

#[test]
fn a_system_singular_at_its_initial_state_names_the_state() {
    // Body-fixed x-y-z angles with q2 = 90°: the first and third axes line up (gimbal
    // lock), so the three angles' second derivatives are not determined.
    let problem = file("singular-initial-state.json");
    let stderr = fails(&["solve", &problem]);
    assert!(stderr.contains("singular"), "{stderr}");
    assert!(stderr.contains("q2 = 1.5708"), "{stderr}");
    assert!(stderr.contains("gimbal lock"), "{stderr}");
    // Away from the lock the same problem solves.
    let output = run(&["solve", &problem, "--state", "q2=0.5"]);
    assert_eq!(
        output.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

#[test]
fn a_spring_between_two_points_of_one_body_is_rejected() {
    let problem = file("spring-on-one-body.json");
    for command in ["check", "solve", "explain"] {
        let stderr = fails(&[command, &problem]);
        assert!(
            stderr.contains(
                "loads[0].between: both points are on `rod`, so the element can never stretch"
            ),
            "{command}: {stderr}"
        );
        assert!(
            stderr.contains("connect points of two different bodies"),
            "{command}: {stderr}"
        );
    }
}
