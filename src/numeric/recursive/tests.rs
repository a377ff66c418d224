//! The recursive form against references it shares no code with: the dense compiled
//! rows of Kane's method on random states (times too, for loads that change with `t`), and
//! equations written by hand: a pendulum, a mass on a spring and damper pushed by a force
//! that varies in time, and a damped pendulum driven by a torque.

use super::Recursive;
use crate::equations::{derive, Derivation, Method, Request, Rows};
use crate::mechanics::Form;
use crate::numeric::evaluate::Compiled;
use crate::problem::{load, Problem};

/// Kane's rows of `problem` for numbers, formed as `rows` says: `Compiled` for Kane's own
/// rows, `Fastest` for the system by composite bodies where it stands alone.
fn kane(problem: &Problem, rows: Rows) -> Derivation<'_> {
    let request = Request {
        form: Form::Numeric,
        rows,
        states: &[],
    };
    derive(problem, Method::Kane, request).expect("derives")
}

/// A repeatable stream of numbers in [-1, 1).
struct Numbers(u64);

impl Numbers {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// A problem file with the fields `fields` taken out.
fn without(path: &str, fields: &[&str]) -> Problem {
    let text = std::fs::read_to_string(path).expect("bundled problem");
    let mut value: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let object = value.as_object_mut().expect("object");
    for field in fields {
        object.remove(*field);
    }
    load(&serde_json::to_string(&value).expect("JSON")).expect("valid problem")
}

/// A problem file with its loads and requested reactions taken out.
fn plain(path: &str) -> Problem {
    without(path, &["loads", "find"])
}

/// A problem file with its loads, its requested reactions taken out.
fn loaded(path: &str) -> Problem {
    without(path, &["find"])
}

/// The recursive q'' equal the dense form's on random states and times, relative to
/// max(1, |q''|), to `tolerance`; the tree, for what else a test asks of it.
fn agrees_to(problem: &Problem, seed: u64, tolerance: f64) -> Recursive {
    let derivation = kane(problem, Rows::Compiled);
    let tree = Recursive::new(&derivation).expect("a tree the recursive form takes");
    let dense = Compiled::new(&derivation);
    let n = problem.coordinates.len();
    let mut numbers = Numbers(seed);
    for _ in 0..6 {
        let t = 2.0 + 2.0 * numbers.next();
        let q: Vec<f64> = (0..n).map(|_| 1.5 * numbers.next()).collect();
        let rates: Vec<f64> = (0..n).map(|_| 2.0 * numbers.next()).collect();
        let ours = tree.accelerations(t, &q, &rates).expect("regular");
        let theirs = dense.motion(t, &q, &rates).expect("regular").accelerations;
        for (i, (a, b)) in ours.iter().zip(&theirs).enumerate() {
            assert!(
                (a - b).abs() <= tolerance * b.abs().max(1.0),
                "{}: q{i}'' {a} against the dense {b} at t = {t}, q = {q:?}, q' = {rates:?}",
                problem.title
            );
        }
    }
    tree
}

fn agrees(problem: &Problem, seed: u64) {
    agrees_to(problem, seed, 1e-9);
}

#[test]
fn every_joint_type_agrees_with_the_dense_form() {
    agrees(&plain("problems/validation/all-joints-3d.json"), 1);
}

#[test]
fn spherical_chain_agrees_with_the_dense_form() {
    agrees(&plain("problems/validation/spherical-chain-3.json"), 2);
}

#[test]
fn planar_chains_agree_with_the_dense_form() {
    agrees(&plain("problems/validation/ten-link-chain.json"), 3);
    agrees(&plain("problems/five-link-chain.json"), 4);
}

#[test]
fn skewed_axes_and_offset_joints_agree_with_the_dense_form() {
    // Axes off the unit vectors, one written against its canonical sign, and joint points
    // off both bodies' origins, so every term of the joint's transform is exercised.
    let problem = load(
        r#"{
      "title": "a skewed chain", "dimension": 3,
      "constants": { "g": 9.81, "m": 1.3, "L": 0.7 },
      "gravity": "-g*N.z",
      "coordinates": { "a": {}, "b": {}, "c": {}, "s": {} },
      "bodies": {
        "A": { "mass": "m", "center": "0.1*A.x - L/2*A.z",
               "inertia": { "xx": "0.03", "yy": "0.04", "zz": "0.02", "xy": "0.002" } },
        "B": { "mass": "2*m", "center": "0.2*B.y",
               "inertia": { "xx": "0.05", "yy": "0.03", "zz": "0.06", "yz": "-0.004" } },
        "C": { "mass": "m/2", "center": "-0.1*C.z",
               "inertia": { "xx": "0.01", "yy": "0.02", "zz": "0.015", "zx": "0.001" } },
        "D": { "mass": "m", "center": "0.05*D.x",
               "inertia": { "xx": "0.01", "yy": "0.01", "zz": "0.01" } }
      },
      "joints": [
        { "name": "J1", "type": "revolute", "parent": "N", "child": "A",
          "axis": "N.x + 2*N.y + 0.5*N.z", "at": "0.1*N.x", "coordinates": ["a"] },
        { "name": "J2", "type": "revolute", "parent": "A", "child": "B",
          "axis": "-A.x + A.z", "at": "-L*A.z", "child_at": "0.1*B.x + 0.2*B.z",
          "coordinates": ["b"] },
        { "name": "J3", "type": "revolute", "parent": "B", "child": "C",
          "axis": "B.y", "at": "0.3*B.y", "child_at": "-0.15*C.y", "coordinates": ["c"] },
        { "name": "J4", "type": "prismatic", "parent": "C", "child": "D",
          "axis": "-C.x - C.z", "at": "0.2*C.z", "child_at": "0.1*D.y", "coordinates": ["s"] }
      ]
    }"#,
    )
    .expect("valid problem");
    agrees(&problem, 5);
}

#[test]
fn compound_pendulum_follows_its_equation_written_by_hand() {
    // θ'' = −m g d sin θ / (I + m d²), the pivot at the origin, the centre d below it.
    let problem = load(
        r#"{
      "title": "a compound pendulum", "dimension": 2,
      "constants": { "g": 9.81, "m": 2.0, "d": 0.4, "I": 0.05 },
      "gravity": "-g*N.y",
      "coordinates": { "th": {} },
      "bodies": { "B": { "mass": "m", "center": "-d*B.y", "inertia": "I" } },
      "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "B",
                    "coordinates": ["th"] } ]
    }"#,
    )
    .expect("valid problem");
    let derivation = kane(&problem, Rows::Compiled);
    let tree = Recursive::new(&derivation).expect("a plain tree");
    let (m, g, d, i) = (2.0, 9.81, 0.4, 0.05);
    for theta in [-2.0, -0.3, 0.0, 0.7, 2.9] {
        for rate in [0.0, 1.5] {
            let ours = tree.accelerations(0.0, &[theta], &[rate]).expect("regular")[0];
            let by_hand = -m * g * d * f64::sin(theta) / (i + m * d * d);
            assert!(
                (ours - by_hand).abs() <= 1e-12,
                "θ = {theta}: {ours} against {by_hand}"
            );
        }
    }
}

#[test]
fn bundled_problems_with_loads_agree_with_the_dense_form() {
    // Springs, dampers, forces and torques between bodies, joint springs, dampers and
    // actuators (some of them functions of t and of the rates), in the plane and in space.
    for (seed, path) in [
        "problems/two-mass-spring-damper.json",
        "problems/plate-on-two-springs.json",
        "problems/floating-plate-springs.json",
        "problems/two-link-robot-arm.json",
        "problems/five-link-chain.json",
        "problems/cart-pole.json",
        "problems/bead-on-rotating-rod.json",
        "problems/compound-pendulum.json",
        "problems/unbalanced-disk-shaft.json",
        "problems/arm-3d-rrp.json",
        "problems/collar-on-spinning-shaft.json",
        "problems/gyroscope-gimbal.json",
        "problems/validation/all-joints-3d.json",
    ]
    .into_iter()
    .enumerate()
    {
        let tree = agrees_to(&loaded(path), 10 + seed as u64, 1e-10);
        assert!(tree.loads.is_some(), "{path}: the loads were not taken");
    }
}

#[test]
fn mass_on_a_spring_and_damper_follows_its_equation_written_by_hand() {
    // x'' = (F0 cos(w t) − k x − c x') / m: a joint spring and a damper between the block
    // and the ground, and a push that varies in time.
    let problem = load(
        r#"{
      "title": "a pushed mass on a spring and damper", "dimension": 2,
      "constants": { "m": 2.5, "k": 40, "c": 3, "F0": 7, "w": 5 },
      "points": { "wall": { "on": "N", "at": "-1*N.x" } },
      "coordinates": { "x": {} },
      "bodies": { "B": { "mass": "m", "inertia": "0.1" } },
      "joints": [ { "name": "track", "type": "prismatic", "parent": "N", "child": "B",
                    "axis": "N.x", "coordinates": ["x"] } ],
      "loads": [
        { "type": "joint_spring", "joint": "track", "coordinate": "x", "stiffness": "k" },
        { "type": "damper", "between": ["wall", "B*"], "coefficient": "c" },
        { "type": "force", "on": "B", "vector": "F0*cos(w*t)*N.x" }
      ]
    }"#,
    )
    .expect("valid problem");
    let derivation = kane(&problem, Rows::Compiled);
    let tree = Recursive::new(&derivation).expect("a tree with loads");
    let (m, k, c, f0, w) = (2.5, 40.0, 3.0, 7.0, 5.0);
    for t in [0.0, 0.4, 1.3] {
        for (x, rate) in [(0.0, 0.0), (0.2, -1.5), (-0.3, 0.8)] {
            let ours = tree.accelerations(t, &[x], &[rate]).expect("regular")[0];
            let by_hand = (f0 * f64::cos(w * t) - k * x - c * rate) / m;
            assert!(
                (ours - by_hand).abs() <= 1e-12,
                "t = {t}, x = {x}, x' = {rate}: {ours} against {by_hand}"
            );
        }
    }
}

#[test]
fn driven_damped_pendulum_follows_its_equation_written_by_hand() {
    // θ'' = (T0 sin(w t) − c θ' − m g d sin θ) / (I + m d²).
    let problem = load(
        r#"{
      "title": "a driven damped pendulum", "dimension": 2,
      "constants": { "g": 9.81, "m": 2.0, "d": 0.4, "I": 0.05, "c": 0.3, "T0": 1.2, "w": 3 },
      "gravity": "-g*N.y",
      "coordinates": { "th": {} },
      "bodies": { "B": { "mass": "m", "center": "-d*B.y", "inertia": "I" } },
      "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "B",
                    "coordinates": ["th"] } ],
      "loads": [
        { "type": "torque", "on": "B", "vector": "T0*sin(w*t)*N.z" },
        { "type": "joint_damper", "joint": "O", "coordinate": "th", "coefficient": "c" }
      ]
    }"#,
    )
    .expect("valid problem");
    let derivation = kane(&problem, Rows::Compiled);
    let tree = Recursive::new(&derivation).expect("a tree with loads");
    let (m, g, d, i, c, t0, w) = (2.0, 9.81, 0.4, 0.05, 0.3, 1.2, 3.0);
    for t in [0.0, 0.5, 2.1] {
        for (theta, rate) in [(0.0, 0.0), (0.7, 1.5), (-2.9, -0.4)] {
            let ours = tree.accelerations(t, &[theta], &[rate]).expect("regular")[0];
            let by_hand =
                (t0 * f64::sin(w * t) - c * rate - m * g * d * f64::sin(theta)) / (i + m * d * d);
            assert!(
                (ours - by_hand).abs() <= 1e-12,
                "t = {t}, θ = {theta}, θ' = {rate}: {ours} against {by_hand}"
            );
        }
    }
}

#[test]
fn constraints_friction_and_declared_speeds_are_left_to_the_dense_form() {
    for path in [
        "problems/four-bar.json",
        "problems/knife-edge.json",
        "problems/block-on-rough-slide.json",
        "problems/torque-free-body-speeds.json",
        "problems/collar-on-driven-rod.json",
    ] {
        let problem = crate::problem::load_file(std::path::Path::new(path)).expect("valid");
        let derivation = kane(&problem, Rows::Compiled);
        assert!(Recursive::new(&derivation).is_none(), "{path}");
    }
}

#[test]
fn gimbal_lock_is_left_to_the_dense_form_which_names_it() {
    // x-y-z angles with the second at a right angle: the first and third axes align.
    let problem = plain("problems/validation/spherical-chain-3.json");
    let derivation = kane(&problem, Rows::Fastest);
    let compiled = Compiled::fastest(&derivation);
    assert!(compiled.is_recursive());
    let n = problem.coordinates.len();
    let mut q = vec![0.1; n];
    q[1] = std::f64::consts::FRAC_PI_2;
    let tree = Recursive::new(&derivation).expect("a plain tree");
    assert!(tree.accelerations(0.0, &q, &vec![0.0; n]).is_none());
    let error = compiled.motion(0.0, &q, &vec![0.0; n]).unwrap_err();
    assert!(
        matches!(error, crate::numeric::SolveError::SingularSystem { .. }),
        "{error}"
    );
}
