//! `sin²x + cos²x = 1` in all its forms inside a sum of monomials.
//!
//! For an argument `x` and a cofactor monomial `M`, the three terms `s·sin²x·M`,
//! `c·cos²x·M` and `p·M` are one group. Replacing `sin²x` by `1 − cos²x`, or `cos²x` by
//! `1 − sin²x`, gives the two other ways to write the group; the one with fewer terms
//! wins, if it has fewer terms than the group:
//! `a·sin²x·M + a·cos²x·M → a·M` and `a·M − a·sin²x·M → a·cos²x·M`.

use super::steps::PYTHAGORAS;
use super::terms::{times, trig_factors, without, Gain, Rewrite, Terms};
use super::Candidate;
use crate::symbolic::build::{cos, pow, sin};
use crate::symbolic::expr::Expr;
use crate::symbolic::number::Number;

/// A group for every `sin²x` or `cos²x` factor of every term.
pub(crate) fn candidates(monomials: &[Expr], out: &mut Vec<Candidate>) {
    for m in monomials {
        for t in trig_factors(m).into_iter().filter(|t| t.power >= 2) {
            let cofactor = without(m, &t.base(), 2);
            out.push(Candidate::Pythagoras {
                arg: t.arg,
                cofactor,
            });
        }
    }
}

/// The shorter way to write the group of `arg` and `cofactor`, if there is one.
pub(crate) fn rewrite(terms: &Terms, arg: &Expr, cofactor: &Expr) -> Option<Rewrite> {
    let square = |f: Expr| pow(f, Expr::int(2));
    let (ks, sin2) = times(cofactor, [square(sin(arg.clone()))]);
    let (kc, cos2) = times(cofactor, [square(cos(arg.clone()))]);
    if !ks.is_one() || !kc.is_one() {
        return None;
    }
    let (s, c, p) = (
        terms.coefficient(&sin2),
        terms.coefficient(&cos2),
        terms.coefficient(cofactor),
    );
    let group = |s: Number, c: Number, p: Number| {
        [(sin2.clone(), s), (cos2.clone(), c), (cofactor.clone(), p)]
            .into_iter()
            .filter(|(_, k)| !k.is_zero())
            .collect::<Vec<_>>()
    };
    let remove = group(s, c, p);
    // sin² = 1 − cos², then cos² = 1 − sin²; on a tie the first (keeping cos²) wins.
    let options = [
        group(Number::ZERO, c.add(s.neg()), p.add(s)),
        group(s.add(c.neg()), Number::ZERO, p.add(c)),
    ];
    let mut best: Option<(Gain, Rewrite)> = None;
    for insert in options {
        let read = vec![sin2.clone(), cos2.clone(), cofactor.clone()];
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
