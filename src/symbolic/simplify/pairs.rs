//! The pairs of sine and cosine factors of one monomial, with the partner monomial each
//! pair looks for: formed once per monomial while an expression is simplified, however
//! many passes over its sums look at them again.
//!
//! For a pair `f(a)·g(b)` of a monomial `M·f(a)·g(b)` the partner is `M·f'(a)·g'(b)` with
//! both functions swapped (`sin a sin b` for `cos a cos b`); whether the partner is in
//! the sum, and with a coefficient of the same size, is asked of the sum at every pass,
//! by the partner's hash kept here.

use super::key::{Key, KeyMap};
use super::terms::{times_power, trig_factors, Hashed};
use super::Options;
use crate::symbolic::expr::{Expr, Func, Node};
use std::rc::Rc;

/// One pair of sine or cosine factors of a monomial.
pub(crate) enum Pair {
    /// `sin x · cos x · cofactor`, for the double angle.
    DoubleAngle { arg: Expr, cofactor: Expr },
    /// `f(a)·g(b)·cofactor` with different arguments (`a < b`), and its partner.
    AngleSum {
        partner: Hashed,
        cosines: bool,
        a: Expr,
        b: Expr,
        cofactor: Expr,
    },
}

/// The pairs of every monomial seen so far, by monomial.
pub(crate) type Pairs = KeyMap<Key, Rc<[Pair]>>;

/// The pairs of `m`, formed on first asking.
pub(crate) fn of(cache: &mut Pairs, m: &Expr, options: &Options) -> Rc<[Pair]> {
    cache
        .entry(Key(m.clone()))
        .or_insert_with(|| form(m, options).into())
        .clone()
}

/// Every pair of `m`'s sine and cosine factors, in factor order.
fn form(m: &Expr, options: &Options) -> Vec<Pair> {
    let trig = trig_factors(m);
    let mut out = Vec::new();
    for (i, x) in trig.iter().enumerate() {
        for y in &trig[i + 1..] {
            let cofactor = times_power(&times_power(m, &x.base(), -1), &y.base(), -1);
            if x.arg == y.arg {
                let symbol = matches!(x.arg.node(), Node::Sym(_));
                if options.double_angle && symbol && x.func != y.func {
                    out.push(Pair::DoubleAngle {
                        arg: x.arg.clone(),
                        cofactor,
                    });
                }
                continue;
            }
            let partner = product(&cofactor, (flip(x.func), flip(y.func)), &x.arg, &y.arg);
            let (a, b) = if x.arg < y.arg {
                (&x.arg, &y.arg)
            } else {
                (&y.arg, &x.arg)
            };
            out.push(Pair::AngleSum {
                partner: Hashed::new(partner),
                cosines: x.func == y.func,
                a: a.clone(),
                b: b.clone(),
                cofactor,
            });
        }
    }
    out
}

/// The other function of the pair: `sin ↔ cos`.
fn flip(f: Func) -> Func {
    if f == Func::Sin {
        Func::Cos
    } else {
        Func::Sin
    }
}

/// The monomial `M · f(a) · g(b)`.
pub(crate) fn product(cofactor: &Expr, (f, g): (Func, Func), a: &Expr, b: &Expr) -> Expr {
    let fa = Expr::from_node(Node::Func(f, vec![a.clone()]));
    let gb = Expr::from_node(Node::Func(g, vec![b.clone()]));
    times_power(&times_power(cofactor, &fa, 1), &gb, 1)
}
