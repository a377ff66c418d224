//! Declared generalized speeds: Kane's method with body-frame angular velocity speeds gives
//! Euler's equations; every method with speeds gives the q'' of the same problem without
//! them; energy is conserved; bad declarations are refused with their JSON path.

use crate::support::{assert_close, column, problem, simulate};
use mbd_tutor::equations::Method;
use mbd_tutor::numeric::Compiled;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::{load, Problem};
use mbd_tutor::symbolic::{simplify, Expr, Symbol};

fn read(name: &str) -> String {
    std::fs::read_to_string(problem(name)).expect("the problem file is readable")
}

/// `text` with its `speeds` replaced by `speeds` (`None`: removed).
fn with_speeds(text: &str, speeds: Option<serde_json::Value>) -> Problem {
    let mut value: serde_json::Value = serde_json::from_str(text).expect("JSON");
    let map = value.as_object_mut().expect("an object");
    match speeds {
        Some(s) => map.insert("speeds".into(), s),
        None => map.remove("speeds"),
    };
    load(&value.to_string()).unwrap_or_else(|e| panic!("{e}"))
}

/// The q'' and the requested reactions by `method` at each state.
fn accelerations(
    problem: &Problem,
    method: Method,
    states: &[(Vec<f64>, Vec<f64>)],
) -> Vec<Vec<f64>> {
    let derivation =
        derive(problem, method, Purpose::Rows).unwrap_or_else(|e| panic!("{}: {e}", method.name()));
    let compiled = Compiled::new(&derivation);
    states
        .iter()
        .map(|(q, rates)| {
            let s = compiled
                .solve(0.0, q, rates)
                .unwrap_or_else(|e| panic!("{}: {e}", method.name()));
            // q'', then the requested reactions' components.
            let mut out = s.accelerations;
            for (_, force, moment) in &s.reactions {
                out.extend(force.iter().chain(moment));
            }
            out
        })
        .collect()
}

/// A few states, seeded so that every run sees the same ones.
fn states(n: usize) -> Vec<(Vec<f64>, Vec<f64>)> {
    let mut seed: u64 = 12345;
    let mut next = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    (0..4)
        .map(|_| {
            let q = (0..n).map(|_| next()).collect();
            let rates = (0..n).map(|_| 2.0 * next()).collect();
            (q, rates)
        })
        .collect()
}

/// With speeds and without, by every method, q'' agree to 1e-9 at several states.
fn agrees_with_the_rates(with: &Problem, without: &Problem) {
    let states = states(with.coordinates.len());
    let reference = accelerations(without, Method::Kane, &states);
    for method in Method::ALL {
        let got = accelerations(with, method, &states);
        for (s, (g, r)) in got.iter().zip(&reference).enumerate() {
            assert_eq!(g.len(), r.len(), "{}: as many values", method.name());
            for (i, (g, r)) in g.iter().zip(r).enumerate() {
                assert_close(
                    *g,
                    *r,
                    1e-9,
                    1.0,
                    &format!("{} state {s} q'' or reaction [{i}]", method.name()),
                );
            }
        }
    }
}

const TORQUE_FREE: &str = "torque-free-body-speeds";

/// `e` with every named quantity replaced by its definition, nested ones too.
fn written_out(e: &Expr) -> Expr {
    mbd_tutor::symbolic::substitute(e, &|s| match s {
        Symbol::Defined(d) => Some(written_out(d.value())),
        _ => None,
    })
}

fn speed(name: &str, order: u8) -> Expr {
    Expr::sym(Symbol::Speed(name.into(), order))
}

#[test]
fn torque_free_body_with_body_frame_speeds_gives_eulers_equations() {
    let problem = load(&read(TORQUE_FREE)).unwrap_or_else(|e| panic!("{e}"));
    let derivation =
        derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{e}"));
    let i = |k: usize| Expr::constant(&format!("I{k}"));
    // Euler's equations by hand, F_r + F_r* = 0 with F_r = 0:
    // -I1 u1' + (I2 - I3) u2 u3, and cyclically.
    let euler = [(1, 2, 3), (2, 3, 1), (3, 1, 2)].map(|(a, b, c)| {
        let na = format!("u{a}");
        let (nb, nc) = (format!("u{b}"), format!("u{c}"));
        &(-(&i(a) * &speed(&na, 1))) + &(&(&i(b) - &i(c)) * &(&speed(&nb, 0) * &speed(&nc, 0)))
    });
    assert_eq!(derivation.rows.len(), 3);
    for (row, expected) in derivation.rows.iter().zip(&euler) {
        // The rows for the numbers name the inertia torque's rest, T = I·α̃ + ω × I·ω.
        assert!(
            simplify(&(&written_out(&row.expression) - expected)).is_zero(),
            "Kane's row {} is not Euler's equation {}",
            row.expression,
            expected
        );
    }
    // The handout prints them so, with the signs changed so that the mass matrix (the
    // diagonal of the central moments) is positive.
    let out = crate::support::run(&[
        "explain",
        problem_path(TORQUE_FREE).as_str(),
        "--method",
        "kane",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    for line in [
        r"I_{1} \dot{u}_{1} + (I_{3} - I_{2}) u_{2} u_{3} = 0",
        r"I_{2} \dot{u}_{2} + (I_{1} - I_{3}) u_{1} u_{3} = 0",
        r"I_{3} \dot{u}_{3} + (I_{2} - I_{1}) u_{1} u_{2} = 0",
    ] {
        assert!(text.contains(line), "the handout lacks {line}");
    }
    // Step 1 shows the kinematic differential equations and their inverse.
    assert!(text.contains(r"u = W(q)\,\dot{q}"));
    assert!(text.contains(r"\dot{a}_{2} = u_{1} s_{3} + u_{2} c_{3}"));
}

fn problem_path(name: &str) -> String {
    problem(name).to_string_lossy().into_owned()
}

#[test]
fn torque_free_body_speeds_agree_with_the_rates() {
    let text = read(TORQUE_FREE);
    agrees_with_the_rates(
        &load(&text).unwrap_or_else(|e| panic!("{e}")),
        &with_speeds(&text, None),
    );
}

#[test]
fn a_general_free_body_with_body_frame_speeds_agrees_with_the_rates() {
    // Six coordinates, products of inertia: translation rates and ω·b_i as speeds.
    let text = read("torque-free-body");
    let speeds = serde_json::json!({
        "vx": { "equals": "x'" }, "vy": { "equals": "y'" }, "vz": { "equals": "z'" },
        "w1": { "equals": "cos(a2)*cos(a3)*a1' + sin(a3)*a2'" },
        "w2": { "equals": "-cos(a2)*sin(a3)*a1' + cos(a3)*a2'" },
        "w3": { "equals": "sin(a2)*a1' + a3'" }
    });
    agrees_with_the_rates(&with_speeds(&text, Some(speeds)), &with_speeds(&text, None));
}

#[test]
fn planar_speeds_agree_with_the_rates() {
    let cases = [
        // The absolute angular velocity of the second rod.
        (
            "double-pendulum-rods",
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q1' + q2'" } }),
        ),
        // Five absolute angular velocities: a 5x5 W, inverted by elimination.
        (
            "five-link-chain",
            serde_json::json!({
                "u1": { "equals": "q1'" }, "u2": { "equals": "q1' + q2'" }, "u3": { "equals": "q1' + q2' + q3'" },
                "u4": { "equals": "q1' + q2' + q3' + q4'" }, "u5": { "equals": "q1' + q2' + q3' + q4' + q5'" }
            }),
        ),
        // Dampers: a load that uses the rates.
        (
            "two-mass-spring-damper",
            serde_json::json!({ "u1": { "equals": "x1'" }, "u2": { "equals": "x2' - x1'" } }),
        ),
        // The plate's velocity in its own unit vectors: W depends on a coordinate.
        (
            "plate-on-two-springs",
            serde_json::json!({
                "u1": { "equals": "cos(theta)*x' + sin(theta)*y'" },
                "u2": { "equals": "-sin(theta)*x' + cos(theta)*y'" },
                "u3": { "equals": "theta'" }
            }),
        ),
        // A speed with a coordinate-dependent coefficient of another rate.
        (
            "bead-on-rotating-rod",
            serde_json::json!({ "u1": { "equals": "theta'" }, "u2": { "equals": "r' + r*theta'" } }),
        ),
    ];
    for (name, speeds) in cases {
        let text = read(name);
        agrees_with_the_rates(&with_speeds(&text, Some(speeds)), &with_speeds(&text, None));
    }
}

#[test]
fn double_pendulum_with_absolute_speeds_prints_the_textbook_form() {
    let text = read("double-pendulum-rods");
    let speeds = serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q1' + q2'" } });
    let problem = with_speeds(&text, Some(speeds));
    let derivation =
        derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{e}"));
    // The angular velocity of B is u2 itself, not u1 + (u2 - u1).
    let b = problem.body_ids().nth(1).expect("two bodies");
    let omega = derivation.model.bodies[b.0]
        .omega
        .components_in(b, &derivation.model.frames);
    assert_eq!(omega[2], speed("u2", 0));
}

#[test]
fn energy_is_conserved_with_speeds() {
    // The kinetic energy by hand, T = (I1 u1² + I2 u2² + I3 u3²)/2 with the body-frame
    // components of the angular velocity computed here from a, a'.
    let (i1, i2, i3) = (4.0, 6.0, 8.0);
    for method in ["kane", "motion-law", "newton-euler"] {
        let (columns, rows) = simulate(
            TORQUE_FREE,
            &["--method", method, "--duration", "5", "--no-checks"],
        );
        let at = |row: &[f64], name: &str| row[column(&columns, name)];
        let energy = |row: &[f64]| {
            let (a2, a3) = (at(row, "a2"), at(row, "a3"));
            let (d1, d2, d3) = (at(row, "a1'"), at(row, "a2'"), at(row, "a3'"));
            let u1 = a2.cos() * a3.cos() * d1 + a3.sin() * d2;
            let u2 = -a2.cos() * a3.sin() * d1 + a3.cos() * d2;
            let u3 = a2.sin() * d1 + d3;
            0.5 * (i1 * u1 * u1 + i2 * u2 * u2 + i3 * u3 * u3)
        };
        let e0 = energy(&rows[0]);
        assert!(rows.len() > 100, "{method}: a long run");
        for row in &rows {
            assert_close(
                energy(row),
                e0,
                1e-7,
                1.0,
                &format!("{method}: T at t = {}", row[0]),
            );
        }
    }
}

/// The report of `check` on a problem whose speeds are `speeds`.
fn refused(speeds: serde_json::Value) -> String {
    let mut value: serde_json::Value =
        serde_json::from_str(&read("double-pendulum-rods")).expect("JSON");
    value["speeds"] = speeds;
    match load(&value.to_string()) {
        Ok(_) => panic!("accepted {value}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_speeds_are_refused_with_their_path() {
    let cases = [
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q1' + q2'^2" } }),
            "speeds.u2.equals, column 7: the speed is not linear in the rates",
        ),
        (
            serde_json::json!({ "u1": { "equals": "sin(q1')" }, "u2": { "equals": "q2'" } }),
            "speeds.u1.equals, column 5: the speed is not linear in the rates",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1' + q2'" }, "u2": { "equals": "2*q1' + 2*q2'" } }),
            "speeds: the speeds do not determine the rates q1, q2 at the initial state",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q1' + q3'" } }),
            "speeds.u2.equals, column 7: unknown name `q3`",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1' + q2'" } }),
            "speeds: 1 speed declared for 2 coordinates",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q1'", "unit": 3 }, "u3": {} }),
            "speeds: 3 speeds declared for 2 coordinates",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "g": { "equals": "q2'" } }),
            "speeds.g: `g` is already a constant",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "t*q2'" } }),
            "speeds.u2.equals, column 1: a speed may not depend on time `t`",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q2' + L1" } }),
            "speeds.u2.equals, column 1: the speed has a part without rates",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "q1''" } }),
            "speeds.u2.equals, column 1: `q1''` is a second rate",
        ),
        (
            serde_json::json!({ "u1": { "equals": "q1'" }, "u2": { "equals": "L1" } }),
            "speeds.u2.equals, column 1: the speed has a part without rates",
        ),
        (serde_json::json!([]), "speeds: expected an object"),
        (serde_json::json!({}), "speeds: `speeds` is empty"),
    ];
    for (speeds, expected) in cases {
        let report = refused(speeds.clone());
        assert!(
            report.contains(expected),
            "{speeds}: expected {expected:?} in\n{report}"
        );
        assert!(report.contains("hint:"), "{speeds}: no hint in\n{report}");
    }
}

#[test]
fn speeds_are_refused_with_constraints() {
    let mut value: serde_json::Value = serde_json::from_str(&read("four-bar")).expect("JSON");
    value["speeds"] = serde_json::json!({
        "u1": { "equals": "q1'" }, "u2": { "equals": "q2'" }, "u3": { "equals": "q3'" }
    });
    let report = load(&value.to_string()).expect_err("refused").to_string();
    assert!(
        report.contains("speeds: declared speeds are not supported with closures"),
        "{report}"
    );
}

#[test]
fn a_singular_w_away_from_the_initial_state_is_a_solve_error_not_a_panic() {
    // u1 = cos(a2) a1' is singular at a2 = pi/2 (gimbal lock of these speeds).
    let out = crate::support::run(&[
        "solve",
        problem_path(TORQUE_FREE).as_str(),
        "--state",
        "a2=1.5707963267948966",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn solve_reports_the_speeds_and_their_rates_as_eulers_equations_give_them() {
    let (i1, i2, i3) = (4.0, 6.0, 8.0);
    for s in crate::support::solve_all(
        TORQUE_FREE,
        &["--state", "a1=0.4,a2=0.3,a3=-1.1,a1'=0.7,a2'=-1.5,a3'=2.5"],
    ) {
        let get = |key: &str, name: &str| {
            s.json[key][name]
                .as_f64()
                .unwrap_or_else(|| panic!("{}: no {key}.{name}", s.method))
        };
        // The speeds by hand from the attitude rates.
        let (a2, a3, d1, d2, d3) = (0.3f64, -1.1f64, 0.7, -1.5, 2.5);
        let u = [
            a2.cos() * a3.cos() * d1 + a3.sin() * d2,
            -a2.cos() * a3.sin() * d1 + a3.cos() * d2,
            a2.sin() * d1 + d3,
        ];
        for (k, u) in u.iter().enumerate() {
            assert_close(get("speeds", &format!("u{}", k + 1)), *u, 1e-12, 1.0, "u");
        }
        // Euler's equations by hand.
        let du = [
            (i2 - i3) * u[1] * u[2] / i1,
            (i3 - i1) * u[2] * u[0] / i2,
            (i1 - i2) * u[0] * u[1] / i3,
        ];
        for (k, du) in du.iter().enumerate() {
            let what = format!("{}: u{}'", s.method, k + 1);
            assert_close(
                get("speed_derivatives", &format!("u{}", k + 1)),
                *du,
                1e-9,
                1.0,
                &what,
            );
        }
    }
}
