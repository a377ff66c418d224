//! Real clients: headless Chromium (through playwright-core, `tests/browser/run.js`) opens
//! the page `serve` serves and edits the problem under it, reads the drawn positions of
//! `motion.svg` at two instants, and plays the HTML handout's motion. Skipped with a notice
//! when Chromium, node or `tests/browser/node_modules` is missing and `CI` is unset.

use std::path::{Path, PathBuf};
use std::process::Command;

fn browser_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser")
}

/// Whether the browser tests can run; panics under CI when they cannot.
fn ready(test: &str) -> bool {
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
    let dir = std::env::temp_dir().join(format!("mbd-browser-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

fn problem(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("problems/{name}.json"))
}

fn node(args: &[&std::ffi::OsStr]) {
    let output = Command::new("node")
        .current_dir(browser_dir())
        .arg("run.js")
        .args(args)
        .output()
        .expect("node runs");
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

fn mbd(args: &[&std::ffi::OsStr]) -> String {
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("mbd-tutor runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// The pendulum served: an edit shows in the page without a reload, within explain's own
/// time for the file + 0.3 s of the save; a broken file shows its error, a fixed one the
/// solution again.
#[test]
fn a_served_page_follows_the_file_through_an_error_and_back() {
    if !ready("serve") {
        return;
    }
    let dir = scratch("serve");
    let file = dir.join("pendulum.json");
    std::fs::copy(problem("simple-pendulum"), &file).expect("copy");
    node(&[
        "serve".as_ref(),
        env!("CARGO_BIN_EXE_mbd-tutor").as_ref(),
        file.as_os_str(),
    ]);
}

/// A chain of six spherical links, whose worked solution takes seconds to build: an edit
/// shows "rebuilding…" in the page until the new solution replaces it (a quick rebuild, as
/// the pendulum's above, must not show it).
#[test]
fn a_slow_rebuild_says_rebuilding_meanwhile() {
    if !ready("rebuilding") {
        return;
    }
    let dir = scratch("rebuilding");
    let file = dir.join("chain.json");
    std::fs::copy(browser_dir().join("six-spherical-links.json"), &file).expect("copy");
    node(&[
        "rebuilding".as_ref(),
        env!("CARGO_BIN_EXE_mbd-tutor").as_ref(),
        file.as_os_str(),
        "m1".as_ref(),
    ]);
}

/// The double pendulum of two uniform rods by hand: O at the origin, A's centre at half
/// A's length down rod A (angle q1 from the downward vertical), P at its end, B's centre at
/// half B's length down rod B (angle q1 + q2).
fn double_pendulum_points(q1: f64, q2: f64) -> Vec<(&'static str, [f64; 3])> {
    let (l1, l2) = (0.6, 0.4);
    let down = |angle: f64, length: f64| [length * angle.sin(), -length * angle.cos(), 0.0];
    let p = down(q1, l1);
    let b = down(q1 + q2, l2 / 2.0);
    vec![
        ("joint-O", [0.0, 0.0, 0.0]),
        ("cm-A", down(q1, l1 / 2.0)),
        ("joint-P", p),
        ("cm-B", [p[0] + b[0], p[1] + b[1], 0.0]),
    ]
}

/// The simulation's own table (`simulate --format json`, at its output step, independent of
/// the motion's frames) at each of `instants`: the coordinates by name.
fn simulated(file: &Path, instants: &[f64]) -> Vec<std::collections::HashMap<String, f64>> {
    let table: serde_json::Value = serde_json::from_str(&mbd(&[
        "simulate".as_ref(),
        file.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
        "--no-checks".as_ref(),
    ]))
    .expect("simulate's JSON");
    let columns: Vec<String> = table["columns"]
        .as_array()
        .expect("columns")
        .iter()
        .map(|c| c.as_str().unwrap_or("").to_string())
        .collect();
    let rows = table["rows"].as_array().expect("rows");
    instants
        .iter()
        .map(|&t| {
            let row = rows
                .iter()
                .find(|r| (r[0].as_f64().unwrap_or(f64::NAN) - t).abs() < 1e-9)
                .expect("a row at the instant");
            columns
                .iter()
                .enumerate()
                .filter_map(|(k, c)| Some((c.clone(), row[k].as_f64()?)))
                .collect()
        })
        .collect()
}

/// `draw --animate` of `problem` into a scratch directory: the directory.
fn animated(name: &str, problem: &Path) -> PathBuf {
    let dir = scratch(name);
    mbd(&[
        "draw".as_ref(),
        problem.as_os_str(),
        "--animate".as_ref(),
        "-o".as_ref(),
        dir.as_os_str(),
    ]);
    dir
}

#[test]
fn motion_svg_draws_the_simulated_double_pendulum_at_two_instants() {
    if !ready("motion") {
        return;
    }
    let file = problem("double-pendulum-rods");
    let dir = animated("motion", &file);
    let times = [0.8, 2.4];
    let instants: Vec<serde_json::Value> = simulated(&file, &times)
        .iter()
        .zip(times)
        .map(|(q, t)| {
            let points: serde_json::Map<String, serde_json::Value> =
                double_pendulum_points(q["q1"], q["q2"])
                    .into_iter()
                    .map(|(id, p)| (id.to_string(), serde_json::json!(p)))
                    .collect();
            serde_json::json!({ "t": t, "points": points })
        })
        .collect();
    let expected = dir.join("expected.json");
    std::fs::write(
        &expected,
        serde_json::json!({ "instants": instants }).to_string(),
    )
    .expect("write");
    node(&[
        "motion".as_ref(),
        dir.join("motion.svg").as_os_str(),
        expected.as_os_str(),
    ]);
}

/// The double pendulum's angle marks follow the simulation: at two instants the arc of
/// q1 at O runs from straight down (rod A at q1 = 0) to along rod A, and that of q2 at P
/// from along rod A to along rod B, each sweeping the simulated coordinate; the labels move
/// with them.
#[test]
fn motion_svg_turns_the_angle_marks_with_the_coordinates() {
    if !ready("gauges") {
        return;
    }
    let file = problem("double-pendulum-rods");
    let dir = animated("gauges", &file);
    let times = [0.8, 1.6];
    let along = |angle: f64| [angle.sin(), -angle.cos(), 0.0];
    let instants: Vec<serde_json::Value> = simulated(&file, &times)
        .iter()
        .zip(times)
        .map(|(q, t)| {
            let (q1, q2) = (q["q1"], q["q2"]);
            let p = [0.6 * q1.sin(), -0.6 * q1.cos(), 0.0];
            serde_json::json!({ "t": t, "gauges": {
                "q_1": { "q": q1, "center": [0.0, 0.0, 0.0], "start": along(0.0), "end": along(q1) },
                "q_2": { "q": q2, "center": p, "start": along(q1), "end": along(q1 + q2) },
            }})
        })
        .collect();
    let expected = dir.join("expected.json");
    std::fs::write(
        &expected,
        serde_json::json!({ "instants": instants }).to_string(),
    )
    .expect("write");
    node(&[
        "gauges".as_ref(),
        dir.join("motion.svg").as_os_str(),
        expected.as_os_str(),
    ]);
}

/// The rolling coin's rim is drawn each frame as the ellipse its disc projects to: its
/// long half-axis the radius, its short one the radius times the axle's component towards
/// the reader, the axle D.y = (−sin ψ cos θ, cos ψ cos θ, sin θ) by hand from the simulated
/// angles (body-fixed z, x, y); it changes as the coin leans and turns.
#[test]
fn motion_svg_draws_a_3d_disc_as_its_changing_projection() {
    if !ready("disc") {
        return;
    }
    let file = problem("rolling-coin");
    let dir = animated("disc", &file);
    // Instants on frames (every 0.04 s), where no in-between blends the transforms.
    let times = [0.48, 2.0];
    let instants: Vec<serde_json::Value> = simulated(&file, &times)
        .iter()
        .zip(times)
        .map(|(q, t)| {
            let (psi, theta) = (q["psi"], q["theta"]);
            let axle = [
                -psi.sin() * theta.cos(),
                psi.cos() * theta.cos(),
                theta.sin(),
            ];
            serde_json::json!({ "t": t, "normal": axle })
        })
        .collect();
    let coin: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).expect("the problem")).expect("JSON");
    let radius = coin["constants"]["R"]["value"].as_f64().expect("R");
    let expected = dir.join("expected.json");
    std::fs::write(
        &expected,
        serde_json::json!({ "body": "D", "radius": radius, "instants": instants }).to_string(),
    )
    .expect("write");
    node(&[
        "disc".as_ref(),
        dir.join("motion.svg").as_os_str(),
        expected.as_os_str(),
    ]);
}

#[test]
fn the_html_handout_plays_its_motion() {
    if !ready("handout") {
        return;
    }
    let dir = scratch("handout");
    let page = dir.join("pendulum.html");
    mbd(&[
        "explain".as_ref(),
        problem("double-pendulum-rods").as_os_str(),
        "--format".as_ref(),
        "html".as_ref(),
        "-o".as_ref(),
        page.as_os_str(),
    ]);
    node(&["handout".as_ref(), page.as_os_str()]);
}

#[test]
fn absurd_frame_counts_are_refused_at_once() {
    let dir = scratch("frames");
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(["draw", "--animate", "--fps", "1000000", "-o"])
        .arg(&dir)
        .arg(problem("double-pendulum-rods"))
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("--fps"));
    assert!(!dir.join("motion.svg").exists());
}
