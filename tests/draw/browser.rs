//! The pictures as a browser lays them out: every bundled problem's pictures and its
//! motion (and those of one whose bodies are named B0, B1, B2, link_1) are drawn, put on
//! one page with `measure.js`, and read back from one headless Chromium for every page
//! (playwright-core, `tests/browser/handouts.js results`). From the browser's own text
//! boxes and stroke geometry: no label overlaps another and no stroke crosses a label, in
//! the stills and at key frames of the motion; a rolling body is a circle (an ellipse in
//! 3D) of its radius; a uniform rod pinned at one end reaches its far end; in 2D the weight
//! points straight down the page.

use crate::support::handouts::two_at_a_time;
use crate::support::{all_problems, run};
use mbd_tutor::problem::{ConstraintKind, Inertia, Problem};
use mbd_tutor::symbolic::{eval, Values};
use serde_json::Value;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-browser-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// The problems measured: every bundled one and the one of awkward names.
fn problems() -> Vec<PathBuf> {
    let mut files = all_problems();
    files.push(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/draw/names.json"));
    files
}

/// Draws `problem` into `dir` and returns the page holding its pictures.
fn page(problem: &Path, dir: &Path) -> String {
    let p = problem.to_string_lossy().into_owned();
    let out = run(&[
        "draw",
        p.as_str(),
        "--animate",
        "-o",
        &dir.to_string_lossy(),
    ]);
    assert!(
        out.status.success(),
        "{p}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("pictures written")
        .map(|e| e.expect("entry").path())
        .filter(|f| f.extension().is_some_and(|e| e == "svg"))
        .collect();
    files.sort();
    let mut body = String::new();
    for f in files {
        let svg = std::fs::read_to_string(&f).expect("readable");
        let svg = svg.find("<svg").map_or(svg.as_str(), |k| &svg[k..]);
        let name = f.file_name().expect("a name").to_string_lossy();
        body.push_str(&format!("<div data-file=\"{name}\">{svg}</div>\n"));
    }
    let script = include_str!("measure.js");
    format!(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"></head><body>\n{body}<pre id=\"result\"></pre>\n<script>{script}</script>\n</body></html>\n"
    )
}

/// Loads every page of `pages` in one headless Chromium (through playwright-core,
/// `tests/browser/handouts.js results`) and returns what `measure.js` wrote on each.
fn measure(pages: &[PathBuf]) -> HashMap<PathBuf, Value> {
    let out = Command::new("node")
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser"))
        .arg("handouts.js")
        .arg("results")
        .args(pages)
        .output()
        .expect("node runs");
    let printed = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "the pages were not measured: {printed}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    printed
        .lines()
        .filter(|line| line.starts_with('{'))
        .map(|line| {
            let mut line: Value = serde_json::from_str(line)
                .unwrap_or_else(|e| panic!("the measurements are JSON: {e}"));
            let file = PathBuf::from(line["file"].as_str().expect("the page's file"));
            (file, line["result"].take())
        })
        .collect()
}

fn constants(problem: &Problem) -> Values {
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(
            mbd_tutor::symbolic::Symbol::Const(c.name.as_str().into()),
            c.value,
        );
    }
    v
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

/// The picture's scale: N's unit length in picture units (the length of a row, as a
/// parallel projection's rows are orthogonal and of one length).
fn scale_of(svg_projection: &[f64]) -> f64 {
    svg_projection[0]
        .hypot(svg_projection[1])
        .hypot(svg_projection[2])
}

/// A picture's projection, read from its file.
fn projection(dir: &Path, file: &str) -> Vec<f64> {
    let svg = std::fs::read_to_string(dir.join(file)).expect("a picture");
    let start = svg.find("data-projection=\"").expect("a projection") + 17;
    let end = start + svg[start..].find('"').expect("closed");
    svg[start..end]
        .split_whitespace()
        .map(|x| x.parse().expect("a number"))
        .collect()
}

/// The point of a marker circle in the picture, from the measurements' own source file.
fn marker(dir: &Path, file: &str, id: &str) -> Option<[f64; 2]> {
    let svg = std::fs::read_to_string(dir.join(file)).ok()?;
    let at = svg.find(&format!("id=\"{id}\""))?;
    let tag_start = svg[..at].rfind('<')?;
    let tag = &svg[tag_start..tag_start + svg[tag_start..].find('>')?];
    let attr = |k: &str| -> Option<f64> {
        let s = tag.find(&format!(" {k}=\""))? + k.len() + 3;
        tag[s..s + tag[s..].find('"')?].parse().ok()
    };
    Some([attr("cx")?, attr("cy")?])
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// One picture of a problem as the browser measured it: what the checks of a body read.
struct Sheet<'a> {
    problem: &'a Problem,
    values: &'a Values,
    planar: bool,
    dir: &'a Path,
    file: &'a str,
    /// Pixels per metre.
    scale: f64,
    /// The picture, and its time in the motion, as a fault names it.
    at: &'a str,
}

/// What the pictures of one problem get wrong.
fn judge(problem_file: &Path, dir: &Path, reports: &Value) -> Vec<String> {
    let problem: Problem = mbd_tutor::problem::load_file(problem_file).expect("a valid problem");
    let name = problem_file
        .file_stem()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    let values = constants(&problem);
    let planar = problem.dimension == mbd_tutor::problem::Dimension::Two;
    let mut faults = Vec::new();
    for report in reports.as_array().expect("one report per picture") {
        let file = report["file"].as_str().unwrap_or("?").to_string();
        let at = match report["time"].as_f64() {
            Some(t) => format!("{name}/{file} at t = {t:.3} s"),
            None => format!("{name}/{file}"),
        };
        let sheet = Sheet {
            problem: &problem,
            values: &values,
            planar,
            dir,
            file: &file,
            scale: scale_of(&projection(dir, &file)),
            at: &at,
        };
        faults.extend(sheet.layout_faults(report));
        let bodies = report["bodies"].as_array().cloned().unwrap_or_default();
        if file == "configuration.svg" {
            for b in problem.body_ids() {
                let body_name = problem.body_name(b);
                if !bodies
                    .iter()
                    .any(|g| g["id"] == format!("body-{body_name}"))
                {
                    faults.push(format!("{at}: no group body-{body_name}"));
                }
            }
        }
        faults.extend(bodies.iter().filter_map(|g| sheet.body_fault(g)));
    }
    faults
}

impl Sheet<'_> {
    /// Labels that overlap or cross a stroke, and (in 2D) a weight not down the page.
    fn layout_faults(&self, report: &Value) -> Vec<String> {
        let at = self.at;
        let mut faults = Vec::new();
        for pair in report["overlaps"].as_array().into_iter().flatten() {
            faults.push(format!("{at}: labels {pair} overlap"));
        }
        for pair in report["crossings"].as_array().into_iter().flatten() {
            faults.push(format!("{at}: label and stroke {pair} cross"));
        }
        if self.planar && self.problem.gravity.is_some() {
            for g in report["gravity"].as_array().into_iter().flatten() {
                let g = numbers(g);
                if !((g[2] - g[0]).abs() < 0.5 && g[3] > g[1]) {
                    faults.push(format!(
                        "{at}: the weight {g:?} does not point down the page"
                    ));
                }
            }
        }
        faults
    }

    /// What is wrong with the group `g` of a body: a wheel not of its radius, a uniform rod
    /// on one joint that does not reach its far end.
    fn body_fault(&self, g: &Value) -> Option<String> {
        let problem = self.problem;
        let id = g["id"].as_str().unwrap_or("");
        let body_name = id.strip_prefix("body-")?;
        let Some(b) = problem
            .body_ids()
            .find(|b| problem.body_name(*b) == body_name)
        else {
            return Some(format!("{}: {id} names no body", self.at));
        };
        let rolling = problem.constraints.iter().find_map(|c| match &c.kind {
            ConstraintKind::Rolling { body, radius, .. } if *body == b => {
                Some(eval(radius, self.values))
            }
            _ => None,
        });
        match rolling {
            Some(radius) => self.wheel_fault(g, id, radius),
            None => self.rod_fault(g, id, b, body_name),
        }
    }

    /// A rolling body: a circle (2D) or an ellipse whose long half-axis is the radius (3D: a
    /// parallel projection keeps the length of the disc's diameter that is parallel to the
    /// page).
    fn wheel_fault(&self, g: &Value, id: &str, radius: f64) -> Option<String> {
        let want = radius * self.scale;
        let drawn: Vec<f64> = if self.planar {
            g["circles"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|c| numbers(c)[2])
                .collect()
        } else {
            g["ellipses"]
                .as_array()
                .into_iter()
                .flatten()
                .chain(g["circles"].as_array().into_iter().flatten())
                .map(|e| {
                    let e = numbers(e);
                    e[2].max(*e.get(3).unwrap_or(&0.0))
                })
                .collect()
        };
        (g["shape"] != "disc" || !drawn.iter().any(|r| (r - want).abs() < 0.6)).then(|| {
            format!(
                "{}: {id} ({}) is no wheel of radius {want:.1}: {drawn:?}",
                self.at, g["shape"]
            )
        })
    }

    /// A uniform rod on one joint: reaches 2d from the joint through its mass centre.
    fn rod_fault(
        &self,
        g: &Value,
        id: &str,
        b: mbd_tutor::problem::BodyId,
        body_name: &str,
    ) -> Option<String> {
        let problem = self.problem;
        let body = problem.body(b);
        let joints: Vec<usize> = problem
            .joints
            .iter()
            .enumerate()
            .filter(|(_, j)| j.child == b || j.parent == b)
            .map(|(k, _)| k)
            .collect();
        let closed = problem
            .closures
            .iter()
            .any(|j| j.child == b || j.parent == b);
        if !self.planar || body.shape.is_some() || closed || joints.len() != 1 {
            return None;
        }
        let Inertia::Planar(izz) = &body.inertia else {
            return None;
        };
        let joint = format!("joint-{}", problem.joints[joints[0]].name);
        let pin = marker(self.dir, self.file, &joint)?;
        let cm = marker(self.dir, self.file, &format!("cm-{body_name}"))?;
        let d = distance(pin, cm) / self.scale;
        let (m, i) = (eval(&body.mass, self.values), eval(izz, self.values));
        if d <= 0.0 || (i - m * d * d / 3.0).abs() > 0.01 * m * d * d / 3.0 {
            return None;
        }
        let far = [2.0 * cm[0] - pin[0], 2.0 * cm[1] - pin[1]];
        let points: Vec<[f64; 2]> = g["points"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|p| {
                let p = numbers(p);
                [p[0], p[1]]
            })
            .collect();
        let nearest = points
            .iter()
            .map(|p| distance(*p, far))
            .fold(f64::MAX, f64::min);
        let beyond = points
            .iter()
            .any(|p| distance(*p, pin) > distance(far, pin) + 6.0);
        (g["shape"] != "rod" || nearest > 4.0 || beyond).then(|| {
            format!(
                "{}: {id} ({}) does not reach its far end {far:?} (nearest {nearest:.1})",
                self.at, g["shape"]
            )
        })
    }
}

#[test]
fn every_picture_measured_in_a_browser_reads_as_a_textbook_figure() {
    if !crate::handouts_in_browser::ready("the pictures measured in a browser") {
        return;
    }
    let root = scratch("pictures");
    let problems = problems();
    let page_of = |problem: &Path| {
        let name = problem.file_stem().unwrap().to_string_lossy().into_owned();
        (root.join(&name), root.join(format!("{name}.html")))
    };
    // The program draws two problems at a time; then one browser measures every page.
    two_at_a_time(&problems, |problem| {
        let (dir, html) = page_of(problem);
        std::fs::write(&html, page(problem, &dir)).expect("page written");
        Vec::new()
    });
    let pages: Vec<PathBuf> = problems.iter().map(|p| page_of(p).1).collect();
    let mut reports = measure(&pages);
    let faults: Vec<String> = problems
        .iter()
        .flat_map(|problem| {
            let (dir, html) = page_of(problem);
            let report = reports
                .remove(&html)
                .unwrap_or_else(|| panic!("{}: not measured", html.display()));
            judge(problem, &dir, &report)
        })
        .collect();
    let _ = std::fs::remove_dir_all(&root);
    assert!(
        faults.is_empty(),
        "{} faults:\n{}",
        faults.len(),
        faults.join("\n")
    );
}
