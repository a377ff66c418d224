//! Kinematics against closed forms written out here, and against finite differences.

use mbd_tutor::mechanics::{Model, Vector};
use mbd_tutor::problem::{load, BodyId, Problem};
use mbd_tutor::symbolic::{eval, Symbol, Values};

/// Values of the constants and of q, q', q'' along q(t) = initial + a sin(w t + p) (and of
/// the declared speeds and their rates, if any).
fn values_on_motion(problem: &Problem, t: f64, seed: u64) -> Values {
    let mut values = Values::new();
    for c in &problem.constants {
        values.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    for (i, c) in problem.coordinates.iter().enumerate() {
        let k = (i as f64 + 1.0) * (seed as f64 + 1.0);
        let (a, w, p) = (
            0.3 + 0.1 * (k * 1.7).sin(),
            1.0 + 0.5 * (k * 2.3).cos(),
            k * 0.77,
        );
        let s = (w * t + p).sin();
        let co = (w * t + p).cos();
        values.set(problem.coordinate_symbol(i, 0), c.initial + a * s);
        values.set(problem.coordinate_symbol(i, 1), a * w * co);
        values.set(problem.coordinate_symbol(i, 2), -a * w * w * s);
    }
    values.set(Symbol::Time, t);
    // Declared speeds and their rates along the same motion: u = W(q) q' and its d/dt.
    for (r, speed) in problem.speeds.iter().enumerate() {
        let du = mbd_tutor::symbolic::time_derivative(&speed.equals).expect("d/dt");
        values.set(problem.speed_symbol(r, 1), eval(&speed.equals, &values));
        values.set(problem.speed_symbol(r, 2), eval(&du, &values));
    }
    values
}

fn in_ground(model: &Model, v: &Vector, values: &Values) -> [f64; 3] {
    let c = v.components_in(BodyId::GROUND, &model.frames);
    [
        eval(&c[0], values),
        eval(&c[1], values),
        eval(&c[2], values),
    ]
}

fn in_frame(model: &Model, v: &Vector, frame: BodyId, values: &Values) -> [f64; 3] {
    let c = v.components_in(frame, &model.frames);
    [
        eval(&c[0], values),
        eval(&c[1], values),
        eval(&c[2], values),
    ]
}

fn assert_close(got: [f64; 3], expected: [f64; 3], tolerance: f64, what: &str) {
    for k in 0..3 {
        let scale = 1.0f64.max(expected[k].abs());
        assert!(
            (got[k] - expected[k]).abs() <= tolerance * scale,
            "{what}[{k}]: got {got:?}, expected {expected:?}"
        );
    }
}

/// Every velocity is the derivative of its position, every acceleration that of its
/// velocity, checked by central differences along a smooth motion.
pub fn check_finite_differences(problem: &Problem) {
    let model = Model::build(problem).expect("model builds");
    let h = 1e-4;
    for seed in 0..3 {
        let t = 0.4 + 0.3 * seed as f64;
        let at = |dt: f64| values_on_motion(problem, t + dt, seed);
        let (before, now, after) = (at(-h), at(0.0), at(h));
        let mut points: Vec<(String, &mbd_tutor::mechanics::PointMotion)> = Vec::new();
        for body in problem.body_ids() {
            points.push((
                format!("{}*", problem.body_name(body)),
                &model.bodies[body.0].center,
            ));
            points.push((
                format!("{}.o", problem.body_name(body)),
                &model.bodies[body.0].origin,
            ));
        }
        for (j, joint) in problem.joints.iter().enumerate() {
            points.push((joint.name.clone(), &model.joints[j].point));
        }
        for (name, p) in points {
            for (of, derivative) in [(&p.position, &p.velocity), (&p.velocity, &p.acceleration)] {
                let (a, b) = (
                    in_ground(&model, of, &before),
                    in_ground(&model, of, &after),
                );
                let difference = [
                    (b[0] - a[0]) / (2.0 * h),
                    (b[1] - a[1]) / (2.0 * h),
                    (b[2] - a[2]) / (2.0 * h),
                ];
                assert_close(
                    in_ground(&model, derivative, &now),
                    difference,
                    1e-6,
                    &format!("{}: {name}", problem.title),
                );
            }
        }
        for body in problem.body_ids() {
            let state = &model.bodies[body.0];
            let (a, b) = (
                in_frame(&model, &state.omega, body, &before),
                in_frame(&model, &state.omega, body, &after),
            );
            let difference = [
                (b[0] - a[0]) / (2.0 * h),
                (b[1] - a[1]) / (2.0 * h),
                (b[2] - a[2]) / (2.0 * h),
            ];
            assert_close(
                in_frame(&model, &state.alpha, body, &now),
                difference,
                1e-6,
                "alpha",
            );
        }
    }
}

#[test]
fn velocities_and_accelerations_are_derivatives_for_every_bundled_problem() {
    let mut count = 0;
    let mut entries: Vec<_> = std::fs::read_dir("problems")
        .expect("problems/")
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for path in entries
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
    {
        let text = std::fs::read_to_string(path).expect("readable");
        let problem = load(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        check_finite_differences(&problem);
        count += 1;
    }
    assert!(count >= 1, "no bundled problems found");
}

const DOUBLE_PENDULUM: &str = r#"{
  "title": "Double pendulum", "dimension": 2,
  "constants": { "m": 1.0, "L": 0.5, "g": 9.81 },
  "coordinates": { "q1": { "initial": 0.5 }, "q2": { "initial": 0.0 } },
  "gravity": "-g*N.y",
  "bodies": {
    "A": { "mass": "m", "center": "-L/2*A.y", "inertia": "m*L^2/12" },
    "B": { "mass": "m", "center": "-L/2*B.y", "inertia": "m*L^2/12" }
  },
  "joints": [
    { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["q1"] },
    { "name": "P", "type": "revolute", "parent": "A", "child": "B", "axis": "A.z", "at": "-L*A.y", "coordinates": ["q2"] }
  ]
}"#;

#[test]
fn double_pendulum_matches_the_closed_form() {
    let problem = load(DOUBLE_PENDULUM).expect("valid");
    let model = Model::build(&problem).expect("model");
    let values = values_on_motion(&problem, 0.8, 7);
    let get = |name: &str, order: u8| values.get(&Symbol::Coord(name.into(), order));
    let (q1, q2, u1, u2, a1, a2) = (
        get("q1", 0),
        get("q2", 0),
        get("q1", 1),
        get("q2", 1),
        get("q1", 2),
        get("q2", 2),
    );
    let l = 0.5;
    let s = q1 + q2;
    // r_B* = L (sin q1, -cos q1) + L/2 (sin s, -cos s); differentiate twice by hand.
    let position = [
        l * q1.sin() + l / 2.0 * s.sin(),
        -l * q1.cos() - l / 2.0 * s.cos(),
        0.0,
    ];
    let velocity = [
        l * u1 * q1.cos() + l / 2.0 * (u1 + u2) * s.cos(),
        l * u1 * q1.sin() + l / 2.0 * (u1 + u2) * s.sin(),
        0.0,
    ];
    let acceleration = [
        l * a1 * q1.cos() - l * u1 * u1 * q1.sin() + l / 2.0 * (a1 + a2) * s.cos()
            - l / 2.0 * (u1 + u2).powi(2) * s.sin(),
        l * a1 * q1.sin()
            + l * u1 * u1 * q1.cos()
            + l / 2.0 * (a1 + a2) * s.sin()
            + l / 2.0 * (u1 + u2).powi(2) * s.cos(),
        0.0,
    ];
    let b = &model.bodies[2];
    assert_close(
        in_ground(&model, &b.center.position, &values),
        position,
        1e-12,
        "r_B*",
    );
    assert_close(
        in_ground(&model, &b.center.velocity, &values),
        velocity,
        1e-12,
        "v_B*",
    );
    assert_close(
        in_ground(&model, &b.center.acceleration, &values),
        acceleration,
        1e-12,
        "a_B*",
    );
    assert_close(
        in_ground(&model, &b.omega, &values),
        [0.0, 0.0, u1 + u2],
        1e-12,
        "omega_B",
    );
    assert_close(
        in_ground(&model, &b.alpha, &values),
        [0.0, 0.0, a1 + a2],
        1e-12,
        "alpha_B",
    );
}

#[test]
fn bead_on_rotating_rod_has_the_coriolis_term() {
    let problem = load(
        r#"{
      "title": "Bead on a rotating rod", "dimension": 2,
      "constants": { "m": 0.1 },
      "bodies": {
        "A": { "mass": 1, "inertia": 0.1 },
        "B": { "mass": "m", "inertia": 0 }
      },
      "joints": [
        { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["theta"] },
        { "name": "S", "type": "prismatic", "parent": "A", "child": "B", "axis": "A.x", "coordinates": ["r"] }
      ]
    }"#,
    )
    .expect("valid");
    let model = Model::build(&problem).expect("model");
    let values = values_on_motion(&problem, 0.3, 2);
    let get = |name: &str, order: u8| values.get(&Symbol::Coord(name.into(), order));
    let (r, rd, rdd, w, wd) = (
        get("r", 0),
        get("r", 1),
        get("r", 2),
        get("theta", 1),
        get("theta", 2),
    );
    // In the rod's frame: a = (r'' - r w^2) a_x + (2 r' w + r w') a_y.
    let expected = [rdd - r * w * w, 2.0 * rd * w + r * wd, 0.0];
    let a = &model.bodies[2].center.acceleration;
    assert_close(
        in_frame(&model, a, BodyId(1), &values),
        expected,
        1e-12,
        "a_B in A",
    );
}

#[test]
fn spherical_joint_angular_velocity_matches_the_body_fixed_zxy_formula() {
    let problem = load(
        r#"{
      "title": "Body on a ball joint", "dimension": 3,
      "bodies": { "B": { "mass": 1, "inertia": { "xx": 1, "yy": 2, "zz": 3 } } },
      "joints": [ { "name": "O", "type": "spherical", "parent": "N", "child": "B", "sequence": "zxy",
                    "coordinates": ["phi", "theta", "psi"] } ]
    }"#,
    )
    .expect("valid");
    let model = Model::build(&problem).expect("model");
    let values = values_on_motion(&problem, 1.1, 4);
    let get = |name: &str, order: u8| values.get(&Symbol::Coord(name.into(), order));
    let (th, ps) = (get("theta", 0), get("psi", 0));
    let (dph, dth, dps) = (get("phi", 1), get("theta", 1), get("psi", 1));
    // Body-fixed z-x-y: w = phi' n_z + theta' x_1 + psi' y_2, written in the body's axes.
    let expected = [
        dth * ps.cos() - dph * th.cos() * ps.sin(),
        dps + dph * th.sin(),
        dth * ps.sin() + dph * th.cos() * ps.cos(),
    ];
    assert_close(
        in_frame(&model, &model.bodies[1].omega, BodyId(1), &values),
        expected,
        1e-12,
        "omega_B",
    );
}
