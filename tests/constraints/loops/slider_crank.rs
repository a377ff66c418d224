//! The four-bar in three dimensions and the slider-cranks: finite differences, inverse dynamics, the power method and energy.

use super::*;

#[test]
fn four_bar_in_three_dimensions_drops_the_redundant_rows_and_moves_as_in_the_plane() {
    // Every axis along N.z: three of R's five rows repeat the others and are dropped.
    // The bars' inertia about their own axes does not matter to a planar motion.
    let file =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/constraints/four-bar-3d.json");
    let want = four_bar(0.9, 2.5, -0.65, 1.6);
    let acc = [
        want.phi_dd[0],
        want.phi_dd[1] - want.phi_dd[0],
        want.phi_dd[2],
    ];
    let scale = largest(acc.iter().copied());
    // R itself may not be requested: its force along N.z and moments about N.x, N.y are
    // shared with the other joints in many ways.
    let mut text: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).expect("readable")).expect("JSON");
    text["find"]["reactions"] = serde_json::json!(["R"]);
    let with_r = std::env::temp_dir().join(format!("mbd-four-bar-3d-{}.json", std::process::id()));
    std::fs::write(&with_r, text.to_string()).expect("written");
    let refused = run(&["solve".as_ref(), with_r.as_os_str()]);
    std::fs::remove_file(&with_r).expect("removed");
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("`R` is not unique"), "{stderr}");
    for method in METHODS {
        let out = run(&[
            "solve".as_ref(),
            file.as_os_str(),
            "--format".as_ref(),
            "json".as_ref(),
            "--method".as_ref(),
            method.as_ref(),
            "--state".as_ref(),
            "q1=0.9,q1'=2.5".as_ref(),
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{method}: {stderr}");
        for row in ["R.Fz", "R.Mx", "R.My"] {
            assert!(
                stderr.contains(&format!("`{row}` left out: redundant")),
                "{method}: {stderr}"
            );
        }
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        for (k, q) in ["q1", "q2", "q3"].iter().enumerate() {
            let got = json["accelerations"][q].as_f64().expect("q''");
            assert_close(got, acc[k], 1e-9, scale, &format!("{method}: {q}''"));
        }
        // The in-plane force at O is unique and is the planar one.
        for k in 0..2 {
            let got = json["reactions"]["O"]["force"][k].as_f64().expect("force");
            assert_close(
                got,
                want.force_o[k],
                1e-9,
                M * G,
                &format!("{method}: O force[{k}]"),
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// The slider-crank: closed-form kinematics.

/// Crank length r, rod length l; crank angle th from N.x, rod angle phi from N.x with
/// r sin th + l sin phi = 0 (the slider on N.x), x = r cos th + l cos phi.
struct Slider {
    phi: [f64; 3],
    x: [f64; 3],
    /// The rod's mass center (at l/2 from the crank pin): position, velocity, acceleration.
    rod: [[f64; 2]; 3],
}

fn slider_crank(r: f64, l: f64, th: [f64; 3]) -> Slider {
    let [t, td, tdd] = th;
    let sphi = -r / l * t.sin();
    let cphi = (1.0 - sphi * sphi).sqrt();
    let phi = sphi.atan2(cphi);
    let phi_d = -r * t.cos() * td / (l * cphi);
    let phi_dd =
        (r * t.sin() * td * td + l * sphi * phi_d * phi_d - r * t.cos() * tdd) / (l * cphi);
    let x = r * t.cos() + l * cphi;
    let x_d = -r * t.sin() * td - l * sphi * phi_d;
    let x_dd =
        -r * t.cos() * td * td - r * t.sin() * tdd - l * cphi * phi_d * phi_d - l * sphi * phi_dd;
    let rod = [
        comb(&[(r, e(t)), (l / 2.0, e(phi))]),
        comb(&[(r * td, e_perp(t)), (l / 2.0 * phi_d, e_perp(phi))]),
        comb(&[
            (r * tdd, e_perp(t)),
            (-r * td * td, e(t)),
            (l / 2.0 * phi_dd, e_perp(phi)),
            (-l / 2.0 * phi_d * phi_d, e(phi)),
        ]),
    ];
    Slider {
        phi: [phi, phi_d, phi_dd],
        x: [x, x_d, x_dd],
        rod,
    }
}

#[test]
fn slider_crank_kinematics_agree_with_finite_differences() {
    // Guards the closed form that the next tests rely on.
    let (r, l, w, h) = (0.1, 0.35, 3.0, 1e-4);
    for t in [0.2, 1.1, 2.9, 4.0] {
        let at = |t: f64| slider_crank(r, l, [w * t, w, 0.0]);
        let (k, before, after) = (at(t), at(t - h), at(t + h));
        assert_close(
            k.x[1],
            (after.x[0] - before.x[0]) / (2.0 * h),
            1e-6,
            1.0,
            "x'",
        );
        assert_close(
            k.x[2],
            (after.x[1] - before.x[1]) / (2.0 * h),
            1e-6,
            1.0,
            "x''",
        );
        assert_close(
            k.phi[1],
            (after.phi[0] - before.phi[0]) / (2.0 * h),
            1e-6,
            1.0,
            "phi'",
        );
        assert_close(
            k.phi[2],
            (after.phi[1] - before.phi[1]) / (2.0 * h),
            1e-6,
            1.0,
            "phi''",
        );
        for i in 0..2 {
            let v = (after.rod[0][i] - before.rod[0][i]) / (2.0 * h);
            assert_close(k.rod[1][i], v, 1e-6, 1.0, "rod velocity");
            let a = (after.rod[1][i] - before.rod[1][i]) / (2.0 * h);
            assert_close(k.rod[2][i], a, 1e-6, 1.0, "rod acceleration");
        }
    }
}

// ---------------------------------------------------------------------------------------
// The slider-crank driven at a constant speed: inverse dynamics.

/// problems/slider-crank-driven.json.
const R_: f64 = 0.1;
const L_: f64 = 0.35;
const MA: f64 = 1.2;
const MB: f64 = 1.5;
const MC: f64 = 2.0;

/// Newton-Euler for each body (forces in N, moments about each mass center), nine
/// equations in F_O (N on A), F_P (A on B), F_Q (B on C), the guide's normal force N_S
/// and couple M_S on C, and the motor torque tau:
///   A: F_O - F_P - mA g N.y = mA a_A,  (-r_A) x F_O + (r_P - r_A) x (-F_P) + tau = 0;
///   B: F_P - F_Q - mB g N.y = mB a_B,  (r_P - r_B) x F_P + (r_Q - r_B) x (-F_Q) = I_B phi'';
///   C: F_Q + N_S N.y - mC g N.y = mC x'' N.x,  M_S = 0.
fn driven_inverse_dynamics(k: &Slider, th: f64, w: f64) -> DVector<f64> {
    let (i_b, a_a) = (MB * L_ * L_ / 12.0, comb(&[(-R_ / 2.0 * w * w, e(th))]));
    let r_a = comb(&[(R_ / 2.0, e(th))]);
    let r_p = comb(&[(R_, e(th))]);
    let r_b = k.rod[0];
    let r_q = [k.x[0], 0.0];
    let minus = |p: [f64; 2], q: [f64; 2]| [p[0] - q[0], p[1] - q[1]];
    // Unknowns: FOx FOy FPx FPy FQx FQy NS MS tau.
    let mut a = DMatrix::zeros(9, 9);
    let mut b = DVector::zeros(9);
    // Crank.
    a[(0, 0)] = 1.0;
    a[(0, 2)] = -1.0;
    b[0] = MA * a_a[0];
    a[(1, 1)] = 1.0;
    a[(1, 3)] = -1.0;
    b[1] = MA * a_a[1] + MA * G;
    let (ra, pa) = ([-r_a[0], -r_a[1]], minus(r_p, r_a));
    a[(2, 0)] = -ra[1];
    a[(2, 1)] = ra[0];
    a[(2, 2)] = pa[1];
    a[(2, 3)] = -pa[0];
    a[(2, 8)] = 1.0;
    // Rod.
    a[(3, 2)] = 1.0;
    a[(3, 4)] = -1.0;
    b[3] = MB * k.rod[2][0];
    a[(4, 3)] = 1.0;
    a[(4, 5)] = -1.0;
    b[4] = MB * k.rod[2][1] + MB * G;
    let (pb, qb) = (minus(r_p, r_b), minus(r_q, r_b));
    a[(5, 2)] = -pb[1];
    a[(5, 3)] = pb[0];
    a[(5, 4)] = qb[1];
    a[(5, 5)] = -qb[0];
    b[5] = i_b * k.phi[2];
    // Slider.
    a[(6, 4)] = 1.0;
    b[6] = MC * k.x[2];
    a[(7, 5)] = 1.0;
    a[(7, 6)] = 1.0;
    b[7] = MC * G;
    a[(8, 7)] = 1.0;
    a.lu().solve(&b).expect("regular")
}

#[test]
fn driven_slider_crank_motor_torque_and_pin_forces() {
    let w = 4.0 * std::f64::consts::PI;
    for time in [0.0, 0.03, 0.1, 0.37] {
        let th = w * time;
        let k = slider_crank(R_, L_, [th, w, 0.0]);
        let x = driven_inverse_dynamics(&k, th, w);
        let tau = x[8];
        // Power balance: tau w = dT/dt + dV/dt, each body's m a.v + I alpha omega + m g v_y.
        let v_a = comb(&[(R_ / 2.0 * w, e_perp(th))]);
        let a_a = comb(&[(-R_ / 2.0 * w * w, e(th))]);
        let dot = |p: [f64; 2], q: [f64; 2]| p[0] * q[0] + p[1] * q[1];
        let power = MA * dot(a_a, v_a)
            + MA * G * v_a[1]
            + MB * dot(k.rod[2], k.rod[1])
            + MB * L_ * L_ / 12.0 * k.phi[2] * k.phi[1]
            + MB * G * k.rod[1][1]
            + MC * k.x[2] * k.x[1];
        assert_close(
            tau * w,
            power,
            1e-12,
            100.0,
            "Newton-Euler and the power balance agree",
        );
        // The guess for the dependent coordinates: near, but not at, the closed loop.
        let guess = state(&[("q2", k.phi[0] - th + 0.05), ("x", k.x[0] + 0.01)]);
        let time_text = format!("{time}");
        for s in solve_all(
            "slider-crank-driven",
            &["--time", &time_text, "--state", &guess],
        ) {
            let what = |w: &str| format!("{} at t = {time}: {w}", s.method);
            let st = &s.json["state"];
            let got = |key: &str| st[key].as_f64().unwrap_or_else(|| panic!("{}", what(key)));
            assert_close(got("q1"), th, 1e-12, 1.0, &what("q1 = w t"));
            assert_close(got("q1'"), w, 1e-12, 1.0, &what("q1' = w"));
            assert_close(got("x"), k.x[0], 1e-9, 1.0, &what("x"));
            let q2 = got("q2");
            assert_close(q2, k.phi[0] - th, 1e-9, 1.0, &what("q2"));
            assert_close(s.acc("q1"), 0.0, 1e-9, w * w, &what("q1''"));
            assert_close(s.acc("x"), k.x[2], 1e-9, R_ * w * w, &what("x''"));
            let q2_dd = k.phi[2];
            assert_close(s.acc("q2"), q2_dd, 1e-9, w * w, &what("q2''"));
            let drive = s.json["drives"]["q1"]
                .as_f64()
                .unwrap_or_else(|| panic!("{}", what("no drive")));
            assert_close(drive, tau, 1e-9, 10.0, &what("motor torque"));
            // O, in N's unit vectors: no moment (the motor's torque is a drive).
            let scale = MC * R_ * w * w;
            for i in 0..2 {
                let f = s.force("O")[i];
                assert_close(f, x[i], 1e-9, scale, &what(&format!("O force[{i}]")));
            }
            assert_close(s.moment("O")[2], 0.0, 1e-12, scale, &what("O moment"));
            // Q, in the rod's unit vectors; turned into N's, its x part is the slider's
            // Newton equation along the guide, mC x''.
            let q = s.force("Q");
            let in_n = turn(th + q2, [q[0], q[1]]);
            let slider = MC * k.x[2];
            assert_close(
                in_n[0],
                slider,
                1e-9,
                scale,
                &what("Q force . N.x = mC x''"),
            );
            assert_close(in_n[1], x[5], 1e-9, scale, &what("Q force . N.y"));
            assert_close(s.moment("Q")[2], 0.0, 1e-12, scale, &what("Q moment"));
        }
    }
}

// ---------------------------------------------------------------------------------------
// The slider-crank with a flywheel and a gas force: one degree of freedom.

/// problems/slider-crank-flywheel.json.
const IA: f64 = 0.05;
const F0: f64 = 100.0;
const EC: f64 = 0.03;
const HEAD: f64 = 0.48;

fn gas_force(x: f64) -> f64 {
    -F0 * (EC / (HEAD - x)).powf(1.4)
}

/// The gas force's potential, U with -dU/dx = gas_force.
fn gas_potential(x: f64) -> f64 {
    F0 * EC.powf(1.4) * (HEAD - x).powf(-0.4) / 0.4
}

/// q1'' by the power method. With the velocity coefficients J (the velocities at th' = 1)
/// and their derivatives along th (the accelerations at th' = 1, th'' = 0):
///   I(th) th'' = Q(th) - th'^2 sum(m J . J_th + I phi_th phi_thth),
/// I(th) = IA + mB |J_B|^2 + I_B phi_th^2 + mC x_th^2, Q = -mB g J_B.y + F_gas x_th.
fn flywheel_q1_dd(th: f64, th_d: f64) -> f64 {
    let k = slider_crank(R_, L_, [th, 1.0, 0.0]);
    let i_b = MB * L_ * L_ / 12.0;
    let jb = k.rod[1];
    let inertia =
        IA + MB * (jb[0] * jb[0] + jb[1] * jb[1]) + i_b * k.phi[1].powi(2) + MC * k.x[1].powi(2);
    let quadratic = MB * (jb[0] * k.rod[2][0] + jb[1] * k.rod[2][1])
        + i_b * k.phi[1] * k.phi[2]
        + MC * k.x[1] * k.x[2];
    let q = -MB * G * jb[1] + gas_force(k.x[0]) * k.x[1];
    (q - th_d * th_d * quadratic) / inertia
}

#[test]
fn flywheel_slider_crank_acceleration_by_the_power_method() {
    for (th, th_d) in [(0.4, 20.0), (2.5, -7.0), (-0.3, 15.0)] {
        let k = slider_crank(R_, L_, [th, th_d, 0.0]);
        let want = flywheel_q1_dd(th, th_d);
        let guess = state(&[
            ("q1", th),
            ("q1'", th_d),
            ("q2", k.phi[0] - th - 0.03),
            ("x", k.x[0] + 0.01),
        ]);
        for s in solve_all("slider-crank-flywheel", &["--state", &guess]) {
            let what = format!("{} at q1 = {th}, q1' = {th_d}: q1''", s.method);
            assert_close(s.acc("q1"), want, 1e-9, th_d * th_d, &what);
            assert_close(
                s.acc("x"),
                slider_crank(R_, L_, [th, th_d, want]).x[2],
                1e-9,
                th_d * th_d * R_,
                &what,
            );
        }
    }
}

/// T + V from the coordinates and rates of a row, with the rod's angle q1 + q2.
fn flywheel_energy(q1: f64, q2: f64, x: f64, q1_d: f64, q2_d: f64, x_d: f64) -> f64 {
    let (phi, phi_d) = (q1 + q2, q1_d + q2_d);
    let v_b = comb(&[(R_ * q1_d, e_perp(q1)), (L_ / 2.0 * phi_d, e_perp(phi))]);
    let y_b = R_ * q1.sin() + L_ / 2.0 * phi.sin();
    0.5 * IA * q1_d * q1_d
        + 0.5 * MB * (v_b[0] * v_b[0] + v_b[1] * v_b[1])
        + 0.5 * MB * L_ * L_ / 12.0 * phi_d * phi_d
        + 0.5 * MC * x_d * x_d
        + MB * G * y_b
        + gas_potential(x)
}

#[test]
fn flywheel_slider_crank_conserves_energy_and_the_methods_agree() {
    // The gas force depends on x alone, so it is conservative: T + V_gravity + U_gas stays.
    let mut finals: Vec<Vec<f64>> = Vec::new();
    for method in METHODS {
        let (cols, rows) = simulate("slider-crank-flywheel", &["--method", method]);
        let c = |n: &str| column(&cols, n);
        let (q1, q2, x) = (c("q1"), c("q2"), c("x"));
        let (q1d, q2d, xd) = (c("q1'"), c("q2'"), c("x'"));
        let energy: Vec<f64> = rows
            .iter()
            .map(|r| flywheel_energy(r[q1], r[q2], r[x], r[q1d], r[q2d], r[xd]))
            .collect();
        let drift = largest(energy.iter().map(|e| e - energy[0]));
        assert!(
            drift <= 1e-8 * energy[0].abs(),
            "{method}: energy drifts by {drift:e} J of {} J",
            energy[0]
        );
        // The crank goes round: the run covers compressions and expansions.
        let last = rows.last().expect("rows");
        assert!(last[q1] > 10.0, "{method}: the crank turns ({})", last[q1]);
        // The loop stays closed: r sin q1 + l sin(q1 + q2) = 0 and x on the closed form.
        for r in &rows {
            let closure = R_ * r[q1].sin() + L_ * (r[q1] + r[q2]).sin();
            assert!(closure.abs() < 1e-9, "{method}: loop open by {closure:e}");
            let k = slider_crank(R_, L_, [r[q1], r[q1d], 0.0]);
            assert_close(r[x], k.x[0], 1e-9, 1.0, "x on the closed form");
            assert_close(r[xd], k.x[1], 1e-9, 1.0, "x' on the closed form");
        }
        finals.push(last.clone());
    }
    for (m, row) in METHODS.iter().zip(&finals).skip(1) {
        for (k, (a, b)) in finals[0].iter().zip(row).enumerate() {
            assert_close(
                *b,
                *a,
                1e-6,
                1.0,
                &format!("{m} and motion-law, column {k} at the end"),
            );
        }
    }
}

#[test]
fn driven_slider_crank_over_a_run_follows_the_inverse_dynamics() {
    // No degree of freedom is left: every row is the closed-form kinematics at q1 = w t, and
    // the drive column is the motor torque of the Newton-Euler solution above.
    let w = 4.0 * std::f64::consts::PI;
    for method in METHODS {
        let (cols, rows) = simulate("slider-crank-driven", &["--method", method]);
        let c = |n: &str| column(&cols, n);
        for row in &rows {
            let t = row[c("t")];
            let th = w * t;
            let k = slider_crank(R_, L_, [th, w, 0.0]);
            let x = driven_inverse_dynamics(&k, th, w);
            let what = |n: &str| format!("{method} at t = {t}: {n}");
            assert_close(row[c("q1")], th, 1e-12, 1.0, &what("q1 = w t"));
            assert_close(row[c("x")], k.x[0], 1e-9, 1.0, &what("x"));
            assert_close(row[c("x''")], k.x[2], 1e-9, R_ * w * w, &what("x''"));
            assert_close(row[c("q1.drive")], x[8], 1e-9, 10.0, &what("motor torque"));
            let scale = MC * R_ * w * w;
            assert_close(row[c("O.force.x")], x[0], 1e-9, scale, &what("O.force.x"));
            assert_close(row[c("O.force.y")], x[1], 1e-9, scale, &what("O.force.y"));
        }
        assert_close(
            rows.last().expect("rows")[c("t")],
            1.0,
            1e-12,
            1.0,
            "two turns",
        );
    }
}

#[test]
fn driven_slider_crank_closed_at_the_guide_by_a_prismatic_closure() {
    // The same mechanism with the slider on the rod's end by a revolute joint and the guide
    // as a prismatic closure S (N on C): S carries the guide's normal force N_S and no
    // couple, Q is now a joint; the Newton-Euler solution above gives them all.
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/constraints/slider-crank-prismatic-closure.json");
    let w = 4.0 * std::f64::consts::PI;
    for time in [0.03, 0.1, 0.37] {
        let th = w * time;
        let k = slider_crank(R_, L_, [th, w, 0.0]);
        let x = driven_inverse_dynamics(&k, th, w);
        let guess = state(&[("q2", k.phi[0] - th + 0.05), ("q3", -k.phi[0] - 0.05)]);
        let time_text = format!("{time}");
        for method in METHODS {
            let out = run(&[
                "solve".as_ref(),
                file.as_os_str(),
                "--format".as_ref(),
                "json".as_ref(),
                "--method".as_ref(),
                method.as_ref(),
                "--time".as_ref(),
                time_text.as_ref(),
                "--state".as_ref(),
                guess.as_ref(),
            ]);
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
            let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
            let what = |n: &str| format!("{method} at t = {time}: {n}");
            let num = |v: &serde_json::Value| v.as_f64().expect("number");
            let q2 = num(&json["state"]["q2"]);
            let q3 = num(&json["state"]["q3"]);
            let turned = (th + q2 + q3).rem_euclid(2.0 * std::f64::consts::PI);
            let turned = turned.min(2.0 * std::f64::consts::PI - turned);
            assert!(turned < 1e-9, "{}", what("the slider stays parallel to N"));
            let acc = &json["accelerations"];
            assert_close(num(&acc["q2"]), k.phi[2], 1e-9, w * w, &what("q2''"));
            assert_close(num(&acc["q3"]), -k.phi[2], 1e-9, w * w, &what("q3''"));
            assert_close(
                num(&json["drives"]["q1"]),
                x[8],
                1e-9,
                10.0,
                &what("motor torque"),
            );
            let scale = MC * R_ * w * w;
            let reaction =
                |joint: &str, which: &str, i: usize| num(&json["reactions"][joint][which][i]);
            let q_in_b = turn(-(th + q2), [x[4], x[5]]);
            for i in 0..2 {
                assert_close(
                    reaction("O", "force", i),
                    x[i],
                    1e-9,
                    scale,
                    &what("O force"),
                );
                assert_close(
                    reaction("Q", "force", i),
                    q_in_b[i],
                    1e-9,
                    scale,
                    &what("Q force"),
                );
            }
            assert_close(
                reaction("S", "force", 0),
                0.0,
                1e-9,
                scale,
                &what("S force along N.x"),
            );
            assert_close(
                reaction("S", "force", 1),
                x[6],
                1e-9,
                scale,
                &what("S: N_S"),
            );
            assert_close(
                reaction("S", "moment", 2),
                0.0,
                1e-9,
                scale,
                &what("S moment"),
            );
        }
    }
}
