//! Massless bodies (`mass: 0`): a light connecting rod, checked against Lagrange's
//! equation written by hand for the one-degree-of-freedom mechanism it leaves, and a
//! massless body that nothing fixes, refused by `check` and `solve` alike.

use crate::support::{assert_close, problem, run, simulate, solve_all};

/// The slider-crank's constants (`problems/slider-crank-light-rod.json`).
const R: f64 = 0.1;
const L: f64 = 0.35;
const IA: f64 = 0.05;
const MC: f64 = 2.0;
const T: f64 = 5.0;
const F0: f64 = 40.0;

/// The piston's position x(q1) = r cos q1 + √(l² − r² sin² q1) and its first two
/// derivatives with respect to q1.
fn piston(q1: f64) -> (f64, f64, f64) {
    let (s, c) = q1.sin_cos();
    let d = (L * L - R * R * s * s).sqrt();
    let x = R * c + d;
    let x_q = -R * s - R * R * s * c / d;
    let x_qq = -R * c - R * R * (c * c - s * s) / d - R.powi(4) * s * s * c * c / d.powi(3);
    (x, x_q, x_qq)
}

/// With the rod massless, the kinetic energy is IA q1'²/2 + mC (x_q q1')²/2 and the
/// generalized force is T − F0 x_q, so Lagrange's equation gives
/// (IA + mC x_q²) q1'' + mC x_q x_qq q1'² = T − F0 x_q.
fn crank_acceleration(q1: f64, w: f64) -> f64 {
    let (_, x_q, x_qq) = piston(q1);
    (T - F0 * x_q - MC * x_q * x_qq * w * w) / (IA + MC * x_q * x_q)
}

#[test]
fn a_light_rod_leaves_a_one_body_problem_by_every_method() {
    let (q1, w) = (0.4, 20.0);
    let (x, x_q, x_qq) = piston(q1);
    let want = crank_acceleration(q1, w);
    for s in solve_all("slider-crank-light-rod", &[]) {
        let what = |q: &str| format!("{}: {q}''", s.method);
        assert_close(s.json["state"]["x"].as_f64().unwrap(), x, 1e-9, 1.0, "x");
        assert_close(s.acc("q1"), want, 1e-9, 1.0, &what("q1"));
        assert_close(s.acc("x"), x_q * want + x_qq * w * w, 1e-9, 1.0, &what("x"));
        // A light rod is a two-force member: the force it exerts on the piston lies along
        // it, so its component across the rod (B.y, the closure's parent's) vanishes, and
        // along the rod it balances the piston's inertia, gas force and drive along N.x.
        let q = s.force("Q");
        assert_close(q[1], 0.0, 1e-9, 50.0, "Q across the rod");
        let rod_angle = q1 + s.json["state"]["q2"].as_f64().unwrap();
        assert_close(
            q[0] * rod_angle.cos(),
            MC * s.acc("x") + F0,
            1e-9,
            50.0,
            "Q along N.x against the piston's m a",
        );
        // And the rod carries the same force to the crank: the pin P pushes the rod with
        // the opposite of what the rod takes from the piston's side.
        let p = s.force("P");
        let p_along = p[0] * (s.json["state"]["q2"].as_f64().unwrap()).cos()
            + p[1] * (s.json["state"]["q2"].as_f64().unwrap()).sin();
        assert_close(p_along, q[0], 1e-9, 50.0, "P along the rod");
    }
}

#[test]
fn a_light_rod_keeps_the_work_energy_balance_in_simulation() {
    // Kinetic energy minus the work of the drive torque and the gas force stays what it
    // was: the light rod stores nothing.
    let (columns, rows) = simulate("slider-crank-light-rod", &["--duration", "0.5"]);
    let at = |name: &str| crate::support::column(&columns, name);
    let (q1, x, w, v) = (at("q1"), at("x"), at("q1'"), at("x'"));
    let balance = |r: &[f64], r0: &[f64]| {
        IA * r[w] * r[w] / 2.0 + MC * r[v] * r[v] / 2.0 - T * (r[q1] - r0[q1]) + F0 * (r[x] - r0[x])
    };
    let start = balance(&rows[0], &rows[0]);
    for row in &rows {
        assert_close(
            balance(row, &rows[0]),
            start,
            1e-6,
            start,
            "kinetic energy − work",
        );
    }
}

#[test]
fn a_massless_body_that_nothing_fixes_is_refused_by_check_and_solve() {
    let path = problem("invalid/massless-undetermined");
    for command in ["check", "solve"] {
        for method in crate::support::METHODS {
            let mut args = vec![command, path.to_str().unwrap()];
            if command == "solve" {
                args.extend(["--method", method]);
            }
            let out = run(&args);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{command}: {stderr}");
            assert!(
                stderr.contains("bodies.C.mass")
                    && stderr.contains(
                        "`q3''` is undetermined: body C has no mass and nothing else fixes it"
                    ),
                "{command}: {stderr}"
            );
        }
    }
}
