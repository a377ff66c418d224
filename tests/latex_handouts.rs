//! pdflatex compiles every LaTeX handout: every bundled problem and tests/draw/names.json
//! (bodies B0 and link_1, a loop closed at J4 on L4, a point P4C of C), by every method,
//! worked and the student's, as `explain` prints them. Each is set once, two at a time.
//!
//! Over 400 handouts, many minutes of pdflatex on two cores: run on demand with
//! `cargo test --release --test main latex_handouts -- --ignored`. The suite compiles the
//! Motion Law's (worked and the student's) and Kane's of every problem in `render`, and
//! every method's of names.json in `names_render`.

use crate::support::handouts::{explained, two_at_a_time};
use crate::support::{all_problems, pdflatex_present, pdflatex_source, METHODS};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// How many handouts pdflatex set.
static SET: AtomicUsize = AtomicUsize::new(0);

/// One handout to set.
struct Handout {
    problem: PathBuf,
    method: &'static str,
    student: bool,
}

impl Handout {
    fn name(&self) -> String {
        let stem = self.problem.file_stem().expect("stem").to_string_lossy();
        let kind = if self.student { "-student" } else { "" };
        format!("{stem}-{}{kind}", self.method)
    }
}

/// What is wrong with `handout`: `explain` failing where the method is not refused, or
/// pdflatex stopping or reporting an error. A method refused for the problem (exit 1
/// with its reason) has no handout to compile.
fn faults(handout: &Handout, dir: &Path) -> Vec<String> {
    let name = handout.name();
    let out = explained(&handout.problem, handout.method, "latex", handout.student);
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return if out.status.code() == Some(1) && err.contains("hint") {
            Vec::new()
        } else {
            vec![format!("{name}: explain failed: {err}")]
        };
    }
    let typeset = pdflatex_source(dir, &name, &String::from_utf8_lossy(&out.stdout));
    SET.fetch_add(1, Ordering::SeqCst);
    let mut found = Vec::new();
    if !typeset.compiled() {
        found.push(format!("{name}: {}", typeset.faults()));
    }
    for ext in ["aux", "log", "pdf", "tex"] {
        let _ = std::fs::remove_file(dir.join(format!("{name}.{ext}")));
    }
    found
}

#[test]
#[ignore = "minutes of pdflatex; run on demand"]
fn every_handout_of_every_problem_compiles_by_every_method() {
    if !pdflatex_present("every handout") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("mbd-latex-handouts-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    let mut problems = all_problems();
    problems.push(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/draw/names.json"));
    let mut jobs = Vec::new();
    for problem in &problems {
        for method in METHODS {
            for student in [false, true] {
                jobs.push(Handout {
                    problem: problem.clone(),
                    method,
                    student,
                });
            }
        }
    }
    let found = two_at_a_time(&jobs, |h| faults(h, &dir));
    let set = SET.load(Ordering::SeqCst);
    assert!(set > 400, "only {set} of {} handouts were set", jobs.len());
    assert!(found.is_empty(), "{}", found.join("\n"));
    let _ = std::fs::remove_dir_all(&dir);
}
