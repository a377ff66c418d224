//! Simplification as a textbook shows it: `sin²x + cos²x = 1` and the angle-sum
//! identities, applied to the canonical sums of monomials of [`crate::symbolic::build`].
//!
//! The canonical form already collects like terms and expands products, so what is left
//! is trigonometry. Each rule family lives in its own file:
//!
//! - `pythagoras`: `a·sin²x·M + a·cos²x·M → a·M`, `a·M − a·sin²x·M → a·cos²x·M`;
//! - `trig`: `cos a cos b − sin a sin b → cos(a+b)` and its three siblings, and (only when
//!   asked for) `sin x cos x → sin(2x)/2`.
//!
//! A sum is held as a hash map from monomial to coefficient. Every term proposes the groups
//! it can belong to (an argument or a pair of arguments, and the cofactor left when the
//! trigonometric factors are taken out), and each group looks its partners up by hash, so
//! a pass costs about one map lookup per trigonometric factor (pair) of every term. Within
//! a pass the rewrites that save most go first; passes repeat until none shortens the sum.
//!
//! "Shorter" means fewer terms and no more operations (`Expr::operation_count`) for the
//! identities that combine terms, so `cos²x − sin²x` is not traded for `2cos²x − 1`; and
//! no more terms and fewer operations for the double angle, which rewrites one term. Every
//! rewrite thus shrinks the sum, so the passes end; [`Options::max_passes`] bounds them
//! anyway.

pub(crate) mod key;
mod memo;
mod pairs;
mod pythagoras;
pub(super) mod steps;
mod terms;
mod trig;

#[cfg(test)]
mod tests;

pub use memo::{leave_to_the_end, with_simplify_memo};
pub use steps::Step;

use crate::symbolic::build::{add, func, mul, pow};
use crate::symbolic::expr::{Expr, Node};
use key::{hash_expr, same, Key, KeyMap, KeySet};
use std::hash::{Hash, Hasher};
use terms::{has_trig, Gain, Rewrite, Terms};

/// What [`simplify_with`] may do.
#[derive(Clone, Debug)]
pub struct Options {
    /// Write `sin x cos x` as `sin(2x)/2` when that is shorter and `x` is a single symbol.
    /// Off by default: textbooks of multibody dynamics keep the products. Default `false`.
    pub double_angle: bool,
    /// The most passes over one sum; each pass applies every rewrite that still shortens
    /// it. Default 64.
    pub max_passes: usize,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            double_angle: false,
            max_passes: 64,
        }
    }
}

/// `e` simplified by the trigonometric identities, numerically equal to `e`.
/// Inside [`with_simplify_memo`], an expression simplified before is not simplified again.
pub fn simplify(e: &Expr) -> Expr {
    if let Some(done) = memo::kept(e) {
        return done;
    }
    let done = simplify_with(e, &Options::default(), None);
    memo::keep(e, &done);
    done
}

/// `e` simplified, with the identity used at each step, in the order they were used.
#[cfg(test)]
pub fn simplify_with_steps(e: &Expr) -> (Expr, Vec<Step>) {
    let mut steps = Vec::new();
    let result = simplify_with(e, &Options::default(), Some(&mut steps));
    (result, steps)
}

/// `e` simplified with `options`, pushing each step onto `steps` when given.
pub fn simplify_with(e: &Expr, options: &Options, steps: Option<&mut Vec<Step>>) -> Expr {
    // Inside a memo scope the pairs formed by earlier simplifications serve this one too.
    let shared = memo::take_pairs(options.double_angle);
    let in_scope = shared.is_some();
    let mut simplifier = Simplifier {
        options,
        steps,
        memo: KeyMap::default(),
        pairs: shared.unwrap_or_default(),
    };
    let simpler = simplifier.expr(e);
    if in_scope {
        memo::give_back_pairs(options.double_angle, simplifier.pairs);
    }
    // A sum over its own power, (r_A + r_B)² sin q / (r_A + r_B)², is cancelled.
    super::cancel::cancel_sums(&simpler)
}

/// The index of the shortest of `candidates` by `Expr::operation_count`, the first on a
/// tie; 0 for an empty slice.
#[cfg(test)]
pub fn shortest_of(candidates: &[Expr]) -> usize {
    candidates
        .iter()
        .enumerate()
        .min_by_key(|(i, e)| (e.operation_count(), *i))
        .map_or(0, |(i, _)| i)
}

/// A group of terms that one rule family may rewrite together.
#[derive(Clone, Debug)]
pub(crate) enum Candidate {
    /// `sin²(arg)·cofactor`, `cos²(arg)·cofactor` and `cofactor`.
    Pythagoras { arg: Expr, cofactor: Expr },
    /// The products of `sin`/`cos` of `a` and `b` (`a < b`) times `cofactor`: the
    /// `cos·cos` and `sin·sin` ones when `cosines`, else the mixed ones.
    AngleSum {
        cosines: bool,
        a: Expr,
        b: Expr,
        cofactor: Expr,
    },
    /// `sin(arg)·cos(arg)·cofactor`.
    DoubleAngle { arg: Expr, cofactor: Expr },
}

/// The angle, or pair of angles, an identity instance is about.
type Angles = (Key, Option<Key>);

impl PartialEq for Candidate {
    fn eq(&self, other: &Candidate) -> bool {
        use Candidate::{AngleSum, DoubleAngle, Pythagoras};
        match (self, other) {
            (
                Pythagoras {
                    arg: x,
                    cofactor: m,
                },
                Pythagoras {
                    arg: y,
                    cofactor: n,
                },
            )
            | (
                DoubleAngle {
                    arg: x,
                    cofactor: m,
                },
                DoubleAngle {
                    arg: y,
                    cofactor: n,
                },
            ) => same(x, y) && same(m, n),
            (
                AngleSum {
                    cosines: c,
                    a,
                    b,
                    cofactor: m,
                },
                AngleSum {
                    cosines: d,
                    a: x,
                    b: y,
                    cofactor: n,
                },
            ) => c == d && same(a, x) && same(b, y) && same(m, n),
            _ => false,
        }
    }
}

impl Eq for Candidate {}

impl Hash for Candidate {
    fn hash<H: Hasher>(&self, state: &mut H) {
        match self {
            Candidate::Pythagoras { arg, cofactor } | Candidate::DoubleAngle { arg, cofactor } => {
                matches!(self, Candidate::Pythagoras { .. }).hash(state);
                hash_expr(arg, state);
                hash_expr(cofactor, state);
            }
            Candidate::AngleSum {
                cosines,
                a,
                b,
                cofactor,
            } => {
                cosines.hash(state);
                hash_expr(a, state);
                hash_expr(b, state);
                hash_expr(cofactor, state);
            }
        }
    }
}

impl Candidate {
    fn angles(&self) -> Angles {
        match self {
            Candidate::Pythagoras { arg, .. } | Candidate::DoubleAngle { arg, .. } => {
                (Key(arg.clone()), None)
            }
            Candidate::AngleSum { a, b, .. } => (Key(a.clone()), Some(Key(b.clone()))),
        }
    }

    /// The best rewrite of the group in the current sum, if one shortens it.
    fn rewrite(&self, terms: &Terms) -> Option<Rewrite> {
        match self {
            Candidate::Pythagoras { arg, cofactor } => pythagoras::rewrite(terms, arg, cofactor),
            Candidate::AngleSum {
                cosines,
                a,
                b,
                cofactor,
            } => trig::angle_sum(terms, *cosines, a, b, cofactor),
            Candidate::DoubleAngle { arg, cofactor } => trig::double_angle(terms, arg, cofactor),
        }
    }
}

struct Simplifier<'a> {
    options: &'a Options,
    steps: Option<&'a mut Vec<Step>>,
    /// Simplified functions and powers: the same `cos(...)` or `(...)^(-1)` recurs in
    /// many terms.
    memo: KeyMap<Key, Expr>,
    /// The pairs of sine and cosine factors of every monomial met so far.
    pairs: pairs::Pairs,
}

impl Simplifier<'_> {
    fn expr(&mut self, e: &Expr) -> Expr {
        if !has_trig(e) {
            return e.clone();
        }
        let rebuilt = match e.node() {
            Node::Add(terms) => add(terms.iter().map(|t| self.term(t)).collect::<Vec<_>>()),
            _ => self.term(e),
        };
        // A single monomial has no partner; only the double angle rewrites one alone.
        if matches!(rebuilt.node(), Node::Add(_)) || self.options.double_angle {
            self.sum(rebuilt)
        } else {
            rebuilt
        }
    }

    fn term(&mut self, t: &Expr) -> Expr {
        match t.node() {
            Node::Mul(factors) => mul(factors.iter().map(|f| self.factor(f)).collect::<Vec<_>>()),
            _ => self.factor(t),
        }
    }

    fn factor(&mut self, f: &Expr) -> Expr {
        if !matches!(f.node(), Node::Func(..) | Node::Pow(..)) {
            return f.clone();
        }
        // Look the memo up first: the same big factor recurs in many terms, and finding
        // out that it holds no sine or cosine costs a walk over all of it.
        let key = Key(f.clone());
        if let Some(done) = self.memo.get(&key) {
            return done.clone();
        }
        let done = match f.node() {
            _ if !has_trig(f) => f.clone(),
            Node::Func(name, args) => func(*name, args.iter().map(|a| self.expr(a)).collect()),
            Node::Pow(base, exponent) => pow(self.expr(base), self.expr(exponent)),
            _ => f.clone(),
        };
        self.memo.insert(key, done.clone());
        done
    }

    /// The rules applied to the terms of `e` until none shortens it.
    fn sum(&mut self, e: Expr) -> Expr {
        let mut terms = Terms::new(&e);
        let mut changed = false;
        for _ in 0..self.options.max_passes {
            let monomials = terms.monomials();
            let mut candidates = Vec::new();
            pythagoras::candidates(&terms, &monomials, &mut candidates);
            trig::candidates(
                &terms,
                &monomials,
                (self.options, &mut self.pairs),
                &mut candidates,
            );
            let mut seen = KeySet::default();
            candidates.retain(|c| seen.insert(c.clone()));
            let scored: Vec<(Gain, Candidate, Rewrite)> = candidates
                .into_iter()
                .filter_map(|c| c.rewrite(&terms).map(|r| (terms.gain(&r), c, r)))
                .collect();
            if scored.is_empty() {
                break;
            }
            // Use one identity instance (one pair of angles) everywhere before the next:
            // in cos(q1+q2+q3) multiplied out, combining q1 with q2 in some terms and q2
            // with q3 in others leaves terms that no longer fit together. The angles whose
            // rewrites save most in total go first, then the biggest single savings; the
            // sort is stable, so ties keep the term order.
            let mut totals: KeyMap<Angles, Gain> = KeyMap::default();
            for (gain, candidate, _) in &scored {
                *totals.entry(candidate.angles()).or_default() += *gain;
            }
            let mut keyed: Vec<(Gain, Angles, Gain, Candidate, Rewrite)> = scored
                .into_iter()
                .map(|(gain, candidate, rewrite)| {
                    let angles = candidate.angles();
                    (
                        totals.get(&angles).copied().unwrap_or_default(),
                        angles,
                        gain,
                        candidate,
                        rewrite,
                    )
                })
                .collect();
            keyed.sort_by(|x, y| {
                y.0.cmp(&x.0)
                    .then_with(|| x.1.cmp(&y.1))
                    .then_with(|| y.2.cmp(&x.2))
            });
            let mut touched: KeySet<Key> = KeySet::default();
            for (_, _, _, candidate, rewrite) in keyed {
                // An earlier rewrite of this pass may have changed the group: look again.
                let rewrite = if rewrite
                    .read
                    .iter()
                    .any(|m| touched.contains(&Key(m.clone())))
                {
                    match candidate.rewrite(&terms) {
                        Some(fresh) => fresh,
                        None => continue,
                    }
                } else {
                    rewrite
                };
                if let Some(steps) = self.steps.as_deref_mut() {
                    steps.push(Step {
                        rule: rewrite.rule,
                        before: rewrite.before(),
                        after: rewrite.after(),
                    });
                }
                touched.extend(
                    rewrite
                        .remove
                        .iter()
                        .chain(&rewrite.insert)
                        .map(|(m, _)| Key(m.clone())),
                );
                terms.apply(&rewrite);
                changed = true;
            }
        }
        let result = if changed { terms.to_expr() } else { e };
        // Fewer operations each time, so this ends.
        match pythagoras::higher_powers(&result) {
            Some(shorter) => self.sum(shorter),
            None => result,
        }
    }
}

/// `M` when `e` simplifies to `M²` for a single term `M` (every factor to an even power,
/// the coefficient the square of a fraction): the square root up to its sign, which the
/// caller chooses (`√(cos²θ) = ±cos θ`). `None` otherwise.
pub fn square_root_of_square(e: &Expr) -> Option<Expr> {
    use crate::symbolic::number::Number;
    let e = simplify(e);
    if e.terms().len() != 1 {
        return None;
    }
    let (c, rest) = e.split_coefficient();
    let root = |n: i64| -> Option<i64> {
        let r = (n as f64).sqrt().round() as i64;
        (r >= 0 && r.checked_mul(r) == Some(n)).then_some(r)
    };
    let Number::Ratio(n, d) = c else {
        return None;
    };
    let mut factors = vec![Expr::num(Number::ratio(root(n)? as i128, root(d)? as i128))];
    if !rest.is_one() {
        for f in rest.factors() {
            let Node::Pow(base, exponent) = f.node() else {
                return None;
            };
            match exponent.as_number() {
                Some(Number::Ratio(k, 1)) if k % 2 == 0 => {
                    factors.push(pow(base.clone(), Expr::int(k / 2)))
                }
                _ => return None,
            }
        }
    }
    Some(mul(factors))
}
