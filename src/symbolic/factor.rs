//! Pulling the factor that all the terms of a sum share out of it, and writing a signed
//! term after others: the pieces both ways of collecting a sum for display use.

use super::build::{add, mul, pow};
use super::expr::{Expr, Node, Symbol};
use super::number::Number;
use super::print::{latex, latex_term};
use std::ops::{Mul as _, Neg as _};

/// The number r with `a = r b`, when there is one.
pub(super) fn multiple_of(a: &Expr, b: &Expr) -> Option<Number> {
    let (first_a, first_b) = (a.terms().first()?, b.terms().first()?);
    if a.terms().len() != b.terms().len() {
        return None;
    }
    let r = first_a.split_coefficient().0 * first_b.split_coefficient().0.recip()?;
    (mul([Expr::num(r), b.clone()]) == *a).then_some(r)
}

/// `coefficient key`, `coefficient` one term, its sign in front and a factor ±1 left out.
pub(super) fn signed_term(coefficient: &Expr, key_text: &str) -> String {
    let (c, rest) = coefficient.split_coefficient();
    let sign = if c.is_negative() { "-" } else { "" };
    let c = if c.is_negative() { c.neg() } else { c };
    if rest.is_one() && c.is_one() {
        format!("{sign}{key_text}")
    } else {
        format!("{sign}{} {key_text}", latex_term(c, &rest))
    }
}

pub(super) fn push_signed(out: &mut String, text: String) {
    match (out.is_empty(), text.strip_prefix('-')) {
        (true, _) => *out = text,
        (false, Some(rest)) => out.push_str(&format!(" - {rest}")),
        (false, None) => out.push_str(&format!(" + {text}")),
    }
}

/// A factor's base and integer exponent (`x³ → (x, 3)`, `sin q → (sin q, 1)`).
fn base_and_exponent(f: &Expr) -> (Expr, i64) {
    if let Node::Pow(base, exponent) = f.node() {
        if let Some(Number::Ratio(n, 1)) = exponent.as_number() {
            return (base.clone(), n);
        }
    }
    (f.clone(), 1)
}

/// `sum = common · inner`: `common` the sign when every term is negative, the fraction
/// all coefficients share (the gcd of the numerators over the lcm of the denominators) and the
/// factors every term has, each to its lowest power.
pub fn pull_common_factor(sum: &Expr) -> (Expr, Expr) {
    let terms = sum.terms();
    let split: Vec<(Number, Expr)> = terms.iter().map(Expr::split_coefficient).collect();
    // The symbolic factors common to all terms, each to its power nearest zero: a factor
    // every term multiplies (L², L → L) or every term divides by (1/σ in each → 1/σ).
    let mut common: Vec<(Expr, i64)> = split[0]
        .1
        .factors()
        .iter()
        .filter(|f| !f.is_one())
        .map(base_and_exponent)
        .filter(|(_, n)| *n != 0)
        .collect();
    for (_, rest) in &split[1..] {
        let powers: Vec<(Expr, i64)> = rest.factors().iter().map(base_and_exponent).collect();
        common = common
            .into_iter()
            .filter_map(|(base, n)| {
                let m = powers
                    .iter()
                    .find(|(b, _)| *b == base)
                    .map_or(0, |(_, m)| *m);
                let shared = if n > 0 { m.min(n) } else { m.max(n) };
                (shared != 0 && shared.signum() == n.signum()).then_some((base, shared))
            })
            .collect();
    }
    let mut number = Number::ONE;
    if split.iter().all(|(c, _)| c.is_negative()) {
        number = Number::MINUS_ONE;
    }
    let ratios: Option<Vec<(i64, i64)>> = split
        .iter()
        .map(|(c, _)| match c {
            Number::Ratio(n, d) => Some((n.abs(), *d)),
            Number::Real(_) => None,
        })
        .collect();
    if let Some(ratios) = ratios {
        // gcd of the numerators over the lcm of the denominators, so that the coefficients
        // left inside are integers: L²m/3 + L²m c/2 = L²m/6 (2 + 3c). Only beside a
        // symbolic factor (a bare 1/3 (3a + b) reads worse than a + b/3), and not for a
        // large lcm, which given decimals make: 0.35 a + 0.2 b stays as it is.
        const LARGEST_DENOMINATOR: i64 = 12;
        let g = ratios.iter().fold(0i64, |g, (n, _)| gcd(g, *n));
        let same = |l: i64| ratios.iter().all(|(_, d)| *d == l);
        let l = ratios
            .iter()
            .try_fold(1i64, |l, (_, d)| (l / gcd(l, *d)).checked_mul(*d))
            .filter(|&l| same(l) || (l <= LARGEST_DENOMINATOR && !common.is_empty()));
        if let (true, Some(l)) = (g > 0, l) {
            number = number.mul(Number::ratio(g as i128, l as i128));
        }
    }
    let mut factors = vec![Expr::num(number)];
    factors.extend(
        common
            .iter()
            .map(|(base, n)| pow(base.clone(), Expr::int(*n))),
    );
    // Each term divided factor by factor: a power of a sum taken out must meet its own
    // power in the term, not be multiplied out first, so a sum taken out of denominators
    // comes back as the sum itself, once per power (`pow` would expand (R − r)²).
    let mut inverse = vec![Expr::num(number.recip().unwrap_or(Number::ONE))];
    for (base, n) in common {
        match base.node() {
            Node::Add(_) if n < 0 => inverse.extend(std::iter::repeat_n(base, (-n) as usize)),
            _ => inverse.push(pow(base, Expr::int(-n))),
        }
    }
    let common = mul(factors);
    let inner = add(terms
        .iter()
        .map(|t| mul(std::iter::once(t.clone()).chain(inverse.iter().cloned()))));
    over_constant_denominator(common, inner)
}

/// The constants that some terms of `inner` divide by moved out with `common`, when a term
/// of `inner` is a number and the sum left is then free of fractions and shorter:
/// 1/y (R/r − 1) becomes 1/(r y) (R − r), as a textbook writes (R − r)/(r y). A sum that
/// divides by anything else stays, and so does one without a number beside its fractions
/// (r/σ (a + b/σ), a named divisor that only some terms have).
fn over_constant_denominator(common: Expr, inner: Expr) -> (Expr, Expr) {
    if !inner.terms().iter().any(|t| t.as_number().is_some()) {
        return (common, inner);
    }
    let mut below: Vec<(Expr, i64)> = Vec::new();
    for f in inner.terms().iter().flat_map(Expr::factors) {
        let (base, n) = base_and_exponent(f);
        if n >= 0 {
            continue;
        }
        if !matches!(base.node(), Node::Sym(Symbol::Const(_))) {
            return (common, inner);
        }
        match below.iter_mut().find(|(b, _)| *b == base) {
            Some((_, k)) => *k = (*k).max(-n),
            None => below.push((base, -n)),
        }
    }
    if below.is_empty() || inner.terms().len() < 2 {
        return (common, inner);
    }
    let denominator = mul(below.into_iter().map(|(b, k)| pow(b, Expr::int(k))));
    let cleared = mul([inner.clone(), denominator.clone()]);
    let fractions = cleared.terms().iter().any(|t| {
        let (c, rest) = t.split_coefficient();
        c.as_integer().is_none() || rest.factors().iter().any(|f| base_and_exponent(f).1 < 0)
    });
    if fractions || cleared.operation_count() >= inner.operation_count() {
        return (common, inner);
    }
    (mul([common, pow(denominator, Expr::int(-1))]), cleared)
}

pub(super) fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

/// `(root)²` in LaTeX.
pub(super) fn square_tex(root: &Expr) -> String {
    format!("\\left({}\\right)^{{2}}", latex(root))
}

/// The sum whose square `sum` is, when it is the square of a sum of two to four terms
/// that each appear squared with coefficient 1: q̇₁² + q̇₂² + 2 q̇₁ q̇₂ → q̇₁ + q̇₂, as a
/// textbook writes a body's (q̇₁ + q̇₂)² of two rates that always turn together.
pub(super) fn square_root_of_sum(sum: &Expr) -> Option<Expr> {
    const MOST_TERMS: usize = 4;
    let squares: Vec<Expr> = sum
        .terms()
        .iter()
        .filter_map(|t| match (t.split_coefficient(), t.node()) {
            ((c, _), Node::Pow(base, exponent))
                if c.is_one() && exponent.as_number() == Some(Number::ratio(2, 1)) =>
            {
                Some(base.clone())
            }
            _ => None,
        })
        .collect();
    let k = squares.len();
    // (a₁ + … + a_k)² has k squares and k(k − 1)/2 cross terms.
    if !(2..=MOST_TERMS).contains(&k) || sum.terms().len() != k * (k + 1) / 2 {
        return None;
    }
    // The first term's sign is free; each other sign is tried both ways.
    (0..1u32 << (k - 1)).find_map(|signs| {
        let root = add(squares.iter().enumerate().map(|(i, base)| {
            if i > 0 && (signs >> (i - 1)) & 1 == 1 {
                base.neg()
            } else {
                base.clone()
            }
        }));
        (mul([root.clone(), root.clone()]) == *sum).then_some(root)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sum_taken_out_of_the_denominators_leaves_the_numerators_as_they_were() {
        let (x, y) = (Expr::coord("x", 0), Expr::coord("y", 0));
        let (r, big) = (Expr::constant("r"), Expr::constant("R"));
        let below = pow(add([big, -r.clone()]), Expr::int(-2));
        let term = |q: &Expr| mul([r.clone(), pow(q.clone(), Expr::int(2)), below.clone()]);
        let (common, inner) = pull_common_factor(&add([term(&x), term(&y)]));
        assert_eq!(common, mul([r.clone(), below.clone()]));
        // x² + y², not (R − r)² multiplied out over (R − r)².
        assert_eq!(inner, add([pow(x, Expr::int(2)), pow(y, Expr::int(2))]));
    }

    #[test]
    fn a_number_beside_a_ratio_of_constants_goes_over_their_denominator() {
        let y = Expr::coord("y", 0);
        let (r, big) = (Expr::constant("r"), Expr::constant("R"));
        let over_y = pow(y, Expr::int(-1));
        // R/(r y) − 1/y = (1/(r y)) (R − r).
        let sum = add([
            mul([big.clone(), pow(r.clone(), Expr::int(-1)), over_y.clone()]),
            -over_y.clone(),
        ]);
        let (common, inner) = pull_common_factor(&sum);
        assert_eq!(common, mul([pow(r.clone(), Expr::int(-1)), over_y]));
        assert_eq!(inner, add([big, -r]));
    }
}
