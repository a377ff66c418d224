//! Every method against equations derived by hand here or taken from textbooks.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{Compiled, StateSolution};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::load;

fn solve_all(text: &str, q: &[f64], rates: &[f64]) -> Vec<(Method, StateSolution)> {
    let problem = load(text).unwrap_or_else(|e| panic!("{e}"));
    Method::ALL
        .iter()
        .map(|&method| {
            let derivation = derive(&problem, method, Purpose::Rows)
                .unwrap_or_else(|e| panic!("{}: {e}", method.name()));
            let solution = Compiled::new(&derivation)
                .solve(0.0, q, rates)
                .unwrap_or_else(|e| panic!("{e}"));
            (method, solution)
        })
        .collect()
}

fn assert_near(got: f64, expected: f64, what: &str) {
    let tolerance = 1e-9 * expected.abs().max(1.0);
    assert!(
        (got - expected).abs() <= tolerance,
        "{what}: got {got}, expected {expected}"
    );
}

const PENDULUM: &str = r#"{
  "title": "Simple pendulum", "dimension": 2,
  "constants": { "m": 2.0, "L": 1.5, "g": 9.81 },
  "coordinates": { "q": { "initial": 0.7 } },
  "gravity": "-g*N.y",
  "bodies": { "A": { "mass": "m", "center": "-L*A.y", "inertia": 0 } },
  "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["q"] } ],
  "find": { "reactions": ["O"] }
}"#;

/// The pin force on the pendulum by hand, F = m (a* - g): tangential m L q'' and
/// centripetal m L q'^2 toward O.
fn pendulum_pin_force(q: f64, u: f64, qdd: f64) -> (f64, f64) {
    let (m, l, g) = (2.0, 1.5, 9.81);
    let fx = m * (l * qdd * q.cos() - l * u * u * q.sin());
    let fy = m * (l * qdd * q.sin() + l * u * u * q.cos() + g);
    (fx, fy)
}

#[test]
fn simple_pendulum_and_its_pin_reaction() {
    let (l, g) = (1.5, 9.81);
    let (q, u) = (0.7f64, -1.3f64);
    for (method, s) in solve_all(PENDULUM, &[q], &[u]) {
        let qdd = -(g / l) * q.sin();
        assert_near(s.accelerations[0], qdd, method.name());
        let (fx, fy) = pendulum_pin_force(q, u, qdd);
        let (_, force, moment) = &s.reactions[0];
        assert_near(force[0], fx, "Fx");
        assert_near(force[1], fy, "Fy");
        assert_near(force[2], 0.0, "Fz");
        assert_eq!(moment, &[0.0, 0.0, 0.0]);
    }
}

/// The pendulum at rest at the bottom (q = 0) and horizontal (q = pi/2): the Motion Law's
/// rows must still determine the pin force there. A plan of `M about A*` with `F along N.x`
/// is independent at generic angles but loses the vertical pin force at q = 0.
#[test]
fn pin_reaction_at_the_bottom_and_at_a_quarter_turn() {
    let (l, g) = (1.5, 9.81);
    for (q, u) in [(0.0f64, 0.0f64), (std::f64::consts::FRAC_PI_2, 0.8)] {
        for (method, s) in solve_all(PENDULUM, &[q], &[u]) {
            let qdd = -(g / l) * q.sin();
            assert_near(s.accelerations[0], qdd, method.name());
            let (fx, fy) = pendulum_pin_force(q, u, qdd);
            let (_, force, _) = &s.reactions[0];
            assert_near(force[0], fx, &format!("Fx by {} at q = {q}", method.name()));
            assert_near(force[1], fy, &format!("Fy by {} at q = {q}", method.name()));
        }
    }
}

#[test]
fn double_pendulum_of_point_masses_matches_the_textbook() {
    let text = r#"{
      "title": "Double pendulum, point masses", "dimension": 2,
      "constants": { "m1": 1.3, "m2": 0.7, "L1": 1.1, "L2": 0.8, "g": 9.81 },
      "gravity": "-g*N.y",
      "bodies": { "A": { "mass": "m1", "center": "-L1*A.y", "inertia": 0 },
                  "B": { "mass": "m2", "center": "-L2*B.y", "inertia": 0 } },
      "joints": [
        { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["q1"] },
        { "name": "P", "type": "revolute", "parent": "A", "child": "B", "axis": "A.z", "at": "-L1*A.y", "coordinates": ["q2"] }
      ]
    }"#;
    let (m1, m2, l1, l2, g) = (1.3, 0.7, 1.1, 0.8, 9.81);
    let (q1, q2, u1, u2) = (0.4f64, -0.9f64, 0.6f64, -1.1f64);
    // Absolute angles t1 = q1, t2 = q1 + q2 (the usual textbook form).
    let (t1, t2, w1, w2) = (q1, q1 + q2, u1, u1 + u2);
    let den = 2.0 * m1 + m2 - m2 * (2.0 * t1 - 2.0 * t2).cos();
    let a1 = (-g * (2.0 * m1 + m2) * t1.sin()
        - m2 * g * (t1 - 2.0 * t2).sin()
        - 2.0 * (t1 - t2).sin() * m2 * (w2 * w2 * l2 + w1 * w1 * l1 * (t1 - t2).cos()))
        / (l1 * den);
    let a2 = 2.0
        * (t1 - t2).sin()
        * (w1 * w1 * l1 * (m1 + m2)
            + g * (m1 + m2) * t1.cos()
            + w2 * w2 * l2 * m2 * (t1 - t2).cos())
        / (l2 * den);
    for (method, s) in solve_all(text, &[q1, q2], &[u1, u2]) {
        assert_near(s.accelerations[0], a1, method.name());
        assert_near(s.accelerations[1], a2 - a1, method.name());
    }
}

#[test]
fn double_pendulum_of_rods_matches_lagrange() {
    let text = r#"{
      "title": "Double pendulum of rods", "dimension": 2,
      "constants": { "m": 1.0, "L": 0.5, "g": 9.81 },
      "gravity": "-g*N.y",
      "bodies": { "A": { "mass": "m", "center": "-L/2*A.y", "inertia": "m*L^2/12" },
                  "B": { "mass": "m", "center": "-L/2*B.y", "inertia": "m*L^2/12" } },
      "joints": [
        { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["q1"] },
        { "name": "P", "type": "revolute", "parent": "A", "child": "B", "axis": "A.z", "at": "-L*A.y", "coordinates": ["q2"] }
      ]
    }"#;
    let (m, l, g) = (1.0, 0.5, 9.81);
    let (q1, q2, u1, u2) = (0.5f64, 0.3f64, -0.2f64, 0.9f64);
    let (t1, t2, w1, w2) = (q1, q1 + q2, u1, u1 + u2);
    // Lagrange in absolute angles:
    //  4/3 mL² t1'' + 1/2 mL² c t2'' + 1/2 mL² s t2'² + 3/2 m g L sin t1 = 0
    //  1/2 mL² c t1'' + 1/3 mL² t2'' - 1/2 mL² s t1'² + 1/2 m g L sin t2 = 0,  c, s of t1 - t2.
    let (c, s) = ((t1 - t2).cos(), (t1 - t2).sin());
    let ml2 = m * l * l;
    let (a11, a12, a22) = (4.0 / 3.0 * ml2, 0.5 * ml2 * c, ml2 / 3.0);
    let b1 = -(0.5 * ml2 * s * w2 * w2 + 1.5 * m * g * l * t1.sin());
    let b2 = 0.5 * ml2 * s * w1 * w1 - 0.5 * m * g * l * t2.sin();
    let det = a11 * a22 - a12 * a12;
    let (x1, x2) = ((b1 * a22 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det);
    for (method, sol) in solve_all(text, &[q1, q2], &[u1, u2]) {
        assert_near(sol.accelerations[0], x1, method.name());
        assert_near(sol.accelerations[1], x2 - x1, method.name());
    }
}

#[test]
fn cart_pole_matches_lagrange() {
    let text = r#"{
      "title": "Cart-pole", "dimension": 2,
      "constants": { "M": 2.0, "m": 0.5, "L": 0.8, "g": 9.81 },
      "gravity": "-g*N.y",
      "bodies": { "C": { "mass": "M", "inertia": 0.1 },
                  "P": { "mass": "m", "center": "-L/2*P.y", "inertia": "m*L^2/12" } },
      "joints": [
        { "name": "S", "type": "prismatic", "parent": "N", "child": "C", "axis": "N.x", "coordinates": ["x"] },
        { "name": "H", "type": "revolute", "parent": "C", "child": "P", "axis": "C.z", "coordinates": ["theta"] }
      ]
    }"#;
    let (big_m, m, l, g) = (2.0, 0.5, 0.8, 9.81);
    let (th, v, w) = (0.6f64, 0.4, -1.7f64);
    // (M+m) x'' + m L/2 cos th th'' = m L/2 sin th th'^2
    // m L/2 cos th x'' + m L^2/3 th'' = -m g L/2 sin th
    let (a11, a12, a22) = (big_m + m, m * l / 2.0 * th.cos(), m * l * l / 3.0);
    let (b1, b2) = (m * l / 2.0 * th.sin() * w * w, -m * g * l / 2.0 * th.sin());
    let det = a11 * a22 - a12 * a12;
    for (method, s) in solve_all(text, &[0.2, th], &[v, w]) {
        assert_near(
            s.accelerations[0],
            (b1 * a22 - a12 * b2) / det,
            method.name(),
        );
        assert_near(
            s.accelerations[1],
            (a11 * b2 - a12 * b1) / det,
            method.name(),
        );
    }
}

#[test]
fn bead_on_a_free_rotating_rod() {
    let text = r#"{
      "title": "Bead on a rotating rod", "dimension": 2,
      "constants": { "J": 0.3, "m": 0.2 },
      "bodies": { "A": { "mass": 1, "inertia": "J" }, "B": { "mass": "m", "inertia": 0 } },
      "joints": [
        { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["theta"] },
        { "name": "S", "type": "prismatic", "parent": "A", "child": "B", "axis": "A.x", "coordinates": ["r"] }
      ]
    }"#;
    let (jj, m) = (0.3, 0.2);
    let (r, w, rd) = (0.7, 2.0, 0.5);
    // (J + m r²) θ'' + 2 m r r' θ' = 0 ;  r'' = r θ'²
    for (method, s) in solve_all(text, &[0.1, r], &[w, rd]) {
        assert_near(
            s.accelerations[0],
            -2.0 * m * r * rd * w / (jj + m * r * r),
            method.name(),
        );
        assert_near(s.accelerations[1], r * w * w, method.name());
    }
}

#[test]
fn two_mass_spring_damper() {
    let text = r#"{
      "title": "Two masses, springs and a damper", "dimension": 2,
      "constants": { "m1": 1.0, "m2": 2.0, "k1": 30.0, "k2": 20.0, "c": 1.5, "l1": 0.5, "l2": 0.4 },
      "bodies": { "A": { "mass": "m1", "inertia": 0 }, "B": { "mass": "m2", "inertia": 0 } },
      "joints": [
        { "name": "S1", "type": "prismatic", "parent": "N", "child": "A", "axis": "N.x", "coordinates": ["x1"] },
        { "name": "S2", "type": "prismatic", "parent": "N", "child": "B", "axis": "N.x", "coordinates": ["x2"] }
      ],
      "loads": [
        { "type": "spring", "between": ["N.o", "A.o"], "stiffness": "k1", "free_length": "l1" },
        { "type": "spring", "between": ["A.o", "B.o"], "stiffness": "k2", "free_length": "l2" },
        { "type": "damper", "between": ["A.o", "B.o"], "coefficient": "c" }
      ]
    }"#;
    let (m1, m2, k1, k2, c, l1, l2) = (1.0, 2.0, 30.0, 20.0, 1.5, 0.5, 0.4);
    let (x1, x2, v1, v2) = (0.6, 1.3, 0.2, -0.4);
    let spring2 = k2 * (x2 - x1 - l2);
    let damper = c * (v2 - v1);
    for (method, s) in solve_all(text, &[x1, x2], &[v1, v2]) {
        assert_near(
            s.accelerations[0],
            (-k1 * (x1 - l1) + spring2 + damper) / m1,
            method.name(),
        );
        assert_near(s.accelerations[1], (-spring2 - damper) / m2, method.name());
    }
}

#[test]
fn torque_free_body_with_products_of_inertia_obeys_euler() {
    let text = r#"{
      "title": "Torque-free body", "dimension": 3,
      "bodies": { "B": { "mass": 2, "inertia": { "xx": 3, "yy": 4, "zz": 5, "xy": -0.4, "yz": 0.3, "zx": 0.2 } } },
      "joints": [ { "name": "F", "type": "free", "parent": "N", "child": "B", "sequence": "zxy",
                    "coordinates": ["x", "y", "z", "phi", "theta", "psi"] } ]
    }"#;
    let q = [0.1, 0.2, 0.3, 0.4, -0.5, 0.6];
    let u = [0.3, -0.2, 0.1, 1.1, -0.7, 0.9];
    let inertia = [[3.0, -0.4, 0.2], [-0.4, 4.0, 0.3], [0.2, 0.3, 5.0]];
    // Body-fixed z-x-y angles: w = (th' cos ps - ph' cos th sin ps, ps' + ph' sin th, th' sin ps + ph' cos th cos ps).
    let omega = |ang: [f64; 3], rate: [f64; 3]| -> [f64; 3] {
        let (th, ps) = (ang[1], ang[2]);
        [
            rate[1] * ps.cos() - rate[0] * th.cos() * ps.sin(),
            rate[2] + rate[0] * th.sin(),
            rate[1] * ps.sin() + rate[0] * th.cos() * ps.cos(),
        ]
    };
    for (method, s) in solve_all(text, &q, &u) {
        for k in 0..3 {
            assert_near(s.accelerations[k], 0.0, "translation");
        }
        let (ang, rate, acc) = (
            [q[3], q[4], q[5]],
            [u[3], u[4], u[5]],
            [s.accelerations[3], s.accelerations[4], s.accelerations[5]],
        );
        // alpha = d/dt omega along q + h (q', q''), by a central difference in h.
        let h = 1e-6;
        let step = |sign: f64| {
            let a: [f64; 3] = std::array::from_fn(|i| ang[i] + sign * h * rate[i]);
            let r: [f64; 3] = std::array::from_fn(|i| rate[i] + sign * h * acc[i]);
            omega(a, r)
        };
        let (plus, minus) = (step(1.0), step(-1.0));
        let alpha: [f64; 3] = std::array::from_fn(|i| (plus[i] - minus[i]) / (2.0 * h));
        let w = omega(ang, rate);
        let iw: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| inertia[i][j] * w[j]).sum());
        let ia: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| inertia[i][j] * alpha[j]).sum());
        let gyro = [
            w[1] * iw[2] - w[2] * iw[1],
            w[2] * iw[0] - w[0] * iw[2],
            w[0] * iw[1] - w[1] * iw[0],
        ];
        for i in 0..3 {
            let residual = ia[i] + gyro[i];
            assert!(
                residual.abs() < 1e-6,
                "{}: Euler's equation {i} residual {residual}",
                method.name()
            );
        }
    }
}
