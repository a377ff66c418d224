//! Exact rational numbers, falling back to `f64` only when an `i64` would overflow.

use std::cmp::Ordering;
use std::fmt;

/// A number in an expression: an exact fraction when it fits, otherwise a real.
#[derive(Clone, Copy, Debug)]
pub enum Number {
    /// `num/den` in lowest terms with `den > 0`.
    Ratio(i64, i64),
    /// A value that could not stay exact (overflow, or an irrational result).
    Real(f64),
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        let r = a % b;
        a = b;
        b = r;
    }
    a
}

impl Number {
    /// Zero.
    pub const ZERO: Number = Number::Ratio(0, 1);
    /// One.
    pub const ONE: Number = Number::Ratio(1, 1);
    /// Minus one.
    pub const MINUS_ONE: Number = Number::Ratio(-1, 1);

    /// An integer.
    pub fn int(n: i64) -> Number {
        Number::Ratio(n, 1)
    }

    /// The fraction `num/den`, reduced; a real if it does not fit.
    pub fn ratio(num: i128, den: i128) -> Number {
        if den == 0 {
            return Number::Real(f64::NAN);
        }
        let g = gcd(num, den).max(1);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        match (i64::try_from(n), i64::try_from(d)) {
            (Ok(n), Ok(d)) => Number::Ratio(n, d),
            _ => Number::Real(num as f64 / den as f64),
        }
    }

    /// Parses a decimal literal such as `0.25` or `1e-3` exactly when it can.
    pub fn parse_decimal(text: &str) -> Option<Number> {
        let value: f64 = text.parse().ok()?;
        if !value.is_finite() {
            return None;
        }
        let (mantissa, exponent) = match text.find(['e', 'E']) {
            Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
            None => (text, 0),
        };
        let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let digits = format!("{int_part}{frac_part}");
        let scale = exponent - frac_part.len() as i32;
        let exact = digits.parse::<i128>().ok().and_then(|n| {
            if scale.abs() > 30 {
                return None;
            }
            let p = 10i128.checked_pow(scale.unsigned_abs())?;
            if scale >= 0 {
                n.checked_mul(p).map(|v| Number::ratio(v, 1))
            } else {
                Some(Number::ratio(n, p))
            }
        });
        match exact {
            Some(n @ Number::Ratio(..)) => Some(n),
            _ => Some(Number::Real(value)),
        }
    }

    /// The value as an `f64`.
    pub fn to_f64(self) -> f64 {
        match self {
            Number::Ratio(n, d) => n as f64 / d as f64,
            Number::Real(x) => x,
        }
    }

    /// Whether this is exactly zero.
    pub fn is_zero(self) -> bool {
        match self {
            Number::Ratio(n, _) => n == 0,
            Number::Real(x) => x == 0.0,
        }
    }

    /// Whether this is exactly one.
    pub fn is_one(self) -> bool {
        matches!(self, Number::Ratio(1, 1)) || matches!(self, Number::Real(x) if x == 1.0)
    }

    /// Whether this is negative.
    pub fn is_negative(self) -> bool {
        self.to_f64() < 0.0
    }

    /// The integer value, when this is an exact integer.
    pub fn as_integer(self) -> Option<i64> {
        match self {
            Number::Ratio(n, 1) => Some(n),
            _ => None,
        }
    }

    /// The reciprocal; `None` for zero.
    pub fn recip(self) -> Option<Number> {
        if self.is_zero() {
            return None;
        }
        Some(match self {
            Number::Ratio(n, d) => Number::ratio(d as i128, n as i128),
            Number::Real(x) => Number::Real(1.0 / x),
        })
    }

    /// An integer power, exact when it fits; `None` for `0^negative`.
    pub fn powi(self, exp: i64) -> Option<Number> {
        if exp < 0 {
            // i64::MIN has no negation: such a power is a real number (0 or infinite) anyway.
            return match exp.checked_neg() {
                Some(positive) => self.recip()?.powi(positive),
                None => Some(Number::Real(self.to_f64().powf(exp as f64))),
            };
        }
        if exp > 64 {
            return Some(Number::Real(self.to_f64().powf(exp as f64)));
        }
        let mut result = Number::ONE;
        for _ in 0..exp {
            result = result * self;
        }
        Some(result)
    }

    /// The exact rational root `self^(1/2)` when it exists.
    pub fn exact_sqrt(self) -> Option<Number> {
        let Number::Ratio(n, d) = self else {
            return None;
        };
        if n < 0 {
            return None;
        }
        let root = |v: i64| {
            let r = (v as f64).sqrt().round() as i64;
            // Near i64::MAX the rounded root squared overflows: then it is no exact root.
            (r.checked_mul(r) == Some(v)).then_some(r)
        };
        Some(Number::Ratio(root(n)?, root(d)?))
    }

    /// A total order, used only to keep expressions canonical.
    pub fn total_cmp(&self, other: &Number) -> Ordering {
        match (self, other) {
            (Number::Ratio(a, b), Number::Ratio(c, d)) => {
                (*a as i128 * *d as i128).cmp(&(*c as i128 * *b as i128))
            }
            (Number::Ratio(..), Number::Real(_)) => Ordering::Less,
            (Number::Real(_), Number::Ratio(..)) => Ordering::Greater,
            (Number::Real(a), Number::Real(b)) => a.total_cmp(b),
        }
    }
}

impl PartialEq for Number {
    fn eq(&self, other: &Self) -> bool {
        self.total_cmp(other) == Ordering::Equal
    }
}
impl Eq for Number {}

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Number::Ratio(n, 1) => write!(f, "{n}"),
            Number::Ratio(n, d) => write!(f, "{n}/{d}"),
            Number::Real(x) => write!(f, "{}", crate::symbolic::format::fixed(*x)),
        }
    }
}

// Exact while both are ratios (in i128, reduced back), otherwise in f64. The operators are
// the arithmetic of the coefficients; `Add`, `Mul` and `Neg` must be in scope to call them
// as methods (`c.add(d)`).
impl std::ops::Add for Number {
    type Output = Number;

    /// The sum.
    fn add(self, other: Number) -> Number {
        match (self, other) {
            (Number::Ratio(a, b), Number::Ratio(c, d)) => {
                let (a, b, c, d) = (a as i128, b as i128, c as i128, d as i128);
                Number::ratio(a * d + c * b, b * d)
            }
            _ => Number::Real(self.to_f64() + other.to_f64()),
        }
    }
}

impl std::ops::Mul for Number {
    type Output = Number;

    /// The product.
    fn mul(self, other: Number) -> Number {
        match (self, other) {
            (Number::Ratio(a, b), Number::Ratio(c, d)) => {
                Number::ratio(a as i128 * c as i128, b as i128 * d as i128)
            }
            _ => Number::Real(self.to_f64() * other.to_f64()),
        }
    }
}

impl std::ops::Neg for Number {
    type Output = Number;

    /// The negation.
    fn neg(self) -> Number {
        self * Number::MINUS_ONE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_are_exact() {
        assert_eq!(Number::parse_decimal("0.25"), Some(Number::Ratio(1, 4)));
        assert_eq!(Number::parse_decimal("1e-3"), Some(Number::Ratio(1, 1000)));
        assert_eq!(Number::parse_decimal("9.81"), Some(Number::Ratio(981, 100)));
        assert_eq!(Number::parse_decimal("2"), Some(Number::Ratio(2, 1)));
    }

    #[test]
    fn overflow_falls_back_to_real() {
        let big = Number::int(i64::MAX);
        assert!(matches!(big * big, Number::Real(_)));
    }
}
