//! Lines of an `aligned` display that fit the page: a long right side broken before a
//! `+` or `-` and continued on the next line, indented past the `=`, as a textbook breaks
//! a long sum.

use crate::render::break_into_lines;

/// How many symbols (see [`crate::render::math_width`]) the right side of one line of an
/// aligned display holds: the page's line less a short left side.
const RIGHT_SYMBOLS: f64 = 46.0;

/// `left &= right`, the right side broken over as many lines as it needs, each
/// continuation `&\quad + …`; the lines joined by `\\`.
pub fn line(left: &str, relation: &str, right: &str) -> String {
    let pieces = break_into_lines(right, RIGHT_SYMBOLS);
    let mut out = String::new();
    for (i, piece) in pieces.iter().enumerate() {
        let piece = piece.trim();
        if i == 0 {
            out.push_str(&format!("{left} &{relation} {piece}"));
        } else {
            out.push_str(&format!(" \\\\ &\\quad {piece}"));
        }
    }
    if pieces.is_empty() {
        out.push_str(&format!("{left} &{relation} {right}"));
    }
    out
}

/// Lines of an aligned display, each already `left & right`, as one display.
pub fn display(lines: &[String]) -> String {
    format!(
        "\\begin{{aligned}} {} \\end{{aligned}}",
        lines.join(" \\\\ ")
    )
}

/// The most characters of LaTeX the whole sum may take as the last line of
/// [`sum_of_parts`]: a longer one is read in the row's sum below it.
const LONGEST_WHOLE: usize = 900;

/// A generalized force as the sum of its bodies' parts, as one display: `name = parts…`,
/// then `lines` (each part worked), then the whole as the row writes it (`whole`,
/// `F^*_r = …`) last, where more than one part adds up to it and it is a formula short
/// enough to read. `None` when the display would pass what one display holds (see
/// [`crate::render::DISPLAY_LIMIT`]).
pub fn sum_of_parts(
    name: &str,
    parts: &[String],
    lines: Vec<String>,
    whole: &str,
) -> Option<String> {
    let mut out = vec![line(name, "=", &parts.join(" + "))];
    out.extend(lines);
    let formula = whole
        .split_once(" = ")
        .map(|(_, f)| f)
        .filter(|f| !whole.contains("\\text{") && f.len() <= LONGEST_WHOLE);
    if let (Some(formula), true) = (formula, parts.len() > 1) {
        out.push(line(name, "=", formula));
    }
    let block = display(&out);
    (block.len() <= crate::render::DISPLAY_LIMIT).then_some(block)
}
