//! Impacts against closed forms worked by hand: a free rod struck at its end
//! (v* = J/m, ω = 6J/(mL)); a pendulum struck at b (ω = J b / I_O, no impulsive pin
//! reaction at the centre of percussion b = 2L/3); a plank falling flat whose end strikes a
//! ledge with e = 0 (ω = 3v/(2L)); a disc striking a rough floor obliquely with spin,
//! sticking and sliding; a double pendulum struck at its lower end (M Δq̇ = Q with M and Q
//! written here); the kinetic energy after never above the one before, equal for e = 1 on a
//! smooth surface. Every method, the same numbers.

use crate::support::{assert_close, method_json, number, problem, run, run_json, METHODS};
use serde_json::Value;
use std::ffi::OsString;

/// `mbd-tutor impact problems/NAME.json --format json --method M EXTRA…`.
fn impact(name: &str, method: &str, extra: &[&str]) -> Value {
    method_json("impact", &problem(name), method, extra)
}

fn after(json: &Value, rate: &str) -> f64 {
    number(&json["after"], rate)
}

fn vector(json: &Value) -> [f64; 3] {
    let items = json.as_array().expect("a vector");
    std::array::from_fn(|k| items[k].as_f64().expect("a number"))
}

fn energies(json: &Value) -> (f64, f64) {
    (
        number(&json["energy"], "before"),
        number(&json["energy"], "after"),
    )
}

#[test]
fn a_free_rod_struck_at_its_end_moves_at_j_over_m_and_turns_at_6j_over_ml() {
    let (m, l, j) = (2.0, 1.2, 3.0);
    for method in METHODS {
        let s = impact("impact-struck-rod", method, &[]);
        assert_eq!(s["method"], method);
        assert_close(after(&s, "y'"), j / m, 1e-9, 1.0, method);
        assert_close(after(&s, "x'"), 0.0, 1e-9, 1.0, method);
        assert_close(after(&s, "theta'"), 6.0 * j / (m * l), 1e-9, 1.0, method);
        // The work of the blow: ½ m v*² + ½ (m L²/12) ω².
        let v = j / m;
        let w = 6.0 * j / (m * l);
        let t = 0.5 * m * v * v + 0.5 * m * l * l / 12.0 * w * w;
        assert_close(energies(&s).1, t, 1e-9, 1.0, method);
    }
}

#[test]
fn a_pendulum_struck_at_b_turns_at_j_b_over_i_o_with_the_pin_impulse_of_momentum() {
    let (m, l, j) = (2.0, 0.9, 4.0);
    let i_o = m * l * l / 3.0;
    for b in [0.6, 0.3, 0.9] {
        let set = format!("b={b}");
        for method in METHODS {
            let s = impact("impact-struck-pendulum", method, &["--set", &set]);
            let w = j * b / i_o;
            let what = format!("{method}, b = {b}");
            assert_close(after(&s, "theta'"), w, 1e-9, 1.0, &what);
            // Linear impulse: m Δv* = J + R, v* = (L/2) ω along N.x.
            let pin = vector(&s["impulses"]["O"]["force"]);
            assert_close(pin[0], m * l / 2.0 * w - j, 1e-9, 1.0, &what);
            assert_close(pin[1], 0.0, 1e-9, 1.0, &what);
        }
    }
    // b = 2L/3 = 0.6 m: the centre of percussion, where the pin feels nothing.
    let s = impact("impact-struck-pendulum", "motion-law", &[]);
    assert_close(
        vector(&s["impulses"]["O"]["force"])[0],
        0.0,
        1e-12,
        1.0,
        "2L/3",
    );
}

#[test]
fn a_plank_falling_flat_onto_a_ledge_turns_at_3v_over_2l() {
    let (m, l, v) = (3.0, 2.0, 4.0);
    for method in METHODS {
        let s = impact("impact-falling-plank", method, &[]);
        // Angular momentum about the ledge: m v L/2 = (m L²/3) ω.
        let w = 3.0 * v / (2.0 * l);
        assert_close(after(&s, "theta'"), w, 1e-9, 1.0, method);
        assert_close(after(&s, "y'"), -v + m * v / 4.0 / m, 1e-9, 1.0, method);
        // The ledge's impulse m (v* after − v* before) = m v / 4, straight up.
        let p = vector(&s["impulses"]["ledge"]);
        assert_close(p[1], m * v / 4.0, 1e-9, 1.0, method);
        assert_close(p[0], 0.0, 1e-9, 1.0, method);
        assert_eq!(s["collision"]["mode"], "smooth");
        let (before, after) = energies(&s);
        assert_close(before, 0.5 * m * v * v, 1e-12, 1.0, method);
        assert!(after < before, "{method}: a plastic impact loses energy");
    }
}

#[test]
fn an_elastic_impact_on_a_smooth_ledge_keeps_the_kinetic_energy() {
    for method in METHODS {
        let s = impact("impact-falling-plank", method, &["--set", "e=1"]);
        let (before, after) = energies(&s);
        assert_close(after, before, 1e-9, 1.0, method);
        // The end leaves the ledge at the speed it struck: v* + ω L/2 = v.
        let end = after_rate(&s, "y'") + after_rate(&s, "theta'") * 1.0;
        assert_close(end, 4.0, 1e-9, 1.0, method);
    }
}

fn after_rate(s: &Value, rate: &str) -> f64 {
    after(s, rate)
}

/// A disc (I = m R²/2) with centre velocity (u, −w) and spin ω₀ strikes the floor at its
/// lowest point: the slip before is s = u + R ω₀; P_n = m (1 + e) w; to stop the slip
/// P_t = −m s / 3; sliding, P_t = −μ P_n sign(s).
fn disc_after(mu: f64) -> (f64, f64, f64, f64, bool) {
    let (m, r, u, w, w0, e): (f64, f64, f64, f64, f64, f64) = (1.5, 0.2, 3.0, 5.0, 10.0, 0.6);
    let slip = u + r * w0;
    let normal = m * (1.0 + e) * w;
    let stick = -m * slip / 3.0;
    let sticks = stick.abs() <= mu * normal;
    let tangential = if sticks {
        stick
    } else {
        -mu * normal * slip.signum()
    };
    let inertia = m * r * r / 2.0;
    (
        u + tangential / m,
        e * w,
        w0 + r * tangential / inertia,
        tangential,
        sticks,
    )
}

#[test]
fn a_spinning_disc_striking_a_rough_floor_sticks_or_slides_as_coulomb_says() {
    for (mu, mode) in [(0.3, "stick"), (0.1, "slide")] {
        let (vx, vy, w, pt, sticks) = disc_after(mu);
        assert_eq!(sticks, mode == "stick", "the hand derivation's case");
        let set = format!("mu={mu}");
        for method in METHODS {
            let s = impact("impact-spinning-disc", method, &["--set", &set]);
            let what = format!("{method}, mu = {mu}");
            assert_eq!(s["collision"]["mode"], mode, "{what}");
            assert_close(after(&s, "x'"), vx, 1e-9, 1.0, &what);
            assert_close(after(&s, "y'"), vy, 1e-9, 1.0, &what);
            assert_close(after(&s, "theta'"), w, 1e-9, 1.0, &what);
            assert_close(vector(&s["impulses"]["floor"])[0], pt, 1e-9, 1.0, &what);
            let (before, after) = energies(&s);
            assert!(
                after <= before,
                "{what}: energy after {after} > before {before}"
            );
        }
    }
}

#[test]
fn a_struck_double_pendulum_jumps_by_the_inverse_mass_matrix_times_the_generalized_impulses() {
    let (m1, l1, m2, l2, j) = (1.2, 0.6, 0.8, 0.4, 2.0);
    let (q1, q2) = (0.3_f64, -0.5_f64);
    let c2 = q2.cos();
    // T = ½ M11 q̇1² + M12 q̇1 q̇2 + ½ M22 q̇2², q2 measured from A.
    let m11 = m1 * l1 * l1 / 3.0 + m2 * (l1 * l1 + l2 * l2 / 3.0 + l1 * l2 * c2);
    let m12 = m2 * (l2 * l2 / 3.0 + l1 * l2 * c2 / 2.0);
    let m22 = m2 * l2 * l2 / 3.0;
    // The blow J N.x at B's end: Q_r = ∂v/∂q̇_r · J N.x.
    let qa = j * (l1 * q1.cos() + l2 * (q1 + q2).cos());
    let qb = j * l2 * (q1 + q2).cos();
    let det = m11 * m22 - m12 * m12;
    let d1 = (m22 * qa - m12 * qb) / det;
    let d2 = (m11 * qb - m12 * qa) / det;
    // The pin's impulse: the change of linear momentum less the blow.
    let px = m1 * l1 / 2.0 * q1.cos() * d1
        + m2 * (l1 * q1.cos() * d1 + l2 / 2.0 * (q1 + q2).cos() * (d1 + d2));
    let py = m1 * l1 / 2.0 * q1.sin() * d1
        + m2 * (l1 * q1.sin() * d1 + l2 / 2.0 * (q1 + q2).sin() * (d1 + d2));
    for method in METHODS {
        let s = impact("impact-double-pendulum", method, &[]);
        assert_close(after(&s, "q1'"), 1.0 + d1, 1e-9, 1.0, method);
        assert_close(after(&s, "q2'"), -0.5 + d2, 1e-9, 1.0, method);
        let pin = vector(&s["impulses"]["O"]["force"]);
        assert_close(pin[0], px - j, 1e-9, 1.0, method);
        assert_close(pin[1], py, 1e-9, 1.0, method);
    }
}

#[test]
fn simulate_and_questions_start_just_after_the_impact_and_solve_keeps_the_state_before() {
    let sim = run_json(&[
        OsString::from("simulate"),
        problem("impact-struck-rod").into(),
        "--format".into(),
        "json".into(),
        "--no-checks".into(),
    ]);
    let columns: Vec<&str> = sim["columns"]
        .as_array()
        .expect("columns")
        .iter()
        .map(|c| c.as_str().expect("name"))
        .collect();
    let first = sim["rows"][0].as_array().expect("a row");
    let at = |name: &str| {
        let i = columns.iter().position(|c| *c == name).expect("column");
        first[i].as_f64().expect("number")
    };
    assert_close(at("y'"), 1.5, 1e-12, 1.0, "y' at the start");
    assert_close(at("theta'"), 7.5, 1e-12, 1.0, "theta' at the start");
    let answers = run_json(&[
        OsString::from("answer"),
        problem("impact-struck-pendulum").into(),
        "--format".into(),
        "json".into(),
    ]);
    let w = 4.0 * 0.6 / (2.0 * 0.81 / 3.0);
    assert_close(
        answers["answers"][0]["value"].as_f64().expect("value"),
        w,
        1e-9,
        1.0,
        "after_impact",
    );
    let solved = run_json(&[
        OsString::from("solve"),
        problem("impact-struck-pendulum").into(),
        "--format".into(),
        "json".into(),
    ]);
    assert_eq!(solved["state"]["theta'"].as_f64(), Some(0.0));
}

/// Runs `impact` on a copy of the bundled `name` changed by `edit`, expecting exit 1 with
/// an error at `path`.
fn refused(name: &str, edit: impl Fn(&mut Value), path: &str) {
    let text = std::fs::read_to_string(problem(name)).expect("problem");
    let mut value: Value = serde_json::from_str(&text).expect("JSON");
    edit(&mut value);
    let dir = std::env::temp_dir().join(format!("mbd-impact-{}-{path}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let file = dir.join("problem.json");
    std::fs::write(&file, value.to_string()).expect("write");
    let out = run(&[OsString::from("impact"), file.into()]);
    let _ = std::fs::remove_dir_all(&dir);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains(path), "no `{path}` in: {stderr}");
    assert!(
        stderr.contains("hint") || stderr.contains("help"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn a_point_leaving_the_surface_a_restitution_outside_0_1_and_unknown_names_are_refused() {
    let disc = "impact-spinning-disc";
    refused(
        disc,
        |v| v["coordinates"]["y"]["rate"] = "w".into(),
        "impact.collision",
    );
    refused(
        disc,
        |v| v["impact"]["collision"]["restitution"] = 1.5.into(),
        "impact.collision.restitution",
    );
    refused(
        disc,
        |v| v["impact"]["collision"]["body"] = "Q".into(),
        "impact.collision.body",
    );
    refused(
        "impact-struck-rod",
        |v| v["impact"]["impulses"][0]["point"] = "P9".into(),
        "impact.impulses[0].point",
    );
}
