//! Products of sines and cosines combined into the sine or cosine of a sum or difference
//! of their arguments, one table row per identity:
//!
//! ```text
//! cos a cos b − sin a sin b = cos(a+b)      sin a cos b + cos a sin b = sin(a+b)
//! cos a cos b + sin a sin b = cos(a−b)      sin a cos b − cos a sin b = sin(a−b)
//! ```
//!
//! A group is an unordered pair of arguments `a < b` and a cofactor monomial `M`; the
//! identity applies when the two products appear times `M` with coefficients that match
//! exactly, and only when the result is shorter.

use super::pairs::{product, Pair, Pairs};
use super::steps::{COS_DIFFERENCE, COS_SUM, DOUBLE_ANGLE, SIN_DIFFERENCE, SIN_SUM};
use super::terms::{times_trig, Gain, Rewrite, Terms};
use super::{Candidate, Options};
use crate::symbolic::build::{add, func};
use crate::symbolic::expr::{Expr, Func};
use crate::symbolic::number::Number;
use std::ops::{Add, Mul, Neg};

use Func::{Cos, Sin};

/// One identity: `first + sign * second = result(a ± b)`, products written as
/// `(function of a, function of b)`.
struct Row {
    rule: &'static str,
    first: (Func, Func),
    second: (Func, Func),
    sign: i64,
    result: Func,
    difference: bool,
}

#[rustfmt::skip]
const ROWS: [Row; 4] = [
    Row { rule: COS_SUM,        first: (Cos, Cos), second: (Sin, Sin), sign: -1, result: Cos, difference: false },
    Row { rule: COS_DIFFERENCE, first: (Cos, Cos), second: (Sin, Sin), sign: 1,  result: Cos, difference: true },
    Row { rule: SIN_SUM,        first: (Sin, Cos), second: (Cos, Sin), sign: 1,  result: Sin, difference: false },
    Row { rule: SIN_DIFFERENCE, first: (Sin, Cos), second: (Cos, Sin), sign: -1, result: Sin, difference: true },
];

/// A group for every pair of sine or cosine factors with different arguments in every
/// term whose partner (both functions swapped, e.g. `sin a sin b` for `cos a cos b`) is
/// present with a coefficient of the same size; and (when asked for) a double-angle group
/// for every `sin x cos x`. The pairs of a monomial are formed once, in `pairs`.
pub(crate) fn candidates(
    terms: &Terms,
    monomials: &[Expr],
    (options, pairs): (&Options, &mut Pairs),
    out: &mut Vec<Candidate>,
) {
    for m in monomials {
        let of_m = super::pairs::of(pairs, m, options);
        if of_m.is_empty() {
            continue;
        }
        let c = terms.coefficient(m);
        for pair in of_m.iter() {
            match pair {
                Pair::DoubleAngle { arg, cofactor } => out.push(Candidate::DoubleAngle {
                    arg: arg.clone(),
                    cofactor: cofactor.clone(),
                }),
                Pair::AngleSum {
                    partner,
                    cosines,
                    a,
                    b,
                    cofactor,
                } => {
                    let p = terms.coefficient_of(partner);
                    if p.is_zero() || !(c.add(p).is_zero() || c.add(p.neg()).is_zero()) {
                        continue;
                    }
                    out.push(Candidate::AngleSum {
                        cosines: *cosines,
                        a: a.clone(),
                        b: b.clone(),
                        cofactor: cofactor.clone(),
                    });
                }
            }
        }
    }
}

/// The shortest identity of the group, if any applies and shortens the sum.
pub(crate) fn angle_sum(
    terms: &Terms,
    cosines: bool,
    a: &Expr,
    b: &Expr,
    cofactor: &Expr,
) -> Option<Rewrite> {
    let mut best: Option<(Gain, Rewrite)> = None;
    for row in ROWS
        .iter()
        .filter(|row| (row.first.0 == row.first.1) == cosines)
    {
        let first = product(cofactor, row.first, a, b);
        let second = product(cofactor, row.second, a, b);
        let (x, y) = (terms.coefficient(&first), terms.coefficient(&second));
        if x.is_zero() || !y.add(x.mul(Number::int(row.sign)).neg()).is_zero() {
            continue;
        }
        let argument = if row.difference {
            add([a.clone(), -b.clone()])
        } else {
            add([a.clone(), b.clone()])
        };
        let (k, result) = times_trig(cofactor, &func(row.result, vec![argument]));
        let read = vec![first.clone(), second.clone(), result.clone()];
        let insert = if k.is_zero() {
            vec![]
        } else {
            vec![(result, x.mul(k))]
        };
        let rewrite = Rewrite {
            rule: row.rule,
            remove: vec![(first, x), (second, y)],
            insert,
            read,
        };
        let gain = terms.gain(&rewrite);
        if gain.fewer_terms() && best.as_ref().is_none_or(|(g, _)| gain > *g) {
            best = Some((gain, rewrite));
        }
    }
    best.map(|(_, r)| r)
}

/// `c·sin x·cos x·M → (c/2)·sin(2x)·M`, when shorter.
pub(crate) fn double_angle(terms: &Terms, arg: &Expr, cofactor: &Expr) -> Option<Rewrite> {
    let m = product(cofactor, (Sin, Cos), arg, arg);
    let c = terms.coefficient(&m);
    if c.is_zero() {
        return None;
    }
    let (k, doubled) = times_trig(cofactor, &func(Sin, vec![Expr::int(2) * arg.clone()]));
    let read = vec![m.clone(), doubled.clone()];
    let insert = vec![(doubled, c.mul(k).mul(Number::ratio(1, 2)))];
    let rewrite = Rewrite {
        rule: DOUBLE_ANGLE,
        remove: vec![(m, c)],
        insert,
        read,
    };
    terms.gain(&rewrite).fewer_operations().then_some(rewrite)
}
