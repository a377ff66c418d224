//! The elimination a student writes to reach one equation of motion free of the reactions:
//! each of step 5's rows solved in turn for the one unknown it brings in besides those
//! already found (`F = −I_B q̈_B / r_B` from (2), `q̈_B = −(r_A/r_B) q̈_A` from (3)), and
//! what is found put into the row left, which then holds only the acceleration kept.

use crate::equations::{Derivation, LinearSystem, Method};
use crate::render::AnswerStep;
use crate::symbolic::{
    eval, latex, linear_split, roots_of_squares, simplify, Expr, Symbol, Values,
};

/// The most rows an elimination is written for: past it the working is a page.
const MOST_ROWS: usize = 5;

/// One unknown found: the row it came from, its value as solved (in the other unknowns),
/// and as a multiple of the kept acceleration plus a rest.
struct Found {
    row: usize,
    unknown: usize,
    written: Expr,
    times: Expr,
    rest: Expr,
}

/// The steps from step 5's rows to `a q̈_k = b`, the kept acceleration `keep` (an index
/// into the system's unknowns); `None` where the rows are not step 5's (Kane's,
/// Lagrange's), are too many, or no row-by-row order reaches it, or `b/a` at `v` differs
/// from `expected`.
pub fn steps(
    derivation: &Derivation,
    keep: usize,
    v: &Values,
    expected: f64,
) -> Option<(Vec<AnswerStep>, usize)> {
    if !matches!(derivation.method, Method::MotionLaw | Method::NewtonEuler) {
        return None;
    }
    let n = derivation.system.unknowns.len();
    if derivation.system.a.len() != n || derivation.rows.len() != n {
        return None;
    }
    let printed = as_printed(derivation)?;
    // The rows that only give a reaction no other row holds (a pin's force along an axis
    // no moment sees) play no part: left out, as a student leaves them.
    let (rows, columns) = needed(&printed, keep);
    if !(2..=MOST_ROWS).contains(&rows.len()) {
        return None;
    }
    let keep_in = columns.iter().position(|&j| j == keep)?;
    let system = &LinearSystem {
        unknowns: columns
            .iter()
            .map(|&j| printed.unknowns[j].clone())
            .collect(),
        a: (rows.iter())
            .map(|&i| columns.iter().map(|&j| printed.a[i][j].clone()).collect())
            .collect(),
        b: rows.iter().map(|&i| printed.b[i].clone()).collect(),
    };
    let found = order(system, keep_in)?;
    let last = (0..rows.len()).find(|i| found.iter().all(|f| f.row != *i))?;
    let (a, b) = put_in(system, &found, keep_in, last);
    let ratio = eval(&b, v) / eval(&a, v);
    if (ratio - expected).abs() > 1e-6 * expected.abs().max(1e-9) {
        return None;
    }
    let x = |j: usize| latex(&Expr::sym(system.unknowns[j].clone()));
    let steps = found
        .iter()
        .map(|f| AnswerStep {
            text: format!("Row ({}) gives ${}$:", rows[f.row] + 1, x(f.unknown)).into(),
            math: format!("{} = {}", x(f.unknown), latex(&f.written)).into(),
        })
        .collect();
    Some((steps, rows[last]))
}

/// The rows and unknowns the elimination needs: a row is left out, with its unknown, while
/// it holds an unknown (not the kept one) that no other row left holds.
fn needed(system: &LinearSystem, keep: usize) -> (Vec<usize>, Vec<usize>) {
    let n = system.unknowns.len();
    let mut rows: Vec<usize> = (0..system.a.len()).collect();
    let mut columns: Vec<usize> = (0..n).collect();
    loop {
        let alone = rows.iter().find_map(|&i| {
            (columns.iter().copied())
                .find(|&j| {
                    j != keep
                        && !system.a[i][j].is_zero()
                        && rows.iter().all(|&r| r == i || system.a[r][j].is_zero())
                })
                .map(|j| (i, j))
        });
        match alone {
            Some((i, j)) => {
                rows.retain(|&r| r != i);
                columns.retain(|&c| c != j);
            }
            None => return (rows, columns),
        }
    }
}

/// Step 5's rows as its "Simplified" prints them (roots of squares taken by the initial
/// signs, coordinates a constraint holds put in), as a linear system.
fn as_printed(derivation: &Derivation) -> Option<LinearSystem> {
    let model = &derivation.model;
    let sign = super::tex::initial_sign(model);
    let held = super::on_constraint::held_coordinates(model);
    let unknowns = derivation.system.unknowns.clone();
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for row in &derivation.rows {
        let e = roots_of_squares(&simplify(&row.expression), &sign);
        let e = super::on_constraint::on_the_constraints(&e, &held);
        let (coefficients, rest) = linear_split(&e, &unknowns).ok()?;
        a.push(coefficients.iter().map(simplify).collect());
        b.push(simplify(&-&rest));
    }
    Some(LinearSystem { unknowns, a, b })
}

/// The rows in the order a student solves them: each a row not used that brings in one
/// unknown besides the kept one and those found, an acceleration before a reaction and a
/// row without the kept acceleration first (the row that drives it is left to the end).
fn order(system: &LinearSystem, keep: usize) -> Option<Vec<Found>> {
    let n = system.unknowns.len();
    let mut found: Vec<Found> = Vec::new();
    while found.len() < n - 1 {
        let known = |j: usize| j == keep || found.iter().any(|f| f.unknown == j);
        let reaction = |j: usize| matches!(system.unknowns[j], Symbol::Unknown(_));
        let (row, unknown) = (0..n)
            .filter(|i| found.iter().all(|f| f.row != *i))
            .filter_map(|i| {
                let new: Vec<usize> = (0..n)
                    .filter(|&j| !system.a[i][j].is_zero() && !known(j))
                    .collect();
                (new.len() == 1).then(|| (i, new[0]))
            })
            .min_by_key(|&(i, j)| (reaction(j), !system.a[i][keep].is_zero(), i))?;
        let a = &system.a[row];
        let pivot = &a[unknown];
        let others: Vec<Expr> = (0..n)
            .filter(|&j| j != unknown && !a[j].is_zero())
            .map(|j| &a[j] * &Expr::sym(system.unknowns[j].clone()))
            .collect();
        let written = simplify(&(&(&system.b[row] - &crate::symbolic::add(others)) / pivot));
        let mut times = -&a[keep];
        let mut rest = system.b[row].clone();
        for f in &found {
            times = &times - &(&a[f.unknown] * &f.times);
            rest = &rest - &(&a[f.unknown] * &f.rest);
        }
        found.push(Found {
            row,
            unknown,
            written,
            times: simplify(&(&times / pivot)),
            rest: simplify(&(&rest / pivot)),
        });
    }
    Some(found)
}

/// Row `last` with every unknown found put in: `a q̈_k = b`.
fn put_in(system: &LinearSystem, found: &[Found], keep: usize, last: usize) -> (Expr, Expr) {
    let row = &system.a[last];
    let mut a = row[keep].clone();
    let mut b = system.b[last].clone();
    for f in found {
        a = &a + &(&row[f.unknown] * &f.times);
        b = &b - &(&row[f.unknown] * &f.rest);
    }
    (simplify(&a), simplify(&b))
}
