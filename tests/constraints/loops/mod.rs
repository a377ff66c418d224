//! Closed loops: the four-bar linkage and the slider-crank, driven at a constant speed and
//! free with a flywheel and a gas force.

use super::{largest, state, turn};
use crate::support::{assert_close, column, run, simulate, solve_all, METHODS};
use nalgebra::{DMatrix, DVector, Matrix2, Vector2};

const G: f64 = 9.81;

fn e(angle: f64) -> [f64; 2] {
    [angle.cos(), angle.sin()]
}

fn e_perp(angle: f64) -> [f64; 2] {
    [-angle.sin(), angle.cos()]
}

/// `sum of k_i v_i` for plane vectors.
fn comb(terms: &[(f64, [f64; 2])]) -> [f64; 2] {
    terms.iter().fold([0.0, 0.0], |acc, (k, v)| {
        [acc[0] + k * v[0], acc[1] + k * v[1]]
    })
}

// ---------------------------------------------------------------------------------------
// The four-bar linkage by Lagrange multipliers in absolute angles.

/// problems/four-bar.json: crank A (O at N.o), coupler B, rocker C (Q at d N.x), uniform
/// bars of mass m; the loop closes where B's tip meets C's tip (closure R, parent B).
const A: f64 = 0.1;
const B: f64 = 0.3;
const C: f64 = 0.25;
const D: f64 = 0.3;
const M: f64 = 1.0;

/// The four-bar at absolute angles phi = (q1, q1 + q2, q3).
struct FourBar {
    phi: [f64; 3],
    phi_d: [f64; 3],
    phi_dd: [f64; 3],
    /// The force of N on A at O, in N's unit vectors.
    force_o: [f64; 2],
    /// The force of B on C at R, in B's unit vectors.
    force_r: [f64; 2],
}

/// Closes the loop from the starting guesses (Newton on the two closure equations),
/// solves the rates from the velocity constraint, then
///   M(phi) phi'' + h = Q + J^T lambda,   J phi'' = -J' phi',
/// with the constraint Phi = (B's tip) - (C's tip), so lambda is the force of C on B.
fn four_bar(q1: f64, q1_d: f64, guess_q2: f64, guess_q3: f64) -> FourBar {
    let (p1, mut p2, mut p3) = (q1, q1 + guess_q2, guess_q3);
    for _ in 0..60 {
        let f = comb(&[(A, e(p1)), (B, e(p2)), (-C, e(p3)), (-D, [1.0, 0.0])]);
        let (u, v) = (e_perp(p2), e_perp(p3));
        let jac = Matrix2::new(B * u[0], -C * v[0], B * u[1], -C * v[1]);
        let step = jac.lu().solve(&Vector2::new(f[0], f[1])).expect("regular");
        p2 -= step[0];
        p3 -= step[1];
    }
    let phi = [p1, p2, p3];
    let jac = DMatrix::from_fn(2, 3, |i, j| {
        let (k, angle) = [(A, p1), (B, p2), (-C, p3)][j];
        k * e_perp(angle)[i]
    });
    // Rates: the dependent columns times (phi2', phi3') = -(first column) q1'.
    let dep = Matrix2::new(jac[(0, 1)], jac[(0, 2)], jac[(1, 1)], jac[(1, 2)]);
    let rates = dep
        .lu()
        .solve(&Vector2::new(-jac[(0, 0)] * q1_d, -jac[(1, 0)] * q1_d))
        .expect("regular");
    let phi_d = [q1_d, rates[0], rates[1]];

    let k = M * A * B / 2.0;
    let s12 = (p1 - p2).sin();
    let mass = DMatrix::from_row_slice(
        3,
        3,
        &[
            M * A * A / 3.0 + M * A * A,
            k * (p1 - p2).cos(),
            0.0,
            k * (p1 - p2).cos(),
            M * B * B / 3.0,
            0.0,
            0.0,
            0.0,
            M * C * C / 3.0,
        ],
    );
    let h = [k * s12 * phi_d[1].powi(2), -k * s12 * phi_d[0].powi(2), 0.0];
    let q = [
        -M * G * 1.5 * A * p1.cos(),
        -M * G * B / 2.0 * p2.cos(),
        -M * G * C / 2.0 * p3.cos(),
    ];
    let gamma = comb(&[
        (A * phi_d[0].powi(2), e(p1)),
        (B * phi_d[1].powi(2), e(p2)),
        (-C * phi_d[2].powi(2), e(p3)),
    ]);
    let mut system = DMatrix::zeros(5, 5);
    let mut rhs = DVector::zeros(5);
    for i in 0..3 {
        for j in 0..3 {
            system[(i, j)] = mass[(i, j)];
        }
        for r in 0..2 {
            system[(i, 3 + r)] = -jac[(r, i)];
            system[(3 + r, i)] = jac[(r, i)];
        }
        rhs[i] = q[i] - h[i];
    }
    rhs[3] = gamma[0];
    rhs[4] = gamma[1];
    let x = system.lu().solve(&rhs).expect("regular");
    let phi_dd = [x[0], x[1], x[2]];
    let lambda = [x[3], x[4]];
    let a_a = comb(&[
        (A / 2.0 * phi_dd[0], e_perp(p1)),
        (-A / 2.0 * phi_d[0].powi(2), e(p1)),
    ]);
    let a_b = comb(&[
        (A * phi_dd[0], e_perp(p1)),
        (-A * phi_d[0].powi(2), e(p1)),
        (B / 2.0 * phi_dd[1], e_perp(p2)),
        (-B / 2.0 * phi_d[1].powi(2), e(p2)),
    ]);
    // B: F_P + lambda - m g N.y = m a_B;  A: F_O - F_P - m g N.y = m a_A.
    let force_p = comb(&[(M, a_b), (M * G, [0.0, 1.0]), (-1.0, lambda)]);
    let force_o = comb(&[(M, a_a), (M * G, [0.0, 1.0]), (1.0, force_p)]);
    FourBar {
        phi,
        phi_d,
        phi_dd,
        force_o,
        force_r: turn(-p2, [-lambda[0], -lambda[1]]),
    }
}

fn check_four_bar(q1: f64, q1_d: f64, extra: &[&str]) {
    let want = four_bar(q1, q1_d, -0.65, 1.6);
    let q2 = want.phi[1] - want.phi[0];
    let acc = [
        want.phi_dd[0],
        want.phi_dd[1] - want.phi_dd[0],
        want.phi_dd[2],
    ];
    let acc_scale = largest(acc.iter().copied());
    for s in solve_all("four-bar", extra) {
        let what = |w: &str| format!("{} at q1 = {q1}, q1' = {q1_d}: {w}", s.method);
        let st = &s.json["state"];
        let got = |k: &str| st[k].as_f64().unwrap_or_else(|| panic!("{}", what(k)));
        assert_close(got("q2"), q2, 1e-9, 1.0, &what("q2"));
        assert_close(got("q3"), want.phi[2], 1e-9, 1.0, &what("q3"));
        let rate_scale = q1_d.abs().max(1.0);
        let q2_d = want.phi_d[1] - want.phi_d[0];
        assert_close(got("q2'"), q2_d, 1e-9, rate_scale, &what("q2'"));
        assert_close(got("q3'"), want.phi_d[2], 1e-9, rate_scale, &what("q3'"));
        for (k, q) in ["q1", "q2", "q3"].iter().enumerate() {
            assert_close(s.acc(q), acc[k], 1e-9, acc_scale, &what(&format!("{q}''")));
        }
        for k in 0..2 {
            assert_close(
                s.force("O")[k],
                want.force_o[k],
                1e-9,
                M * G,
                &what(&format!("O force[{k}]")),
            );
            assert_close(
                s.force("R")[k],
                want.force_r[k],
                1e-9,
                M * G,
                &what(&format!("R force[{k}]")),
            );
        }
        for k in 0..3 {
            assert_close(s.moment("O")[k], 0.0, 1e-12, M * G, &what("O moment"));
            assert_close(s.moment("R")[k], 0.0, 1e-12, M * G, &what("R moment"));
        }
    }
}

mod four_bar;
mod slider_crank;
