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
    line_within(left, relation, right, RIGHT_SYMBOLS)
}

/// As [`line`], the right side broken to `width` symbols a line: a display of its own
/// whose left sides are short (Kane's `F̃^*_{r,B}`) holds more than one set beside words.
pub fn line_within(left: &str, relation: &str, right: &str, width: f64) -> String {
    let pieces = break_into_lines(right, width);
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

/// The most symbols a chain of steps joined into one line may take: with `F_r` and the
/// reaction beside it, a third of the line is left for it.
const ONE_LINE_SYMBOLS: f64 = 40.0;

/// `a &= b`, `&= c`, … as the one line `a &= b = c`, where each step after the first is a
/// whole right side (no continued sum) and together they fit [`ONE_LINE_SYMBOLS`].
fn in_one_line(lines: &[String]) -> Option<String> {
    // A line as given may hold several, joined already.
    let lines: Vec<&str> = (lines.iter())
        .flat_map(|l| l.split(" \\\\ "))
        .map(str::trim)
        .collect();
    let (first, rest) = lines.split_first()?;
    if rest.is_empty() || !rest.iter().all(|l| l.starts_with("&= ")) {
        return None;
    }
    let mut joined = first.to_string();
    for step in rest {
        joined.push(' ');
        joined.push_str(&step[1..]);
    }
    (crate::render::symbols(&joined) <= ONE_LINE_SYMBOLS).then_some(joined)
}

/// The most characters of LaTeX the whole sum may take as the last line of
/// [`sum_of_parts`]: a longer one is read in the row's sum below it.
const LONGEST_WHOLE: usize = 900;

/// A generalized force as the sum of its bodies' parts, as one display: `name = parts…`,
/// then `lines` (each part worked), then the whole as the row writes it (`whole`,
/// `F^*_r = …`) last, where more than one part adds up to it and it is a formula short
/// enough to read. A problem of one body has no parts to sum: its one part is the whole,
/// worked under the whole's name. `None` when the display would pass what one display
/// holds (see [`crate::render::DISPLAY_LIMIT`]).
pub fn sum_of_parts(
    name: &str,
    parts: &[String],
    mut lines: Vec<String>,
    whole: &str,
    one_body: bool,
) -> Option<String> {
    let mut out = Vec::new();
    match (parts, lines.first_mut()) {
        ([only], Some(first)) if first.starts_with(only.as_str()) => {
            // Of several bodies, the one that moves with the speed is named in the line.
            let rest = &first[only.len()..];
            *first = if one_body {
                format!("{name}{rest}")
            } else {
                let rest = rest.trim_start().trim_start_matches('&');
                format!("{name} &= {only} {rest}")
            };
        }
        _ => out.push(line(name, "=", &parts.join(" + "))),
    }
    out.extend(lines);
    // One body's few short steps read in one line: `F^*_4 = v_4 · R^* + ω_4 · T^* = −m ẍ`.
    if let Some(one_line) = (parts.len() == 1).then(|| in_one_line(&out)).flatten() {
        out = vec![one_line];
    }
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

#[cfg(test)]
mod tests {
    use super::sum_of_parts;

    #[test]
    fn one_bodys_part_is_worked_under_the_wholes_name() {
        let lines = vec![
            "F^{*}_{4,D} &= \\mathbf{v}^{D^*}_{4} \\cdot \\mathbf{R}^{*}_{D}".to_string(),
            " &= -m \\ddot{x}".to_string(),
        ];
        let parts = ["F^{*}_{4,D}".to_string()];
        let one = sum_of_parts("F^{*}_{4}", &parts, lines.clone(), "", true).expect("short");
        assert_eq!(
            one,
            "\\begin{aligned} F^{*}_{4} &= \\mathbf{v}^{D^*}_{4} \\cdot \\mathbf{R}^{*}_{D} = -m \\ddot{x} \\end{aligned}"
        );
        // The same steps given as one line already joined.
        let joined = vec![lines.join(" \\\\ ")];
        let again = sum_of_parts("F^{*}_{4}", &parts, joined, "", true).expect("short");
        assert_eq!(again, one);
        // Of two bodies, the one that moves with the speed is named in the same line.
        let two = sum_of_parts("F^{*}_{4}", &parts, lines, "", false).expect("short");
        assert_eq!(
            two,
            "\\begin{aligned} F^{*}_{4} &= F^{*}_{4,D} = \\mathbf{v}^{D^*}_{4} \\cdot \\mathbf{R}^{*}_{D} = -m \\ddot{x} \\end{aligned}"
        );
    }

    #[test]
    fn a_long_chain_of_steps_keeps_its_lines() {
        let long = "a_{1} + a_{2} + a_{3} + a_{4} + a_{5} + a_{6} + a_{7} + a_{8} + a_{9} + a_{10}";
        let lines = vec![format!("F^{{*}}_{{1,D}} &= {long}"), format!("&= {long}")];
        let parts = ["F^{*}_{1,D}".to_string()];
        let block = sum_of_parts("F^{*}_{1}", &parts, lines, "", true).expect("short");
        assert!(block.contains(" \\\\ &= "), "{block}");
        assert!(
            block.starts_with("\\begin{aligned} F^{*}_{1} &= a_{1}"),
            "{block}"
        );
    }
}
