//! Comparing the values of two quantities at the sampled states: equal, zero, or a
//! constant multiple, and that multiple written as a course writes it.

use crate::symbolic::{Expr, Number};

/// The relative tolerance of every comparison of expressions at the sampled states.
pub(super) const TOLERANCE: f64 = 1e-6;

/// The largest magnitude among `values`.
pub(super) fn norm(values: &[f64]) -> f64 {
    values.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Whether `a` and `b` agree at every state, relative to the larger of the two (and to
/// `scale`, the size of the whole expression they are parts of).
pub(super) fn close(a: &[f64], b: &[f64], scale: f64) -> bool {
    let size = norm(a).max(norm(b)).max(scale * 1e-3);
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= TOLERANCE * size + 1e-12)
        && a.iter().chain(b).all(|x| x.is_finite())
}

/// Whether `a` is zero at every state, relative to `scale`.
pub(super) fn is_zero(a: &[f64], scale: f64) -> bool {
    norm(a) <= TOLERANCE * scale.max(1e-300)
}

/// The constant `k` with `a = k b` at every state, if there is one (`b` not zero).
pub(super) fn ratio(a: &[f64], b: &[f64]) -> Option<f64> {
    let bb: f64 = b.iter().map(|x| x * x).sum();
    if bb <= 0.0 || !bb.is_finite() {
        return None;
    }
    let k = a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>() / bb;
    let scaled: Vec<f64> = b.iter().map(|y| k * y).collect();
    close(a, &scaled, 0.0).then_some(k)
}

/// `x` as a fraction with a small denominator, when it is one.
pub(super) fn fraction(x: f64) -> Option<Number> {
    (1..=24i64).find_map(|den| {
        let num = (x * den as f64).round();
        let close = (num / den as f64 - x).abs() <= 1e-9 * x.abs().max(1e-12);
        (close && num.abs() < 1e6).then(|| Number::ratio(num as i128, i128::from(den)))
    })
}

/// `x` as an expression: a fraction where it is one, else the number.
pub(super) fn factor_expr(x: f64) -> Expr {
    fraction(x).map_or_else(|| Expr::real(x), Expr::num)
}

/// `x` as text: `2`, `1/4`, `-3`, or six significant digits.
pub(super) fn factor_text(x: f64) -> String {
    match fraction(x) {
        Some(n) => n.to_string(),
        None => format!("{x:.6}"),
    }
}

/// A relative difference as a percentage with two significant digits: `3.0 %`.
pub(super) fn percent(given: f64, expected: f64) -> String {
    let p = 100.0 * (given - expected).abs() / expected.abs().max(1e-300);
    if p >= 10.0 {
        format!("{p:.0} %")
    } else {
        format!("{p:.1} %")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multiples_and_fractions() {
        assert_eq!(ratio(&[2.0, -4.0], &[1.0, -2.0]), Some(2.0));
        assert_eq!(ratio(&[2.0, 4.0], &[1.0, -2.0]), None);
        assert_eq!(factor_text(0.25), "1/4");
        assert_eq!(factor_text(-2.0), "-2");
        assert!(close(&[1.0, 2.0], &[1.0 + 1e-9, 2.0], 0.0));
        assert!(!close(&[1.0, 2.0], &[1.01, 2.0], 0.0));
        assert_eq!(percent(103.0, 100.0), "3.0 %");
    }
}
