//! `√(M²) = σ M` as the worked solution shows it, with the sign `σ` that `M` has at the
//! initial state, as a one-dimensional spring's length `|a + x|` is shown as `a + x`: the
//! rolling coin's `√(cos²θ)` reads `cos θ`, and `cos θ / √(cos²θ)` cancels. It holds as
//! long as `M` keeps its sign (the coin does not fall flat); the numbers keep the root.

use super::build::{add, func, mul, pow};
use super::expr::{Expr, Func, Node};
use super::number::Number;
use super::simplify::{simplify, square_root_of_square};
use std::collections::HashMap;

/// `e` with every odd power of a square root of a square, `(M²)^(k/2)`, written `(σM)^k`,
/// where `sign_of(M)` gives `σ` (`0` leaves that root alone), then simplified; `e` itself
/// when it has no such root.
pub fn roots_of_squares(e: &Expr, sign_of: &dyn Fn(&Expr) -> f64) -> Expr {
    if !has_root(e, &mut std::collections::HashSet::new()) {
        return e.clone();
    }
    let mut memo = HashMap::new();
    let rewritten = walk(e, sign_of, &mut memo);
    if rewritten == *e {
        e.clone()
    } else {
        simplify(&rewritten)
    }
}

/// Whether `e` has a square root (or an odd power of one) outside definitions.
fn has_root(e: &Expr, seen: &mut std::collections::HashSet<*const Node>) -> bool {
    if !seen.insert(std::rc::Rc::as_ptr(&e.0)) {
        return false;
    }
    match e.node() {
        Node::Num(_) | Node::Sym(_) => false,
        Node::Pow(b, x) => half_odd(x).is_some() || has_root(b, seen),
        Node::Func(Func::Sqrt, _) => true,
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
            items.iter().any(|x| has_root(x, seen))
        }
    }
}

fn half_odd(exponent: &Expr) -> Option<i64> {
    match exponent.as_number() {
        Some(Number::Ratio(k, 2)) if k % 2 != 0 => Some(k),
        _ => None,
    }
}

fn walk(e: &Expr, sign_of: &dyn Fn(&Expr) -> f64, memo: &mut HashMap<*const Node, Expr>) -> Expr {
    let key = std::rc::Rc::as_ptr(&e.0);
    if let Some(done) = memo.get(&key) {
        return done.clone();
    }
    let root = |base: &Expr, k: i64| -> Option<Expr> {
        let m = square_root_of_square(base)
            .or_else(|| super::perfect_square::square_root_of_sum(base))?;
        let sign = sign_of(&m);
        (sign != 0.0 && sign.is_finite()).then(|| {
            let signed = if sign < 0.0 { &m * &Expr::int(-1) } else { m };
            pow(signed, Expr::int(k))
        })
    };
    let out = match e.node() {
        Node::Num(_) | Node::Sym(_) => e.clone(),
        Node::Add(items) => add(items.iter().map(|x| walk(x, sign_of, memo))),
        Node::Mul(items) => mul(items.iter().map(|x| walk(x, sign_of, memo))),
        Node::Pow(base, exponent) => {
            let base = walk(base, sign_of, memo);
            match half_odd(exponent).and_then(|k| root(&base, k)) {
                Some(r) => r,
                None => pow(base, walk(exponent, sign_of, memo)),
            }
        }
        Node::Func(Func::Sqrt, args) => {
            let base = walk(&args[0], sign_of, memo);
            root(&base, 1).unwrap_or_else(|| func(Func::Sqrt, vec![base]))
        }
        Node::Func(f, args) => func(*f, args.iter().map(|x| walk(x, sign_of, memo)).collect()),
    };
    memo.insert(key, out.clone());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{cos, sin, sqrt};

    #[test]
    fn a_root_of_a_square_takes_the_sign_it_has_at_the_initial_state() {
        let theta = Expr::coord("theta", 0);
        let phi = Expr::coord("phi", 0);
        let (c, s) = (cos(theta.clone()), sin(theta.clone()));
        let square = |x: &Expr| x * x;
        // √(sin²φ cos²θ + cos²φ cos²θ) = |cos θ| = cos θ while cos θ > 0.
        let w = &(&square(&sin(phi.clone())) * &square(&c)) + &(&square(&cos(phi)) * &square(&c));
        let e = &(&c * &s) / &sqrt(w.clone());
        assert_eq!(roots_of_squares(&e, &|_| 1.0), s);
        // Where cos θ < 0 at the start, √(cos²θ) = −cos θ.
        assert_eq!(
            roots_of_squares(&sqrt(square(&c)), &|_| -1.0),
            &c * &Expr::int(-1)
        );
        // (cos²θ)^(3/2) = cos³θ; a root of what is not a square stays.
        let cubed = pow(square(&c), Expr::ratio(3, 2));
        assert_eq!(
            roots_of_squares(&cubed, &|_| 1.0),
            pow(c.clone(), Expr::int(3))
        );
        let not_square = sqrt(&c + &Expr::int(2));
        assert_eq!(roots_of_squares(&not_square, &|_| 1.0), not_square);
    }
}
