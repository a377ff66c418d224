//! Every name renders: a loop closed at J4 on a body L4, a point P4C of a body C, bodies B0
//! and link_1 give LaTeX that pdflatex compiles by every method (no double subscript), and
//! no HTML handout or `draw` SVG prints a literal `^`, `_` or `ˆ` in a text node.

use crate::support::handouts::{explained, two_at_a_time};
use crate::support::{all_problems, pdflatex_present, pdflatex_source, run, METHODS};
use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-names-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    dir
}

/// tests/draw/names.json: a body L4 on B0 and a body C on link_1, their loop closed at J4,
/// a point P4C of C pushed along n̂_x.
fn names_with_a_loop(_dir: &Path) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/draw/names.json")
}

#[test]
fn two_part_names_compile_by_every_method() {
    if !pdflatex_present("the names' handouts") {
        return;
    }
    let dir = scratch("latex");
    let problem = names_with_a_loop(&dir);
    let jobs: Vec<(&str, bool)> = METHODS
        .iter()
        .flat_map(|m| [(*m, false), (*m, true)])
        .collect();
    // As `explain` prints them (the suite's other tests read the same runs), two at a time.
    let faults = two_at_a_time(&jobs, |&(method, student)| {
        let name = format!("{method}{}", if student { "-student" } else { "" });
        let out = explained(&problem, method, "latex", student);
        if !out.status.success() {
            return vec![format!("{name}: {}", String::from_utf8_lossy(&out.stderr))];
        }
        let source = String::from_utf8_lossy(&out.stdout);
        let mut found = Vec::new();
        if source.contains("}_{L_{4}}") {
            found.push(format!("{name}: a double subscript"));
        }
        // The worksheet leaves the closure's rows blank.
        if !student && !source.contains("J_{4,L_{4}}") {
            found.push(format!("{name}: J4 of L4 not in one group"));
        }
        let typeset = pdflatex_source(&dir, &name, &source);
        if !typeset.compiled() {
            found.push(format!("{name}.tex does not compile: {}", typeset.faults()));
        }
        found
    });
    assert!(faults.is_empty(), "{}", faults.join("\n"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The text nodes of an HTML or SVG document that hold `^`, `_` or `ˆ`, outside scripts
/// and styles (their code), and outside the user's own statement and title. The `ˆ` an
/// accent's `<mo>` sets over its letter in a `<mover>` is a hat drawn, not a literal.
fn literal_scripts(markup: &str) -> Vec<String> {
    let mut found = Vec::new();
    let markup = markup.replace("<mo stretchy=\"false\">ˆ</mo></mover>", "</mover>");
    let mut rest = markup.as_str();
    let mut skip = 0usize;
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        if skip == 0 && text.contains(['^', '_', 'ˆ']) {
            found.push(text.trim().chars().take(80).collect());
        }
        let close = rest[open..].find('>').map_or(rest.len(), |i| open + i + 1);
        let tag = &rest[open..close];
        let name: String = tag
            .trim_start_matches(['<', '/'])
            .chars()
            .take_while(char::is_ascii_alphanumeric)
            .collect();
        if matches!(name.as_str(), "script" | "style" | "title" | "h1") && !tag.ends_with("/>") {
            if tag.starts_with("</") {
                skip = skip.saturating_sub(1);
            } else {
                skip += 1;
            }
        }
        rest = &rest[close..];
    }
    found
}

#[test]
fn no_html_handout_or_picture_prints_a_literal_script() {
    let dir = scratch("html");
    let mut problems = all_problems();
    problems.push(names_with_a_loop(&dir));
    for path in &problems {
        let html = dir.join("page.html");
        let out = run(&[
            "explain".as_ref(),
            path.as_os_str(),
            "--format".as_ref(),
            "html".as_ref(),
            "-o".as_ref(),
            html.as_os_str(),
        ]);
        assert!(out.status.success(), "{}", path.display());
        let page = std::fs::read_to_string(&html).expect("written");
        // The statement is the user's text, as written.
        let page = match page.find("<div class=\"statement\"") {
            Some(a) => match page[a..].find("</div>") {
                Some(b) => format!("{}{}", &page[..a], &page[a + b..]),
                None => page,
            },
            None => page,
        };
        let literal = literal_scripts(&page);
        assert!(literal.is_empty(), "{}: {literal:?}", path.display());
        let files: Vec<_> = std::fs::read_dir(&dir)
            .expect("dir")
            .filter_map(|e| e.ok())
            .filter(|e| e.path().extension().is_some_and(|x| x == "svg"))
            .collect();
        assert!(
            files.is_empty(),
            "{}: the HTML wrote files beside itself",
            path.display()
        );
    }
    let drawn = dir.join("drawn");
    let out = run(&[
        "draw".as_ref(),
        problems.last().expect("names").as_os_str(),
        "-o".as_ref(),
        drawn.as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for entry in std::fs::read_dir(&drawn).expect("drawn") {
        let svg = std::fs::read_to_string(entry.expect("entry").path()).expect("svg");
        let literal = literal_scripts(&svg);
        assert!(literal.is_empty(), "draw: {literal:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
