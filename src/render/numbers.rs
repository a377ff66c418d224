//! Numbers as print shows them, in a field of their own or in a sentence: `1e-9` as
//! $10^{-9}$ in LaTeX and as 10⁻⁹ in text, `-2.5e7` as −2.5×10⁷.

/// `text` with each number in scientific notation (`1e-9`, `-2.5e+07`) written by
/// `number` and the text between them by `other`.
pub(super) fn with_numbers(
    text: &str,
    number: impl Fn(&str) -> String,
    other: impl Fn(&str) -> String,
) -> String {
    pieces(text)
        .map(|(is_number, piece)| {
            if is_number {
                number(piece)
            } else {
                other(piece)
            }
        })
        .collect()
}

/// `text` with each negative number written apart from its words (`-0.396863` at the start
/// or after a space or bracket, not the hyphen of `t-1`) by `number`, so that it prints
/// with a minus sign, and the text between by `other`.
pub(super) fn with_negatives(
    text: &str,
    number: impl Fn(&str) -> String,
    other: impl Fn(&str) -> String,
) -> String {
    let bytes = text.as_bytes();
    let mut out = String::new();
    let (mut start, mut i) = (0, 0);
    while i < bytes.len() {
        let boundary = i == 0 || matches!(bytes[i - 1], b' ' | b'(' | b'[' | b'=' | b',');
        let negative =
            boundary && bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit);
        if !negative {
            i += 1;
            continue;
        }
        let mut end = i + 1;
        while end < bytes.len() && (bytes[end].is_ascii_digit() || bytes[end] == b'.') {
            end += 1;
        }
        if text[i + 1..end].ends_with('.') {
            end -= 1;
        }
        if start < i {
            out.push_str(&other(&text[start..i]));
        }
        out.push_str(&number(&text[i..end]));
        (start, i) = (end, end);
    }
    if start < text.len() {
        out.push_str(&other(&text[start..]));
    }
    out
}

/// `escape` of `piece`, whose leading and trailing spaces (which the escapes trim, as for a
/// whole field) separate it from the numbers beside it.
pub(super) fn keeping_spaces(piece: &str, escape: impl Fn(&str) -> String) -> String {
    let space = |present: bool| if present { " " } else { "" };
    format!(
        "{}{}{}",
        space(piece.starts_with(char::is_whitespace)),
        escape(piece.trim()),
        space(piece.ends_with(char::is_whitespace) && !piece.trim().is_empty())
    )
}

/// `text` cut into the numbers in scientific notation (`1e-9`, `-2.5e+07`) and the rest, in
/// order: `(true, number)` or `(false, other text)`.
fn pieces(text: &str) -> impl Iterator<Item = (bool, &str)> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let (mut start, mut i) = (0, 0);
    while i < bytes.len() {
        let boundary = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'.');
        match scientific_at(bytes, i).filter(|_| boundary) {
            Some(end) => {
                if start < i {
                    out.push((false, &text[start..i]));
                }
                out.push((true, &text[i..end]));
                (start, i) = (end, end);
            }
            None => i += 1,
        }
    }
    if start < text.len() {
        out.push((false, &text[start..]));
    }
    out.into_iter()
}

/// The end of a number in scientific notation starting at `i`, if one does: an optional
/// `-`, digits, an optional fraction, `e`, an optional sign and digits, and then no letter
/// or digit.
fn scientific_at(bytes: &[u8], i: usize) -> Option<usize> {
    let digits = |from: usize| {
        let n = bytes[from..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        (n > 0).then_some(from + n)
    };
    let mut at = i + usize::from(bytes.get(i) == Some(&b'-'));
    at = digits(at)?;
    if bytes.get(at) == Some(&b'.') {
        at = digits(at + 1)?;
    }
    if bytes.get(at) != Some(&b'e') {
        return None;
    }
    at += 1;
    if matches!(bytes.get(at), Some(b'-' | b'+')) {
        at += 1;
    }
    at = digits(at)?;
    match bytes.get(at) {
        Some(b) if b.is_ascii_alphanumeric() => None,
        _ => Some(at),
    }
}

/// A number in scientific notation as plain text prints it: `5.99959e-10` as
/// `5.99959×10⁻¹⁰`, `1e-6` as `10⁻⁶`; any other number as it is.
pub(super) fn unicode_number(text: &str) -> String {
    let Some((mantissa, exponent)) = text.split_once('e') else {
        return text.to_string();
    };
    let power: String = exponent
        .trim_start_matches('+')
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            d => char::from_u32(0x2070 + d.to_digit(10).unwrap_or(0)).unwrap_or(d),
        })
        .collect();
    match mantissa {
        "1" => format!("10{power}"),
        "-1" => format!("−10{power}"),
        _ => format!("{}×10{power}", mantissa.replace('-', "−")),
    }
}

/// Whether `text` is a number as [`crate::symbolic::fixed`] writes it.
pub(super) fn is_number(text: &str) -> bool {
    matches!(text, "NaN" | "inf" | "-inf")
        || (text.parse::<f64>().is_ok()
            && text
                .chars()
                .all(|c| c.is_ascii_digit() || "+-.e".contains(c)))
}

/// A number in math mode, so that `-` is a minus sign and `1e-9` is `1 \times 10^{-9}`.
pub(super) fn latex_number(text: &str) -> String {
    match text {
        "NaN" => "NaN".into(),
        _ => format!("${}$", math_number(text)),
    }
}

/// A number as math-mode LaTeX (without `$`): `1e-9` as `1 \times 10^{-9}`, `inf` as
/// `\infty`.
pub(super) fn math_number(text: &str) -> String {
    match text {
        "NaN" => "\\text{NaN}".into(),
        "inf" => "\\infty".into(),
        "-inf" => "-\\infty".into(),
        _ => match text.split_once('e') {
            Some((mantissa, exponent)) => {
                let exponent = exponent.trim_start_matches('+');
                if mantissa == "1" {
                    format!("10^{{{exponent}}}")
                } else {
                    format!("{mantissa} \\times 10^{{{exponent}}}")
                }
            }
            None => text.to_string(),
        },
    }
}
