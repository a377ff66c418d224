//! pdflatex as every LaTeX test runs it: in the file's own directory, without a shell
//! escape, never waiting for input, stopping at the first error. The same source set twice
//! in the suite is set once: a handout is self-contained (its pictures are TikZ in the
//! text), so the bytes of the source decide what pdflatex makes of it. A test of what TeX
//! reads beside the file calls [`pdflatex_afresh`].

use std::collections::HashMap;
use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex, OnceLock};

/// What pdflatex made of one source.
#[derive(Clone, Debug)]
pub struct Typeset {
    /// Whether pdflatex ran to the end (exit 0).
    pub finished: bool,
    /// The log's error lines, those that start with `!`.
    pub errors: Vec<String>,
    /// The whole log.
    pub log: String,
}

impl Typeset {
    /// pdflatex ran to the end without an error.
    pub fn compiled(&self) -> bool {
        self.finished && self.errors.is_empty()
    }

    /// The pages written, from the log's "Output written on x.pdf (N pages, …)"; 0 where
    /// no PDF was written.
    pub fn pages(&self) -> usize {
        self.log
            .split("Output written on ")
            .nth(1)
            .and_then(|rest| rest.split('(').nth(1))
            .and_then(|rest| rest.split_whitespace().next())
            .and_then(|n| n.parse().ok())
            .unwrap_or(0)
    }

    /// How far the widest overfull line sticks out of the margin, in points (0 where none
    /// does).
    pub fn widest_overfull(&self) -> f64 {
        self.log
            .lines()
            .filter_map(|l| l.strip_prefix("Overfull \\hbox ("))
            .filter_map(|rest| rest.split("pt").next()?.parse::<f64>().ok())
            .fold(0.0, f64::max)
    }

    /// What to print when the source does not compile: pdflatex's status and the log's
    /// errors.
    pub fn faults(&self) -> String {
        let status = if self.finished { "finished" } else { "stopped" };
        format!("pdflatex {status}: {:?}", self.errors)
    }
}

/// The sources set so far, each in its own cell so that one compilation waits only for
/// the same source.
type Sets = HashMap<Vec<u8>, Arc<OnceLock<Typeset>>>;
static SET: OnceLock<Mutex<Sets>> = OnceLock::new();

/// Sets the LaTeX file `tex` once, in its directory, where it leaves its `.log`, `.aux`
/// and `.pdf`. A source already set in this run of the suite is not set again (with
/// `MBD_TUTOR_TESTS_AFRESH` set, every source is): its files are then those of the first
/// setting, in the first one's directory.
pub fn pdflatex(tex: &Path) -> Typeset {
    let source = std::fs::read(tex).unwrap_or_else(|e| panic!("{}: {e}", tex.display()));
    if std::env::var_os("MBD_TUTOR_TESTS_AFRESH").is_some() {
        return set(tex);
    }
    let cell = {
        let mut sets = SET.get_or_init(Mutex::default).lock().expect("lock");
        Arc::clone(sets.entry(source).or_default())
    };
    cell.get_or_init(|| set(tex)).clone()
}

/// Writes `source` to `dir/NAME.tex` and sets it with [`pdflatex`].
pub fn pdflatex_source(dir: &Path, name: &str, source: &str) -> Typeset {
    let tex = dir.join(format!("{name}.tex"));
    std::fs::write(&tex, source).unwrap_or_else(|e| panic!("{}: {e}", tex.display()));
    pdflatex(&tex)
}

/// Sets `tex` in a new pdflatex run, whatever ran before: for the tests of what TeX reads
/// or runs beside the file (a hostile text naming `/etc/passwd` or a file it finds there).
pub fn pdflatex_afresh(tex: &Path) -> Typeset {
    set(tex)
}

/// Runs pdflatex on `tex`.
fn set(tex: &Path) -> Typeset {
    let dir = tex.parent().expect("the file's directory");
    let name = tex.file_name().expect("a file name");
    let output = Command::new("pdflatex")
        .args([
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-no-shell-escape",
        ])
        .arg(name)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .expect("pdflatex runs");
    let log = std::fs::read_to_string(tex.with_extension("log")).unwrap_or_default();
    Typeset {
        finished: output.success(),
        errors: log
            .lines()
            .filter(|l| l.starts_with('!'))
            .map(str::to_string)
            .collect(),
        log,
    }
}

/// Whether pdflatex can be run here. Without it a LaTeX check is skipped with a notice
/// naming `what` was not compiled, except in CI (`CI` set), where skipping would hide a
/// failure.
pub fn pdflatex_present(what: &str) -> bool {
    let present = Command::new("pdflatex")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    assert!(
        present || std::env::var_os("CI").is_none(),
        "pdflatex is missing, and CI must compile the LaTeX"
    );
    if !present {
        eprintln!("notice: pdflatex not found; {what} was not compiled");
    }
    present
}

#[test]
fn the_log_gives_the_pages_and_the_widest_overfull_line() {
    let typeset = Typeset {
        finished: true,
        errors: Vec::new(),
        log: "Overfull \\hbox (2.5pt too wide) in paragraph\n\
              Overfull \\hbox (12.25pt too wide) detected at line 3\n\
              Overfull \\vbox (30pt too high)\n\
              Output written on x.pdf (3 pages, 1234 bytes)."
            .into(),
    };
    assert_eq!(typeset.pages(), 3);
    assert!((typeset.widest_overfull() - 12.25).abs() < 1e-12);
}
