//! Limits: a problem beyond sensible size is refused at once with a message that names
//! the limit and the flag that raises it (README, "Limits").

use super::scratch;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// A refusal comes before any derivation: well under this even on a busy machine.
const QUICK: Duration = Duration::from_secs(10);

fn run(args: &[&str]) -> (Output, Duration) {
    let start = Instant::now();
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("the binary runs");
    (output, start.elapsed())
}

fn refused(args: &[&str]) -> String {
    let (output, took) = run(args);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert_eq!(output.status.code(), Some(1), "{args:?}: {stderr}");
    assert!(output.stdout.is_empty(), "{args:?}");
    assert!(took < QUICK, "{args:?} took {took:?} to refuse");
    stderr
}

fn succeeds(args: &[&str]) -> String {
    let (output, _) = run(args);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{args:?}: {stderr}");
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// A planar chain of `n` rods on pins, written to `dir`.
fn chain(dir: &Path, n: usize) -> PathBuf {
    let mut bodies = Vec::new();
    let mut joints = Vec::new();
    let mut coordinates = Vec::new();
    for i in 1..=n {
        bodies.push(format!(
            r#""B{i}": {{ "mass": "m", "center": "-L/2*B{i}.y", "inertia": "m*L^2/12" }}"#
        ));
        let (parent, at) = if i == 1 {
            ("N".to_string(), "0".to_string())
        } else {
            (format!("B{}", i - 1), format!("-L*B{}.y", i - 1))
        };
        joints.push(format!(
            r#"{{ "name": "J{i}", "type": "revolute", "parent": "{parent}", "child": "B{i}", "at": "{at}", "coordinates": ["q{i}"] }}"#
        ));
        coordinates.push(format!(r#""q{i}": {{ "initial": 0.1 }}"#));
    }
    let text = format!(
        r#"{{ "title": "A chain of {n} rods", "dimension": 2,
  "constants": {{ "m": 1, "L": 0.1, "g": 9.81 }},
  "coordinates": {{ {} }},
  "gravity": "-g*N.y",
  "bodies": {{ {} }},
  "joints": [ {} ] }}"#,
        coordinates.join(", "),
        bodies.join(",\n"),
        joints.join(",\n")
    );
    let path = dir.join(format!("chain-{n}.json"));
    std::fs::write(&path, text).expect("written");
    path
}

/// `n` free bodies in space, 6 coordinates each, written to `dir`.
fn free_bodies(dir: &Path, n: usize) -> PathBuf {
    let bodies: Vec<String> = (1..=n)
        .map(|i| {
            format!(
                r#""B{i}": {{ "mass": "m", "inertia": {{ "xx": "1", "yy": "1", "zz": "1" }} }}"#
            )
        })
        .collect();
    let joints: Vec<String> = (1..=n)
        .map(|i| {
            let names: Vec<String> = ["x", "y", "z", "a", "b", "c"].iter().map(|c| format!("\"{c}{i}\"")).collect();
            format!(
                r#"{{ "name": "F{i}", "type": "free", "parent": "N", "child": "B{i}", "sequence": "zyx", "coordinates": [{}] }}"#,
                names.join(", ")
            )
        })
        .collect();
    let text = format!(
        r#"{{ "title": "{n} free bodies", "dimension": 3, "constants": {{ "m": 1 }},
  "bodies": {{ {} }}, "joints": [ {} ] }}"#,
        bodies.join(", "),
        joints.join(", ")
    );
    let path = dir.join(format!("free-{n}.json"));
    std::fs::write(&path, text).expect("written");
    path
}

#[test]
fn too_many_bodies_are_refused_naming_the_flag() {
    let dir = scratch("too-many-bodies");
    let big = chain(&dir, 31);
    let big = big.to_str().expect("UTF-8 path");
    // check applies the same limits, and the same flag raises them.
    assert!(succeeds(&["check", big, "--max-bodies", "31"])
        .contains("31 bodies, 31 joints, 31 coordinates"));
    for command in ["check", "solve", "simulate", "explain"] {
        let stderr = refused(&[command, big]);
        assert!(
            stderr.contains("bodies: the problem has 31 bodies, more than the limit of 30"),
            "{command}: {stderr}"
        );
        assert!(stderr.contains("--max-bodies 31"), "{command}: {stderr}");
        assert!(
            !stderr.contains("coordinates, more than"),
            "{command}: {stderr}"
        );
    }
    std::fs::remove_dir_all(&dir).expect("removed");
}

#[test]
fn too_many_coordinates_are_refused_naming_the_flag() {
    let dir = scratch("too-many-coordinates");
    let big = free_bodies(&dir, 11);
    let big = big.to_str().expect("UTF-8 path");
    let stderr = refused(&["solve", big]);
    assert!(
        stderr.contains("the problem has 66 coordinates, more than the limit of 60"),
        "{stderr}"
    );
    assert!(stderr.contains("--max-coordinates 66"), "{stderr}");
    assert!(!stderr.contains("bodies, more than"), "{stderr}");
    std::fs::remove_dir_all(&dir).expect("removed");
}

#[test]
fn the_flags_raise_and_lower_the_limits() {
    let dir = scratch("limit-flags");
    let two = chain(&dir, 2);
    let two = two.to_str().expect("UTF-8 path");
    let stderr = refused(&["solve", two, "--max-bodies", "1"]);
    assert!(
        stderr.contains("2 bodies, more than the limit of 1"),
        "{stderr}"
    );
    let stderr = refused(&["solve", two, "--max-coordinates", "1"]);
    assert!(
        stderr.contains("2 coordinates, more than the limit of 1"),
        "{stderr}"
    );
    succeeds(&["solve", two, "--max-bodies", "2", "--max-coordinates", "2"]);
    std::fs::remove_dir_all(&dir).expect("removed");
}

#[test]
fn a_simulation_that_would_write_too_many_rows_is_refused_at_once() {
    let pendulum = concat!(env!("CARGO_MANIFEST_DIR"), "/problems/simple-pendulum.json");
    // 10^6 s at the problem's output step of 0.01 s: 10^8 + 1 rows.
    let stderr = refused(&["simulate", pendulum, "--duration", "1000000"]);
    assert!(
        stderr.contains("would write 100000001 rows, more than the limit of 1000000"),
        "{stderr}"
    );
    assert!(stderr.contains("--max-rows 100000001"), "{stderr}");
    // 1 s at 0.01 s is 101 rows: refused below that, written at it.
    let stderr = refused(&["simulate", pendulum, "--duration", "1", "--max-rows", "100"]);
    assert!(stderr.contains("--max-rows 101"), "{stderr}");
    let csv = succeeds(&["simulate", pendulum, "--duration", "1", "--max-rows", "101"]);
    assert_eq!(csv.lines().count(), 1 + 101, "a header and 101 rows");
}

#[test]
fn an_expression_longer_than_the_limit_is_refused() {
    let dir = scratch("long-expression");
    let pendulum = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/simple-pendulum.json"
    ))
    .expect("read");
    // 100,001 bytes: one past the limit.
    let long = format!("m{}", "+0".repeat(50_000));
    let text = pendulum.replace(r#""mass": "m""#, &format!(r#""mass": "{long}""#));
    let path = dir.join("long.json");
    std::fs::write(&path, text).expect("written");
    let stderr = refused(&["check", path.to_str().expect("UTF-8 path")]);
    assert!(stderr.contains("bodies.bob.mass"), "{stderr}");
    assert!(stderr.contains("100001 bytes long"), "{stderr}");
    assert!(stderr.contains("limited to 100000 bytes"), "{stderr}");
    std::fs::remove_dir_all(&dir).expect("removed");
}

#[test]
fn a_derivation_past_the_work_limit_is_refused_naming_the_step_and_the_flag() {
    let arm = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/validation/whipple-bicycle.json"
    );
    let dir = scratch("work-limit");
    let kept = dir.join("kept.csv");
    std::fs::write(&kept, "earlier output\n").expect("written");
    let kept = kept.to_str().expect("UTF-8 path");
    // The Motion Law's candidate rows are its largest step (Kane's whole derivation of the
    // bicycle now fits in one million units).
    for (command, method) in [("solve", "motion-law"), ("simulate", "motion-law")] {
        let stderr = refused(&[
            command,
            arm,
            "--method",
            method,
            "--max-work",
            "1",
            "-o",
            kept,
        ]);
        assert!(
            stderr.contains("passed its limit of 1 million units")
                && stderr.contains("(step 3)")
                && stderr.contains("--method newton-euler")
                && stderr.contains("--max-work 4"),
            "{command}: {stderr}"
        );
    }
    // Newton–Euler is not offered to itself.
    let stderr = refused(&["solve", arm, "--method", "newton-euler", "--max-work", "0"]);
    assert!(
        stderr.contains("--max-work") && !stderr.contains("--method newton-euler"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(kept).expect("kept"),
        "earlier output\n"
    );
    // The default limit leaves the problem alone.
    succeeds(&["solve", arm, "--method", "newton-euler"]);
    std::fs::remove_dir_all(&dir).expect("removed");
}

/// Every bundled problem and method, cut off at several points of its derivation: the
/// overrun is the error every time, never a panic or a system built from the zeros.
#[test]
fn cutting_a_derivation_short_anywhere_gives_the_overrun_and_never_a_panic() {
    use mbd_tutor::equations::Method;
    use mbd_tutor::symbolic::budget;
    for path in crate::support::all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem loads");
        for method in Method::ALL {
            budget::set_limit(u64::MAX);
            let full = mbd_tutor::pipeline::derive(
                &problem,
                method,
                mbd_tutor::pipeline::Purpose::Numbers,
            );
            let needed = budget::spent();
            for fraction in [1, 10, 50, 90] {
                budget::set_limit((needed * fraction / 100).max(1));
                match mbd_tutor::pipeline::derive(
                    &problem,
                    method,
                    mbd_tutor::pipeline::Purpose::Numbers,
                ) {
                    Err(mbd_tutor::Error::TooMuchWork { .. }) => {}
                    other => panic!(
                        "{} {} at {fraction}% of {needed}: {:?}",
                        path.display(),
                        method.name(),
                        other.map(|d| d.rows.len())
                    ),
                }
            }
            budget::set_limit(needed.saturating_add(1));
            let again = mbd_tutor::pipeline::derive(
                &problem,
                method,
                mbd_tutor::pipeline::Purpose::Numbers,
            );
            assert_eq!(again.is_ok(), full.is_ok(), "{}", path.display());
        }
    }
    budget::set_limit(u64::MAX);
}
