//! `sin²x + cos²x = 1` in all its forms inside a sum of monomials.
//!
//! For an argument `x` and a cofactor monomial `M`, the three terms `s·sin²x·M`,
//! `c·cos²x·M` and `p·M` are one group. Replacing `sin²x` by `1 − cos²x`, or `cos²x` by
//! `1 − sin²x`, gives the two other ways to write the group; the one with fewer terms
//! wins, if it has fewer terms than the group:
//! `a·sin²x·M + a·cos²x·M → a·M` and `a·M − a·sin²x·M → a·cos²x·M`.

use super::steps::PYTHAGORAS;
use super::terms::{times_power, trig_factors, Gain, Rewrite, Terms};
use super::Candidate;
use crate::symbolic::build::{cos, sin};
use crate::symbolic::expr::Expr;
use crate::symbolic::number::Number;
use std::ops::{Add, Neg};

/// The monomials `sin²x·M`, `cos²x·M` and `M` of the group of `x` and `M`.
fn group(arg: &Expr, cofactor: &Expr) -> [Expr; 3] {
    let sin2 = times_power(cofactor, &sin(arg.clone()), 2);
    let cos2 = times_power(cofactor, &cos(arg.clone()), 2);
    [sin2, cos2, cofactor.clone()]
}

/// A group for every `sin²x` or `cos²x` factor of every term that has a partner.
pub(crate) fn candidates(terms: &Terms, monomials: &[Expr], out: &mut Vec<Candidate>) {
    for m in monomials {
        for t in trig_factors(m).into_iter().filter(|t| t.power >= 2) {
            let cofactor = times_power(m, &t.base(), -2);
            let present = group(&t.arg, &cofactor)
                .iter()
                .filter(|g| !terms.coefficient(g).is_zero())
                .count();
            if present >= 2 {
                out.push(Candidate::Pythagoras {
                    arg: t.arg,
                    cofactor,
                });
            }
        }
    }
}

/// The shorter way to write the group of `arg` and `cofactor`, if there is one.
pub(crate) fn rewrite(terms: &Terms, arg: &Expr, cofactor: &Expr) -> Option<Rewrite> {
    let [sin2, cos2, one] = group(arg, cofactor);
    let (s, c, p) = (
        terms.coefficient(&sin2),
        terms.coefficient(&cos2),
        terms.coefficient(&one),
    );
    let terms_of = |s: Number, c: Number, p: Number| {
        [(sin2.clone(), s), (cos2.clone(), c), (one.clone(), p)]
            .into_iter()
            .filter(|(_, k)| !k.is_zero())
            .collect::<Vec<_>>()
    };
    let remove = terms_of(s, c, p);
    // sin² = 1 − cos², then cos² = 1 − sin²; on a tie the first (keeping cos²) wins.
    let options = [
        terms_of(Number::ZERO, c.add(s.neg()), p.add(s)),
        terms_of(s.add(c.neg()), Number::ZERO, p.add(c)),
    ];
    let mut best: Option<(Gain, Rewrite)> = None;
    for insert in options {
        let read = vec![sin2.clone(), cos2.clone(), one.clone()];
        let rewrite = Rewrite {
            rule: PYTHAGORAS,
            remove: remove.clone(),
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

/// `sin⁴x + 2 sin²x cos²x + cos⁴x = 1` and the other identities of higher powers, which
/// no single rewrite of a group shortens: every `cos²x` of the sum replaced by `1 − sin²x`
/// (or every `sin²x` by `1 − cos²x`) and multiplied out, when that gives fewer operations.
/// Tried only for an argument that some term holds to a power of 4 or more.
pub(crate) fn higher_powers(e: &Expr) -> Option<Expr> {
    use crate::symbolic::build::{add, mul, pow};
    use crate::symbolic::expr::{Func, Node};
    let power_of = |f: &Expr| -> Option<(Func, Expr, i64)> {
        let (base, k) = match f.node() {
            Node::Pow(b, x) => match x.as_number() {
                Some(Number::Ratio(k, 1)) if k > 0 => (b, k),
                _ => return None,
            },
            _ => (f, 1),
        };
        match base.node() {
            Node::Func(g @ (Func::Sin | Func::Cos), args) => Some((*g, args[0].clone(), k)),
            _ => None,
        }
    };
    let mut args: Vec<Expr> = Vec::new();
    for t in e.terms() {
        let powers: Vec<(Func, Expr, i64)> = t.factors().iter().filter_map(power_of).collect();
        for (_, x, _) in &powers {
            let total: i64 = powers.iter().filter(|(_, y, _)| y == x).map(|p| p.2).sum();
            if total >= 4 && !args.contains(x) {
                args.push(x.clone());
            }
        }
    }
    if args.is_empty() {
        return None;
    }
    let mut best: Option<Expr> = None;
    let mut best_count = e.operation_count();
    for x in &args {
        for (from, to) in [(Func::Cos, Func::Sin), (Func::Sin, Func::Cos)] {
            let other = pow(
                crate::symbolic::build::func(to, vec![x.clone()]),
                Expr::int(2),
            );
            let one_minus = add([Expr::one(), &other * &Expr::int(-1)]);
            let substituted = add(e.terms().iter().map(|t| {
                mul(t.factors().iter().map(|f| match power_of(f) {
                    Some((g, y, k)) if g == from && y == *x && k >= 2 => {
                        let rest = crate::symbolic::build::func(from, vec![x.clone()]);
                        &pow(one_minus.clone(), Expr::int(k / 2)) * &pow(rest, Expr::int(k % 2))
                    }
                    _ => f.clone(),
                }))
            }));
            let count = substituted.operation_count();
            if count < best_count {
                best_count = count;
                best = Some(substituted);
            }
        }
    }
    best
}
