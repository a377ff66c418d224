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
