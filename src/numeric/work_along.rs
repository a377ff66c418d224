//! The work of a power along a simulated run, for the energy balances: the state between
//! two rows from the quintic through both rows' `q, q', q''`, the power integrated over each
//! step by three-point Gauss–Legendre, so the work is as accurate as the run's rows.

use super::simulate::Trajectory;

/// The work of `power(t, state)` from the first row to each row, where `state` holds each
/// coordinate's `(q, q')` and `columns` each coordinate's `[q, q', q'']` columns of the
/// rows. `None` where the power cannot be evaluated somewhere along the run.
pub(super) fn work_along(
    rows: &[Vec<f64>],
    columns: &[[usize; 3]],
    mut power: impl FnMut(f64, &[(f64, f64)]) -> Option<f64>,
) -> Option<Vec<f64>> {
    let mut work = vec![0.0; rows.len()];
    for i in 1..rows.len() {
        let (before, after) = (&rows[i - 1], &rows[i]);
        let h = after[0] - before[0];
        let mut interval = 0.0;
        for (s, weight) in GAUSS_LEGENDRE_3 {
            let at = |row: &[f64], c: &[usize; 3]| [row[c[0]], row[c[1]], row[c[2]]];
            let state: Vec<(f64, f64)> = (columns.iter())
                .map(|c| hermite(at(before, c), at(after, c), h, s))
                .collect();
            interval += weight * power(before[0] + s * h, &state)?;
        }
        work[i] = work[i - 1] + h * interval;
    }
    Some(work)
}

/// What the balance `E(t) = E(0) + W(t)` leaves along a run: the largest `|E(t) − E(0) −
/// W(t)|`, the time it is reached, and the energy scale it is judged against (the larger
/// of the kinetic energy and the work).
pub(super) struct Imbalance {
    pub worst: f64,
    pub at: f64,
    pub scale: f64,
}

impl Imbalance {
    /// The imbalance of `trajectory`'s total energy with `work`, one value per row; `None`
    /// where the run has no energy columns.
    pub fn of(trajectory: &Trajectory, work: &[f64]) -> Option<Self> {
        let rows = &trajectory.rows;
        let total = trajectory.column("total")?;
        let kinetic = trajectory.column("kinetic")?;
        let first = rows.first()?[total];
        let (mut worst, mut at) = (0.0f64, 0.0);
        for (row, w) in rows.iter().zip(work) {
            let error = (row[total] - first - w).abs();
            if error > worst || error.is_nan() {
                (worst, at) = (error, row[0]);
            }
        }
        let scale = (rows.iter().map(|r| r[kinetic].abs()))
            .chain(work.iter().map(|w| w.abs()))
            .fold(0.0f64, f64::max)
            .max(f64::MIN_POSITIVE);
        Some(Self { worst, at, scale })
    }
}

/// Three-point Gauss–Legendre on [0, 1]: (node, weight), exact for polynomials of degree 5.
const GAUSS_LEGENDRE_3: [(f64, f64); 3] = [
    (0.112_701_665_379_258_3, 5.0 / 18.0),
    (0.5, 8.0 / 18.0),
    (0.887_298_334_620_741_7, 5.0 / 18.0),
];

/// The quintic through a coordinate's `[q, q', q'']` at both ends of a step of `h` seconds,
/// at the fraction `s` of the step: its value and its rate.
fn hermite(start: [f64; 3], end: [f64; 3], h: f64, s: f64) -> (f64, f64) {
    let (s2, s3, s4, s5) = (s * s, s * s * s, s.powi(4), s.powi(5));
    let value = [
        1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5,
        s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5,
        0.5 * (s2 - 3.0 * s3 + 3.0 * s4 - s5),
        10.0 * s3 - 15.0 * s4 + 6.0 * s5,
        -4.0 * s3 + 7.0 * s4 - 3.0 * s5,
        0.5 * (s3 - 2.0 * s4 + s5),
    ];
    let slope = [
        -30.0 * s2 + 60.0 * s3 - 30.0 * s4,
        1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4,
        0.5 * (2.0 * s - 9.0 * s2 + 12.0 * s3 - 5.0 * s4),
        30.0 * s2 - 60.0 * s3 + 30.0 * s4,
        -12.0 * s2 + 28.0 * s3 - 15.0 * s4,
        0.5 * (3.0 * s2 - 8.0 * s3 + 5.0 * s4),
    ];
    let data = [
        start[0],
        h * start[1],
        h * h * start[2],
        end[0],
        h * end[1],
        h * h * end[2],
    ];
    let dot = |basis: [f64; 6]| basis.iter().zip(&data).map(|(b, d)| b * d).sum::<f64>();
    (dot(value), dot(slope) / h)
}

#[cfg(test)]
mod tests {
    use super::{hermite, GAUSS_LEGENDRE_3};

    #[test]
    fn the_quintic_through_the_ends_is_exact_for_a_quintic() {
        // p(t) = t^5 - 2 t^2 + 1 on [0.3, 0.8]
        let p = |t: f64| {
            [
                t.powi(5) - 2.0 * t * t + 1.0,
                5.0 * t.powi(4) - 4.0 * t,
                20.0 * t.powi(3) - 4.0,
            ]
        };
        let (t0, t1) = (0.3, 0.8);
        for s in [0.0, 0.25, 0.6, 1.0] {
            let t = t0 + s * (t1 - t0);
            let (value, rate) = hermite(p(t0), p(t1), t1 - t0, s);
            assert!((value - p(t)[0]).abs() < 1e-13, "value at {t}");
            assert!((rate - p(t)[1]).abs() < 1e-12, "rate at {t}");
        }
    }

    #[test]
    fn gauss_legendre_integrates_a_quintic_exactly() {
        // ∫₀¹ (6 s^5 + s^2) ds = 1 + 1/3
        let integral: f64 = GAUSS_LEGENDRE_3
            .iter()
            .map(|(s, w)| w * (6.0 * s.powi(5) + s * s))
            .sum();
        assert!((integral - 4.0 / 3.0).abs() < 1e-14);
    }
}
