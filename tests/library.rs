//! The library of classic problems in `problems/`: every file checks, every method agrees,
//! and each problem's answer matches an independent, hand-derived reference (in the
//! submodules, one test or more per problem).

mod machines;
mod pendulums;
mod planar;
mod spatial;

use crate::support::{all_problems, assert_close, problem, run, solve, METHODS};
use serde_json::Value;
use std::collections::BTreeSet;

/// The classic problems of the library (other files in `problems/` exercise the format).
const LIBRARY: [&str; 17] = [
    "simple-pendulum",
    "compound-pendulum",
    "double-pendulum-rods",
    "cart-pole",
    "bead-on-rotating-rod",
    "two-mass-spring-damper",
    "block-on-wedge",
    "two-link-robot-arm",
    "floating-plate-springs",
    "spherical-pendulum",
    "heavy-symmetric-top",
    "gyroscope-gimbal",
    "arm-3d-rrp",
    "unbalanced-disk-shaft",
    "collar-on-spinning-shaft",
    "five-link-chain",
    "torque-free-body",
];

fn read(path: &std::path::Path) -> Value {
    let text = std::fs::read_to_string(path).expect("problem file is readable");
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn stem(path: &std::path::Path) -> String {
    path.file_stem()
        .expect("file name")
        .to_string_lossy()
        .into_owned()
}

#[test]
fn every_problem_checks() {
    for path in all_problems() {
        let out = run(&["check".as_ref(), path.as_os_str()]);
        assert!(
            out.status.success(),
            "check {} failed:\n{}{}",
            path.display(),
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// The four methods form different equations (different free bodies, unknowns and
/// directions), so agreement between them is a real check on each.
#[test]
fn the_methods_agree_on_every_problem() {
    for path in all_problems() {
        let name = stem(&path);
        let first = solve(&name, METHODS[0], &[]);
        for method in &METHODS[1..] {
            let other = solve(&name, method, &[]);
            assert_eq!(
                other.json["method"].as_str(),
                Some(*method),
                "{name}: the answer names its method"
            );
            let accelerations = first.json["accelerations"]
                .as_object()
                .expect("accelerations");
            for q in accelerations.keys() {
                let scale = accelerations
                    .values()
                    .filter_map(Value::as_f64)
                    .fold(1.0, |a: f64, b| a.max(b.abs()));
                assert_close(
                    other.acc(q),
                    first.acc(q),
                    1e-9,
                    scale,
                    &format!("{name}: {q}'' by {method}"),
                );
            }
            for joint in first.json["reactions"]
                .as_object()
                .into_iter()
                .flat_map(|r| r.keys())
            {
                for (a, b, what) in [
                    (other.force(joint), first.force(joint), "force"),
                    (other.moment(joint), first.moment(joint), "moment"),
                ] {
                    let scale = a.iter().chain(&b).fold(1e-6, |s: f64, x| s.max(x.abs()));
                    for i in 0..3 {
                        assert_close(
                            a[i],
                            b[i],
                            1e-9,
                            scale,
                            &format!("{name}: {joint}.{what}[{i}] by {method}"),
                        );
                    }
                }
            }
        }
    }
}

/// The library is meant to teach every part of the format: every joint type, every load
/// type, `reaction_on`, points, requested reactions, simulation settings, and constants
/// and coordinates documented with units and descriptions.
#[test]
fn the_library_uses_every_joint_and_load_type() {
    let mut joints = BTreeSet::new();
    let mut loads = BTreeSet::new();
    let (mut points, mut reactions, mut simulate, mut reaction_on) = (false, false, false, false);
    for name in LIBRARY {
        let p = read(&problem(name));
        let title = p["title"].as_str().expect("title");
        assert!(!title.contains('\n'), "{name}: the title is one line");
        assert!(
            p["statement"].as_str().is_some_and(|s| s.len() > 100),
            "{name}: a full statement"
        );
        for (c, v) in p["constants"].as_object().into_iter().flatten() {
            assert!(
                v["unit"].is_string() && v["description"].is_string(),
                "{name}: constant {c} documented"
            );
        }
        for (c, v) in p["coordinates"].as_object().into_iter().flatten() {
            assert!(
                v["unit"].is_string() && v["description"].is_string(),
                "{name}: coordinate {c} documented"
            );
        }
        for j in p["joints"].as_array().expect("joints") {
            joints.insert(j["type"].as_str().expect("joint type").to_string());
        }
        for l in p["loads"].as_array().into_iter().flatten() {
            loads.insert(l["type"].as_str().expect("load type").to_string());
            reaction_on |= l.get("reaction_on").is_some();
        }
        points |= p.get("points").is_some();
        reactions |= p["find"]["reactions"]
            .as_array()
            .is_some_and(|r| !r.is_empty());
        simulate |= p.get("simulate").is_some();
    }
    let want = |names: &[&str]| names.iter().map(|s| s.to_string()).collect::<BTreeSet<_>>();
    let joint_types = want(&[
        "revolute",
        "prismatic",
        "cylindrical",
        "planar",
        "universal",
        "spherical",
        "free",
        "weld",
    ]);
    let load_types = want(&[
        "force",
        "torque",
        "spring",
        "damper",
        "joint_spring",
        "joint_damper",
        "joint_actuator",
    ]);
    assert_eq!(joints, joint_types);
    assert_eq!(loads, load_types);
    assert!(points && reactions && simulate && reaction_on);
}

/// Solves `a x = b` by Gaussian elimination with partial pivoting (the small systems of
/// the hand derivations: mass matrices of two to six coordinates).
pub(crate) fn solve_linear(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .expect("rows");
        a.swap(col, pivot);
        b.swap(col, pivot);
        let (upper, lower) = a.split_at_mut(col + 1);
        let pivot_row = &upper[col];
        for (i, row) in lower.iter_mut().enumerate() {
            let f = row[col] / pivot_row[col];
            for (x, p) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            b[col + 1 + i] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x
}

/// Small 3-vector and rotation helpers for the hand derivations of the spatial problems.
pub(crate) mod v3 {
    pub type V = [f64; 3];
    pub type M = [[f64; 3]; 3];

    pub fn cross(a: V, b: V) -> V {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }

    pub fn dot(a: V, b: V) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    pub fn add(a: V, b: V) -> V {
        [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
    }

    pub fn scale(k: f64, a: V) -> V {
        [k * a[0], k * a[1], k * a[2]]
    }

    pub fn mul(m: M, v: V) -> V {
        [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
    }

    pub fn transpose(m: M) -> M {
        [
            [m[0][0], m[1][0], m[2][0]],
            [m[0][1], m[1][1], m[2][1]],
            [m[0][2], m[1][2], m[2][2]],
        ]
    }

    pub fn matmul(a: M, b: M) -> M {
        let bt = transpose(b);
        [0, 1, 2].map(|i| [0, 1, 2].map(|j| dot(a[i], bt[j])))
    }

    /// The rotation by `angle` about the unit vector x (0), y (1) or z (2): its columns are
    /// the rotated frame's unit vectors in the original frame.
    pub fn rot(axis: usize, angle: f64) -> M {
        let (s, c) = angle.sin_cos();
        match axis {
            0 => [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]],
            1 => [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]],
            _ => [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]],
        }
    }

    /// The unit vector `axis` of the standard basis.
    pub fn e(axis: usize) -> V {
        let mut v = [0.0; 3];
        v[axis] = 1.0;
        v
    }
}
