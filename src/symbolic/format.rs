//! Fixed-precision number formatting, so that output is byte-identical run to run.

/// Significant digits used wherever a number reaches text that may be snapshotted.
pub const SIGNIFICANT_DIGITS: usize = 6;

/// `x` with `SIGNIFICANT_DIGITS` significant digits, trailing zeros removed,
/// scientific notation outside 1e-4 ..= 1e6, and no negative zero.
pub fn fixed(x: f64) -> String {
    if !x.is_finite() {
        return if x.is_nan() {
            "NaN".into()
        } else if x > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        };
    }
    let magnitude = x.abs();
    let rounded: f64 = format!("{:.*e}", SIGNIFICANT_DIGITS - 1, x)
        .parse()
        .unwrap_or(x);
    if rounded == 0.0 {
        return "0".into();
    }
    if !(1e-4..1e6).contains(&magnitude) {
        let text = format!("{:.*e}", SIGNIFICANT_DIGITS - 1, rounded);
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        return format!("{}e{}", trim_zeros(mantissa), exponent);
    }
    let decimals =
        (SIGNIFICANT_DIGITS as i32 - 1 - rounded.abs().log10().floor() as i32).max(0) as usize;
    trim_zeros(&format!("{rounded:.decimals$}"))
}

/// `x` as [`fixed`] writes it, or `0` below 1e-12 in magnitude: a value that cancels at a
/// state (an acceleration of a system in equilibrium, an entry of a matrix) prints as 0,
/// not as its rounding error.
pub fn fixed_or_zero(x: f64) -> String {
    fixed(if x.abs() < 1e-12 { 0.0 } else { x })
}

fn trim_zeros(text: &str) -> String {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::fixed;

    #[test]
    fn fixed_precision() {
        assert_eq!(fixed(9.81), "9.81");
        assert_eq!(fixed(1.0 / 3.0), "0.333333");
        assert_eq!(fixed(-0.0), "0");
        assert_eq!(fixed(1e-9), "1e-9");
        assert_eq!(fixed(123456789.0), "1.23457e8");
        assert_eq!(fixed(-2.5), "-2.5");
        assert_eq!(fixed(100.0), "100");
    }
}
