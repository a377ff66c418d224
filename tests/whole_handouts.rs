//! Whole handouts, five problems in three formats, one snapshot each: a change to any part
//! of a handout shows as a diff to review. A snapshot only shows that nothing changed; the
//! numbers are checked against references elsewhere (`library`, `methods`, `questions`).

use std::process::Command;

/// One problem of each kind a course sets first: a particle, two links, a closed loop, a
/// switch from sliding to rolling, a nonholonomic rolling body.
const PROBLEMS: [(&str, &str); 5] = [
    ("simple-pendulum", "motion-law"),
    ("double-pendulum-rods", "kane"),
    ("four-bar", "motion-law"),
    ("bowling-ball", "newton-euler"),
    ("rolling-coin", "lagrange"),
];

fn explain(problem: &str, method: &str, format: &str) -> String {
    let path = format!("{}/problems/{problem}.json", env!("CARGO_MANIFEST_DIR"));
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(["explain", &path, "--method", method, "--format", format])
        .output()
        .expect("the binary runs");
    assert_eq!(
        output.status.code(),
        Some(0),
        "{problem} by {method} as {format}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout).expect("UTF-8")
}

#[test]
fn five_handouts_in_three_formats_are_as_reviewed() {
    for (problem, method) in PROBLEMS {
        for format in ["markdown", "latex", "html"] {
            insta::assert_snapshot!(
                format!("whole-{problem}-{method}-{format}"),
                explain(problem, method, format)
            );
        }
    }
}
