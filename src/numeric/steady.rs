//! Steady motions: Newton's method for the coordinates and rates that make chosen
//! expressions (by default every second derivative) vanish, the rest of the state held.

use super::system::System;
use crate::problem::Problem;
use crate::symbolic::{eval, Expr, Symbol, Values};
use nalgebra::DVector;

/// Why no steady motion was found, and a hint.
pub(super) type Failure = (String, &'static str);

/// The values of the `zero` expressions at the state with `unknowns` set to `u`.
fn residual(
    problem: &Problem,
    system: &dyn System,
    t: f64,
    (q, rates): (&[f64], &[f64]),
    unknowns: &[crate::problem::StateEntry],
    zero: &[(Expr, String)],
    u: &DVector<f64>,
) -> Option<DVector<f64>> {
    let (mut q, mut rates) = (q.to_vec(), rates.to_vec());
    for (e, &x) in unknowns.iter().zip(u.iter()) {
        let target = if e.order == 0 { &mut q } else { &mut rates };
        target[e.coordinate] = x;
    }
    system.assemble(t, &mut q, &mut rates).ok()?;
    let a = system.accelerations(t, &q, &rates).ok()?;
    let values = state_values(problem, t, &q, &rates, &a);
    let r = DVector::from_iterator(zero.len(), zero.iter().map(|(e, _)| eval(e, &values)));
    r.iter().all(|x| x.is_finite()).then_some(r)
}

/// The values of the constants, the coordinates, their rates and second rates, and `t`.
pub(super) fn state_values(
    problem: &Problem,
    t: f64,
    q: &[f64],
    rates: &[f64],
    a: &[f64],
) -> Values {
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    for (i, c) in problem.coordinates.iter().enumerate() {
        let s = |order| Symbol::Coord(c.name.as_str().into(), order);
        v.set(s(0), q[i]);
        v.set(s(1), rates[i]);
        v.set(s(2), a[i]);
    }
    v.set(Symbol::Time, t);
    v
}

/// Newton's method for the unknowns; on success `q` and `rates` hold the steady state.
pub(super) fn steady(
    problem: &Problem,
    system: &dyn System,
    t: f64,
    q: &mut [f64],
    rates: &mut [f64],
    unknowns: &[crate::problem::StateEntry],
    zero: &[(Expr, String)],
) -> Result<(f64, usize), Failure> {
    let get = |q: &[f64], rates: &[f64], e: &crate::problem::StateEntry| {
        if e.order == 0 {
            q[e.coordinate]
        } else {
            rates[e.coordinate]
        }
    };
    let u = DVector::from_iterator(unknowns.len(), unknowns.iter().map(|e| get(q, rates, e)));
    let (q0, rates0) = (q.to_vec(), rates.to_vec());
    let f = |u: &DVector<f64>| residual(problem, system, t, (&q0, &rates0), unknowns, zero, u);
    let root = super::newton::solve(f, u).map_err(|failure| match failure {
        super::newton::NewtonFailure::NotSolvable => (
            "the equations cannot be solved at the starting guess".to_string(),
            "start from another guess in `at.state`",
        ),
        super::newton::NewtonFailure::NoRoot { left, iterations } => no_root(left, iterations),
    })?;
    let (u, left, iterations) = (root.u, root.left, root.iterations);
    for (e, &x) in unknowns.iter().zip(u.iter()) {
        if e.order == 0 {
            q[e.coordinate] = x;
        } else {
            rates[e.coordinate] = x;
        }
    }
    Ok((left, iterations))
}

fn no_root(left: f64, iterations: usize) -> Failure {
    (
        format!(
            "no steady motion found: after {iterations} Newton iterations the largest of the expressions to make zero is still {}",
            crate::symbolic::fixed(left)
        ),
        "start nearer a solution in `at.state`, or check that the unknowns can make these second derivatives zero",
    )
}
