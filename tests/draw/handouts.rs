//! Every handout compiles with pdflatex, its pictures embedded as TikZ, including one whose
//! bodies are named B0, B1, B2 and link_1 (a body origin's caption once wrote
//! `$B_{0}_{o}$`, a double subscript); and a body's `shape` is what its picture draws, a
//! bad one refused with its JSON path.

use crate::support::handouts::{handout_of, two_at_a_time};
use crate::support::{all_problems, pdflatex_source, run};
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-handouts-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

fn names_problem() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/draw/names.json")
}

#[test]
fn every_handout_compiles_with_its_pictures() {
    if !crate::support::pdflatex_present("the handouts") {
        return;
    }
    let dir = scratch("latex");
    let mut problems = all_problems();
    problems.push(names_problem());
    // The Motion Law's handout is the default one; the suite writes it once for every test
    // that reads it (`support::run`), and pdflatex, single-threaded, runs on both cores.
    let failed = two_at_a_time(&problems, |problem| {
        let name = problem.file_stem().unwrap().to_string_lossy().into_owned();
        let Some(source) = handout_of(problem, "motion-law", "latex") else {
            return vec![format!("{name}: explain failed")];
        };
        if !source.contains("\\begin{tikzpicture}") {
            return vec![format!("{name}: no picture")];
        }
        let typeset = pdflatex_source(&dir, &name, &source);
        if typeset.compiled() {
            return Vec::new();
        }
        vec![format!("{name}: {}", typeset.faults())]
    });
    assert!(
        failed.is_empty(),
        "handouts that do not compile ({}):\n{}",
        dir.display(),
        failed.join("\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn names_with_digits_and_underscores_print_in_svg_and_tikz() {
    let dir = scratch("names");
    let out = run(&[
        "draw",
        &names_problem().to_string_lossy(),
        "-o",
        &dir.to_string_lossy(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("configuration.svg")).expect("drawn");
    for body in ["B0", "B1", "B2", "link_1"] {
        assert!(
            svg.contains(&format!("id=\"body-{body}\"")),
            "no group for {body}"
        );
        assert!(
            svg.contains(&format!("id=\"origin-{body}\"")) || body == "B1",
            "no origin of {body}"
        );
    }
    let tex = dir.join("names.tex");
    let out = run(&[
        "explain",
        &names_problem().to_string_lossy(),
        "--format",
        "latex",
        "-o",
        &tex.to_string_lossy(),
    ]);
    assert!(out.status.success());
    let source = std::fs::read_to_string(&tex).expect("written");
    assert!(
        !source.contains("}_{o}$") || !source.contains("$B_{0}_{o}$"),
        "a double subscript"
    );
    assert!(
        source.contains("{B_{0}}_{o}"),
        "the origin of B0 captioned as a group with its subscript"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A problem of one body of each declared shape.
fn shaped(shape: &str) -> String {
    format!(
        r#"{{
  "title": "A shaped pendulum", "dimension": 2,
  "constants": {{ "m": 1, "L": 1, "g": 9.81 }},
  "coordinates": {{ "q": {{ "initial": 0.3 }} }},
  "gravity": "-g*N.y",
  "bodies": {{ "A": {{ "mass": "m", "center": "-L/2*A.y", "inertia": "m*L^2/12", "shape": {shape} }} }},
  "joints": [ {{ "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["q"] }} ]
}}"#
    )
}

#[test]
fn a_declared_shape_is_what_the_picture_draws() {
    let dir = scratch("shapes");
    for (shape, kind, element) in [
        (r#"{ "type": "disc", "radius": "L/4" }"#, "disc", "<circle"),
        (
            r#"{ "type": "block", "size": ["L/3", "L"], "center": "-L/2*A.y" }"#,
            "block",
            "<path",
        ),
        (
            r#"{ "type": "rod", "from": "0", "to": "-L*A.y" }"#,
            "rod",
            "<",
        ),
        (r#"{ "type": "particle" }"#, "particle", "<circle"),
        (
            r#"{ "type": "polygon", "points": ["0", "-L*A.y + L/4*A.x", "-L*A.y - L/4*A.x"] }"#,
            "outline",
            "<path",
        ),
    ] {
        let file = dir.join(format!("{kind}.json"));
        std::fs::write(&file, shaped(shape)).expect("written");
        let out_dir = dir.join(kind);
        let out = run(&[
            "draw",
            &file.to_string_lossy(),
            "-o",
            &out_dir.to_string_lossy(),
        ]);
        assert!(
            out.status.success(),
            "{kind}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        for picture in ["configuration.svg", "fbd-A.svg"] {
            let svg = std::fs::read_to_string(out_dir.join(picture)).expect("drawn");
            let open = format!("<g class=\"body\" id=\"body-A\" data-shape=\"{kind}\">");
            let at = svg
                .find(&open)
                .unwrap_or_else(|| panic!("{kind}: {picture} has no {open}"));
            let group = &svg[at..at + svg[at..].find("</g>").expect("the group ends")];
            assert!(group.contains(element), "{kind}: {picture}: {group}");
        }
    }
    // The disc is a circle of its radius: L/4 at the picture's scale.
    let svg = std::fs::read_to_string(dir.join("disc/configuration.svg")).expect("drawn");
    let numbers: Vec<f64> = svg
        .split("data-projection=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .expect("a projection")
        .split_whitespace()
        .map(|x| x.parse().expect("a number"))
        .collect();
    let scale = numbers[0].hypot(numbers[3]);
    let group = &svg[svg.find("id=\"body-A\"").expect("the group")..];
    let r: f64 = group
        .split(" r=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .expect("a radius")
        .parse()
        .expect("a number");
    assert!(
        (r - 0.25 * scale).abs() < 0.06,
        "radius {r} against {}",
        0.25 * scale
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_bad_shape_is_refused_with_its_path() {
    let dir = scratch("bad-shapes");
    for (shape, path) in [
        (r#"{ "type": "wheel" }"#, "bodies.A.shape.type"),
        (
            r#"{ "type": "disc", "radius": "-L" }"#,
            "bodies.A.shape.radius",
        ),
        (
            r#"{ "type": "block", "size": ["L"] }"#,
            "bodies.A.shape.size",
        ),
        (
            r#"{ "type": "polygon", "points": ["0", "L*A.x"] }"#,
            "bodies.A.shape.points",
        ),
        (r#"{ "type": "rod", "from": "0" }"#, "bodies.A.shape.to"),
        (
            r#"{ "type": "rod", "from": "0", "to": "L*B.x" }"#,
            "bodies.A.shape.to",
        ),
    ] {
        let file = dir.join("bad.json");
        std::fs::write(&file, shaped(shape)).expect("written");
        let out = run(&["check", &file.to_string_lossy()]);
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        assert_eq!(out.status.code(), Some(1), "{shape}: {text}");
        assert!(
            text.contains(path),
            "{shape}: the error names {path}: {text}"
        );
        assert!(!text.contains("panicked"), "{shape}: {text}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
