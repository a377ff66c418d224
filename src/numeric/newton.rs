//! Newton's method for `f(u) = 0` (Gauss-Newton where `f` has more components than `u`):
//! central-difference Jacobians, a least-squares step, and a halving line search. The
//! `steady` question's unknowns and the equilibria of `statics` are both found with it.

use nalgebra::{DMatrix, DVector};

/// The most Newton iterations.
pub const MAX_ITERATIONS: usize = 100;

/// Why no root was found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NewtonFailure {
    /// `f` could not be evaluated at the start or while forming a Jacobian.
    NotSolvable,
    /// The iteration stalled or ran out of iterations with `left` the largest |f|.
    NoRoot {
        /// The largest |f| left.
        left: f64,
        /// The iterations made.
        iterations: usize,
    },
}

/// A root: the unknowns, the largest |f| left, and the iterations taken.
#[derive(Clone, Debug, PartialEq)]
pub struct Root {
    pub u: DVector<f64>,
    pub left: f64,
    pub iterations: usize,
}

/// Newton's method from `u`, to |f| ≤ 1e-10 times the larger of 1 and |f(u)| at the start
/// (accepting 1e-7 where no step lowers |f| any more: a root reached to rounding).
///
/// # Errors
/// [`NewtonFailure`] when `f` cannot be evaluated or no root is reached.
pub fn solve(
    f: impl Fn(&DVector<f64>) -> Option<DVector<f64>>,
    mut u: DVector<f64>,
) -> Result<Root, NewtonFailure> {
    let mut r = f(&u).ok_or(NewtonFailure::NotSolvable)?;
    let scale = r.amax().max(1.0);
    let tolerance = 1e-10 * scale;
    let mut iterations = 0;
    let no_root = |r: &DVector<f64>, iterations| NewtonFailure::NoRoot {
        left: r.amax(),
        iterations,
    };
    while r.amax() > tolerance {
        if iterations == MAX_ITERATIONS {
            return Err(no_root(&r, iterations));
        }
        iterations += 1;
        let mut jacobian = DMatrix::zeros(r.len(), u.len());
        for k in 0..u.len() {
            let h = 1e-6 * u[k].abs().max(1.0);
            let (mut up, mut down) = (u.clone(), u.clone());
            up[k] += h;
            down[k] -= h;
            let (Some(rp), Some(rd)) = (f(&up), f(&down)) else {
                return Err(NewtonFailure::NotSolvable);
            };
            jacobian.set_column(k, &((rp - rd) / (2.0 * h)));
        }
        let step = jacobian
            .svd(true, true)
            .solve(&(-&r), 1e-14 * scale)
            .map_err(|_| no_root(&r, iterations))?;
        // Halve the step until the residual decreases.
        let mut lambda = 1.0;
        let mut accepted = None;
        for _ in 0..30 {
            let trial = &u + &step * lambda;
            if let Some(rt) = f(&trial) {
                if rt.norm() < r.norm() {
                    accepted = Some((trial, rt));
                    break;
                }
            }
            lambda /= 2.0;
        }
        let Some((next, rn)) = accepted else {
            // No decrease: a root is reached to rounding, or there is none near.
            if r.amax() <= 1e-7 * scale {
                break;
            }
            return Err(no_root(&r, iterations));
        };
        u = next;
        r = rn;
    }
    Ok(Root {
        u,
        left: r.amax(),
        iterations,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_root_of_two() {
        let f = |u: &DVector<f64>| Some(DVector::from_vec(vec![u[0] * u[0] - 2.0]));
        let root = solve(f, DVector::from_vec(vec![1.0])).unwrap();
        assert!((root.u[0] - 2f64.sqrt()).abs() < 1e-10);
    }

    #[test]
    fn no_real_root_is_reported() {
        let f = |u: &DVector<f64>| Some(DVector::from_vec(vec![u[0] * u[0] + 1.0]));
        assert!(matches!(
            solve(f, DVector::from_vec(vec![0.5])),
            Err(NewtonFailure::NoRoot { .. })
        ));
    }
}
