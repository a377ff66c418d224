//! Robustness: hostile and broken input never panics or hangs, invalid physics gets an
//! error a student understands, output is never lost, user text is never executed, and
//! oversized problems are refused. TESTING.md describes the suites and the long campaign.

mod escaping;
mod generate;
mod harness;
mod hostile;
mod injection;
mod limits;
mod mutate;
mod output;
mod physics;
mod properties;
mod serve;
mod targets;

use std::path::PathBuf;

/// Every bundled problem (`problems/*.json` and `problems/validation/*.json`) as
/// `(file name, text)`.
pub fn problem_texts() -> Vec<(String, String)> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("problems");
    let mut files = Vec::new();
    for dir in [root.clone(), root.join("validation")] {
        for entry in std::fs::read_dir(&dir).expect("problems/ is readable") {
            let path = entry.expect("a directory entry").path();
            if path.extension().is_some_and(|e| e == "json") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
        .into_iter()
        .map(|path| {
            let text = std::fs::read_to_string(&path).expect("a bundled problem is UTF-8");
            (path.display().to_string(), text)
        })
        .collect()
}

/// The path of `tests/robustness/NAME`.
pub fn beside(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/robustness")
        .join(name)
}

/// A fresh, empty scratch directory for one test, removed by the test when it passes.
pub fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "mbd-tutor-robustness-{test}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("the scratch directory is created");
    dir
}
