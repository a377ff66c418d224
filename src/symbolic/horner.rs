//! Greedy multivariate Horner factoring of a sum, for compiling: `a b + a c + d` becomes
//! `a (b + c) + d`, so that a sum of many monomials costs far fewer multiplications.
//! The canonical form keeps sums expanded (good for cancelling and comparing); this undoes
//! the expansion only where it saves work, and only inside the compiled program.

use super::expr::{Expr, Node};
use super::number::Number;

/// A monomial: its coefficient and its factors as (base, positive integer power).
pub type Monomial = (Number, Vec<(Expr, i64)>);

/// How to evaluate a sum.
#[derive(Clone, Debug, PartialEq)]
pub enum Plan {
    /// One monomial.
    Term(Monomial),
    /// `base` times a sum.
    Product(Expr, Box<Plan>),
    /// A sum of parts.
    Sum(Vec<Plan>),
}

/// A term of a canonical sum as a monomial; powers that are not positive integers stay whole.
pub fn monomial(term: &Expr) -> Monomial {
    let (coefficient, rest) = term.split_coefficient();
    if rest.is_one() {
        return (coefficient, Vec::new());
    }
    let factors = rest
        .factors()
        .iter()
        .map(|f| match f.node() {
            Node::Pow(base, exponent) => match exponent.as_number().and_then(Number::as_integer) {
                Some(k) if k > 0 => (base.clone(), k),
                _ => (f.clone(), 1),
            },
            _ => (f.clone(), 1),
        })
        .collect();
    (coefficient, factors)
}

/// The factoring plan of a sum of monomials.
pub fn factor(terms: Vec<Monomial>) -> Plan {
    if terms.len() == 1 {
        return Plan::Term(
            terms
                .into_iter()
                .next()
                .unwrap_or((Number::ZERO, Vec::new())),
        );
    }
    // The base that the most terms share (first seen wins a tie, so the plan is deterministic).
    let mut counts: std::collections::HashMap<&Expr, (usize, usize)> = Default::default();
    for (_, factors) in &terms {
        for (base, _) in factors {
            let seen = counts.len();
            counts.entry(base).or_insert((seen, 0)).1 += 1;
        }
    }
    let best = counts
        .iter()
        .min_by_key(|(_, (first, count))| (std::cmp::Reverse(*count), *first))
        .map(|(base, (_, count))| ((*base).clone(), *count));
    let Some((base, count)) = best else {
        return Plan::Sum(terms.into_iter().map(Plan::Term).collect());
    };
    if count < 2 {
        return Plan::Sum(terms.into_iter().map(Plan::Term).collect());
    }
    let (mut with, mut without) = (Vec::new(), Vec::new());
    for (c, factors) in terms {
        if factors.iter().any(|(b, _)| *b == base) {
            let reduced = factors
                .into_iter()
                .filter_map(|(b, k)| {
                    if b == base {
                        (k > 1).then(|| (b, k - 1))
                    } else {
                        Some((b, k))
                    }
                })
                .collect();
            with.push((c, reduced));
        } else {
            without.push((c, factors));
        }
    }
    let product = Plan::Product(base, Box::new(factor(with)));
    if without.is_empty() {
        product
    } else {
        match factor(without) {
            Plan::Sum(mut parts) => {
                parts.insert(0, product);
                Plan::Sum(parts)
            }
            other => Plan::Sum(vec![product, other]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(name: &str) -> Expr {
        Expr::constant(name)
    }

    #[test]
    fn shares_the_common_factor() {
        let e = &(&s("a") * &s("b")) + &(&(&s("a") * &s("c")) + &s("d"));
        let plan = factor(e.terms().iter().map(monomial).collect());
        let Plan::Sum(parts) = plan else {
            panic!("a sum")
        };
        assert!(matches!(&parts[0], Plan::Product(base, _) if *base == s("a")));
    }
}
