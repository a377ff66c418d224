//! The linear solve every evaluation ends in: LU with partial pivoting.

use nalgebra::{DMatrix, DVector};

/// Solves `a x = b` by LU with partial pivoting; `None` when `a` is singular to working precision.
pub fn solve_linear(a: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    solve_linear_owned(a.clone(), b.clone())
}

/// As [`solve_linear`], factoring `a` in place and solving into `b`: no copies.
pub fn solve_linear_owned(a: DMatrix<f64>, b: DVector<f64>) -> Option<DVector<f64>> {
    let n = a.nrows() as f64;
    let lu = a.lu();
    // The diagonal of the packed factors is U's (L's is ones and not stored).
    let diagonal = lu.lu_internal().diagonal();
    let largest = diagonal.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let smallest = diagonal.iter().fold(f64::INFINITY, |m, x| m.min(x.abs()));
    if largest.is_nan() || largest <= 0.0 || smallest <= 1e-13 * largest * n {
        return None;
    }
    let mut x = b;
    lu.solve_mut(&mut x).then_some(x)
}
