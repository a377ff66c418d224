//! Shared helpers: run the built binary and read its JSON.

use serde_json::Value;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The three equation-forming methods, as the command line names them.
pub const METHODS: [&str; 4] = ["motion-law", "newton-euler", "kane", "lagrange"];

/// The path of `problems/NAME.json`.
pub fn problem(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("problems")
        .join(format!("{name}.json"))
}

/// The text of the bundled problem `problems/NAME.json`.
pub fn problem_text(name: &str) -> String {
    std::fs::read_to_string(problem(name)).expect("the bundled problem is readable")
}

/// The bundled problem `problems/NAME.json` as JSON, for a test to change and write with
/// [`scratch`].
pub fn problem_json(name: &str) -> Value {
    serde_json::from_str(&problem_text(name)).expect("the bundled problem is JSON")
}

/// Writes `text` to `FILE` in this run's folder `mbd-TAG-PID` of the temporary directory,
/// and gives its path.
pub fn scratch_file(tag: &str, file: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("the temporary directory is writable");
    let path = dir.join(file);
    std::fs::write(&path, text).expect("the temporary directory is writable");
    path
}

/// Writes the problem `problem` to `NAME.json` in this run's folder `mbd-TAG-PID` of the
/// temporary directory, and gives its path.
pub fn scratch(tag: &str, name: &str, problem: &Value) -> PathBuf {
    let text = serde_json::to_string_pretty(problem).expect("JSON is written");
    scratch_file(tag, &format!("{name}.json"), &text)
}

/// Every `problems/*.json` file (not the `invalid/` ones), sorted.
pub fn all_problems() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("problems");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("problems/ is readable")
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

/// Runs `mbd-tutor ARGS...`. A command that only reads its files and prints (see
/// [`runs::key`]) runs once for the whole suite: the program gives the same bytes for the
/// same input, so the handouts that many tests read are written once. The key holds the
/// bytes of every file named, so a file written again is run again.
pub fn run<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Output {
    match runs::key(args) {
        Some(key) => runs::once(key, || run_afresh(args)),
        None => run_afresh(args),
    }
}

/// Runs `mbd-tutor ARGS...` in a new process, whatever ran before: for the tests of what
/// two runs give.
pub fn run_afresh<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// The answers of `answer --format json` of a problem file by `method` (its name).
pub fn answers_json(path: &std::path::Path, method: &str) -> Vec<Value> {
    let out = run_json(&[
        "answer".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
        "--method".as_ref(),
        method.as_ref(),
    ]);
    out["answers"].as_array().expect("answers").clone()
}

/// Runs the command and parses its standard output as JSON, failing with its stderr.
pub fn run_json<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Value {
    let out = run(args);
    let shown: Vec<String> = args
        .iter()
        .map(|a| a.as_ref().to_string_lossy().into_owned())
        .collect();
    assert!(
        out.status.success(),
        "mbd-tutor {} failed ({}):\n{}",
        shown.join(" "),
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "mbd-tutor {}: output is not JSON ({e}):\n{}",
            shown.join(" "),
            String::from_utf8_lossy(&out.stdout)
        )
    })
}

/// `mbd-tutor COMMAND PATH --format json --method METHOD EXTRA…` as JSON.
pub fn method_json(command: &str, path: &Path, method: &str, extra: &[&str]) -> Value {
    let mut args: Vec<OsString> = vec![command.into(), path.into()];
    args.extend(
        ["--format", "json", "--method", method]
            .iter()
            .chain(extra)
            .map(OsString::from),
    );
    run_json(&args)
}

/// The answer of `solve --format json`.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The method that formed the equations.
    pub method: String,
    /// The whole JSON answer.
    pub json: Value,
}

impl Solution {
    /// The second derivative of coordinate `q`.
    pub fn acc(&self, q: &str) -> f64 {
        self.json["accelerations"][q]
            .as_f64()
            .unwrap_or_else(|| panic!("{}: no acceleration for {q} in {}", self.method, self.json))
    }

    /// The reaction force at `joint`, in the parent's unit vectors.
    pub fn force(&self, joint: &str) -> [f64; 3] {
        self.vector(joint, "force")
    }

    /// The reaction moment at `joint` about its point on the child, in the parent's unit vectors.
    pub fn moment(&self, joint: &str) -> [f64; 3] {
        self.vector(joint, "moment")
    }

    fn vector(&self, joint: &str, which: &str) -> [f64; 3] {
        let v = &self.json["reactions"][joint][which];
        let get = |i: usize| {
            v[i].as_f64().unwrap_or_else(|| {
                panic!(
                    "{}: no reaction {joint}.{which} in {}",
                    self.method, self.json
                )
            })
        };
        [get(0), get(1), get(2)]
    }
}

/// `mbd-tutor solve PROBLEM --format json --method METHOD EXTRA...`.
pub fn solve(name: &str, method: &str, extra: &[&str]) -> Solution {
    Solution {
        method: method.to_string(),
        json: method_json("solve", &problem(name), method, extra),
    }
}

/// The same solve by each of the three methods.
pub fn solve_all(name: &str, extra: &[&str]) -> Vec<Solution> {
    METHODS.iter().map(|m| solve(name, m, extra)).collect()
}

/// `mbd-tutor simulate PROBLEM --format json EXTRA...`: the column names and the rows.
pub fn simulate(name: &str, extra: &[&str]) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut args: Vec<OsString> = vec!["simulate".into(), problem(name).into()];
    args.extend(["--format", "json"].iter().chain(extra).map(OsString::from));
    table(&run_json(&args))
}

/// The column names and the rows of `simulate --format json` output.
pub fn table(json: &Value) -> (Vec<String>, Vec<Vec<f64>>) {
    let columns = json["columns"]
        .as_array()
        .expect("columns")
        .iter()
        .map(|c| c.as_str().expect("column name").to_string())
        .collect();
    let rows = json["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .map(|r| {
            r.as_array()
                .expect("row")
                .iter()
                .map(|x| x.as_f64().expect("number"))
                .collect()
        })
        .collect();
    (columns, rows)
}

/// Asserts `|got - want| <= tol * max(|want|, scale)`: relative, with `scale` the size of
/// the quantity in the problem, so that a value that should vanish is judged fairly.
#[track_caller]
pub fn assert_close(got: f64, want: f64, tol: f64, scale: f64, what: &str) {
    let bound = tol * want.abs().max(scale);
    assert!(
        (got - want).abs() <= bound,
        "{what}: got {got:.15e}, want {want:.15e} (difference {:.3e}, allowed {bound:.3e})",
        (got - want).abs()
    );
}

/// The `friction` entry of `solve --format json` for the site `name`.
pub fn friction_site<'a>(json: &'a Value, name: &str) -> &'a Value {
    &json["friction"][name]
}

/// The number under `key` of a JSON object.
pub fn number(value: &Value, key: &str) -> f64 {
    value[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number `{key}` in {value}"))
}

/// The index of column `name` in a simulation's columns.
pub fn column(columns: &[String], name: &str) -> usize {
    columns
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no column {name} in {columns:?}"))
}

pub mod handouts;
mod latex;
pub mod mathml;
pub mod runs;

pub use latex::{pdflatex, pdflatex_afresh, pdflatex_present, pdflatex_source, Typeset};

/// `mbd-tutor explain problems/NAME.json ARGS…`: its standard output, failing with its stderr.
pub fn explain(name: &str, args: &[&str]) -> String {
    explain_file(&problem(name), args)
}

/// `explain PATH ARGS…`'s standard output; the run must succeed.
pub fn explain_file(path: &Path, args: &[&str]) -> String {
    let mut all = vec![std::ffi::OsStr::new("explain"), path.as_os_str()];
    all.extend(args.iter().map(std::ffi::OsStr::new));
    let out = run(&all);
    assert!(
        out.status.success(),
        "{}: {}",
        path.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The Markdown handout of the bundled problem `name` by `method`.
pub fn markdown_handout(name: &str, method: &str) -> String {
    explain(name, &["--method", method, "--format", "markdown"])
}

/// The text from `from` up to `to` (or the end); `from` must be there.
pub fn between<'t>(text: &'t str, from: &str, to: &str) -> &'t str {
    let start = text
        .find(from)
        .unwrap_or_else(|| panic!("{from} in {text}"));
    let rest = &text[start..];
    &rest[..rest.find(to).unwrap_or(rest.len())]
}

/// The HTML page without step 6's motion controls, the one script the page may hold
/// (cli.md, "draw --animate": "a small inline script is allowed there"). Exactly that
/// script goes, byte for byte as the template writes it: anything else, such as a script
/// smuggled in through the problem's text, stays for the caller to find.
pub fn without_motion_script(html: &str) -> String {
    const START: &str =
        "<script>\n/* The motion's controls: play, pause, the time slider, and the plots' markers at its time. */\n";
    let Some(start) = html.find(START) else {
        return html.to_string();
    };
    let end = html[start..]
        .find("</script>")
        .map_or(html.len(), |e| start + e + "</script>".len());
    let script = &html[start..end];
    // The controls touch only the motion's own elements.
    assert!(
        !script.contains("fetch(") && !script.contains("innerHTML") && !script.contains("eval("),
        "the motion's script does more than drive the motion"
    );
    format!("{}{}", &html[..start], &html[end..])
}

/// A seeded generator of numbers in [-1, 1), so that a failure names a state that can be
/// replayed.
pub struct Lcg(pub u64);

impl Lcg {
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }

    /// A state near `problem`'s initial one: each coordinate within `spread` of its initial
    /// value, each rate within 1 of its initial rate (the coordinates drawn first).
    pub fn state_near(
        &mut self,
        problem: &mbd_tutor::problem::Problem,
        spread: f64,
    ) -> (Vec<f64>, Vec<f64>) {
        let q: Vec<f64> = (problem.coordinates.iter())
            .map(|c| c.initial + spread * self.next())
            .collect();
        let rates: Vec<f64> = (problem.coordinates.iter())
            .map(|c| c.rate + self.next())
            .collect();
        (q, rates)
    }
}
