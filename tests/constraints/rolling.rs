//! Rolling contacts: the cylinder on an incline, the rolling coin, a wheel carrying a
//! pendulum and a two-wheeled cart.

use super::{largest, state, turn};
use crate::support::{assert_close, column, simulate, solve_all, METHODS};
use nalgebra::{Matrix2, Vector2, Vector3};

const G: f64 = 9.81;

#[test]
fn cylinder_rolls_down_the_incline_at_two_thirds_g_sin_alpha() {
    // m x'' = m g sin(a) - F, (m R^2/2) (-theta'') = F R, x'' = -R theta'':
    // x'' = 2/3 g sin(a), friction F = m g sin(a)/3 up the slope, normal force m g cos(a).
    let (m, r) = (2.0, 0.1);
    for alpha in [std::f64::consts::PI / 6.0, 0.2] {
        let set = format!("alpha={alpha:.17e}");
        let x_dd = 2.0 / 3.0 * G * alpha.sin();
        for s in solve_all("cylinder-on-incline", &["--set", &set]) {
            let what = |w: &str| format!("{} at alpha = {alpha}: {w}", s.method);
            assert_close(s.acc("x"), x_dd, 1e-9, G, &what("x''"));
            assert_close(s.acc("y"), 0.0, 1e-9, G, &what("y''"));
            assert_close(s.acc("theta"), -x_dd / r, 1e-9, G / r, &what("theta''"));
            let want = [-m * G * alpha.sin() / 3.0, m * G * alpha.cos(), 0.0];
            for (k, want_k) in want.iter().enumerate() {
                let f = s.force("contact")[k];
                assert_close(
                    f,
                    *want_k,
                    1e-9,
                    m * G,
                    &what(&format!("contact force[{k}]")),
                );
                let c = s.moment("contact")[k];
                assert_close(c, 0.0, 1e-12, m * G * r, &what("contact moment"));
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The rolling coin (problems/rolling-coin.json): free joint, body-fixed zxy (yaw psi about
// N.z, lean theta about the turned x, spin phi about the axle D.y).

const M_COIN: f64 = 0.5;
const R_COIN: f64 = 0.1;
const I_DIAMETRAL: f64 = M_COIN * R_COIN * R_COIN / 4.0;
const I_AXIAL: f64 = M_COIN * R_COIN * R_COIN / 2.0;

/// The unit vectors x1 (heading), y2 (axle) and z2 (from the contact up to the centre),
/// and the angular velocity psi' N.z + theta' x1 + phi' y2.
fn coin_frame(psi: f64, theta: f64, rates: [f64; 3]) -> [Vector3<f64>; 4] {
    let z = Vector3::z();
    let x1 = Vector3::new(psi.cos(), psi.sin(), 0.0);
    let y1 = Vector3::new(-psi.sin(), psi.cos(), 0.0);
    let y2 = theta.cos() * y1 + theta.sin() * z;
    let z2 = -theta.sin() * y1 + theta.cos() * z;
    let w = rates[0] * z + rates[1] * x1 + rates[2] * y2;
    [x1, y2, z2, w]
}

#[test]
fn coin_in_steady_precession() {
    // Euler's equation about the centre in the frame (x1, y2, z2), which turns at Omega N.z:
    // with s = w . y2, H = I_a s y2 + I_d Omega cos(theta) z2, and the contact force
    // m a_C + m g N.z at -R z2, the x1 component gives
    //   m g R sin(theta) = I_d Omega^2 sin(theta) cos(theta) - (I_a + m R^2) s Omega cos(theta).
    // The centre moves at R s along x1, on a circle at the rate Omega: a_C = R s Omega y1.
    let (theta, omega, psi) = (0.3_f64, 3.0_f64, 0.7_f64);
    let (m, r) = (M_COIN, R_COIN);
    let s = (I_DIAMETRAL * omega * omega * theta.sin() * theta.cos() - m * G * r * theta.sin())
        / ((I_AXIAL + m * r * r) * omega * theta.cos());
    let phi_d = s - omega * theta.sin();
    let given = state(&[
        ("x", 0.2),
        ("y", -0.1),
        ("psi", psi),
        ("theta", theta),
        ("phi", 0.4),
        ("psi'", omega),
        ("theta'", 0.0),
        ("phi'", phi_d),
    ]);
    let a_c = r * s * omega;
    for sol in solve_all("rolling-coin", &["--state", &given]) {
        let what = |w: &str| format!("{}: {w}", sol.method);
        let st = &sol.json["state"];
        let got = |k: &str| st[k].as_f64().unwrap_or_else(|| panic!("{}", what(k)));
        assert_close(
            got("z"),
            r * theta.cos(),
            1e-9,
            r,
            &what("z = R cos(theta)"),
        );
        assert_close(
            got("x'"),
            r * s * psi.cos(),
            1e-9,
            r * s.abs(),
            &what("x' = R s cos(psi)"),
        );
        assert_close(
            got("y'"),
            r * s * psi.sin(),
            1e-9,
            r * s.abs(),
            &what("y' = R s sin(psi)"),
        );
        assert_close(got("z'"), 0.0, 1e-9, r * s.abs(), &what("z'"));
        let scale = a_c.abs().max(G);
        for q in ["theta", "psi", "phi", "z"] {
            assert_close(sol.acc(q), 0.0, 1e-9, scale / r, &what(&format!("{q}''")));
        }
        assert_close(sol.acc("x"), -a_c * psi.sin(), 1e-9, scale, &what("x''"));
        assert_close(sol.acc("y"), a_c * psi.cos(), 1e-9, scale, &what("y''"));
        let want = [-m * a_c * psi.sin(), m * a_c * psi.cos(), m * G];
        for (k, want_k) in want.iter().enumerate() {
            let f = sol.force("floor")[k];
            assert_close(
                f,
                *want_k,
                1e-9,
                m * scale,
                &what(&format!("floor force[{k}]")),
            );
        }
    }
}

#[test]
fn coin_conserves_energy_and_rolls_without_slipping() {
    let (m, r) = (M_COIN, R_COIN);
    for method in METHODS {
        let (cols, rows) = simulate("rolling-coin", &["--method", method]);
        let c = |n: &str| column(&cols, n);
        assert_close(rows.last().expect("rows")[c("t")], 10.0, 1e-12, 1.0, "10 s");
        let mut energy = Vec::new();
        let mut slip: f64 = 0.0;
        for row in &rows {
            let [x1, y2, z2, w] = coin_frame(
                row[c("psi")],
                row[c("theta")],
                [row[c("psi'")], row[c("theta'")], row[c("phi'")]],
            );
            let v = Vector3::new(row[c("x'")], row[c("y'")], row[c("z'")]);
            let kinetic = 0.5 * m * v.norm_squared()
                + 0.5
                    * (I_DIAMETRAL * w.dot(&x1).powi(2)
                        + I_AXIAL * w.dot(&y2).powi(2)
                        + I_DIAMETRAL * w.dot(&z2).powi(2));
            energy.push(kinetic + m * G * row[c("z")]);
            // The disc's material point at the contact, -R z2 from the centre.
            let contact = v + w.cross(&(-r * z2));
            slip = slip.max(contact.norm());
            let height = row[c("z")] - r * row[c("theta")].cos();
            slip = slip.max(height.abs());
        }
        let drift = largest(energy.iter().map(|e| e - energy[0]));
        assert!(
            drift < 1e-8 * energy[0],
            "{method}: energy drifts by {drift:e} J of {} J",
            energy[0]
        );
        assert!(
            slip < 1e-8,
            "{method}: the contact point moves at {slip:e} m/s"
        );
        // It does move: the coin falls over or precesses, far from its start.
        let turned = largest(rows.iter().map(|row| row[c("psi")]));
        assert!(turned > 1.0, "{method}: the coin turns ({turned})");
    }
}

// ---------------------------------------------------------------------------------------
// A wheel on level ground with a pendulum from its axle (problems/wheel-pendulum.json).

const MW: f64 = 3.0;
const RW: f64 = 0.2;
const MP: f64 = 1.0;
const LP: f64 = 0.6;

/// Lagrange in x (the centre) and alpha = th + phi (the rod's absolute angle), with
/// th' = -x'/R: T = 1/2 (3/2 M + m) x'^2 + m Lp/2 cos(alpha) x' alpha' + 1/2 m Lp^2/3 alpha'^2,
/// V = -m g Lp/2 cos(alpha). Returns (x'', alpha'').
fn wheel_pendulum(alpha: f64, alpha_d: f64) -> (f64, f64) {
    let k = MP * LP / 2.0;
    let mass = Matrix2::new(
        1.5 * MW + MP,
        k * alpha.cos(),
        k * alpha.cos(),
        MP * LP * LP / 3.0,
    );
    let rhs = Vector2::new(k * alpha.sin() * alpha_d * alpha_d, -k * G * alpha.sin());
    let a = mass.lu().solve(&rhs).expect("regular");
    (a[0], a[1])
}

#[test]
fn wheel_with_pendulum_matches_lagrange() {
    for (th, phi, th_d, phi_d) in [(0.0, 0.8, 0.0, 0.0), (0.7, -0.2, -2.0, 3.5)] {
        let given = state(&[
            ("theta", th),
            ("phi", phi),
            ("theta'", th_d),
            ("phi'", phi_d),
        ]);
        let (alpha, alpha_d) = (th + phi, th_d + phi_d);
        let (x_dd, alpha_dd) = wheel_pendulum(alpha, alpha_d);
        // The ground's force on the wheel: the whole system's momentum balance.
        let a_p = [
            x_dd + LP / 2.0 * (alpha_dd * alpha.cos() - alpha_d * alpha_d * alpha.sin()),
            LP / 2.0 * (alpha_dd * alpha.sin() + alpha_d * alpha_d * alpha.cos()),
        ];
        let ground = [MW * x_dd + MP * a_p[0], (MW + MP) * G + MP * a_p[1]];
        // The pin's force on the rod, m a_P + m g N.y, in the wheel's unit vectors.
        let pin = turn(-th, [MP * a_p[0], MP * (a_p[1] + G)]);
        for s in solve_all("wheel-pendulum", &["--state", &given]) {
            let what = |w: &str| format!("{} at phi = {phi}, th' = {th_d}: {w}", s.method);
            let xd = s.json["state"]["x'"].as_f64().expect("x'");
            assert_close(xd, -RW * th_d, 1e-12, 1.0, &what("x' = -R th'"));
            assert_close(s.acc("x"), x_dd, 1e-9, G, &what("x''"));
            assert_close(s.acc("y"), 0.0, 1e-9, G, &what("y''"));
            assert_close(s.acc("theta"), -x_dd / RW, 1e-9, G / RW, &what("th''"));
            let phi_dd = alpha_dd + x_dd / RW;
            assert_close(s.acc("phi"), phi_dd, 1e-9, G / RW, &what("phi''"));
            for (k, want_k) in ground.iter().enumerate() {
                let f = s.force("ground")[k];
                assert_close(
                    f,
                    *want_k,
                    1e-9,
                    MW * G,
                    &what(&format!("ground force[{k}]")),
                );
            }
            for (k, want_k) in pin.iter().enumerate() {
                let f = s.force("pin")[k];
                assert_close(f, *want_k, 1e-9, MW * G, &what(&format!("pin force[{k}]")));
            }
            assert_close(s.moment("pin")[2], 0.0, 1e-12, MW * G, &what("pin moment"));
        }
    }
}

#[test]
fn wheel_with_pendulum_conserves_energy() {
    let mut finals = Vec::new();
    for method in METHODS {
        let (cols, rows) = simulate("wheel-pendulum", &["--method", method]);
        let c = |n: &str| column(&cols, n);
        let energy: Vec<f64> = rows
            .iter()
            .map(|row| {
                let (alpha, alpha_d) = (
                    row[c("theta")] + row[c("phi")],
                    row[c("theta'")] + row[c("phi'")],
                );
                let (xd, yd) = (row[c("x'")], row[c("y'")]);
                let vp = [
                    xd + LP / 2.0 * alpha_d * alpha.cos(),
                    yd + LP / 2.0 * alpha_d * alpha.sin(),
                ];
                let y_p = row[c("y")] - LP / 2.0 * alpha.cos();
                0.5 * MW * (xd * xd + yd * yd)
                    + 0.5 * MW * RW * RW / 2.0 * row[c("theta'")].powi(2)
                    + 0.5 * MP * (vp[0] * vp[0] + vp[1] * vp[1])
                    + 0.5 * MP * LP * LP / 12.0 * alpha_d * alpha_d
                    + MW * G * row[c("y")]
                    + MP * G * y_p
            })
            .collect();
        // Energy scale: the pendulum's drop from its start to hanging straight down.
        let scale = MP * G * LP / 2.0 * (1.0 - 0.8_f64.cos());
        let drift = largest(energy.iter().map(|e| e - energy[0]));
        assert!(
            drift < 1e-8 * scale,
            "{method}: energy drifts by {drift:e} J"
        );
        for row in &rows {
            let slip = row[c("x'")] + RW * row[c("theta'")];
            assert!(
                slip.abs() < 1e-9,
                "{method}: the wheel slips at {slip:e} m/s"
            );
            assert!(
                (row[c("y")] - RW).abs() < 1e-12,
                "{method}: the wheel leaves the ground"
            );
        }
        finals.push(rows.last().expect("rows").clone());
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

// ---------------------------------------------------------------------------------------
// The two-wheeled cart (problems/two-wheeled-cart.json).

#[test]
fn cart_accelerates_straight_under_equal_torques() {
    // Straight ahead, with the body's mass center on the axle: the ground's forward friction
    // F on each wheel gives (mC + 2 mW) a = 2F; each wheel (I_w a/R = tau - F R) spins up;
    // the motors' reactions -tau pitch the body: Iyy phi'' = -2 tau. So
    //   a = 2 tau/R / (mC + 2 mW + 2 I_w/R^2),  qL'' = qR'' = a/R - phi''.
    let (mc, mw, r, iyy) = (6.0, 1.0, 0.15, 0.1);
    let iw = mw * r * r / 2.0;
    for tau in [0.6, -1.3] {
        let set = format!("tauL={tau:.17e},tauR={tau:.17e}");
        let a = 2.0 * tau / r / (mc + 2.0 * mw + 2.0 * iw / (r * r));
        let phi_dd = -2.0 * tau / iyy;
        for given in ["", "phi=0.3,x=1,y=2,phi'=1,qL'=5,qR'=5"] {
            let mut extra = vec!["--set", set.as_str()];
            if !given.is_empty() {
                extra.extend(["--state", given]);
            }
            for s in solve_all("two-wheeled-cart", &extra) {
                let what = |w: &str| format!("{} at tau = {tau}, state {given:?}: {w}", s.method);
                assert_close(s.acc("x"), a, 1e-9, 1.0, &what("x''"));
                for q in ["y", "z", "psi", "theta"] {
                    assert_close(s.acc(q), 0.0, 1e-9, 1.0, &what(&format!("{q}''")));
                }
                assert_close(s.acc("phi"), phi_dd, 1e-9, 1.0, &what("phi''"));
                assert_close(s.acc("qL"), a / r - phi_dd, 1e-9, 1.0, &what("qL''"));
                assert_close(s.acc("qR"), a / r - phi_dd, 1e-9, 1.0, &what("qR''"));
            }
        }
    }
}

#[test]
fn cart_turning_under_unequal_torques_the_methods_agree() {
    let extra = [
        "--set",
        "tauL=0.9,tauR=-0.2",
        "--state",
        "psi=0.4,phi=0.2,phi'=-0.5,qL'=6,qR'=2",
    ];
    let all = solve_all("two-wheeled-cart", &extra);
    // The heading turns at R (qR' - qL')/(2 b) (the wheels' speeds over the track).
    let psi_d = all[0].json["state"]["psi'"].as_f64().expect("psi'");
    assert_close(psi_d, 0.15 * (2.0 - 6.0) / 0.5, 1e-9, 1.0, "psi'");
    for s in &all[1..] {
        for q in ["x", "y", "z", "psi", "theta", "phi", "qL", "qR"] {
            let what = format!("{} and motion-law: {q}''", s.method);
            assert_close(s.acc(q), all[0].acc(q), 1e-9, 10.0, &what);
        }
    }
}

/// Kane's worked solution of the coin shows the dependent rates as a linear map of the
/// independent ones at the initial state (θ = 0.3, ψ = 0): with the centre's velocity
/// R (φ' + ψ' sin θ) along the heading and −R θ' along the axle turned by the lean,
/// ż = −R sin θ θ', ẋ = R sin θ ψ' + R φ', ẏ = −R cos θ θ'.
#[test]
fn kane_shows_the_coins_dependent_speeds() {
    let out = crate::support::run(&[
        "explain".as_ref(),
        crate::support::problem("rolling-coin").as_os_str(),
        "--method".as_ref(),
        "kane".as_ref(),
    ]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    // By hand: the contact point P = C − R b₃ is at rest, so ż = −R sin θ θ' and the
    // centre's horizontal velocity is R (φ' + ψ' sin θ) along the rolling direction
    // (cos ψ, sin ψ) plus R cos θ θ' across it; written with the rows' abbreviations.
    for want in [
        "\\dot{z} &= -R s_{\\theta} \\dot{\\theta}",
        "\\dot{x} &= R c_{\\psi} \\dot{\\phi} + R s_{\\theta} c_{\\psi} \\dot{\\psi} + R s_{\\psi} c_{\\theta} \\dot{\\theta}",
        "{}^{N}\\tilde{\\mathbf{v}}^{D^*}_{3}",
        "{}^{N}\\tilde{\\boldsymbol{\\omega}}^{D}_{3} = \\hat{\\mathbf{a}}_{y}",
    ] {
        assert!(text.contains(want), "no {want} in Kane's dependent speeds");
    }
}

/// Newton–Euler's worked solution of the coin states the same map as equations, one per
/// dependent rate (by hand as above, at θ = 0.3), and writes each rolling row once: the
/// constraint ż + R sin θ θ' = 0 differentiated is z'' + R sin θ θ'' + R cos θ θ'² = 0,
/// which as formed is that sum in another order.
#[test]
fn newton_euler_states_the_coins_dependent_rates_as_equations() {
    let text = crate::support::explain("rolling-coin", &["--method", "newton-euler"]);
    // The contact point P = C* − R ẑ′ at rest: ż = −R θ̇ sin θ, as derived by hand, in
    // general; released with θ̇ = 0 it is 0 at the start.
    let expected = "in general, $\\dot{z} = -R \\dot{\\theta} s_{\\theta}$";
    assert!(text.contains(expected), "no {expected}");
    assert!(
        text.contains("at the initial state, $\\dot{z} = 0\\ \\mathrm{m/s}$"),
        "{text}"
    );
    let row = text
        .split("**9. ")
        .nth(1)
        .and_then(|rest| rest.split("The velocity constraints").next())
        .expect("row 9, the last");
    assert!(row.contains(
        "R s_{\\theta} \\ddot{\\theta} + \\ddot{z} + R c_{\\theta} \\dot{\\theta}^{2} = 0"
    ));
    assert_eq!(row.matches(" = 0").count(), 1, "{row}");
}
