//! `mbd-tutor schema` against the files the reader accepts: every bundled problem, every
//! validation problem and every test fixture that `check` passes must validate against
//! the JSON Schema the program prints (a draft 2020-12 validator that is not ours:
//! Python's `jsonschema`). A key the reader takes and the schema forbids fails here.

use crate::support::run;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Whether Python's `jsonschema` can be imported; without it the check is skipped with a
/// notice, except in CI (`CI` set), where skipping would hide a failure.
fn validator_present() -> bool {
    let present = Command::new("python3")
        .args(["-c", "import jsonschema"])
        .output()
        .is_ok_and(|o| o.status.success());
    assert!(
        present || std::env::var_os("CI").is_none(),
        "python3 with jsonschema is missing, and CI must validate the schema"
    );
    if !present {
        eprintln!("notice: python3's jsonschema not found; the schema was not checked");
    }
    present
}

/// The `.json` files under `dir`, depth first, in name order.
fn json_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
    paths.sort();
    for path in paths {
        let skipped = ["invalid", "robustness", "node_modules", "snapshots"];
        if path.is_dir() {
            if !skipped.iter().any(|s| path.ends_with(s)) {
                json_files(&path, out);
            }
        } else if path.extension().is_some_and(|e| e == "json") {
            out.push(path);
        }
    }
}

/// The problems the reader accepts: files with `bodies` that `check` passes.
fn accepted_problems() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in ["problems", "tests", "tools/reference/cases"] {
        json_files(
            Path::new(env!("CARGO_MANIFEST_DIR")).join(dir).as_path(),
            &mut files,
        );
    }
    files
        .into_iter()
        .filter(|f| {
            std::fs::read_to_string(f).is_ok_and(|t| t.contains("\"bodies\""))
                && run(&[Path::new("check"), f.as_path()]).status.success()
        })
        .collect()
}

const VALIDATE: &str = r#"
import json, sys, jsonschema
schema = json.load(open(sys.argv[1]))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
for name in sys.argv[2:]:
    for e in validator.iter_errors(json.load(open(name))):
        where = "/".join(map(str, e.absolute_path))
        print(f"{name}: {where}: {e.message[:200]}")
"#;

#[test]
fn every_problem_the_reader_accepts_validates_against_the_schema() {
    if !validator_present() {
        return;
    }
    let schema = run(&["schema"]);
    assert!(schema.status.success());
    let dir = std::env::temp_dir().join(format!("schema-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    let schema_file = dir.join("schema.json");
    std::fs::write(&schema_file, &schema.stdout).expect("written");
    let problems = accepted_problems();
    assert!(problems.len() > 100, "found {} problems", problems.len());
    let out = Command::new("python3")
        .args(["-c", VALIDATE])
        .arg(&schema_file)
        .args(&problems)
        .output()
        .expect("python3 runs");
    std::fs::remove_dir_all(&dir).ok();
    let errors = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success() && errors.trim().is_empty(),
        "accepted by the reader, refused by the schema:\n{errors}{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
