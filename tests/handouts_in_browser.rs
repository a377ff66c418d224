//! The handouts and pictures as a student sees them in headless Chromium (through
//! playwright-core, `tests/browser/handouts.js`): no text shows a literal `^`, `_` or `ˆ`;
//! the dots of q̇ and q̈ are drawn, above their letters, unclipped, inked, inside fractions
//! and brackets; the bowling ball's sliding friction points against the slip; no two force
//! arrows of a free body lie on top of each other; unit vectors stand clear of bodies and
//! pins; no two labels overlap; the rack, the cart and the four-bar's links are drawn as
//! their shapes. Skipped with a notice when Chromium, node or `tests/browser/node_modules`
//! is missing and `CI` is unset.

use crate::support::{all_problems, problem, run, METHODS};
use std::path::{Path, PathBuf};
use std::process::Command;

fn browser_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser")
}

/// Whether Chromium, node and the node modules are here; CI must have them.
pub(crate) fn ready(test: &str) -> bool {
    let chromium = Path::new("/usr/bin/chromium").exists();
    let node = Command::new("node").arg("--version").output().is_ok();
    let modules = browser_dir().join("node_modules/playwright-core").exists();
    if chromium && node && modules {
        return true;
    }
    let missing = format!(
        "{test}: needs /usr/bin/chromium ({chromium}), node ({node}) and `npm ci` in tests/browser ({modules})"
    );
    assert!(std::env::var_os("CI").is_none(), "CI {missing}");
    eprintln!("skipped {missing}");
    false
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-handouts-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// Runs `node handouts.js MODE ARGS...` and fails with what it printed unless every check
/// passed.
fn node(mode: &str, args: &[PathBuf]) {
    let output = Command::new("node")
        .current_dir(browser_dir())
        .arg("handouts.js")
        .arg(mode)
        .args(args)
        .output()
        .expect("node runs");
    assert!(
        output.status.success(),
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

fn ok(args: &[&str]) {
    let out = run(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The HTML handout of `file` by `method`, as `explain` prints it (the run the suite's
/// other tests of every handout share; the page holds its plots), written into `dir`.
fn handout(file: &Path, method: &str, dir: &Path) -> PathBuf {
    let stem = file.file_stem().expect("a name").to_string_lossy();
    let page = dir.join(format!("{stem}-{method}.html"));
    let out = crate::support::handouts::explained(file, method, "html", false);
    assert!(
        out.status.success(),
        "{stem} by {method}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::write(&page, &out.stdout).expect("the page is written");
    page
}

/// The pictures `draw` writes of `file` by `method` (with the motion when `animate`).
fn pictures(file: &Path, method: &str, dir: &Path, animate: bool) -> Vec<PathBuf> {
    let stem = file.file_stem().expect("a name").to_string_lossy();
    let out = dir.join(format!("{stem}-{method}"));
    let (f, o) = (file.to_string_lossy(), out.to_string_lossy());
    let mut args = vec!["draw", &f, "--method", method, "-o", &o];
    if animate {
        args.push("--animate");
    }
    ok(&args);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&out)
        .expect("pictures written")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    files.sort();
    files
}

/// Every bundled problem and the one of awkward names (B0, link_1, J4 on L4, P4 of C).
fn problems() -> Vec<PathBuf> {
    let mut files = all_problems();
    files.push(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/draw/names.json"));
    files
}

#[test]
fn no_handout_or_picture_shows_a_literal_script_mark() {
    if !ready("texts") {
        return;
    }
    let dir = scratch("texts");
    let mut pages = Vec::new();
    for file in problems() {
        for (k, method) in METHODS.iter().enumerate() {
            pages.push(handout(&file, method, &dir));
            pages.extend(pictures(&file, method, &dir, k == 0));
        }
    }
    node("texts", &pages);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Problems whose rows put q̇ and q̈ inside fractions (Lagrange's ∂L/∂q̇) and brackets
/// (Kane's and the Motion Law's velocities and accelerations).
#[test]
fn overdots_are_seen_inside_fractions_and_brackets() {
    if !ready("overdots") {
        return;
    }
    let dir = scratch("overdots");
    let mut pages = Vec::new();
    for name in [
        "four-bar",
        "double-pendulum-rods",
        "heavy-symmetric-top",
        "disc-in-cylinder",
    ] {
        for method in ["lagrange", "kane"] {
            pages.push(handout(&problem(name), method, &dir));
        }
    }
    node("overdots", &pages);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The unit vectors of the frame tables and rows (the ladder's l̂, the top's and the coin's
/// tilted frames, the four-bar's bars): each hat over the middle of its letter.
#[test]
fn hats_stand_over_the_middle_of_their_letters() {
    if !ready("hats") {
        return;
    }
    let dir = scratch("hats");
    let mut pages = Vec::new();
    for (name, method) in [
        ("ladder-about-to-slip", "motion-law"),
        ("heavy-symmetric-top", "kane"),
        ("rolling-coin", "kane"),
        ("four-bar", "newton-euler"),
    ] {
        pages.push(handout(&problem(name), method, &dir));
    }
    node("hats", &pages);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The projection's image of N's x axis on the page (y down), as a unit vector.
fn page_x(svg: &Path) -> [f64; 2] {
    let text = std::fs::read_to_string(svg).expect("a picture");
    let start = text.find("data-projection=\"").expect("a projection") + 17;
    let end = start + text[start..].find('"').expect("closed");
    let n: Vec<f64> = text[start..end]
        .split_whitespace()
        .map(|x| x.parse().expect("a number"))
        .collect();
    let length = n[0].hypot(n[3]);
    [n[0] / length, n[3] / length]
}

/// The ball released with its centre at v0 and no spin: the point of the ball at the lane
/// moves at ẋ + R θ̇ along N.x (v of the centre plus θ̇ n̂_z × (−R n̂_y) = R θ̇ n̂_x), here
/// v0 > 0, so it slips forward and the lane's friction on it acts along −N.x, drawn so in
/// every free body (`draw`'s and the handout's) of every method.
#[test]
fn the_bowling_balls_friction_is_drawn_against_the_slip() {
    if !ready("friction") {
        return;
    }
    let file = problem("bowling-ball");
    let ball: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).expect("the problem")).expect("JSON");
    let constant = |k: &str| ball["constants"][k]["value"].as_f64().expect("a constant");
    let rate = ball["coordinates"]["theta"]["rate"].as_f64().expect("θ̇");
    let slip = constant("v0") + constant("R") * rate;
    assert!(slip > 0.0, "the ball slips forward at release");
    let dir = scratch("friction");
    let mut pages = Vec::new();
    let mut along = None;
    for method in METHODS {
        let drawn = pictures(&file, method, &dir, false);
        let body = drawn
            .iter()
            .find(|p| p.ends_with("fbd-B.svg"))
            .expect("the ball's free body");
        let x = page_x(body);
        along = Some([-slip.signum() * x[0], -slip.signum() * x[1]]);
        pages.push(body.clone());
        pages.push(handout(&file, method, &dir));
    }
    let [ux, uy] = along.expect("a direction");
    let expected = dir.join("expected.json");
    std::fs::write(
        &expected,
        // `draw` names the contact as the handout does, by its letter (P), never by its
        // word (lane).
        serde_json::json!({ "labels": ["-F^P_x"], "page": [ux, uy] }).to_string(),
    )
    .expect("write");
    let mut args = vec![expected];
    args.extend(pages);
    node("friction", &args);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn no_two_force_arrows_of_a_free_body_lie_on_top_of_each_other() {
    if !ready("arrows") {
        return;
    }
    let dir = scratch("arrows");
    let mut pictures_drawn = Vec::new();
    for file in problems() {
        for method in METHODS {
            pictures_drawn.extend(
                pictures(&file, method, &dir, false)
                    .into_iter()
                    .filter(|p| {
                        p.file_name()
                            .is_some_and(|n| n.to_string_lossy().starts_with("fbd-"))
                    }),
            );
        }
    }
    node("arrows", &pictures_drawn);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every configuration `draw` writes (and so every handout's step 1): each frame's unit
/// vectors clear of every body's outline and every pin.
#[test]
fn unit_vectors_stand_clear_of_bodies_and_pins() {
    if !ready("triads") {
        return;
    }
    let dir = scratch("triads");
    let mut configurations = Vec::new();
    for file in problems() {
        configurations.extend(
            pictures(&file, METHODS[0], &dir, false)
                .into_iter()
                .filter(|p| p.ends_with("configuration.svg")),
        );
    }
    node("triads", &configurations);
    let _ = std::fs::remove_dir_all(&dir);
}

/// No label of a configuration or a free body lies on another (a weight's "m g" on a
/// reaction's name, a top's Ḣ on its m a*).
#[test]
fn no_two_labels_of_a_picture_overlap() {
    if !ready("labels") {
        return;
    }
    let dir = scratch("labels");
    let mut drawn = Vec::new();
    for file in problems() {
        for method in METHODS {
            drawn.extend(pictures(&file, method, &dir, false));
        }
    }
    node("labels", &drawn);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The bodies of the free bodies drawn as their shapes, not as points: the rack a bar along
/// its motion, the cart a block, each of the four-bar's links a rod from pin to pin, as
/// long as the bar (a = 0.1 m, b = 0.3 m, c = 0.25 m), in `draw`'s free bodies and in the
/// handouts' (every method).
#[test]
fn the_rack_the_cart_and_the_links_are_drawn_as_shapes() {
    if !ready("shapes") {
        return;
    }
    let dir = scratch("shapes");
    let expected = dir.join("expected.json");
    std::fs::write(
        &expected,
        serde_json::json!({ "bodies": {
            "R": { "shape": "block", "elongated": 3, "thick": 4 },
            "C": { "shape": "block", "thick": 10 },
        } })
        .to_string(),
    )
    .expect("write");
    let links = dir.join("links.json");
    std::fs::write(
        &links,
        serde_json::json!({ "bodies": {
            "A": { "shape": "rod", "length": 0.1 },
            "B": { "shape": "rod", "length": 0.3 },
            "C": { "shape": "rod", "length": 0.25 },
        } })
        .to_string(),
    )
    .expect("write");
    for (names, wanted) in [
        (&["rack-and-pinion", "disc-on-cart"][..], &expected),
        (&["four-bar"][..], &links),
    ] {
        let mut args = vec![wanted.clone()];
        for name in names {
            for method in METHODS {
                args.extend(
                    pictures(&problem(name), method, &dir, false)
                        .into_iter()
                        .filter(|p| {
                            p.file_name()
                                .is_some_and(|n| n.to_string_lossy().starts_with("fbd-"))
                        }),
                );
                args.push(handout(&problem(name), method, &dir));
            }
        }
        node("shapes", &args);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
