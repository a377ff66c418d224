//! A relation that holds on the motion but not identically, and rewriting a sum with it.
//!
//! A disc rolling inside a ring keeps its centre at `R − r` from the ring's: `x² + y² =
//! (R − r)²` wherever the distance constraint holds, though no identity of algebra makes
//! it so. The unit line of centres `(x, y)/(R − r)` is of unit length there, and a textbook
//! writes the no-slip row with `r θ̇`, not `r (x² + y²)/(R − r)² θ̇`. The rows built with
//! the relation are equal to the others on the motion, which is where they are evaluated.

use super::build::{add, mul, pow};
use super::expr::Expr;
use super::number::Number;
use std::collections::BTreeMap;

/// `square = root²` wherever the position constraints hold: the squared length of a vector
/// whose length the constraints fix.
#[derive(Clone, Debug, PartialEq)]
pub struct Relation {
    /// A sum of monomials, e.g. `x² + y²`.
    pub square: Expr,
    /// What its square root is on the motion, e.g. `R − r`.
    pub root: Expr,
}

impl Relation {
    /// `square = root²`.
    pub fn new(square: Expr, root: Expr) -> Relation {
        Relation { square, root }
    }

    /// As the handout writes it: `x^{2} + y^{2} = \left(R - r\right)^{2}`.
    pub fn latex(&self) -> String {
        format!(
            "{} = \\left({}\\right)^{{2}}",
            super::print::latex(&self.square),
            super::print::latex(&self.root)
        )
    }

    /// `e` (a canonical sum) with each group of terms `a (square) M` replaced by
    /// `a root² M`, where that makes it shorter (fewer operations): `r x² θ̇/(R − r)² +
    /// r y² θ̇/(R − r)² → r θ̇`. A group must hold every term of `square` in proportion;
    /// `e` is returned as it is when none does.
    pub fn reduce(&self, e: &Expr) -> Expr {
        let parts: Vec<(Number, Expr)> = self
            .square
            .terms()
            .iter()
            .map(Expr::split_coefficient)
            .collect();
        let Some((lead, lead_monomial)) = parts.first().cloned() else {
            return e.clone();
        };
        let Some(lead_inverse) = lead.recip() else {
            return e.clone();
        };
        if parts.len() < 2 {
            return e.clone();
        }
        let mut best = e.clone();
        // Each rewrite taken makes `best` shorter, so this ends.
        'shorter: loop {
            let mut coefficients: BTreeMap<Expr, Number> = BTreeMap::new();
            for t in best.terms() {
                let (c, m) = t.split_coefficient();
                let entry = coefficients.entry(m).or_insert(Number::ZERO);
                *entry = *entry + c;
            }
            for t in best.terms() {
                let (a, m) = t.split_coefficient();
                // The term as `a · lead_monomial · cofactor`: the group it would lead.
                let cofactor = mul([m, pow(lead_monomial.clone(), Expr::int(-1))]);
                let scale = a * lead_inverse;
                let group: Option<Vec<Expr>> = parts
                    .iter()
                    .map(|(c, monomial)| {
                        let (k, m) = mul([monomial.clone(), cofactor.clone()]).split_coefficient();
                        let wanted = scale * *c * k;
                        (coefficients.get(&m) == Some(&wanted)).then(|| mul([Expr::num(wanted), m]))
                    })
                    .collect();
                let Some(group) = group else {
                    continue;
                };
                // The root's factors one by one, so that a sum meets its own inverse power
                // in the cofactor, (R − r)² / (R − r)², rather than being multiplied out.
                let replaced = mul([
                    Expr::num(scale),
                    self.root.clone(),
                    self.root.clone(),
                    cofactor,
                ]);
                let candidate = add(std::iter::once(best.clone())
                    .chain(group.into_iter().map(|g| -g))
                    .chain(std::iter::once(replaced)));
                if candidate.operation_count() < best.operation_count() {
                    best = candidate;
                    continue 'shorter;
                }
            }
            return best;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    /// `x`, `y` are coordinates, a name with primes a rate, anything else a constant.
    fn p(text: &str) -> Expr {
        crate::symbolic::parse::parse_scalar(text, |name| name == "x" || name == "y")
    }

    /// `text` times (R − r)^k, built as the mechanics builds it: the parser would square
    /// the sum out before inverting it.
    fn over(text: &str, k: i64) -> Expr {
        mul([p(text), pow(p("R - r"), Expr::int(-k))])
    }

    /// `e` rewritten with x² + y² = (R − r)² is `expected`.
    fn check(e: Expr, expected: Expr) {
        let circle = Relation::new(p("x^2 + y^2"), p("R - r"));
        assert_eq!(circle.reduce(&e), expected, "{e}");
    }

    #[test]
    fn the_circle_of_centres() {
        // The no-slip row of a disc inside a ring, and its rate map.
        let row = |spin: Expr| add([over("x*y' - x'*y", 1), spin]);
        check(row(over("r*theta'*(x^2 + y^2)", 2)), row(p("r*theta'")));
        check(over("(x^2 + y^2)/(r*y)", 1), p("(R - r)/(r*y)"));
        check(
            add([over("-2*x^2 - 2*y^2", 1), p("x")]),
            p("-2*(R - r) + x"),
        );
        // Kane's row of the disc: m (1 + x²/y²) ẍ + (m/2) (R − r)² ẍ/y².
        check(
            add([p("m*x'' + m*x^2*x''/y^2"), over("m*x''/(2*y^2)", -2)]),
            over("3*m*x''/(2*y^2)", -2),
        );
    }

    #[test]
    fn only_a_whole_group_in_proportion_and_only_where_shorter() {
        for e in [
            over("x^2 + 2*y^2", 2),
            p("x^2 + y"),
            // m (R − r)² x'' multiplied out is longer.
            p("m*x^2*x'' + m*y^2*x''"),
            p("1 + x^2/y^2"),
        ] {
            check(e.clone(), e);
        }
    }
}
