//! Coulomb friction on rough prismatic joints and closures, against closed forms worked by
//! hand: a block on a rough incline (sticks iff tan α ≤ μ, else s'' = −g(sin α − μ cos α)),
//! one pushed along a rough floor (a = (P − μmg)/m), a collar pulled along a rough rod (a
//! prismatic closure: N = mg − P sin β, a = (P cos β − μ|N|)/m), a bead on a rough rail in
//! space (|N| the root sum of the squares of two components) and a bead on a rough rail
//! across a cart (|N| depends on the friction, solved here by a fixed point of our own).

use crate::support::{
    assert_close, column, friction_site, number, problem, run, run_json, solve_all, table, METHODS,
};
use serde_json::Value;
use std::ffi::OsString;

const G: f64 = 9.81;
const SLOPE: f64 = std::f64::consts::PI / 6.0;
const BLOCK: f64 = 2.0;

// ---- a block on a rough incline, on a prismatic joint up the slope ----

#[test]
fn a_block_on_a_rough_slide_slips_down_with_g_sin_minus_mu_cos() {
    let mu = 0.4_f64;
    assert!(SLOPE.tan() > mu, "the case slides");
    let normal = BLOCK * G * SLOPE.cos();
    for s in solve_all("block-on-rough-slide", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        // s is measured up the slope: it slides down.
        let a = -G * (SLOPE.sin() - mu * SLOPE.cos());
        assert_close(s.acc("s"), a, 1e-9, 1.0, &what("s''"));
        let slope = friction_site(&s.json, "slope");
        assert_eq!(slope["mode"], "slip", "{}", what("mode"));
        assert_close(number(slope, "normal"), normal, 1e-9, 1.0, &what("N"));
        assert_close(
            number(slope, "tangential"),
            mu * normal,
            1e-9,
            1.0,
            &what("|F|"),
        );
        assert_close(number(slope, "ratio"), mu, 1e-9, 1.0, &what("ratio"));
        // The plane's force in N's unit vectors: friction up the slope, along
        // (−cos α, sin α) (the slope rises toward −x), N out of it, along (sin α, cos α).
        let (sin, cos) = SLOPE.sin_cos();
        let force = s.force("slope");
        assert_close(
            force[0],
            -mu * normal * cos + normal * sin,
            1e-9,
            1.0,
            &what("Fx"),
        );
        assert_close(
            force[1],
            mu * normal * sin + normal * cos,
            1e-9,
            1.0,
            &what("Fy"),
        );
        assert_close(s.moment("slope")[2], 0.0, 1e-9, 1.0, &what("M"));
    }
}

#[test]
fn a_block_on_a_rough_slide_sticks_on_either_side_of_tan_alpha_equal_to_mu() {
    let critical = SLOPE.tan();
    for (mu, mode) in [
        (critical + 1e-6, "stick"),
        (critical - 1e-6, "slip"),
        (0.7, "stick"),
    ] {
        let set = format!("mu={mu}");
        for s in solve_all("block-on-rough-slide", &["--set", &set]) {
            let what = |q: &str| format!("{} at μ = {mu}: {q}", s.method);
            let slope = friction_site(&s.json, "slope");
            assert_eq!(slope["mode"], mode, "{}", what("mode"));
            let (a, friction) = if mode == "slip" {
                let normal = BLOCK * G * SLOPE.cos();
                (-G * (SLOPE.sin() - mu * SLOPE.cos()), mu * normal)
            } else {
                (0.0, BLOCK * G * SLOPE.sin())
            };
            assert_close(s.acc("s"), a, 1e-9, 1.0, &what("s''"));
            assert_close(
                number(slope, "tangential"),
                friction,
                1e-9,
                1.0,
                &what("|F|"),
            );
        }
    }
}

/// `simulate` with `--set SET`: the standard error's switches, the columns and the rows.
fn thrown(set: &str) -> (String, Vec<String>, Vec<Vec<f64>>) {
    let out = run(&[
        "simulate",
        problem("block-on-rough-slide").to_str().unwrap_or_default(),
        "--format",
        "json",
        "--set",
        set,
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{stderr}");
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let (columns, rows) = table(&json);
    (stderr, columns, rows)
}

fn switch_time(stderr: &str, what: &str) -> f64 {
    let line = stderr
        .lines()
        .find(|l| l.contains(what))
        .unwrap_or_else(|| panic!("no switch `{what}` in:\n{stderr}"));
    line.trim_start_matches("t = ")
        .split(" s:")
        .next()
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no time in `{line}`"))
}

#[test]
fn a_block_thrown_up_a_rough_slide_stops_at_v_over_g_sin_plus_mu_cos_and_sticks() {
    let (mu, v) = (0.7_f64, 3.0);
    assert!(SLOPE.tan() <= mu, "it sticks once stopped");
    let stop = v / (G * (SLOPE.sin() + mu * SLOPE.cos()));
    let (stderr, columns, rows) = thrown("mu=0.7,v=3");
    let t = switch_time(&stderr, "slider slope stops slipping (sticks)");
    assert_close(t, stop, 1e-8, 1.0, "the instant it stops");
    assert_eq!(stderr.matches("slider slope").count(), 1, "{stderr}");
    let (s, rate, total) = (
        column(&columns, "s"),
        column(&columns, "s'"),
        column(&columns, "total"),
    );
    let reach = v * v / (2.0 * G * (SLOPE.sin() + mu * SLOPE.cos()));
    let last = rows.last().expect("rows");
    assert_close(last[s], reach, 1e-8, 1.0, "where it stops");
    assert_close(last[rate], 0.0, 1e-8, 1.0, "at rest after");
    // The energy lost is the friction's work, μ m g cos α over the distance slid.
    let lost = rows[0][total] - last[total];
    let work = mu * BLOCK * G * SLOPE.cos() * reach;
    assert_close(lost, work, 1e-8, 1.0, "energy lost = friction's work");
}

#[test]
fn a_block_thrown_up_a_steeper_rough_slide_stops_and_slides_back() {
    let (mu, v) = (0.4_f64, 3.0);
    let up = G * (SLOPE.sin() + mu * SLOPE.cos());
    let down = G * (SLOPE.sin() - mu * SLOPE.cos());
    let stop = v / up;
    let (stderr, columns, rows) = thrown("v=3");
    let t = switch_time(&stderr, "slider slope stops, and slips the other way");
    assert_close(t, stop, 1e-8, 1.0, "the instant it stops");
    let (time, s, total) = (
        column(&columns, "t"),
        column(&columns, "s"),
        column(&columns, "total"),
    );
    let reach = v * v / (2.0 * up);
    let last = rows.last().expect("rows");
    let back = 0.5 * down * (last[time] - stop).powi(2);
    assert_close(last[s], reach - back, 1e-8, 1.0, "where it is at the end");
    let lost = rows[0][total] - last[total];
    let work = mu * BLOCK * G * SLOPE.cos() * (reach + back);
    assert_close(lost, work, 1e-8, 1.0, "energy lost = friction's work");
}

// ---- a block pushed along a rough floor ----

#[test]
fn a_block_pushed_along_a_rough_floor_moves_with_p_minus_mu_m_g_over_m() {
    let (m, mu) = (2.0, 0.3);
    for (p, mode) in [(20.0, "slip"), (5.0, "stick"), (mu * m * G - 1e-6, "stick")] {
        let set = format!("P={p}");
        for s in solve_all("block-pushed-on-rough-floor", &["--set", &set]) {
            let what = |q: &str| format!("{} at P = {p}: {q}", s.method);
            let floor = friction_site(&s.json, "floor");
            assert_eq!(floor["mode"], mode, "{}", what("mode"));
            let (a, friction) = if mode == "slip" {
                ((p - mu * m * G) / m, -mu * m * G)
            } else {
                (0.0, -p)
            };
            assert_close(s.acc("x"), a, 1e-9, 1.0, &what("x''"));
            assert_close(s.force("floor")[0], friction, 1e-9, 1.0, &what("Fx"));
            assert_close(s.force("floor")[1], m * G, 1e-9, 1.0, &what("Fy"));
            assert_close(number(floor, "normal"), m * G, 1e-9, 1.0, &what("N"));
        }
    }
}

// ---- a collar on a rough rod: a prismatic closure ----

#[test]
fn a_collar_pulled_along_a_rough_rod_presses_on_its_top_and_slides() {
    let (m, p, beta, mu) = (1.0_f64, 20.0_f64, 40f64.to_radians(), 0.3);
    // The rope lifts more than the weight: the rod pushes down on the collar.
    let normal = m * G - p * beta.sin();
    assert!(normal < 0.0);
    let a = (p * beta.cos() - mu * normal.abs()) / m;
    for s in solve_all("collar-on-rough-rod", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("x"), a, 1e-9, 1.0, &what("x''"));
        assert_close(s.acc("y"), 0.0, 1e-9, 1.0, &what("y''"));
        let rod = friction_site(&s.json, "rod");
        assert_eq!(rod["mode"], "slip", "{}", what("mode"));
        assert_close(number(rod, "normal"), normal, 1e-9, 1.0, &what("N"));
        assert_close(
            s.force("rod")[0],
            -mu * normal.abs(),
            1e-9,
            1.0,
            &what("Fx"),
        );
        assert_close(s.force("rod")[1], normal, 1e-9, 1.0, &what("Fy"));
    }
    // A gentler pull leaves it at rest: the friction needed, P cos β, is within μ|N|.
    for s in solve_all("collar-on-rough-rod", &["--set", "P=2"]) {
        let rod = friction_site(&s.json, "rod");
        assert_eq!(rod["mode"], "stick", "{}", s.method);
        assert_close(s.acc("x"), 0.0, 1e-9, 1.0, &s.method);
        assert_close(s.force("rod")[0], -2.0 * beta.cos(), 1e-9, 1.0, &s.method);
    }
}

// ---- in space: two normal components ----

#[test]
fn a_bead_on_a_rough_rail_in_space_takes_the_magnitude_of_both_normal_components() {
    let (m, p, q, mu) = (1.0_f64, 20.0, 5.0_f64, 0.3);
    let normal = q.hypot(m * G);
    for s in solve_all("bead-on-rough-rail-3d", &[]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("x"), (p - mu * normal) / m, 1e-9, 1.0, &what("x''"));
        let rail = friction_site(&s.json, "rail");
        assert_eq!(rail["mode"], "slip", "{}", what("mode"));
        assert_close(number(rail, "normal"), normal, 1e-9, 1.0, &what("|N|"));
        let force = s.force("rail");
        assert_close(force[0], -mu * normal, 1e-9, 1.0, &what("Fx"));
        assert_close(force[1], -q, 1e-9, 1.0, &what("Fy"));
        assert_close(force[2], m * G, 1e-9, 1.0, &what("Fz"));
    }
    for s in solve_all("bead-on-rough-rail-3d", &["--set", "P=2"]) {
        assert_eq!(
            friction_site(&s.json, "rail")["mode"],
            "stick",
            "{}",
            s.method
        );
        assert_close(s.acc("x"), 0.0, 1e-9, 1.0, &s.method);
    }
}

const CART: &str = r#"{
  "title": "A bead on a rough rail across a cart",
  "dimension": 3,
  "constants": {
    "m": { "value": 1 }, "M": { "value": 2 }, "P": { "value": 20 }, "mu": { "value": 0.3 },
    "g": { "value": 9.81 }, "gamma": { "value": 0.6 }
  },
  "coordinates": { "y": { "initial": 0, "rate": 0 }, "s": { "initial": 0, "rate": 0 } },
  "gravity": "-g*N.z",
  "bodies": {
    "C": { "mass": "M", "inertia": { "xx": 1, "yy": 1, "zz": 1 } },
    "B": { "mass": "m", "inertia": { "xx": 0.001, "yy": 0.001, "zz": 0.001 } }
  },
  "joints": [
    { "name": "track", "type": "prismatic", "parent": "N", "child": "C", "axis": "N.y", "coordinates": ["y"] },
    { "name": "rail", "type": "prismatic", "parent": "C", "child": "B",
      "axis": "cos(gamma)*C.x + sin(gamma)*C.y", "coordinates": ["s"], "friction": "mu" }
  ],
  "loads": [ { "name": "push", "type": "force", "on": "B", "at": "B*", "vector": "P*N.x" } ]
}"#;

#[test]
fn a_bead_on_a_rough_rail_across_a_free_cart_agrees_with_a_fixed_point_worked_by_hand() {
    // The cart (M) runs freely along N.y; the rail on it is along u = (cos γ, sin γ, 0). With
    // F the friction along u and N₁ the rail's push along (−sin γ, cos γ, 0):
    // M y'' = −F sin γ − N₁ cos γ, m y'' cos γ = N₁ − P sin γ, so
    // y'' = −(F + P cos γ) sin γ / (M + m cos² γ); N₂ = mg; sliding, F = −μ √(N₁² + N₂²),
    // which depends on y'' and so on F: iterate.
    let (m, big_m, p, mu, gamma) = (1.0_f64, 2.0, 20.0, 0.3, 0.6_f64);
    let (sin, cos) = gamma.sin_cos();
    let (mut f, mut y, mut n1) = (0.0, 0.0, 0.0);
    for _ in 0..200 {
        y = -(f + p * cos) * sin / (big_m + m * cos * cos);
        n1 = m * y * cos + p * sin;
        f = -mu * n1.hypot(m * G);
    }
    let s_acc = (f + p * cos) / m - y * sin;
    let path = std::env::temp_dir().join(format!("mbd-rough-cart-{}.json", std::process::id()));
    std::fs::write(&path, CART).expect("write the problem");
    for method in METHODS {
        let args: Vec<OsString> = vec![
            "solve".into(),
            path.clone().into(),
            "--format".into(),
            "json".into(),
            "--method".into(),
            method.into(),
        ];
        let json = run_json(&args);
        let acc = |q: &str| number(&json["accelerations"], q);
        assert_close(acc("y"), y, 1e-9, 1.0, &format!("{method}: y''"));
        assert_close(acc("s"), s_acc, 1e-9, 1.0, &format!("{method}: s''"));
        let rail = friction_site(&json, "rail");
        assert_close(number(rail, "normal"), n1.hypot(m * G), 1e-9, 1.0, method);
        assert_close(number(rail, "tangential"), -f, 1e-9, 1.0, method);
    }
    let _ = std::fs::remove_file(&path);
}

#[test]
fn explain_shows_the_slider_s_assumption_check_and_second_solve() {
    let text = crate::support::explain("block-on-rough-slide", &[]);
    for wanted in [
        "**Friction at the slope",
        "The block is at rest relative to the surface at this state. Assume that it sticks",
        "The check fails: friction cannot hold the block, and it slips.",
        "= 9.81\\ \\mathrm{N} > \\mu",
    ] {
        assert!(text.contains(wanted), "no `{wanted}` in the handout");
    }
}

#[test]
fn a_rough_slider_crank_passes_its_dead_centres_sliding_and_only_loses_energy() {
    // At a dead centre the slider stops while the crank turns on: sticking is impossible
    // (the kinematics accelerate the slider), so it slides back, against the acceleration.
    let text = std::fs::read_to_string(problem("slider-crank-flywheel")).expect("read");
    let mut json: Value = serde_json::from_str(&text).expect("JSON");
    json["loads"] = Value::Array(Vec::new());
    let slider = json["joints"]
        .as_array_mut()
        .and_then(|joints| joints.iter_mut().find(|j| j["type"] == "prismatic"))
        .expect("a prismatic joint");
    slider["friction"] = Value::from(0.3);
    let name = slider["name"].as_str().unwrap_or_default().to_string();
    let path = std::env::temp_dir().join(format!("mbd-rough-crank-{}.json", std::process::id()));
    std::fs::write(&path, json.to_string()).expect("write the problem");
    let out = run(&[
        OsString::from("simulate"),
        path.clone().into(),
        "--format".into(),
        "json".into(),
    ]);
    let _ = std::fs::remove_file(&path);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{stderr}");
    let reversals = stderr
        .lines()
        .filter(|l| l.contains(&format!("slider {name} stops, and slips the other way")))
        .count();
    assert!(reversals >= 2, "{stderr}");
    assert!(
        stderr.contains("energy never rises") && !stderr.contains("FAIL"),
        "{stderr}"
    );
    let (columns, rows) = table(&serde_json::from_slice(&out.stdout).expect("JSON"));
    let total = column(&columns, "total");
    for pair in rows.windows(2) {
        assert!(pair[1][total] <= pair[0][total] + 1e-9, "energy rose");
    }
    assert!(
        rows[rows.len() - 1][total] < rows[0][total] * 0.9,
        "friction took energy"
    );
}
