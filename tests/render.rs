//! The worked solution's rendering: the hand-written sample in every format, LaTeX that
//! pdflatex compiles, HTML with MathML and no script, and hostile text that stays text.

use mbd_tutor::render::sample::sample;
use mbd_tutor::render::{render, Format, Solution};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

const HOSTILE: &str = "\\input{/etc/passwd} {{ x }} <script>alert(1)</script> 100% & $ # _ ~ ^";

fn rendered(solution: &Solution, format: Format, student: bool) -> String {
    render(solution, format, None, student).unwrap_or_else(|e| panic!("{format:?}: {e}"))
}

/// A fresh scratch directory, removed when the test passes and kept for a look when it fails.
struct Scratch(PathBuf);

impl Scratch {
    fn join(&self, path: impl AsRef<Path>) -> PathBuf {
        self.0.join(path)
    }
}

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

fn scratch(name: &str) -> Scratch {
    let dir = std::env::temp_dir().join(format!("mbd-tutor-render-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("the temporary directory is writable");
    Scratch(dir)
}

/// Whether LaTeX can be checked here. Without pdflatex the check is skipped with a notice,
/// except in CI (`CI` set), where skipping would hide a failure.
fn pdflatex_present() -> bool {
    let present = Command::new("pdflatex")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    if !present {
        assert!(
            std::env::var_os("CI").is_none(),
            "pdflatex is missing, and CI must compile the LaTeX"
        );
        eprintln!("notice: pdflatex not found; LaTeX compilation not checked");
    }
    present
}

/// Compiles `source` with pdflatex (no shell escape, stop at the first error) and returns
/// the log; panics with the log's errors when it does not compile.
fn compile(dir: &Path, name: &str, source: &str) -> String {
    let tex = dir.join(format!("{name}.tex"));
    std::fs::write(&tex, source).expect("the .tex is writable");
    let output = Command::new("pdflatex")
        .args([
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-no-shell-escape",
        ])
        .arg(format!("{name}.tex"))
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("pdflatex runs");
    let log = std::fs::read_to_string(dir.join(format!("{name}.log"))).unwrap_or_default();
    let errors: Vec<&str> = log.lines().filter(|line| line.starts_with('!')).collect();
    assert!(
        output.status.success() && errors.is_empty() && dir.join(format!("{name}.pdf")).is_file(),
        "{} does not compile: {errors:?}\n{}",
        tex.display(),
        String::from_utf8_lossy(&output.stdout)
    );
    log
}

#[test]
fn sample_latex_compiles_full_and_student() {
    if !pdflatex_present() {
        return;
    }
    let dir = scratch("sample");
    compile(&dir, "full", &rendered(&sample(), Format::Latex, false));
    compile(&dir, "student", &rendered(&sample(), Format::Latex, true));
}

/// More than four unknowns: the matrix entry by entry, and a very long equation.
#[test]
fn large_system_latex_compiles() {
    if !pdflatex_present() {
        return;
    }
    let mut solution = sample();
    let long = (1..=60)
        .map(|i| format!("m L^{{2}} \\cos(q_{{{i}}}) \\ddot{{q}}_{{{i}}}"))
        .collect::<Vec<_>>()
        .join(" + ");
    solution.equations[0].simplified_tex = format!("{long} = 0");
    solution.equations[1].grouped_tex = format!("\\left({long}\\right) = 0");
    solution.matrix.whole = None;
    solution.matrix.entries = (1..=6)
        .map(|row| mbd_tutor::render::context::MatrixEntry {
            row,
            column: "b".into(),
            value_tex: format!("b_{{{row}}} = {long}"),
        })
        .collect();
    let source = rendered(&solution, Format::Latex, false);
    assert!(source.contains("row 6, column b"));
    compile(&scratch("large"), "large", &source);
}

#[test]
fn html_is_self_contained_mathml_without_script() {
    let html = rendered(&sample(), Format::Html, false);
    assert!(html.contains("<math"), "no MathML");
    assert!(!html.to_lowercase().contains("<script"), "a script");
    assert!(
        !html.contains("http://") || !html.contains("src=\"http"),
        "a network resource"
    );
    assert!(
        !html.contains("code class=\"tex\""),
        "some LaTeX did not convert to MathML"
    );
    // The 4x4 matrix is a MathML table, and q-double-dot is an accent under its subscript.
    assert!(html.contains("<mtable"));
    assert!(html.contains("<msub><mover accent=\"true\"><mrow><mi>q</mi></mrow><mi>¨</mi></mover><mrow><mn>1</mn></mrow></msub>"));
    // Plots are inlined as data URIs.
    assert!(
        html.contains("<img alt=\"The coordinates against time\" src=\"data:image/svg+xml;base64,")
    );
    let student = rendered(&sample(), Format::Html, true);
    assert!(student.contains("class=\"blank\"") && !student.contains("Step 5"));
}

#[test]
fn markdown_math_is_dollar_delimited_and_matches_snapshot() {
    let markdown = rendered(&sample(), Format::Markdown, false);
    assert!(markdown.contains(
        "| $q_{1}$ | angle of rod A from the downward vertical | O (revolute) | rad | 0.5 | 0 |"
    ));
    assert!(markdown.contains("$$\n\\begin{bmatrix}"));
    insta::assert_snapshot!("render_sample_markdown", markdown);
    insta::assert_snapshot!(
        "render_sample_markdown_student",
        rendered(&sample(), Format::Markdown, true)
    );
}

/// Every user-text field of the sample replaced by hostile text.
fn hostile_sample() -> Solution {
    let mut s = sample();
    s.title = HOSTILE.into();
    s.statement = Some(format!(
        "{HOSTILE}\n\n{{% include \"/etc/passwd\" %}} second paragraph"
    ));
    s.constants[0].description = HOSTILE.into();
    s.constants[0].unit = HOSTILE.into();
    s.coordinates[0].description = HOSTILE.into();
    s.free_bodies[0].contact[0].label = HOSTILE.into();
    s.plan.rejected[0].reason = HOSTILE.into();
    s.equations[0].label = HOSTILE.into();
    s.simulation.checks[0].name = HOSTILE.into();
    s.simulation.plots[0].title = HOSTILE.into();
    s.simulation.note = HOSTILE.into();
    s
}

#[test]
fn hostile_text_compiles_without_running_anything() {
    if !pdflatex_present() {
        return;
    }
    let dir = scratch("hostile");
    for (name, student) in [("hostile", false), ("hostile-student", true)] {
        let source = rendered(&hostile_sample(), Format::Latex, student);
        assert!(!source.contains("\\input{/etc/passwd}"));
        let log = compile(&dir, name, &source);
        // TeX logs every file it opens as `(/path`.
        assert!(!log.contains("passwd"), "the log mentions passwd:\n{log}");
    }
}

#[test]
fn hostile_text_is_escaped_in_html_and_never_evaluated() {
    let html = rendered(&hostile_sample(), Format::Html, false);
    assert!(!html.to_lowercase().contains("<script"), "a script");
    assert!(html.contains("&lt;script&gt;alert(1)&lt;&#x2F;script&gt;"));
    assert!(
        html.contains("{{ x }}"),
        "the Tera syntax was not kept as text"
    );
    assert!(html.contains("{% include &quot;&#x2F;etc&#x2F;passwd&quot; %}"));
    assert!(html.contains("100% &amp; $ # _ ~ ^"));
    let student = rendered(&hostile_sample(), Format::Html, true);
    assert!(!student.to_lowercase().contains("<script") && student.contains("{{ x }}"));
}

#[test]
fn hostile_text_is_escaped_in_markdown() {
    let markdown = rendered(&hostile_sample(), Format::Markdown, false);
    assert!(!markdown.contains("<script"));
    assert!(markdown.contains("\\\\input\\{/etc/passwd\\} \\{\\{ x \\}\\} &lt;script&gt;alert(1)&lt;/script&gt; 100% &amp; \\$ \\# \\_ \\~ \\^"));
}

#[test]
fn templates_directory_overrides_only_the_files_it_has() {
    let dir = scratch("templates");
    std::fs::write(
        dir.join("solution.md.tera"),
        "Custom: {{ title }} ({{ coordinates | length }} coordinates)\n",
    )
    .expect("writable");
    let custom =
        render(&sample(), Format::Markdown, Some(&dir), false).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        custom,
        "Custom: Double pendulum of two uniform rods (2 coordinates)\n"
    );
    // No solution.html.tera there: the built-in one is used.
    let html = render(&sample(), Format::Html, Some(&dir), false).unwrap_or_else(|e| panic!("{e}"));
    assert!(html.starts_with("<!DOCTYPE html>"));
}

#[test]
fn template_errors_name_the_template_and_the_cause() {
    let dir = scratch("broken");
    std::fs::write(dir.join("solution.tex.tera"), "{{ missing_variable }}\n").expect("writable");
    let error =
        render(&sample(), Format::Latex, Some(&dir), false).expect_err("an unknown variable fails");
    let message = error.to_string();
    assert!(message.contains("solution.tex.tera"), "{message}");
    assert!(
        message.contains("missing_variable"),
        "the cause is missing: {message}"
    );
    std::fs::write(dir.join("solution.tex.tera"), "{% if %}\n").expect("writable");
    let error =
        render(&sample(), Format::Latex, Some(&dir), false).expect_err("a syntax error fails");
    assert!(error.to_string().contains("solution.tex.tera"), "{error}");
}

fn problem_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("problems/ is readable")
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|path| path.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

fn file_stem(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Every problem of `problems/`, as the pipeline builds it, in every format; every `.tex`
/// (solution and handout) compiles.
#[test]
fn every_problem_renders_and_its_latex_compiles() {
    let mut documents = Vec::new();
    for path in problem_files() {
        let problem = mbd_tutor::problem::load_file(&path)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let solution =
            mbd_tutor::render::build::solution(&problem, mbd_tutor::equations::Method::MotionLaw)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for student in [false, true] {
            let html = rendered(&solution, Format::Html, student);
            assert!(
                html.contains("<math") && !html.to_lowercase().contains("<script"),
                "{}",
                path.display()
            );
            assert!(
                !html.contains("code class=\"tex\""),
                "{}: some LaTeX did not convert",
                path.display()
            );
            rendered(&solution, Format::Markdown, student);
            let name = format!(
                "{}{}",
                file_stem(&path),
                if student { "-student" } else { "" }
            );
            documents.push((name, rendered(&solution, Format::Latex, student)));
        }
    }
    assert!(!documents.is_empty(), "no problems found");
    if !pdflatex_present() {
        return;
    }
    let dir = scratch("problems");
    // Two at a time: pdflatex is single-threaded and most of the time of this test.
    let (first, second) = documents.split_at(documents.len() / 2);
    std::thread::scope(|scope| {
        for half in [first, second] {
            let dir: &Path = &dir;
            scope.spawn(move || {
                half.iter()
                    .for_each(|(name, source)| drop(compile(dir, name, source)))
            });
        }
    });
}

fn binary() -> Command {
    Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
}

#[test]
fn explain_writes_one_problem_to_a_file() {
    let dir = scratch("explain-file");
    let target = dir.join("pendulum.html");
    let problem = problem_files().into_iter().next().expect("a problem");
    let output = binary()
        .args(["explain", "--format", "html", "-o"])
        .arg(&target)
        .arg(&problem)
        .output()
        .expect("runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(output.stdout.is_empty());
    let html = std::fs::read_to_string(&target).expect("written");
    assert!(html.starts_with("<!DOCTYPE html>") && html.contains("<math"));
}

#[test]
fn explain_directory_goes_on_past_failures_and_lists_them() {
    let input = scratch("batch-in");
    let out_parent = scratch("batch-out");
    let out = out_parent.join("nested");
    let problems = problem_files();
    for path in problems.iter().take(2) {
        std::fs::copy(path, input.join(path.file_name().expect("a file name"))).expect("copied");
    }
    std::fs::write(input.join("a-broken.json"), "{ \"title\": \"broken\" ").expect("writable");
    std::fs::write(input.join("notes.txt"), "not a problem").expect("writable");
    std::fs::create_dir_all(input.join("sub")).expect("writable");
    std::fs::write(input.join("sub").join("skipped.json"), "{}").expect("writable");
    let output = binary()
        .args(["explain", "--format", "latex"])
        .arg(&*input)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("1 of 3 problems failed") && stderr.contains("a-broken.json"),
        "{stderr}"
    );
    assert!(!stderr.contains("skipped.json"), "{stderr}");
    for path in problems.iter().take(2) {
        assert!(
            out.join(format!("{}.tex", file_stem(path))).is_file(),
            "{} not written",
            path.display()
        );
    }
    assert!(!out.join("a-broken.tex").exists());
    // A directory needs -o.
    let output = binary()
        .args(["explain"])
        .arg(&*input)
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(2));
}

/// Hostile text in every free-text field of a problem file (title, statement, units,
/// descriptions, load names) and names with underscores, through the whole pipeline.
#[test]
fn hostile_problem_file_renders_safely_in_every_format() {
    let problem = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/render/hostile-problem.json");
    let dir = scratch("hostile-problem");
    let explain = |format: &str, student: bool, target: &Path| {
        let mut command = binary();
        command
            .args(["explain", "--format", format, "-o"])
            .arg(target)
            .arg(&problem);
        if student {
            command.arg("--student");
        }
        let output = command.output().expect("runs");
        assert!(
            output.status.success(),
            "{format}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        std::fs::read_to_string(target).expect("written")
    };
    for student in [false, true] {
        let suffix = if student { "-student" } else { "" };
        let html = explain("html", student, &dir.join(format!("hostile{suffix}.html")));
        let lower = html.to_lowercase();
        assert!(
            !lower.contains("<script") && !lower.contains("<img src=x") && !lower.contains("<b>")
        );
        assert!(
            html.contains("{{ x }} &lt;script&gt;alert(1)&lt;&#x2F;script&gt;"),
            "title not kept"
        );
        let markdown = explain(
            "markdown",
            student,
            &dir.join(format!("hostile{suffix}.md")),
        );
        assert!(!markdown.contains("<script") && !markdown.contains("<img src=x"));
        let latex = explain("latex", student, &dir.join(format!("hostile{suffix}.tex")));
        if pdflatex_present() {
            let log = compile(&dir, &format!("compiled{suffix}"), &latex);
            assert!(!log.contains("passwd"), "the log mentions passwd:\n{log}");
        }
    }
}
