//! `mbd-tutor check` on every file of `problems/invalid/`: each is rejected with exit
//! status 1, and the report names where the problem is.

use std::process::Command;

/// Whether a report line starts with a JSON path such as `joints[1].axis` or `bodies.A.mass`.
fn names_a_json_path(line: &str) -> bool {
    let Some(rest) = line.strip_prefix("  ") else {
        return false;
    };
    let Some((location, _)) = rest.split_once(": ") else {
        return false;
    };
    let path = location.split(", column ").next().unwrap_or(location);
    let first = path.chars().next();
    first.is_some_and(|c| c.is_ascii_alphabetic())
        && path
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_.[]\"".contains(c))
}

#[test]
fn names_a_json_path_recognizes_paths_only() {
    assert!(names_a_json_path(
        "  joints[1].axis, column 3: unknown frame"
    ));
    assert!(names_a_json_path(
        "  bodies.A.mass: the mass must not be negative"
    ));
    assert!(!names_a_json_path("  the file is empty"));
    assert!(!names_a_json_path("    hint: did you mean `q1`?"));
}

#[test]
fn every_invalid_problem_is_rejected_with_its_paths() {
    insta::glob!("../problems/invalid", "*.json", |path| {
        let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
            .arg("check")
            .arg(path)
            .output()
            .unwrap();
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
        assert_eq!(output.status.code(), Some(1), "{name}: {stderr}");
        assert!(
            output.stdout.is_empty(),
            "{name}: nothing on standard output"
        );
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
        // Files that are not JSON at all have no path to name; every other does.
        let whole_file =
            ["empty", "not-json", "not-utf8", "number-out-of-range"].contains(&name.as_str());
        if whole_file {
            assert!(stderr.contains("the file is"), "{name}: {stderr}");
        } else {
            assert!(
                stderr.lines().any(names_a_json_path),
                "{name}: no JSON path in {stderr}"
            );
        }
        insta::assert_snapshot!(format!("invalid-{name}"), stderr);
    });
}

#[test]
fn a_valid_problem_is_summarized() {
    let problem = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/validation/all-joints-3d.json"
    );
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(["check", problem])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "ok: A spatial mechanism with every joint type: 7 bodies, 7 joints, 15 coordinates (3D)\n"
    );
}

#[test]
fn set_overrides_are_checked() {
    let problem = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/validation/all-joints-3d.json"
    );
    let run = |set: &str| {
        Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
            .args(["check", problem, "--set", set])
            .output()
            .unwrap()
    };
    assert_eq!(run("m=2,L=0.4").status.code(), Some(0));
    let negative = run("M=-1");
    assert_eq!(negative.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&negative.stderr);
    assert!(
        stderr.contains("bodies.A.mass: the mass must not be negative"),
        "{stderr}"
    );
    let unknown = run("mm=1");
    assert_eq!(unknown.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&unknown.stderr).contains("did you mean `m`?"));
    assert_eq!(
        run("m").status.code(),
        Some(2),
        "a malformed --set is a usage error"
    );
}

#[test]
fn schema_is_printed() {
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg("schema")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0));
    let schema: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(
        schema["$schema"],
        "https://json-schema.org/draft/2020-12/schema"
    );
}
