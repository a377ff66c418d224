//! Markdown's math with plain brackets where nothing tall stands between them: `(a + b)`
//! for `\left(a + b\right)`, as a textbook writes a flat group. A group holding a fraction,
//! a sum, a root or an array keeps its sized brackets. The text is shorter to read in the
//! Markdown source and prints the same at the size of the line.

/// What makes a group taller than the line, so that its brackets are sized to it.
const TALL: [&str; 10] = [
    "\\frac", "\\dfrac", "\\tfrac", "\\sum", "\\prod", "\\int", "\\sqrt", "\\begin", "\\binom",
    "\\middle",
];

/// `math` with every `\left(…\right)` and `\left[…\right]` around flat content written
/// with plain brackets; every other `\left…\right` pair kept, and the text unchanged when
/// its `\left` and `\right` do not pair up.
pub fn flat_brackets(math: &str) -> String {
    let mut open: Vec<usize> = Vec::new();
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for (at, _) in math.match_indices('\\') {
        let rest = &math[at..];
        if rest.starts_with("\\left") && delimiter(&rest[5..]) {
            open.push(at);
        } else if rest.starts_with("\\right") && delimiter(&rest[6..]) {
            match open.pop() {
                Some(left) => pairs.push((left, at)),
                None => return math.to_string(),
            }
        }
    }
    if !open.is_empty() {
        return math.to_string();
    }
    let mut dropped: Vec<(usize, usize)> = pairs
        .into_iter()
        .filter(|&(left, right)| {
            let (opening, closing) = (&math[left + 5..], &math[right + 6..]);
            let round = opening.starts_with('(') && closing.starts_with(')');
            let square = opening.starts_with('[') && closing.starts_with(']');
            let inside = &math[left + 6..right];
            (round || square) && !TALL.iter().any(|t| inside.contains(t))
        })
        .flat_map(|(left, right)| [(left, 5), (right, 6)])
        .collect();
    dropped.sort_unstable();
    let mut out = String::with_capacity(math.len());
    let mut from = 0;
    for (at, length) in dropped {
        out.push_str(&math[from..at]);
        from = at + length;
    }
    out.push_str(&math[from..]);
    out
}

/// Whether `rest` opens with a delimiter (`(`, `[`, `.`, `|`, `\{`, `\langle`, …), not
/// with the letters of a longer command (`\leftarrow`, `\rightarrow`).
fn delimiter(rest: &str) -> bool {
    rest.chars()
        .next()
        .is_some_and(|c| !c.is_ascii_alphabetic())
}

#[cfg(test)]
mod tests {
    use super::flat_brackets;

    fn check(math: &str, flat: &str) {
        assert_eq!(flat_brackets(math), flat, "{math}");
    }

    #[test]
    fn flat_groups_take_plain_brackets_and_tall_ones_keep_theirs() {
        check("\\left(a + b\\right)^{2}", "(a + b)^{2}");
        check("\\left[F_{x} - m a\\right] = 0", "[F_{x} - m a] = 0");
        check(
            "\\left(\\frac{L}{2} + x\\right)",
            "\\left(\\frac{L}{2} + x\\right)",
        );
        check(
            "\\left(a \\left(b + c\\right)\\right) + \\left(\\sqrt{x}\\right)",
            "(a (b + c)) + \\left(\\sqrt{x}\\right)",
        );
        check(
            "\\left(\\left(\\frac{1}{2}\\right) + c\\right)",
            "\\left(\\left(\\frac{1}{2}\\right) + c\\right)",
        );
        check("\\left\\{a\\right\\}", "\\left\\{a\\right\\}");
        check("\\left. x \\right|_{0}", "\\left. x \\right|_{0}");
        check(
            "a \\leftarrow b \\rightarrow c",
            "a \\leftarrow b \\rightarrow c",
        );
        check("\\left(a", "\\left(a");
    }
}
