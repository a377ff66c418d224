//! A linearization over a range of one constant (`linearize --sweep`), and where between
//! the values tried the stability changes, by bisection.

use super::Linearizer;
use crate::error::Error;
use crate::numeric::{is_stable, Linearization, ROUND_OFF};
use crate::problem::Problem;

/// `--sweep NAME=FROM:TO:COUNT`, parsed.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// The constant.
    pub name: String,
    /// Its values, first `FROM`, last `TO`.
    pub values: Vec<f64>,
}

/// The linearizations of a sweep, one per value, and where stability changes.
#[derive(Clone, Debug)]
pub struct Swept {
    /// One per value of the sweep, in order.
    pub results: Vec<Linearization>,
    /// Each value of the constant between two values tried where stability changes, and
    /// whether the system is stable beyond it.
    pub edges: Vec<(f64, bool)>,
}

/// The state a linearization is taken at, for a problem with the swept constant set:
/// coordinates and rates.
pub type StateOf<'a> = &'a dyn Fn(&Problem) -> Result<(Vec<f64>, Vec<f64>), Error>;

/// Linearizes `problem` at time `t` and the state `state_of` gives, for each value of
/// `sweep`, and bisects every change of stability between two neighbouring values.
///
/// # Errors
/// A value the problem rejects, a singular system, or eigenvalues that do not converge.
pub fn sweep(
    problem: &Problem,
    linearizer: &Linearizer,
    sweep: &Sweep,
    t: f64,
    state_of: StateOf<'_>,
) -> Result<Swept, Error> {
    let at = |value: f64| -> Result<Linearization, Error> {
        let mut swept = problem.clone();
        crate::problem::apply_overrides(&mut swept, &[(sweep.name.clone(), value)])?;
        let (q, rates) = state_of(&swept)?;
        linearizer.at(&swept, t, &q, &rates)
    };
    let results = sweep
        .values
        .iter()
        .map(|&value| at(value))
        .collect::<Result<Vec<_>, Error>>()?;
    let stable: Vec<bool> = results.iter().map(|l| is_stable(&l.eigen, 0.0)).collect();
    let mut edges = Vec::new();
    for i in 1..results.len() {
        if stable[i] != stable[i - 1] {
            let (a, b) = (sweep.values[i - 1], sweep.values[i]);
            edges.push((boundary(&at, a, b)?, stable[i]));
        }
    }
    Ok(Swept { results, edges })
}

/// Where stability changes between `a` and `b` (whose stability differs), by bisection on
/// the largest real part of the eigenvalues that are not structural zeros (those of
/// ignorable coordinates, counted where the bracket's ends agree).
fn boundary(
    at: &dyn Fn(f64) -> Result<Linearization, Error>,
    a: f64,
    b: f64,
) -> Result<f64, Error> {
    let raw = |value: f64| -> Result<Vec<nalgebra::Complex<f64>>, Error> {
        let l = at(value)?;
        let a = without_ignorable(&l.a);
        let mut values = crate::numeric::eigenvalues(&a).unwrap_or_default();
        values.sort_by(|x, y| x.norm().total_cmp(&y.norm()));
        Ok(values)
    };
    let zeros = |values: &[nalgebra::Complex<f64>]| -> usize {
        let scale = values.iter().map(|v| v.norm()).fold(0.0, f64::max);
        values
            .iter()
            .filter(|v| v.norm() <= ROUND_OFF * scale)
            .count()
    };
    let (low, high) = (raw(a)?, raw(b)?);
    let structural = zeros(&low).min(zeros(&high));
    let largest = |values: &[nalgebra::Complex<f64>]| -> f64 {
        values
            .iter()
            .skip(structural)
            .map(|v| v.re)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (mut a, mut b) = (a, b);
    let sign_a = largest(&low) > 0.0;
    for _ in 0..60 {
        let middle = 0.5 * (a + b);
        if (b - a).abs() <= 1e-13 * middle.abs().max(1.0) {
            break;
        }
        if (largest(&raw(middle)?) > 0.0) == sign_a {
            a = middle;
        } else {
            b = middle;
        }
    }
    Ok(0.5 * (a + b))
}

/// `a` without the rows and columns of the states nothing depends on (zero columns, such
/// as a bicycle's position and heading), repeated until none is left. Expanding the
/// determinant along such a column, each removal takes away one eigenvalue 0 and keeps the
/// others exactly; left in, these zeros form Jordan blocks whose round-off of 1e-16 moves
/// them by 1e-8, enough to blur a slow mode's crossing of zero.
fn without_ignorable(a: &nalgebra::DMatrix<f64>) -> nalgebra::DMatrix<f64> {
    let mut a = a.clone();
    let scale = a.amax();
    while let Some(i) =
        (0..a.ncols()).find(|&i| a.column(i).iter().all(|x| x.abs() <= 1e-14 * scale))
    {
        if a.ncols() == 1 {
            break;
        }
        a = a.remove_row(i).remove_column(i);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ignorable_states_go_and_the_slow_mode_stays_exact() {
        // x' = ψ (a heading that moves the position), ψ' = 0, and a slow mode s' = 1e-9 s:
        // x's column is zero, then ψ's; what is left is the slow mode alone, exactly.
        let a = nalgebra::DMatrix::from_row_slice(
            3,
            3,
            &[0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1e-9],
        );
        let reduced = without_ignorable(&a);
        assert_eq!(reduced, nalgebra::DMatrix::from_element(1, 1, 1e-9));
        // Nothing to take away from a matrix without a zero column.
        let full = nalgebra::DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -1.0, 0.0]);
        assert_eq!(without_ignorable(&full), full);
    }
}
