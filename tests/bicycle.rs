//! The Whipple bicycle of `problems/validation/whipple-bicycle.json` against the linearized equations
//! published by Meijaard, Papadopoulos, Ruina and Schwab (2007), "Linearized dynamics
//! equations for the balance and steer of a bicycle: a benchmark and review", Proc. R. Soc.
//! A 463, 1955–1982, its benchmark values: M q'' + v C1 q' + (g K0 + v² K2) q = 0 for
//! q = (roll φ, steer δ). The tool has no linearization here: the nonlinear roll and steer
//! accelerations are differenced about the upright straight run, at constant rear wheel
//! rate θR' = −v/rR, and compared with the paper's −M⁻¹(v C1 q' + (g K0 + v² K2) q).

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{Compiled, System};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::load_file;
use nalgebra::{Matrix2, Vector2};

const G: f64 = 9.81;
const REAR_RADIUS: f64 = 0.3;

/// The paper's benchmark matrices, to the digits it prints.
fn published() -> (Matrix2<f64>, Matrix2<f64>, Matrix2<f64>, Matrix2<f64>) {
    let m = Matrix2::new(
        80.81722,
        2.31941332208709,
        2.31941332208709,
        0.29784188199686,
    );
    let c1 = Matrix2::new(0.0, 33.86641391492494, -0.85035641456978, 1.68540397397560);
    let k0 = Matrix2::new(
        -80.95,
        -2.59951685249872,
        -2.59951685249872,
        -0.80329488458618,
    );
    let k2 = Matrix2::new(0.0, 76.59734589573222, 0.0, 2.65431523794604);
    (m, c1, k0, k2)
}

/// The paper's (φ'', δ'') derivatives at speed v: with respect to (φ, δ) and to (φ', δ').
fn published_jacobians(v: f64) -> (Matrix2<f64>, Matrix2<f64>) {
    let (m, c1, k0, k2) = published();
    let m_inv = m.try_inverse().expect("M is invertible");
    (-m_inv * (G * k0 + v * v * k2), -m_inv * (v * c1))
}

/// The state matrix's eigenvalues' largest real part, for the stability speeds.
fn largest_real_part(v: f64) -> f64 {
    let (kq, kr) = published_jacobians(v);
    let mut a = nalgebra::Matrix4::<f64>::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    a.fixed_view_mut::<2, 2>(2, 0).copy_from(&kq);
    a.fixed_view_mut::<2, 2>(2, 2).copy_from(&kr);
    a.complex_eigenvalues()
        .iter()
        .map(|l| l.re)
        .fold(f64::NEG_INFINITY, f64::max)
}

/// The copy of the matrices above is checked against the paper's weave and capsize speeds,
/// 4.29238253634111 and 6.02426201538837 m/s: the straight run is stable between them.
#[test]
fn the_published_matrices_give_the_published_stability_speeds() {
    let weave = 4.29238253634111;
    let capsize = 6.02426201538837;
    assert!(largest_real_part(weave - 1e-6) > 0.0);
    assert!(largest_real_part(weave + 1e-6) < 0.0);
    assert!(largest_real_part(capsize - 1e-6) < 0.0);
    assert!(largest_real_part(capsize + 1e-6) > 0.0);
    assert!(largest_real_part(weave).abs() < 1e-8);
    assert!(largest_real_part(capsize).abs() < 1e-8);
}

struct Bicycle {
    compiled: Compiled,
    names: Vec<String>,
    initial_q: Vec<f64>,
    initial_rates: Vec<f64>,
}

impl Bicycle {
    fn new(method: Method) -> Bicycle {
        let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("problems/validation/whipple-bicycle.json");
        let problem = load_file(&path).expect("the bicycle loads");
        let derivation = derive(&problem, method, Purpose::Rows).expect("the bicycle derives");
        Bicycle {
            names: problem.coordinates.iter().map(|c| c.name.clone()).collect(),
            initial_q: problem.initial_coordinates(),
            initial_rates: problem.coordinates.iter().map(|c| c.rate).collect(),
            compiled: Compiled::new(&derivation),
        }
    }

    fn index(&self, name: &str) -> usize {
        self.names
            .iter()
            .position(|n| n == name)
            .unwrap_or_else(|| panic!("no coordinate {name}"))
    }

    /// All q'' at speed v, with `changes` (coordinate or rate, value) applied before
    /// assembly.
    fn accelerations(&self, v: f64, changes: &[(&str, f64)]) -> Vec<f64> {
        let mut q = self.initial_q.clone();
        let mut rates = self.initial_rates.clone();
        rates[self.index("thetaR")] = -v / REAR_RADIUS;
        for &(name, value) in changes {
            match name.strip_suffix('\'') {
                Some(base) => rates[self.index(base)] = value,
                None => q[self.index(name)] = value,
            }
        }
        self.compiled
            .assemble(0.0, &mut q, &mut rates)
            .expect("the bicycle assembles");
        self.compiled
            .solve(0.0, &q, &rates)
            .expect("the bicycle solves")
            .accelerations
    }
}

const SPEEDS: [f64; 3] = [2.0, 4.5, 6.0];
const EPSILON: f64 = 1e-6;

fn check_method(method: Method) {
    let bike = Bicycle::new(method);
    let (roll, steer) = (bike.index("phi"), bike.index("delta"));
    for v in SPEEDS {
        // The straight upright run is a steady motion: nothing accelerates.
        let steady = bike.accelerations(v, &[]);
        for (name, a) in bike.names.iter().zip(&steady) {
            assert!(
                a.abs() < 1e-9,
                "{}, v = {v}: {name}'' = {a:e} in the steady run",
                method.name()
            );
        }
        let (kq, kr) = published_jacobians(v);
        for (column, variable) in ["phi", "delta", "phi'", "delta'"].iter().enumerate() {
            let plus = bike.accelerations(v, &[(variable, EPSILON)]);
            let minus = bike.accelerations(v, &[(variable, -EPSILON)]);
            let got = Vector2::new(
                (plus[roll] - minus[roll]) / (2.0 * EPSILON),
                (plus[steer] - minus[steer]) / (2.0 * EPSILON),
            );
            let want = if column < 2 {
                kq.column(column).into_owned()
            } else {
                kr.column(column - 2).into_owned()
            };
            let error = (got - want).norm() / want.norm();
            eprintln!(
                "{}, v = {v}, d/d{variable}: got [{:.10}, {:.10}], published [{:.10}, {:.10}], relative {error:.1e}",
                method.name(), got[0], got[1], want[0], want[1]
            );
            assert!(
                error < 1e-6,
                "{}, v = {v}: d(phi'', delta'')/d{variable} = {got:?}, published {want:?} (relative error {error:e})",
                method.name()
            );
        }
    }
}

#[test]
fn kane_matches_the_published_linear_model() {
    check_method(Method::Kane);
}

#[test]
fn newton_euler_matches_the_published_linear_model() {
    check_method(Method::NewtonEuler);
}

#[test]
fn the_motion_law_matches_the_published_linear_model() {
    check_method(Method::MotionLaw);
}

/// `linearize --sweep` over the speed finds the benchmark's weave and capsize speeds, where
/// the straight run becomes stable and unstable again (Meijaard et al. 2007, Table 2):
/// the exact Jacobians of the nonlinear model, reduced through the rolling constraints.
#[test]
fn linearize_finds_the_weave_and_capsize_speeds() {
    let path = crate::support::problem("validation/whipple-bicycle");
    let out = crate::support::run(&[
        "linearize".as_ref(),
        path.as_os_str(),
        "--method".as_ref(),
        "kane".as_ref(),
        "--sweep".as_ref(),
        "v=4:6.5:6".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let speed = |prefix: &str| -> f64 {
        let line = text
            .lines()
            .find(|l| l.starts_with(prefix))
            .unwrap_or_else(|| panic!("no line `{prefix}` in:\n{text}"));
        line[prefix.len()..]
            .split_whitespace()
            .next()
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("no number in `{line}`"))
    };
    let weave = speed("stable from v = ");
    let capsize = speed("unstable from v = ");
    assert!(
        (weave - 4.29238253634111).abs() < 1e-10,
        "weave speed {weave}"
    );
    assert!(
        (capsize - 6.02426201538837).abs() < 1e-10,
        "capsize speed {capsize}"
    );
}

/// The statement's questions, answered by `answer`: each disturbed state's roll and steer
/// accelerations against the paper's linear equations, to the order of the disturbance
/// squared (a lean of 10⁻³ rad) or to rounding (a roll rate, which enters linearly here).
#[test]
fn the_answers_match_the_published_linear_equations() {
    let out = crate::support::run_json(&[
        "answer",
        "problems/validation/whipple-bicycle.json",
        "--format",
        "json",
    ]);
    let answers = out["answers"].as_array().expect("answers");
    // Four accelerations, then the weave and capsize speeds (tests/course_answers.rs).
    assert_eq!(answers.len(), 5);
    assert_eq!(answers[4]["kind"], "stability");
    let v = 5.0;
    let (kq, kr) = published_jacobians(v);
    let lean = kq * Vector2::new(1e-3, 0.0);
    let roll_rate = kr * Vector2::new(1e-3, 0.0);
    let expected = [lean[0], lean[1], roll_rate[0], roll_rate[1]];
    for (answer, (want, tolerance)) in answers
        .iter()
        .zip(expected.iter().zip([1e-8, 1e-8, 1e-12, 1e-12]))
    {
        let found = answer["value"].as_f64().expect("value");
        assert!(
            (found - want).abs() <= tolerance,
            "{}: {found} against the paper's {want}",
            answer["text"]
        );
    }
}
