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
    // The bases are numbered once, so that the greedy search below counts and compares
    // integers instead of hashing and comparing expressions at every level.
    let mut numbers: super::fast_hash::FastMap<Expr, u32> = Default::default();
    let mut bases: Vec<Expr> = Vec::new();
    let numbered: Vec<NumberedTerm> = terms
        .into_iter()
        .map(|(coefficient, factors)| {
            let factors = factors
                .into_iter()
                .map(|(base, k)| {
                    let id = *numbers.entry(base.clone()).or_insert_with(|| {
                        bases.push(base);
                        (bases.len() - 1) as u32
                    });
                    (id, k)
                })
                .collect();
            (coefficient, factors)
        })
        .collect();
    let mut tally = Tally::new(bases.len());
    greedy(numbered, &mut tally).into_plan(&bases)
}

/// A monomial with its bases numbered.
type NumberedTerm = (Number, Vec<(u32, i64)>);

/// [`Plan`] over numbered bases.
enum NumberedPlan {
    Term(NumberedTerm),
    Product(u32, Box<NumberedPlan>),
    Sum(Vec<NumberedPlan>),
}

impl NumberedPlan {
    fn into_plan(self, bases: &[Expr]) -> Plan {
        match self {
            NumberedPlan::Term((c, factors)) => Plan::Term((
                c,
                factors
                    .into_iter()
                    .map(|(id, k)| (bases[id as usize].clone(), k))
                    .collect(),
            )),
            NumberedPlan::Product(id, inner) => {
                Plan::Product(bases[id as usize].clone(), Box::new(inner.into_plan(bases)))
            }
            NumberedPlan::Sum(parts) => {
                Plan::Sum(parts.into_iter().map(|p| p.into_plan(bases)).collect())
            }
        }
    }
}

/// For [`most_shared`]: by base number, how many factors of the terms have it and where
/// the first is; zero between calls, so that each call costs the factors it counts rather
/// than a sort of them (the recursion calls it once per level).
struct Tally {
    count: Vec<usize>,
    first: Vec<usize>,
    seen: Vec<u32>,
}

impl Tally {
    fn new(bases: usize) -> Tally {
        Tally {
            count: vec![0; bases],
            first: vec![0; bases],
            seen: Vec::new(),
        }
    }
}

/// The base that the most terms share, if two or more do; of those sharing the most, the
/// one seen first, so that the plan is deterministic.
fn most_shared(terms: &[NumberedTerm], tally: &mut Tally) -> Option<u32> {
    let ids = terms
        .iter()
        .flat_map(|(_, factors)| factors.iter().map(|(id, _)| *id));
    for (position, id) in ids.enumerate() {
        let i = id as usize;
        if tally.count[i] == 0 {
            tally.first[i] = position;
            tally.seen.push(id);
        }
        tally.count[i] += 1;
    }
    let mut best: Option<(usize, usize, u32)> = None; // (count, first position, base)
    for id in tally.seen.drain(..) {
        let i = id as usize;
        let (count, first) = (tally.count[i], tally.first[i]);
        tally.count[i] = 0;
        let better = match best {
            None => true,
            Some((c, f, _)) => count > c || (count == c && first < f),
        };
        if better {
            best = Some((count, first, id));
        }
    }
    best.filter(|(count, _, _)| *count >= 2)
        .map(|(_, _, id)| id)
}

fn greedy(terms: Vec<NumberedTerm>, tally: &mut Tally) -> NumberedPlan {
    if terms.len() == 1 {
        return NumberedPlan::Term(
            terms
                .into_iter()
                .next()
                .unwrap_or((Number::ZERO, Vec::new())),
        );
    }
    let Some(base) = most_shared(&terms, tally) else {
        return NumberedPlan::Sum(terms.into_iter().map(NumberedPlan::Term).collect());
    };
    let (mut with, mut without) = (Vec::new(), Vec::new());
    for (c, mut factors) in terms {
        if factors.iter().any(|(b, _)| *b == base) {
            // One power of the base less, in place: no new list for every term.
            factors.retain_mut(|(b, k)| {
                if *b == base {
                    *k -= 1;
                }
                *k > 0
            });
            with.push((c, factors));
        } else {
            without.push((c, factors));
        }
    }
    let product = NumberedPlan::Product(base, Box::new(greedy(with, tally)));
    if without.is_empty() {
        product
    } else {
        match greedy(without, tally) {
            NumberedPlan::Sum(mut parts) => {
                parts.insert(0, product);
                NumberedPlan::Sum(parts)
            }
            other => NumberedPlan::Sum(vec![product, other]),
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
