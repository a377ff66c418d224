//! Long displayed math broken into lines: before a `+`, `-` or `=` outside braces and
//! environments, each line filled to a width measured by [`math_width`], a bracket split
//! over lines the textbook way (`\\right.` … `\\left.`).

use super::math_width;

/// The longest LaTeX a broken display is measured whole for: a longer one cannot fit a line.
pub(super) const MEASURED_AT_MOST: usize = 500;

/// How many symbols (see [`math_width`]) a line of displayed math holds in the HTML page.
pub(super) const HTML_WIDTH: f64 = 64.0;

/// How many symbols a line of a LaTeX display holds. A `multline*` line has 489 pt; over
/// the bundled handouts (every line measured by LaTeX's `\settowidth`) 72 symbols made the
/// widest line 484 pt, so 70 leaves room for symbols wider than those seen.
pub const LINE_SYMBOLS: f64 = 70.0;

/// The most characters of LaTeX one displayed equation holds: a longer one goes on in the
/// next display, since `multline*` cannot break across pages and a reader cannot take in
/// more at once.
pub const DISPLAY_LIMIT: usize = 2400;

/// Lines of math as displays: one line in `\[…\]` (`multline*` would stretch its spaces
/// to the full width), several in `multline*`, and a new display wherever the next line
/// would take one past [`DISPLAY_LIMIT`] characters.
pub(super) fn displays(lines: &[String]) -> String {
    let mut groups: Vec<Vec<&str>> = Vec::new();
    let mut length = 0;
    for line in lines {
        match groups.last_mut() {
            Some(group) if length + line.len() <= DISPLAY_LIMIT => {
                group.push(line);
                length += line.len() + 4;
            }
            _ => {
                groups.push(vec![line]);
                length = line.len();
            }
        }
    }
    groups
        .iter()
        .map(|group| match group.as_slice() {
            [one] => format!("\\[\n{one}\n\\]"),
            _ => format!(
                "\\begin{{multline*}}\n{}\n\\end{{multline*}}",
                group.join(" \\\\ ")
            ),
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Breaks LaTeX math before `+`, `-` and `=` so that no line is much wider than `width`
/// symbols as printed; lines are joined by `\\`, for `multline*`.
#[cfg(test)]
fn break_lines(latex: &str, width: f64) -> String {
    break_into_lines(latex, width).join(" \\\\ ")
}

/// The lines of `break_lines`, each whole: a `\left` left open at a break is closed by
/// `\right.` and reopened by `\left.` on the next line.
///
/// It never breaks inside braces (`\frac{…}{…}`) or environments (`bmatrix`), where a `\\`
/// would not compile. Inside `\left( … \right)` it closes the open delimiters with
/// `\right.` before the break and reopens them with `\left.` after it, the textbook way to
/// split a long bracket over lines.
pub fn break_into_lines(latex: &str, width: f64) -> Vec<String> {
    let opened = open_long_fractions(latex, width);
    let latex = opened.as_str();
    // (where a piece starts, how many `\left` are open there)
    let mut starts: Vec<(usize, usize)> = vec![(0, 0)];
    let (mut braces, mut environments, mut open) = (0i32, 0i32, 0usize);
    // For each open `\left`, whether it holds a function's argument, cos(λ + θ), which
    // a textbook never splits over lines.
    let mut arguments: Vec<bool> = Vec::new();
    let bytes = latex.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let rest = &latex[i..];
        if let Some(length) = command_at(rest, "\\left") {
            open += 1;
            arguments.push(ends_with_function(&latex[..i]));
            i += length;
            continue;
        }
        if let Some(length) = command_at(rest, "\\right") {
            open = open.saturating_sub(1);
            arguments.pop();
            i += length;
            continue;
        }
        if let Some(length) = command_at(rest, "\\begin") {
            environments += 1;
            i += length;
            continue;
        }
        if let Some(length) = command_at(rest, "\\end") {
            environments -= 1;
            i += length;
            continue;
        }
        match bytes[i] {
            b'\\' => i += 1, // `\{`, `\}`, `\\` are not groups
            b'{' => braces += 1,
            b'}' => braces -= 1,
            b'+' | b'-' | b'='
                if braces == 0
                    && environments == 0
                    && !arguments.contains(&true)
                    && i > 0
                    && bytes[i - 1] == b' ' =>
            {
                starts.push((i, open));
            }
            _ => {}
        }
        i += 1;
    }
    let ends = starts
        .iter()
        .skip(1)
        .map(|&(at, _)| at)
        .chain([latex.len()]);
    let pieces: Vec<Piece> = starts
        .iter()
        .zip(ends)
        .map(|(&(start, open), end)| Piece {
            start,
            open,
            width: math_width::symbols(&latex[start..end]),
        })
        .collect();
    line_starts(&pieces, width)
        .windows(2)
        .map(|line| {
            let (first, next) = (&pieces[line[0]], pieces.get(line[1]));
            let mut text = "\\left.".repeat(first.open);
            text.push(' ');
            text.push_str(&latex[first.start..next.map_or(latex.len(), |p| p.start)]);
            text.push_str(&"\\right.".repeat(next.map_or(0, |p| p.open)));
            text.trim().to_string()
        })
        .collect()
}

/// A stretch of an equation between two places it may break.
struct Piece {
    start: usize,
    /// How many `\left` are open where it starts.
    open: usize,
    width: f64,
}

/// Where each line starts (indices into `pieces`), and `pieces.len()` last: lines filled up
/// to `width`, a short last piece (`= 0`) kept on its line, and a line that would break
/// inside a bracket broken before the bracket's term instead when that leaves the line at
/// least [`FULL_ENOUGH`] full, as a textbook keeps a term whole.
fn line_starts(pieces: &[Piece], width: f64) -> Vec<usize> {
    let mut starts = vec![0];
    let mut line_width = 0.0;
    for (i, piece) in pieces.iter().enumerate() {
        let line_start = *starts.last().unwrap_or(&0);
        let short_end = i + 1 == pieces.len() && piece.width <= 6.0;
        if i == line_start || line_width + piece.width <= width || short_end {
            line_width += piece.width;
            continue;
        }
        let mut at = i;
        if piece.open > 0 {
            let outside = (line_start + 1..i).rev().find(|&j| pieces[j].open == 0);
            if let Some(j) = outside {
                let before: f64 = pieces[line_start..j].iter().map(|p| p.width).sum();
                // The term that starts at `j`, to where the next one starts outside brackets:
                // a term that fits a line of its own is kept whole, however short the line
                // before it is left.
                let end = (j + 1..pieces.len())
                    .find(|&k| pieces[k].open == 0)
                    .unwrap_or(pieces.len());
                let term: f64 = pieces[j..end].iter().map(|p| p.width).sum();
                if before >= FULL_ENOUGH * width || term <= width {
                    at = j;
                }
            }
        }
        starts.push(at);
        line_width = pieces[at..=i].iter().map(|p| p.width).sum();
    }
    starts.push(pieces.len());
    starts
}

/// How full a line must be for a break to move back out of a bracket.
const FULL_ENOUGH: f64 = 0.6;

/// `latex` with every `\\frac{N}{D}` outside braces whose numerator prints wider than
/// `width` written `\\frac{1}{D} \\left(N\\right)`, and every `\\sqrt{R}` whose sum
/// under the root does `\\left(R\\right)^{1/2}`, the same values, which
/// [`break_into_lines`] can then break inside the bracket (never inside braces).
fn open_long_fractions(latex: &str, width: f64) -> String {
    let bytes = latex.as_bytes();
    let mut out = String::with_capacity(latex.len() + 16);
    let (mut copied, mut braces, mut i) = (0, 0i32, 0);
    while i < bytes.len() {
        if braces == 0 {
            if let Some(length) = latex.get(i..).and_then(|rest| command_at(rest, "\\sqrt")) {
                if let Some((open, close)) = brace_group(latex, i + length) {
                    let radicand = &latex[open..close];
                    let sum = radicand.contains(" + ") || radicand.contains(" - ");
                    if sum && math_width::symbols(radicand) > width {
                        out.push_str(&latex[copied..i]);
                        out.push_str(&format!(
                            "\\left({}\\right)^{{1/2}}",
                            open_long_fractions(radicand, width)
                        ));
                        copied = close + 1;
                        i = close + 1;
                        continue;
                    }
                }
            }
            if let Some(length) = latex.get(i..).and_then(|rest| command_at(rest, "\\frac")) {
                if let Some((numerator, denominator, end)) = two_groups(latex, i + length) {
                    // Only a sum can be broken; a long product stays a fraction.
                    let sum = numerator.contains(" + ") || numerator.contains(" - ");
                    if sum
                        && math_width::symbols(numerator) > width
                        && math_width::symbols(denominator) <= 12.0
                    {
                        out.push_str(&latex[copied..i]);
                        out.push_str(&format!(
                            "\\frac{{1}}{{{denominator}}} \\left({}\\right)",
                            open_long_fractions(numerator, width)
                        ));
                        copied = end;
                        i = end;
                        continue;
                    }
                }
            }
        }
        match bytes[i] {
            b'\\' => i += 1, // `\{`, `\}` are not groups
            b'{' => braces += 1,
            b'}' => braces -= 1,
            _ => {}
        }
        i += 1;
    }
    out.push_str(&latex[copied.min(latex.len())..]);
    out
}

/// Where the contents of the brace group that starts at `from` (after spaces) begin and
/// end (its closing brace).
fn brace_group(latex: &str, from: usize) -> Option<(usize, usize)> {
    let bytes = latex.as_bytes();
    let mut i = from;
    while bytes.get(i) == Some(&b' ') {
        i += 1;
    }
    if bytes.get(i) != Some(&b'{') {
        return None;
    }
    let (open, mut depth) = (i, 0i32);
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => i += 1,
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return Some((open + 1, i));
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// The contents of the two brace groups that start at `start` (after spaces), and where
/// the second ends.
fn two_groups(latex: &str, start: usize) -> Option<(&str, &str, usize)> {
    let (a, a_end) = brace_group(latex, start)?;
    let (b, b_end) = brace_group(latex, a_end + 1)?;
    Some((&latex[a..a_end], &latex[b..b_end], b_end + 1))
}

/// Whether `before` ends with a function's name (`\\cos`, `\\sin^{2}`), so that a bracket
/// opened next holds its argument.
fn ends_with_function(before: &str) -> bool {
    const FUNCTIONS: [&str; 12] = [
        "sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "arcsin", "arccos", "arctan",
    ];
    let mut text = before.trim_end();
    // A power written before the argument, as in sin²(λ + θ).
    if let Some(stem) = text.strip_suffix('}') {
        if let Some(at) = stem.rfind("^{") {
            text = &text[..at];
        }
    }
    let name_start = text
        .rfind(|c: char| !c.is_ascii_alphabetic())
        .map_or(0, |at| at + 1);
    text[..name_start].ends_with('\\') && FUNCTIONS.contains(&&text[name_start..])
}

/// The length of `command` if `text` starts with it as a whole word (`\\left`, not `\\leftarrow`).
fn command_at(text: &str, command: &str) -> Option<usize> {
    let after = text.strip_prefix(command)?;
    (!after.starts_with(|c: char| c.is_ascii_alphabetic())).then_some(command.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_math_breaks_only_at_top_level() {
        let latex = "aaaaaaa + bbbbbbb + ccccccc = 0";
        assert_eq!(break_lines(latex, 1000.0), latex);
        assert_eq!(
            break_lines(latex, 10.0),
            "aaaaaaa \\\\ + bbbbbbb \\\\ + ccccccc = 0"
        );
        let grouped = "x = \\left(aaaaaaa + \\sqrt{bbbbbbb + c}\\right)^{2} + {ddddddd - eeeeeee}";
        assert_eq!(
            break_lines(grouped, 11.0),
            "x = \\left(aaaaaaa \\right. \\\\ \\left. + \\sqrt{bbbbbbb + c}\\right)^{2} \\\\ + {ddddddd - eeeeeee}"
        );
        let matrix = "\\begin{bmatrix} aaaaaaa - bbbbbbb \\end{bmatrix}";
        assert_eq!(break_lines(matrix, 3.0), matrix);
        assert_eq!(
            break_lines("a \\rightarrow b + cccccccc", 1.0),
            "a \\rightarrow b \\\\ + cccccccc"
        );
        // A long numerator is taken out of the fraction, and broken inside the bracket.
        let fraction = "- \\frac{L \\left(aaaaaaa + bbbbbbb\\right) c}{2} = 0";
        assert_eq!(
            break_lines(fraction, 10.0),
            "- \\frac{1}{2} \\left(L \\left(aaaaaaa \\right.\\right. \\\\ \\left.\\left. + bbbbbbb\\right) c\\right) = 0"
        );
        assert_eq!(break_lines(fraction, 100.0), fraction);
        // A function's argument is never split over lines.
        assert_eq!(
            break_lines("a \\cos\\left(\\lambda + \\theta\\right) + b + c", 3.0),
            "a \\cos\\left(\\lambda + \\theta\\right) \\\\ + b + c"
        );
        assert_eq!(
            break_lines("\\sin^{2}\\left(x - y\\right) + bbbbbbbb", 1.0),
            "\\sin^{2}\\left(x - y\\right) \\\\ + bbbbbbbb"
        );
        // A long sum under a root is raised to the power 1/2, and broken in its bracket.
        let root = "V = \\frac{1}{2} k \\left(\\sqrt{aaaaaaa + bbbbbbb - c} - l\\right)^{2}";
        let lines = break_into_lines(root, 14.0);
        assert!(lines.len() > 1, "{lines:?}");
        let joined = lines.concat();
        assert!(!joined.contains("\\sqrt"), "{lines:?}");
        assert!(joined.contains("\\left(aaaaaaa"), "{lines:?}");
        assert!(joined.contains("c\\right)^{1/2}"), "{lines:?}");
        assert_eq!(break_lines(root, 100.0), root);
        let short = "x = \\sqrt{a + b} + ccccccccccccccc";
        assert_eq!(
            break_lines(short, 10.0),
            "x = \\sqrt{a + b} \\\\ + ccccccccccccccc"
        );
        // A long product has nowhere to break: it stays a fraction.
        let product = "\\frac{L a b c d e f g h i j k}{2}";
        assert_eq!(break_lines(product, 5.0), product);
    }

    #[test]
    fn a_line_fills_up_and_breaks_before_a_term_rather_than_inside_its_bracket() {
        let row = "-\\frac{L^{2} m}{2} \\left(8 + 5 c_{3} + 6 c_{4} + 2 c_{5} + 5 c_{23} + 3 c_{34} + 2 c_{45}\\right) \\ddot{q}_{1} - \\frac{L^{2} m}{2} \\left(8 + 5 c_{3} + 6 c_{4}\\right) \\ddot{q}_{2} = 0";
        // The first term is 40 symbols and the line holds 46: the second term's bracket
        // would be broken after "(8", so the line ends before that term instead.
        let lines = break_into_lines(row, 46.0);
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(lines[0].ends_with("\\ddot{q}_{1}"), "{lines:?}");
        assert!(
            lines[1].starts_with("- \\frac{L^{2} m}{2} \\left(8 + 5"),
            "{lines:?}"
        );
        // A term that fits a line of its own is not split, even after a short line: the
        // first term's bracket ends the line "bb) x", and the second term starts the next.
        let row =
            "\\left(aaaaaaaaaa + bbbbbbbbbb\\right) x - c \\left(dddddd + eeeeee\\right) y = 0";
        let lines = break_into_lines(row, 22.0);
        let second = lines
            .iter()
            .find(|l| l.contains("dddddd"))
            .expect("second term");
        assert!(
            second.contains("eeeeee") && second.starts_with("- c"),
            "{lines:?}"
        );
        assert!(!second.contains("\\left."), "{lines:?}");
        // Many short terms still fill lines: none is let past the width.
        let sum = (1..=40)
            .map(|i| format!("a_{{{i}}}"))
            .collect::<Vec<_>>()
            .join(" + ");
        for line in break_into_lines(&sum, 30.0) {
            assert!(math_width::symbols(&line) <= 30.0, "{line}");
        }
    }
}
