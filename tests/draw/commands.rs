//! The command line and `explain`: files written, usage errors, embedded pictures that keep
//! their ids unique on a page, TikZ that pdflatex compiles.

use super::{drawings, read};
use crate::support::{pdflatex, pdflatex_present, pdflatex_source, problem as problem_path, run};
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::View;

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-draw-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn the_command_writes_one_file_per_picture_into_a_new_directory() {
    let dir = scratch("files").join("new");
    let p = problem_path("double-pendulum-rods");
    let out = run(&[
        std::ffi::OsStr::new("draw"),
        p.as_os_str(),
        "-o".as_ref(),
        dir.as_os_str(),
        "--state".as_ref(),
        "q1=0.2".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .expect("the directory")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(files, ["configuration.svg", "fbd-A+B.svg", "fbd-B.svg"]);
    let svg = std::fs::read_to_string(dir.join("configuration.svg")).expect("written");
    let r = read("cli", &svg);
    let want = r.project([0.6 * 0.2f64.sin(), -0.6 * 0.2f64.cos(), 0.0]);
    let got = r.points["joint-P"];
    assert!(
        (want[0] - got[0]).hypot(want[1] - got[1]) < 0.01,
        "--state moves the picture"
    );
    // The group A + B is cut at O alone: P, the pin between A and B, carries no force on
    // it, so it is drawn with the bodies and not marked as a point forces act at; B alone
    // is cut at P.
    let group = read(
        "cli",
        &std::fs::read_to_string(dir.join("fbd-A+B.svg")).expect("written"),
    );
    assert!(group.points.contains_key("joint-O"));
    assert!(!group.points.contains_key("joint-P"));
    let single = read(
        "cli",
        &std::fs::read_to_string(dir.join("fbd-B.svg")).expect("written"),
    );
    assert!(single.points.contains_key("joint-P"));
    let _ = std::fs::remove_dir_all(dir.parent().expect("scratch"));
}

#[test]
fn bad_views_and_states_are_usage_errors() {
    let dir = scratch("usage");
    let p = problem_path("heavy-symmetric-top");
    let d = dir.to_string_lossy().into_owned();
    let p = p.to_string_lossy().into_owned();
    for (args, needle) in [
        (vec!["draw", &p, "-o", &d, "--view", "sideways"], "--view"),
        (vec!["draw", &p, "-o", &d, "--view", "0,0,0"], "zero"),
        (vec!["draw", &p, "-o", &d, "--state", "nope=1"], "nope"),
        (vec!["draw", &p, "-o", &d, "--state", "q1"], "NAME=VALUE"),
        (vec!["draw", &p], "-o DIR"),
    ] {
        let out = run(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(needle), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
    assert!(!dir.exists(), "a refused run writes nothing");
}

#[test]
fn tikz_pictures_compile_with_pdflatex() {
    if !pdflatex_present("the TikZ pictures") {
        return;
    }
    let mut body = String::new();
    for name in [
        "double-pendulum-rods",
        "floating-plate-springs",
        "gyroscope-gimbal",
        "two-mass-spring-damper",
    ] {
        let problem = mbd_tutor::problem::load_file(&problem_path(name)).expect("bundled");
        for d in drawings(&problem, Method::MotionLaw, View::Isometric).1 {
            // Set as a handout sets a figure: on a line of its own, not indented.
            body.push_str("\\noindent\n");
            body.push_str(&d.tikz());
            body.push_str("\n\n");
        }
    }
    let source = format!(
        "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\usepackage{{tikz}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    let dir = scratch("tikz");
    std::fs::create_dir_all(&dir).expect("scratch");
    let typeset = pdflatex_source(&dir, "pictures", &source);
    assert!(
        typeset.compiled() && typeset.pages() > 0,
        "{}: {}",
        dir.display(),
        typeset.faults()
    );
    assert!(
        !typeset.log.contains("Overfull \\hbox"),
        "a picture is wider than the page: {}",
        dir.display()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The `<svg>…</svg>` elements of a page.
fn inline_pictures(page: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = page;
    while let Some(start) = rest.find("<svg") {
        let end = rest[start..].find("</svg>").expect("a closed <svg>") + start + "</svg>".len();
        out.push(&rest[start..end]);
        rest = &rest[end..];
    }
    out
}

#[test]
fn explain_embeds_the_pictures_with_ids_unique_on_the_page() {
    let p = problem_path("double-pendulum-rods");
    let p = p.to_string_lossy().into_owned();
    for format in ["html", "markdown"] {
        let out = run(&["explain", p.as_str(), "--format", format]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let page = String::from_utf8_lossy(&out.stdout).into_owned();
        // Step 6's motion (HTML only) is checked by tests/browser.rs.
        let pictures: Vec<&str> = inline_pictures(&page)
            .into_iter()
            .filter(|svg| !svg.contains("class=\"mbd motion\""))
            .collect();
        assert_eq!(
            pictures.len(),
            3,
            "{format}: the configuration and the plan's two free bodies"
        );
        let mut ids = std::collections::BTreeSet::new();
        for (svg, name) in pictures.iter().zip(["configuration", "fbd-A+B", "fbd-B"]) {
            let r = read(name, svg);
            for id in r.points.keys() {
                assert!(
                    id.starts_with(&format!("{name}-")),
                    "{format}: {id} is not prefixed by {name}"
                );
                assert!(ids.insert(id.clone()), "{format}: {id} twice on the page");
            }
            for (g, _) in &r.arrows {
                let at = g.attr("data-at").unwrap_or("");
                assert!(
                    r.points.contains_key(at),
                    "{format}: data-at {at} names no point of {name}"
                );
            }
        }
        // Step 2 shows each diagram just before its force table.
        let step2 = page.find("Step 2").expect("step 2");
        assert!(page[step2..].find("fbd-A+B-joint-O").is_some(), "{format}");
    }
    let out = run(&["explain", p.as_str(), "--student"]);
    let page = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        page.contains("id=\"configuration-joint-O\""),
        "the handout shows the system"
    );
    assert!(
        !page.contains("fbd-"),
        "the handout leaves the free bodies to draw"
    );
}

#[test]
fn explain_latex_with_tikz_pictures_compiles() {
    if !pdflatex_present("the handouts with TikZ pictures") {
        return;
    }
    let dir = scratch("explain-tex");
    std::fs::create_dir_all(&dir).expect("scratch");
    for (name, student) in [
        ("gyroscope-gimbal", false),
        ("floating-plate-springs", true),
    ] {
        let p = problem_path(name).to_string_lossy().into_owned();
        let tex = dir
            .join(format!("{name}.tex"))
            .to_string_lossy()
            .into_owned();
        let mut args = vec![
            "explain",
            p.as_str(),
            "--format",
            "latex",
            "-o",
            tex.as_str(),
        ];
        if student {
            args.push("--student");
        }
        let out = run(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let source = std::fs::read_to_string(&tex).expect("written");
        assert!(
            source.contains("\\begin{tikzpicture}"),
            "{name}: no TikZ picture"
        );
        let typeset = pdflatex(std::path::Path::new(&tex));
        assert!(
            typeset.compiled(),
            "{name}.tex does not compile: {}: {}",
            typeset.faults(),
            dir.display()
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The bowling ball skids forward at release: the lane's friction on it, μ times the
/// normal force, is drawn backward (−n̂_x), against the slip, in `draw`'s free body.
#[test]
fn the_bowling_balls_friction_points_against_the_slip() {
    let dir = scratch("bowling").join("out");
    let p = problem_path("bowling-ball");
    let out = run(&[
        std::ffi::OsStr::new("draw"),
        p.as_os_str(),
        "-o".as_ref(),
        dir.as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("fbd-B.svg")).expect("written");
    let r = read("bowling", &svg);
    let (g, m) = r
        .arrows
        .iter()
        .find(|(g, _)| g.attr("data-label") == Some("-F^P_x"))
        .expect("the friction arrow");
    assert_eq!(g.attr("data-kind"), Some("reaction"));
    let (tail, head) = super::line(g, *m).expect("straight");
    let back = r.project_direction([-1.0, 0.0, 0.0]);
    let got = [head[0] - tail[0], head[1] - tail[1]];
    assert!(
        super::angle_between(got, back) < 1e-3,
        "friction drawn along {got:?}"
    );
    // The kinetic diagram's m a^{B*}: the star raised with its letters (a text "B*" in a
    // raised span), not printed as "^*".
    let texts: Vec<&str> = svg.split('>').filter_map(|t| t.split('<').next()).collect();
    assert!(
        texts.iter().all(|t| !t.contains('^')),
        "a literal ^ in the SVG's text"
    );
}
