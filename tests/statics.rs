//! Statics against closed forms worked by hand in each test: an inverted pendulum on a
//! torsion spring (k θ = m g d sin θ, and the stability of each rest), a two-link arm held
//! under a tip load (the holding torques), a ladder on a rough floor against a smooth wall
//! (the reactions, and slip impending at tan θ = 2μ), a block pushed on a rough incline
//! (the pushes at which it starts up and down), a tall block that tips before it slides
//! (P = m g b / 2h against P = μ m g), a slider-crank held by its motor (τ = F ∂x/∂q), and
//! a four-bar held at its crank (every pin reaction, from the nine equilibrium equations of
//! its three bars solved in the test). Then held coordinates in dynamics and bad input.

use crate::support::{
    answers_json, assert_close, method_json, problem, problem_text, run, run_json, scratch_file,
    METHODS,
};
use serde_json::Value;

const G: f64 = 9.81;

fn statics(name: &str, method: &str, extra: &[&str]) -> Value {
    let json = method_json("statics", &problem(name), method, extra);
    assert_eq!(json["method"], method);
    json
}

fn answers(name: &str, method: &str) -> Vec<Value> {
    answers_json(&problem(name), method)
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn force(e: &Value, site: &str) -> [f64; 3] {
    let f = &e["reactions"][site]["force"];
    [num(&f[0]), num(&f[1]), num(&f[2])]
}

/// Components of a vector of N in a frame turned by `angle` about z.
fn in_frame(v: [f64; 2], angle: f64) -> [f64; 2] {
    let (s, c) = angle.sin_cos();
    [c * v[0] + s * v[1], -s * v[0] + c * v[1]]
}

// ---- an inverted pendulum on a torsion spring ----

/// The leaning rest of k θ = m g d sin θ (θ > 0), by bisection.
fn leaning_rest(k: f64, mgd: f64) -> f64 {
    let (mut lo, mut hi) = (1e-6, std::f64::consts::PI);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if k * mid - mgd * mid.sin() < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn a_pendulum_on_a_torsion_spring_rests_where_k_theta_equals_m_g_d_sin_theta() {
    let (m, l, k) = (2.0, 1.0, 7.0);
    let (mgd, inertia) = (m * G * l / 2.0, m * l * l / 3.0);
    let theta = leaning_rest(k, mgd);
    for method in METHODS {
        let json = statics(
            "statics-torsion-pendulum",
            method,
            &[
                "--near", "theta=0", "--near", "theta=1", "--near", "theta=-1",
            ],
        );
        let e = json["equilibria"].as_array().unwrap();
        assert_eq!(e.len(), 3);
        // Upright: unstable, λ = ±√((m g d − k)/I_O).
        assert_close(num(&e[0]["state"]["theta"]), 0.0, 1e-9, 1.0, "upright");
        assert_eq!(e[0]["stability"], "unstable", "{method}");
        let lambda = ((mgd - k) / inertia).sqrt();
        assert_close(
            num(&e[0]["eigenvalues"][1][0]),
            lambda,
            1e-7,
            1.0,
            "λ upright",
        );
        // Leaning either way: stable, ω = √((k − m g d cos θ)/I_O).
        let omega = ((k - mgd * theta.cos()) / inertia).sqrt();
        for (rest, sign) in [(&e[1], 1.0), (&e[2], -1.0)] {
            assert_close(num(&rest["state"]["theta"]), sign * theta, 1e-9, 1.0, "θ*");
            assert_eq!(rest["stability"], "stable", "{method}");
            let eig = &rest["eigenvalues"];
            assert_close(num(&eig[0][0]), 0.0, 1e-7, 1.0, "re");
            assert_close(num(&eig[1][1]).abs(), omega, 1e-7, 1.0, "ω");
            // The pin carries the weight; the spring's couple needs no force.
            let f = force(rest, "O");
            assert_close(f[0], 0.0, 1e-9, m * G, "O x");
            assert_close(f[1], m * G, 1e-9, 1.0, "O y");
        }
    }
}

#[test]
fn a_stiff_torsion_spring_holds_the_pendulum_upright_and_stable() {
    let (m, l, k) = (2.0, 1.0, 12.0);
    let (mgd, inertia) = (m * G * l / 2.0, m * l * l / 3.0);
    let json = statics(
        "statics-torsion-pendulum",
        "kane",
        &["--set", "k=12", "--near", "theta=0.2"],
    );
    let e = &json["equilibria"][0];
    assert_close(num(&e["state"]["theta"]), 0.0, 1e-9, 1.0, "θ");
    assert_eq!(e["stability"], "stable");
    let omega = ((k - mgd) / inertia).sqrt();
    assert_close(num(&e["eigenvalues"][1][1]), omega, 1e-7, 1.0, "ω");
}

// ---- a two-link arm held under a tip load ----

#[test]
fn a_two_link_arm_under_a_tip_load_needs_the_torques_of_its_weights_and_load() {
    let (m1, l1, m2, l2, w) = (3.0, 0.5, 2.0, 0.4, 50.0);
    let (q1, q2) = (std::f64::consts::PI / 6.0, 2.0 * std::f64::consts::PI / 9.0);
    let (c1, c12) = (q1.cos(), (q1 + q2).cos());
    // Moments about each motor's axis of everything beyond it.
    let tau2 = m2 * G * l2 / 2.0 * c12 + w * l2 * c12;
    let tau1 =
        m1 * G * l1 / 2.0 * c1 + m2 * G * (l1 * c1 + l2 / 2.0 * c12) + w * (l1 * c1 + l2 * c12);
    for method in METHODS {
        let json = statics("statics-two-link-arm", method, &[]);
        let e = &json["equilibria"][0];
        assert_close(num(&e["held"]["q1"]), tau1, 1e-9, 1.0, "τ1");
        assert_close(num(&e["held"]["q2"]), tau2, 1e-9, 1.0, "τ2");
        assert!(e.get("stability").is_none(), "nothing is free to be stable");
        // The elbow carries the forearm and the load, straight up, in A's unit vectors.
        let up = in_frame([0.0, m2 * G + w], q1);
        let f = force(e, "elbow");
        assert_close(f[0], up[0], 1e-9, 1.0, "elbow a_x");
        assert_close(f[1], up[1], 1e-9, 1.0, "elbow a_y");
        assert_close(
            force(e, "shoulder")[1],
            (m1 + m2) * G + w,
            1e-9,
            1.0,
            "shoulder",
        );
        // The drive questions read the same holding torques.
        let a = answers("statics-two-link-arm", method);
        assert_close(num(&a[0]["value"]), tau1, 1e-9, 1.0, "drive q1");
        assert_close(num(&a[1]["value"]), tau2, 1e-9, 1.0, "drive q2");
    }
}

// ---- a ladder on a rough floor against a smooth wall ----

#[test]
fn a_ladder_rests_on_friction_m_g_tan_theta_over_2_and_slips_at_tan_theta_2_mu() {
    let (m, mu, theta) = (10.0, 0.3, 25f64.to_radians());
    // Moments about the foot: N_wall 2ℓ cos θ = m g ℓ sin θ; the floor's friction balances
    // the wall and its normal force the weight.
    let wall = m * G * theta.tan() / 2.0;
    for method in METHODS {
        let json = statics("statics-ladder", method, &[]);
        let e = &json["equilibria"][0];
        let floor = force(e, "floor");
        assert_close(floor[0], -wall, 1e-9, 1.0, "friction");
        assert_close(floor[1], m * G, 1e-9, 1.0, "floor N");
        assert_close(force(e, "wall")[0], wall, 1e-9, 1.0, "wall N");
        let site = &e["friction"]["floor"];
        assert_close(num(&site["normal"]), m * G, 1e-9, 1.0, "N");
        assert_close(num(&site["tangential"]), wall, 1e-9, 1.0, "|F|");
        let ratio = theta.tan() / (2.0 * mu);
        assert_close(num(&site["ratio"]), ratio, 1e-9, 1.0, "ratio");
        let a = answers("statics-ladder", method);
        assert_eq!(a[2]["kind"], "slips");
        assert_eq!(a[2]["value"], false);
        assert_close(num(&a[2]["ratio"]), ratio, 1e-9, 1.0, "slips ratio");
        assert_eq!(a[3]["kind"], "impending");
        assert_close(num(&a[3]["value"]), (2.0 * mu).atan(), 1e-7, 1.0, "angle");
    }
    // Past the angle, friction cannot hold it.
    let path = problem("statics-ladder");
    let json = run_json(&[
        "statics",
        path.to_str().unwrap(),
        "--format",
        "json",
        "--set",
        "alpha=0.6",
    ]);
    let ratio = num(&json["equilibria"][0]["friction"]["floor"]["ratio"]);
    assert_close(ratio, 0.6f64.tan() / 0.6, 1e-9, 1.0, "ratio past");
    assert!(ratio > 1.0);
}

// ---- a block pushed along a rough incline ----

#[test]
fn a_block_on_a_rough_incline_starts_up_and_down_at_m_g_sin_plus_and_minus_mu_cos() {
    let (m, mu, alpha, p) = (2.0, 0.3, std::f64::consts::PI / 6.0, 8.0);
    let (s, c) = alpha.sin_cos();
    for method in METHODS {
        let a = answers("statics-block-on-incline", method);
        let ratio = (m * G * s - p).abs() / (mu * m * G * c);
        assert_eq!(a[0]["value"], false);
        assert_close(num(&a[0]["ratio"]), ratio, 1e-9, 1.0, "ratio");
        assert_close(num(&a[1]["value"]), m * G * (s + mu * c), 1e-7, 1.0, "up");
        assert_close(num(&a[2]["value"]), m * G * (s - mu * c), 1e-7, 1.0, "down");
    }
}

// ---- a tall block that tips before it slides ----

#[test]
fn a_tall_block_tips_at_m_g_b_over_2h_before_it_slides_at_mu_m_g() {
    let (m, b, h, mu, p) = (10.0, 0.4, 1.0, 0.4, 10.0);
    let tip = m * G * b / (2.0 * h);
    let slide = mu * m * G;
    assert!(tip < slide, "the case tips first");
    for method in METHODS {
        let a = answers("validation/statics-tall-block", method);
        assert_eq!(a[0]["value"], false, "no slip at P = 10 N");
        assert_close(num(&a[0]["ratio"]), p / (mu * m * G), 1e-9, 1.0, "ratio");
        // Moments about the front edge: N_back b = m g b/2 − P h.
        assert_eq!(a[1]["value"], false, "no tip at P = 10 N");
        assert_close(
            num(&a[1]["normal"]),
            m * G / 2.0 - p * h / b,
            1e-9,
            m * G,
            "N back",
        );
        assert_close(num(&a[2]["value"]), slide, 1e-7, 1.0, "slide");
        assert_close(num(&a[3]["value"]), tip, 1e-7, 1.0, "tip");
    }
    let handout = crate::support::explain("validation/statics-tall-block", &[]);
    assert!(
        handout.contains(
            "tipping at back (P = 19.62 N) impends first, before slip at front (P = 39.24 N)"
        ),
        "the handout says which happens first"
    );
}

// ---- a slider-crank held by its motor ----

#[test]
fn a_crank_held_against_the_gas_force_needs_tau_equal_to_f_dx_dq() {
    let (r, l, f, q) = (0.1, 0.35, 400.0, 50f64.to_radians());
    let root = (l * l - (r * q.sin()).powi(2)).sqrt();
    // x = r cos q + √(l² − r² sin² q); the motor's work balances the gas force's.
    let dx_dq = -r * q.sin() - r * r * q.sin() * q.cos() / root;
    let phi = (r * q.sin() / l).asin();
    for method in METHODS {
        let json = statics("statics-crank-held", method, &[]);
        let e = &json["equilibria"][0];
        assert_close(num(&e["held"]["q1"]), f * dx_dq, 1e-9, 1.0, "τ");
        // The rod is a two-force member: the bearing O takes its thrust.
        let o = force(e, "O");
        assert_close(o[0], f, 1e-9, 1.0, "O x");
        assert_close(o[1], -f * phi.tan(), 1e-9, f, "O y");
        assert_close(force(e, "Q")[0], f / phi.cos(), 1e-9, 1.0, "rod thrust");
    }
}

// ---- a four-bar held at its crank ----

/// The pin forces and the holding torque of the four-bar at (q1, q2, q3), from the force and
/// moment balance of each bar: O on A, P on B (from A), Q on C, R on C (from B), in N, and τ.
fn four_bar_by_hand(q1: f64, q2: f64, q3: f64) -> ([f64; 8], f64) {
    let (a, b, c, m) = (0.1, 0.3, 0.25, 1.0);
    let w = -m * G;
    let (u1, u2, u3) = (
        [q1.cos(), q1.sin()],
        [(q1 + q2).cos(), (q1 + q2).sin()],
        [q3.cos(), q3.sin()],
    );
    let cross = |r: [f64; 2], col: usize| -> [f64; 2] {
        // The z moment of a unit force along x (col 0) or y (col 1) at r.
        if col == 0 {
            [-r[1], 0.0]
        } else {
            [r[0], 0.0]
        }
    };
    // Unknowns: Ox Oy Px Py Qx Qy Rx Ry τ.
    let mut mat = nalgebra::DMatrix::<f64>::zeros(9, 9);
    let mut rhs = nalgebra::DVector::<f64>::zeros(9);
    // A: O − P + weight = 0; about O: (a u1) × (−P) + (a/2 u1) × weight + τ = 0.
    mat[(0, 0)] = 1.0;
    mat[(0, 2)] = -1.0;
    mat[(1, 1)] = 1.0;
    mat[(1, 3)] = -1.0;
    rhs[1] = -w;
    for col in 0..2 {
        mat[(2, 2 + col)] = -cross([a * u1[0], a * u1[1]], col)[0];
    }
    mat[(2, 8)] = 1.0;
    rhs[2] = -(a / 2.0 * u1[0] * w);
    // B: P − R + weight = 0; about its pin P: (b u2) × (−R) + (b/2 u2) × weight = 0.
    mat[(3, 2)] = 1.0;
    mat[(3, 6)] = -1.0;
    mat[(4, 3)] = 1.0;
    mat[(4, 7)] = -1.0;
    rhs[4] = -w;
    for col in 0..2 {
        mat[(5, 6 + col)] = -cross([b * u2[0], b * u2[1]], col)[0];
    }
    rhs[5] = -(b / 2.0 * u2[0] * w);
    // C: Q + R + weight = 0; about Q: (c u3) × R + (c/2 u3) × weight = 0.
    mat[(6, 4)] = 1.0;
    mat[(6, 6)] = 1.0;
    mat[(7, 5)] = 1.0;
    mat[(7, 7)] = 1.0;
    rhs[7] = -w;
    for col in 0..2 {
        mat[(8, 6 + col)] = cross([c * u3[0], c * u3[1]], col)[0];
    }
    rhs[8] = -(c / 2.0 * u3[0] * w);
    let x = mat
        .lu()
        .solve(&rhs)
        .expect("the bars' equations are regular");
    let mut forces = [0.0; 8];
    forces.copy_from_slice(&x.as_slice()[..8]);
    (forces, x[8])
}

#[test]
fn a_four_bar_held_at_its_crank_carries_the_pin_forces_of_its_bars_balance() {
    let (a, b, c, d) = (0.1, 0.3, 0.25, 0.3);
    for method in METHODS {
        let json = statics("statics-four-bar-held", method, &[]);
        let e = &json["equilibria"][0];
        let q = |n: &str| num(&e["state"][n]);
        let (q1, q2, q3) = (q("q1"), q("q2"), q("q3"));
        assert_close(q1, 1.2, 1e-12, 1.0, "held q1");
        // The loop closes: O→P→R equals O→Q→R.
        let rx = a * q1.cos() + b * (q1 + q2).cos() - d - c * q3.cos();
        let ry = a * q1.sin() + b * (q1 + q2).sin() - c * q3.sin();
        assert!(rx.abs() < 1e-9 && ry.abs() < 1e-9, "the loop closes");
        let (f, tau) = four_bar_by_hand(q1, q2, q3);
        assert_close(num(&e["held"]["q1"]), tau, 1e-9, 1.0, "τ");
        let o = force(e, "O");
        assert_close(o[0], f[0], 1e-9, 10.0, "O x");
        assert_close(o[1], f[1], 1e-9, 10.0, "O y");
        let p = in_frame([f[2], f[3]], q1);
        let pin = force(e, "P");
        assert_close(pin[0], p[0], 1e-9, 10.0, "P a_x");
        assert_close(pin[1], p[1], 1e-9, 10.0, "P a_y");
        let qq = force(e, "Q");
        assert_close(qq[0], f[4], 1e-9, 10.0, "Q x");
        assert_close(qq[1], f[5], 1e-9, 10.0, "Q y");
        let r = in_frame([f[6], f[7]], q1 + q2);
        let pin = force(e, "R");
        assert_close(pin[0], r[0], 1e-9, 10.0, "R b_x");
        assert_close(pin[1], r[1], 1e-9, 10.0, "R b_y");
    }
}

// ---- held coordinates in dynamics, the output, and bad input ----

/// A problem file in the test's temporary directory.
fn written(name: &str, text: &str) -> std::path::PathBuf {
    scratch_file("statics", name, text)
}

fn two_link_with(q1: &str) -> String {
    let text = problem_text("statics-two-link-arm");
    let start = text.find("\"q1\": {").unwrap();
    let end = start + text[start..].find('\n').unwrap();
    let text = format!("{}\"q1\": {q1},{}", &text[..start], &text[end..]);
    text.replace("\"held\": true, \"drive\": { \"symbol\": \"tau_2\" }, ", "")
}

#[test]
fn a_held_shoulder_leaves_the_forearm_a_pendulum_about_the_elbow() {
    let (m2, l2, w) = (2.0, 0.4, 50.0);
    let path = written(
        "held-shoulder.json",
        &two_link_with(r#"{ "initial": "pi/6", "held": true }"#),
    );
    let q12 = std::f64::consts::PI / 6.0 + 2.0 * std::f64::consts::PI / 9.0;
    // About the elbow: (m2 L2²/3) q2'' = −(m2 g L2/2 + W L2) cos(q1 + q2).
    let want = -(m2 * G * l2 / 2.0 + w * l2) * q12.cos() / (m2 * l2 * l2 / 3.0);
    for method in METHODS {
        let json = method_json("solve", &path, method, &[]);
        assert_close(num(&json["accelerations"]["q1"]), 0.0, 1e-9, 1.0, "q1''");
        assert_close(num(&json["accelerations"]["q2"]), want, 1e-9, 1.0, "q2''");
        assert!(
            json["drives"]["q1"].is_number(),
            "the brake's torque is reported"
        );
    }
}

#[test]
fn statics_output_is_the_same_run_to_run() {
    let path = problem("statics-ladder");
    let first = run(&["statics", path.to_str().unwrap()]);
    let second = run(&["statics", path.to_str().unwrap()]);
    assert!(first.status.success());
    assert_eq!(first.stdout, second.stdout);
}

#[track_caller]
fn refused(args: &[&str], needles: &[&str]) {
    let out = run(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "exit 1: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    for needle in needles {
        assert!(stderr.contains(needle), "`{needle}` in: {stderr}");
    }
}

#[test]
fn held_with_motion_is_refused_at_its_path() {
    let path = written(
        "held-and-moving.json",
        &two_link_with(r#"{ "motion": "t", "held": true }"#),
    );
    refused(
        &["check", path.to_str().unwrap()],
        &["coordinates.q1.held", "hint"],
    );
}

#[test]
fn bad_statics_questions_and_no_equilibrium_are_refused_with_a_hint() {
    let ladder = problem_text("statics-ladder");
    let no_constant = written(
        "no-constant.json",
        &ladder.replace("\"find\": \"alpha\"", "\"find\": \"beta\""),
    );
    refused(
        &["answer", no_constant.to_str().unwrap()],
        &["find.questions[3].impending.find", "not a constant", "hint"],
    );
    let smooth = written(
        "smooth-site.json",
        &ladder.replace("\"slips\": \"floor\"", "\"slips\": \"wall\""),
    );
    refused(
        &["answer", smooth.to_str().unwrap()],
        &["find.questions[2].slips", "no friction", "hint"],
    );
    // A pendulum under a couple larger than its weight can resist rests nowhere.
    let pendulum = problem_text("statics-torsion-pendulum");
    let pushed = written(
        "pushed.json",
        &pendulum.replace(
            "\"type\": \"joint_spring\", \"joint\": \"O\", \"coordinate\": \"theta\", \"stiffness\": \"k\"",
            "\"type\": \"joint_actuator\", \"joint\": \"O\", \"coordinate\": \"theta\", \"value\": \"3*k\"",
        ),
    );
    refused(
        &["statics", pushed.to_str().unwrap()],
        &["no equilibrium found", "--near"],
    );
}
