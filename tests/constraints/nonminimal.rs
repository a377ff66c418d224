//! Prescribed motion, a position constraint among non-minimal coordinates and a velocity
//! constraint: the collar on a driven rod, the pendulum in Cartesian coordinates and the
//! knife edge.

use super::{largest, state};
use crate::support::{assert_close, column, problem, run, simulate, solve_all, METHODS};

const G: f64 = 9.81;

// ---------------------------------------------------------------------------------------
// The collar on a rod turned at a constant rate w (problems/collar-on-driven-rod.json).

const M_COLLAR: f64 = 0.3;
const W: f64 = 3.0;

#[test]
fn collar_on_driven_rod_closed_form() {
    // In the rod's turning frame, with theta'' = 0: radially m (r'' - r w^2) = 0; across the
    // rod the normal force N = m (r theta'' + 2 r' w) = 2 m r' w. The drive torque is the rate
    // of change of the angular momentum about the axle, (I_rod + I_c + m r^2) w:
    // tau = 2 m r r' w.
    let m = M_COLLAR;
    for (time, r, r_d) in [(0.0, 0.2, 0.1), (0.3, 0.5, -0.2), (1.7, 0.05, 0.8)] {
        let given = state(&[("r", r), ("r'", r_d)]);
        let time_text = format!("{time}");
        for s in solve_all(
            "collar-on-driven-rod",
            &["--time", &time_text, "--state", &given],
        ) {
            let what = |w: &str| format!("{} at t = {time}: {w}", s.method);
            let theta = s.json["state"]["theta"].as_f64().expect("theta");
            assert_close(theta, W * time, 1e-12, 1.0, &what("theta = w t"));
            assert_close(s.acc("theta"), 0.0, 1e-9, W * W, &what("theta''"));
            assert_close(s.acc("r"), r * W * W, 1e-9, W * W, &what("r''"));
            let drive = s.json["drives"]["theta"].as_f64().expect("drive");
            assert_close(
                drive,
                2.0 * m * r * r_d * W,
                1e-9,
                m * W * W,
                &what("drive torque"),
            );
            let want = [0.0, 2.0 * m * r_d * W, 0.0];
            for (k, want_k) in want.iter().enumerate() {
                let f = s.force("slide")[k];
                assert_close(
                    f,
                    *want_k,
                    1e-9,
                    m * W * W,
                    &what(&format!("slide force[{k}]")),
                );
                let c = s.moment("slide")[k];
                assert_close(c, 0.0, 1e-9, m * W * W, &what("slide moment"));
            }
        }
    }
}

#[test]
fn collar_slides_out_on_the_hyperbolic_cosine() {
    // r'' = w^2 r: r = r0 cosh(w t) + r0'/w sinh(w t); the drive follows 2 m r r' w.
    let (r0, r0_d) = (0.2, 0.1);
    for method in METHODS {
        let (cols, rows) = simulate("collar-on-driven-rod", &["--method", method]);
        let c = |n: &str| column(&cols, n);
        for row in &rows {
            let t = row[c("t")];
            let r = r0 * (W * t).cosh() + r0_d / W * (W * t).sinh();
            let r_d = r0 * W * (W * t).sinh() + r0_d * (W * t).cosh();
            assert_close(
                row[c("r")],
                r,
                1e-8,
                1.0,
                &format!("{method}: r at t = {t}"),
            );
            assert_close(
                row[c("r'")],
                r_d,
                1e-8,
                1.0,
                &format!("{method}: r' at t = {t}"),
            );
            assert_close(row[c("theta")], W * t, 1e-12, 1.0, "theta = w t");
            let drive = 2.0 * M_COLLAR * r * r_d * W;
            let got = row[c("theta.drive")];
            assert_close(
                got,
                drive,
                1e-8,
                1.0,
                &format!("{method}: drive at t = {t}"),
            );
        }
    }
}

#[test]
fn a_prescribed_coordinate_given_in_state_is_ignored_and_said_so() {
    let out = run(&[
        "solve".as_ref(),
        problem("collar-on-driven-rod").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
        "--time".as_ref(),
        "0.2".as_ref(),
        "--state".as_ref(),
        "theta=1,theta'=5".as_ref(),
    ]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let theta = json["state"]["theta"].as_f64().expect("theta");
    assert_close(
        theta,
        W * 0.2,
        1e-12,
        1.0,
        "theta = w t, not the --state value",
    );
    let rate = json["state"]["theta'"].as_f64().expect("theta'");
    assert_close(rate, W, 1e-12, 1.0, "theta' = w");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--state theta: ignored"), "{stderr}");
    assert!(stderr.contains("--state theta': ignored"), "{stderr}");
}

#[test]
fn the_energy_check_of_a_driven_problem_counts_the_drives_work() {
    let out = run(&[
        "simulate".as_ref(),
        problem("collar-on-driven-rod").as_os_str(),
    ]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("energy"), "{stderr}");
}

// ---------------------------------------------------------------------------------------
// The pendulum in Cartesian coordinates (problems/pendulum-cartesian.json).

/// With x = L sin(th), y = -L cos(th) and the carriage's mass mX moving with x only,
/// T = 1/2 L^2 th'^2 (M cos^2 th + m sin^2 th), M = m + mX, V = -m g L cos th, so
///   L (M cos^2 + m sin^2) th'' = mX L sin cos th'^2 - m g sin th,
/// which is the simple pendulum's th'' = -g/L sin th when mX = 0. Returns (x'', y'').
fn cartesian_pendulum(mx: f64, l: f64, x: f64, x_d: f64) -> (f64, f64) {
    let m = 1.0;
    let th = (x / l).asin();
    let th_d = x_d / (l * th.cos());
    let (s, c) = th.sin_cos();
    let th_dd = (mx * l * s * c * th_d * th_d - m * G * s) / (l * ((m + mx) * c * c + m * s * s));
    let x_dd = l * (c * th_dd - s * th_d * th_d);
    let y_dd = l * (s * th_dd + c * th_d * th_d);
    (x_dd, y_dd)
}

#[test]
fn cartesian_pendulum_matches_the_angle_form() {
    let l = 0.5;
    for (mx, x, x_d) in [(0.05, 0.3, 0.6), (1e-13, 0.3, 0.6), (0.05, -0.45, -1.1)] {
        let (x_dd, y_dd) = cartesian_pendulum(mx, l, x, x_d);
        if mx < 1e-12 {
            // The simple pendulum, written out: th'' = -g/L sin th, and the centripetal part.
            let th = (x / l).asin();
            let th_d = x_d / (l * th.cos());
            let th_dd = -G / l * th.sin();
            let want_x = l * (th.cos() * th_dd - th.sin() * th_d * th_d);
            let want_y = l * (th.sin() * th_dd + th.cos() * th_d * th_d);
            assert_close(
                x_dd,
                want_x,
                1e-11,
                G,
                "the light carriage gives the simple pendulum",
            );
            assert_close(
                y_dd,
                want_y,
                1e-11,
                G,
                "the light carriage gives the simple pendulum",
            );
        }
        let set = format!("mX={mx:.17e}");
        let given = state(&[("x", x), ("x'", x_d)]);
        for s in solve_all("pendulum-cartesian", &["--set", &set, "--state", &given]) {
            let what = |w: &str| format!("{} with mX = {mx} at x = {x}: {w}", s.method);
            let y = s.json["state"]["y"].as_f64().expect("y");
            assert_close(
                y,
                -(l * l - x * x).sqrt(),
                1e-9,
                l,
                &what("y on the circle"),
            );
            let y_d = s.json["state"]["y'"].as_f64().expect("y'");
            assert_close(y_d, -x * x_d / y, 1e-9, 1.0, &what("y' = -x x'/y"));
            assert_close(s.acc("x"), x_dd, 1e-9, G, &what("x''"));
            assert_close(s.acc("y"), y_dd, 1e-9, G, &what("y''"));
        }
    }
}

// ---------------------------------------------------------------------------------------
// The knife edge (problems/knife-edge.json): -x' sin th + y' cos th = 0 at the mass center.

#[test]
fn knife_edge_keeps_its_speed_along_the_blade() {
    // The blade's force is across the blade and through the mass center: theta'' = 0 and
    // the speed u = x' cos th + y' sin th along the blade stays, so
    // x'' = -u sin th th', y'' = u cos th th'.
    let (m, i) = (2.0, 0.03);
    for (th, x_d, th_d) in [(0.3, 1.2, 2.0), (2.0, -0.7, -5.0)] {
        let given = state(&[("theta", th), ("x'", x_d), ("theta'", th_d)]);
        let y_d = x_d * th.tan();
        let u = x_d * th.cos() + y_d * th.sin();
        for s in solve_all("knife-edge", &["--state", &given]) {
            let what = |w: &str| format!("{} at theta = {th}: {w}", s.method);
            let got = s.json["state"]["y'"].as_f64().expect("y'");
            assert_close(got, y_d, 1e-9, 1.0, &what("y' = x' tan th"));
            assert_close(s.acc("theta"), 0.0, 1e-9, u * th_d, &what("theta''"));
            assert_close(
                s.acc("x"),
                -u * th.sin() * th_d,
                1e-9,
                u * th_d,
                &what("x''"),
            );
            assert_close(
                s.acc("y"),
                u * th.cos() * th_d,
                1e-9,
                u * th_d,
                &what("y''"),
            );
        }
    }
    // Along a run: the path is a circle of radius u/th', and the energy stays.
    let (th0, x_d0, th_d) = (0.3_f64, 1.2, 1.0);
    let u = x_d0 / th0.cos();
    let energy0 = 0.5 * m * u * u + 0.5 * i * th_d * th_d;
    for method in METHODS {
        let (cols, rows) = simulate("knife-edge", &["--method", method]);
        let c = |n: &str| column(&cols, n);
        for row in &rows {
            let t = row[c("t")];
            let th = th0 + th_d * t;
            let x = u / th_d * (th.sin() - th0.sin());
            let y = -u / th_d * (th.cos() - th0.cos());
            let what = |w: &str| format!("{method} at t = {t}: {w}");
            assert_close(row[c("theta")], th, 1e-8, 1.0, &what("theta"));
            assert_close(row[c("x")], x, 1e-8, 1.0, &what("x"));
            assert_close(row[c("y")], y, 1e-8, 1.0, &what("y"));
            let (xd, yd, thd) = (row[c("x'")], row[c("y'")], row[c("theta'")]);
            let across = -xd * th.sin() + yd * th.cos();
            assert!(
                across.abs() < 1e-9,
                "{}",
                what(&format!("slips across at {across:e}"))
            );
            let energy = 0.5 * m * (xd * xd + yd * yd) + 0.5 * i * thd * thd;
            assert_close(energy, energy0, 1e-8, energy0, &what("energy"));
        }
        let turned = largest(rows.iter().map(|row| row[c("theta")]));
        assert!(turned > 1.2, "{method}: it turns");
    }
}

#[test]
fn knife_edge_turns_round_with_constant_energy() {
    let (m, i) = (2.0, 0.03);
    let (cols, rows) = simulate("knife-edge", &["--duration", "5", "--no-checks"]);
    let c = |n: &str| column(&cols, n);
    let energy = |row: &Vec<f64>| {
        let (xd, yd, thd) = (row[c("x'")], row[c("y'")], row[c("theta'")]);
        0.5 * m * (xd * xd + yd * yd) + 0.5 * i * thd * thd
    };
    let e0 = energy(&rows[0]);
    let drift = largest(rows.iter().map(|row| energy(row) - e0));
    // The integrator's tolerance is 1e-9; each switch of the dependent rate near
    // cos(theta) = 0 costs a little of it.
    assert!(
        drift < 1e-7 * e0,
        "the energy drifts by {drift:e} J of {e0} J"
    );
}

// ---------------------------------------------------------------------------------------
// A velocity constraint that depends on time: the cart's speed is a0 t
// (tests/constraints/pendulum-on-accelerating-cart.json).

const CART_FILE: &str = "tests/constraints/pendulum-on-accelerating-cart.json";

/// In the cart's frame the bob feels g down and a0 backwards: L th'' = -g sin th - a0 cos th.
fn cart_pendulum_th_dd(th: f64) -> f64 {
    -(G * th.sin() + 1.5 * th.cos()) / 0.4
}

#[test]
fn pendulum_on_a_cart_whose_speed_is_prescribed_in_time() {
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(CART_FILE);
    for method in METHODS {
        let out = run(&[
            "solve".as_ref(),
            file.as_os_str(),
            "--format".as_ref(),
            "json".as_ref(),
            "--method".as_ref(),
            method.as_ref(),
            "--time".as_ref(),
            "0.7".as_ref(),
            "--state".as_ref(),
            "th=0.4,th'=1.2".as_ref(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        let get = |k: &str, q: &str| json[k][q].as_f64().expect("number");
        assert_close(get("state", "x'"), 1.5 * 0.7, 1e-12, 1.0, "x' = a0 t");
        assert_close(get("accelerations", "x"), 1.5, 1e-9, G, "x'' = a0");
        let want = cart_pendulum_th_dd(0.4);
        assert_close(get("accelerations", "th"), want, 1e-9, G, "th''");
    }
    // Over a run: x = a0 t^2/2, and th against a fine RK4 integration of the same equation.
    let (dt, steps_per_row) = (1e-4, 100);
    let mut reference = vec![(0.3_f64, 0.0_f64)];
    let (mut th, mut w) = (0.3_f64, 0.0_f64);
    for _ in 0..200 {
        for _ in 0..steps_per_row {
            let f = |th: f64, w: f64| (w, cart_pendulum_th_dd(th));
            let k1 = f(th, w);
            let k2 = f(th + dt / 2.0 * k1.0, w + dt / 2.0 * k1.1);
            let k3 = f(th + dt / 2.0 * k2.0, w + dt / 2.0 * k2.1);
            let k4 = f(th + dt * k3.0, w + dt * k3.1);
            th += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
            w += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        }
        reference.push((th, w));
    }
    for method in METHODS {
        let out = run(&[
            "simulate".as_ref(),
            file.as_os_str(),
            "--format".as_ref(),
            "json".as_ref(),
            "--method".as_ref(),
            method.as_ref(),
            "--no-checks".as_ref(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        let cols: Vec<String> = json["columns"]
            .as_array()
            .expect("columns")
            .iter()
            .map(|c| c.as_str().expect("name").to_string())
            .collect();
        let c = |n: &str| column(&cols, n);
        let rows = json["rows"].as_array().expect("rows");
        assert_eq!(rows.len(), reference.len());
        for (row, (th, w)) in rows.iter().zip(&reference) {
            let v = |k: usize| row[k].as_f64().expect("number");
            let t = v(c("t"));
            let what = |n: &str| format!("{method} at t = {t}: {n}");
            assert_close(v(c("x")), 0.75 * t * t, 1e-8, 1.0, &what("x = a0 t^2/2"));
            assert_close(v(c("x'")), 1.5 * t, 1e-8, 1.0, &what("x' = a0 t"));
            assert_close(v(c("th")), *th, 1e-7, 1.0, &what("th"));
            assert_close(v(c("th'")), *w, 1e-7, 1.0, &what("th'"));
        }
    }
}

#[test]
fn the_energy_check_does_not_fail_where_a_constraint_does_work() {
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(CART_FILE);
    let out = run(&["simulate".as_ref(), file.as_os_str()]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("FAIL"), "{stderr}");
}

// A drive is written as the statement names it: τ by default for a crank's torque, the
// `drive.symbol` when the problem gives one; the output's key stays the coordinate's.
#[test]
fn a_drive_is_written_as_the_statement_names_it() {
    let markdown = crate::support::explain("slider-crank-driven", &["--method", "motion-law"]);
    assert!(markdown.contains(
        "the motor's torque at O driving q1 as prescribed (couple) | $\\tau \\hat{\\mathbf{n}}_{z}$"
    ));
    assert!(!markdown.contains("Q_{q_{1}}"), "the drive is still Q");
    let mut problem: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(crate::support::problem("slider-crank-driven")).expect("read"),
    )
    .expect("JSON");
    problem["coordinates"]["q1"]["drive"] = serde_json::json!({ "symbol": "M_m" });
    let path = std::env::temp_dir().join(format!("mbd-drive-{}.json", std::process::id()));
    std::fs::write(&path, problem.to_string()).expect("write");
    let run = |args: &[&str]| {
        let mut all: Vec<&std::ffi::OsStr> = vec![std::ffi::OsStr::new(args[0]), path.as_os_str()];
        all.extend(args[1..].iter().map(std::ffi::OsStr::new));
        crate::support::run(&all)
    };
    let explained = run(&["explain", "--method", "kane"]);
    let solved = run(&["solve", "--format", "json"]);
    let _ = std::fs::remove_file(&path);
    let markdown = String::from_utf8_lossy(&explained.stdout);
    assert!(markdown.contains("M_{m}"), "no M_m in the handout");
    assert!(!markdown.contains("\\tau"), "τ beside the statement's M_m");
    let json: serde_json::Value = serde_json::from_slice(&solved.stdout).expect("JSON");
    assert!(json["drives"]["q1"].as_f64().is_some(), "{json}");
}
