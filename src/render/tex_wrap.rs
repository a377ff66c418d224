//! Inline math that a LaTeX table cell or a list item can wrap.
//!
//! TeX breaks inline math only after a relation or a binary operator at the formula's
//! outer level: never after a comma, never inside `\left( … \right)` (a subformula) or
//! `\text{…}` (a box). So a list of unknowns, an orientation "rotated by … about …" or a
//! position with brackets would stick out of a narrow column. [`wrap`] writes the same
//! math so that it can break there: a permitted break after each comma of a list, `\bigl(`
//! and `\bigr)` for `\left(` and `\right)`, and the words of `\text{…}` as text.

/// The longest source line [`short_source_lines`] leaves, in bytes.
const LONGEST_SOURCE_LINE: usize = 200;

/// `tex` with every source line longer than `LONGEST_SOURCE_LINE` broken at spaces. TeX
/// reads a single line end as a space, so the pages are the same, and an editor or a diff
/// copes with the source. A line with a comment is left whole (a break before the `%` would
/// be safe, one after it would not), and so is a space after a backslash (a control space).
pub fn short_source_lines(tex: &str) -> String {
    let mut out = String::with_capacity(tex.len() + tex.len() / LONGEST_SOURCE_LINE);
    for line in tex.split_inclusive('\n') {
        if line.len() <= LONGEST_SOURCE_LINE || has_comment(line) {
            out.push_str(line);
            continue;
        }
        let mut run = 0;
        let mut previous = '\0';
        for c in line.chars() {
            if c == ' ' && run >= LONGEST_SOURCE_LINE && previous != '\\' {
                out.push('\n');
                run = 0;
            } else {
                out.push(c);
                run += c.len_utf8();
            }
            previous = c;
        }
    }
    out
}

/// Whether `line` holds a `%` that starts a comment (one not written `\%`).
fn has_comment(line: &str) -> bool {
    let bytes = line.as_bytes();
    (0..bytes.len()).any(|i| bytes[i] == b'%' && (i == 0 || bytes[i - 1] != b'\\'))
}

/// `math` (LaTeX math, without `$`) as LaTeX text-mode source: `$…$` pieces that may break
/// after commas and inside brackets, and the words of top-level `\text{…}` as text between
/// them. Empty for empty math.
pub fn wrap(math: &str) -> String {
    let math = math.trim();
    if math.is_empty() {
        return String::new();
    }
    let mut out = String::with_capacity(math.len() + 32);
    let mut piece = String::new();
    let flush = |piece: &mut String, out: &mut String| {
        let mut trimmed = piece.trim();
        // A control space `\ ` before the words loses its space to the trim: drop its
        // backslash too, or it would escape the closing `$`.
        if trimmed.ends_with('\\') && !trimmed.ends_with("\\\\") {
            trimmed = trimmed[..trimmed.len() - 1].trim_end();
        }
        if !trimmed.is_empty() {
            // Spaces around the math separate it from the words.
            if piece.starts_with(' ') {
                out.push(' ');
            }
            out.push('$');
            out.push_str(&breakable(trimmed));
            out.push('$');
            if piece.ends_with(' ') {
                out.push(' ');
            }
        }
        piece.clear();
    };
    let mut depth = 0i32;
    let mut rest = math;
    while let Some(c) = rest.chars().next() {
        if depth == 0 {
            if let Some(after) = rest.strip_prefix("\\text{") {
                if let Some(end) = group_end(after) {
                    flush(&mut piece, &mut out);
                    out.push_str(&after[..end]);
                    rest = &after[end + 1..];
                    continue;
                }
            }
        }
        match c {
            '\\' => {
                // A command or an escaped character goes over whole (`\{` is no group).
                let name = rest[1..]
                    .chars()
                    .take_while(char::is_ascii_alphabetic)
                    .count();
                let length = match name {
                    0 => 1 + rest[1..].chars().next().map_or(0, char::len_utf8),
                    _ => 1 + name,
                };
                piece.push_str(&rest[..length]);
                rest = &rest[length..];
                continue;
            }
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        piece.push(c);
        rest = &rest[c.len_utf8()..];
    }
    flush(&mut piece, &mut out);
    // A space of the math beside a space of the text: one is enough.
    out.split(' ')
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// Where the group that `text` is the inside of closes (the index of its `}`).
fn group_end(text: &str) -> Option<usize> {
    let mut depth = 0i32;
    let mut escaped = false;
    for (i, c) in text.char_indices() {
        match c {
            _ if escaped => escaped = false,
            '\\' => escaped = true,
            '{' => depth += 1,
            '}' if depth == 0 => return Some(i),
            '}' => depth -= 1,
            _ => {}
        }
    }
    None
}

/// `math` with a permitted break after each comma outside braces, and `\left`/`\right`
/// as `\bigl`/`\bigr` so that TeX can break inside the brackets (not for matrices, whose
/// brackets must grow).
fn breakable(math: &str) -> String {
    let mut math = math.to_string();
    if !math.contains("\\begin") {
        math = replace_command(&math, "\\left", "\\bigl");
        math = replace_command(&math, "\\right", "\\bigr");
    }
    let mut out = String::with_capacity(math.len() + 16);
    let (mut depth, mut brackets) = (0i32, 0i32);
    let mut rest = math.as_str();
    while let Some(c) = rest.chars().next() {
        if let Some(length) = ["\\bigl", "\\bigr"]
            .iter()
            .find_map(|command| command_at(rest, command))
        {
            brackets += if rest.starts_with("\\bigl") { 1 } else { -1 };
            out.push_str(&rest[..length]);
            rest = &rest[length..];
            continue;
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
        match c {
            '\\' => {
                if let Some(next) = rest.chars().next() {
                    out.push(next);
                    rest = &rest[next.len_utf8()..];
                }
            }
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => out.push_str("\\allowbreak"),
            // A sign of a sum inside a bracket (a binary one, with a space either side):
            // a break there costs more than one between the outer terms, so that TeX
            // breaks there only where no outer break will do.
            '+' | '-'
                if depth == 0
                    && brackets > 0
                    && out.ends_with(&format!(" {c}"))
                    && rest.starts_with(' ') =>
            {
                out.push_str(INSIDE_BRACKET);
            }
            _ => {}
        }
    }
    out
}

/// The penalty after a sign inside a bracket: TeX's after a binary sign between the outer
/// terms is 700 (`\binoppenalty`); this one outweighs two such breaks.
const INSIDE_BRACKET: &str = "\\penalty2500";

/// The length of `command` if `text` starts with it as a whole word (`\bigl`, not `\bigll`).
fn command_at(text: &str, command: &str) -> Option<usize> {
    let after = text.strip_prefix(command)?;
    (!after.starts_with(|c: char| c.is_ascii_alphabetic())).then_some(command.len())
}

/// `text` with the command `from` (a whole word: `\left`, not `\leftarrow`) written `to`.
fn replace_command(text: &str, from: &str, to: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(from) {
        let after = &rest[at + from.len()..];
        out.push_str(&rest[..at]);
        if after.starts_with(|c: char| c.is_ascii_alphabetic()) {
            out.push_str(from);
        } else {
            out.push_str(to);
        }
        rest = after;
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_break_after_commas() {
        assert_eq!(
            wrap("\\ddot{x}, F^{O}_{x}, \\sin(a, b)"),
            "$\\ddot{x},\\allowbreak F^{O}_{x},\\allowbreak \\sin(a,\\allowbreak b)$"
        );
        assert_eq!(wrap("a_{1,2}"), "$a_{1,2}$");
        assert_eq!(wrap(""), "");
    }

    #[test]
    fn text_comes_out_of_the_math() {
        assert_eq!(
            wrap("\\text{rotated by } q_{1} \\text{ about } \\hat{\\mathbf{n}}_{z}"),
            "rotated by $q_{1}$ about $\\hat{\\mathbf{n}}_{z}$"
        );
        assert_eq!(wrap("\\text{couple}"), "couple");
        // A value and a unit that is words: the control space does not escape the `$`.
        assert_eq!(wrap("x = 2\\ \\text{ m per s}"), "$x = 2$ m per s");
        assert_eq!(wrap("\\text{a\\{b\\}} x"), "a\\{b\\} $x$");
    }

    #[test]
    fn brackets_can_break_but_matrices_keep_theirs() {
        assert_eq!(
            wrap("\\left(a + b\\right) \\leftarrow c"),
            "$\\bigl(a +\\penalty2500 b\\bigr) \\leftarrow c$"
        );
        // A sum breaks more cheaply at its own signs than inside its brackets: a sign in a
        // bracket carries a penalty; a leading minus, one in a fraction or outside, none.
        let sum = "v = a \\hat{x} + \\left(-b - \\frac{c - d}{2}\\right) \\hat{y}";
        assert_eq!(
            wrap(sum),
            "$v = a \\hat{x} + \\bigl(-b -\\penalty2500 \\frac{c - d}{2}\\bigr) \\hat{y}$"
        );
        let matrix = "\\left[\\begin{matrix} a \\end{matrix}\\right]";
        assert_eq!(wrap(matrix), format!("${matrix}$"));
    }

    #[test]
    fn long_source_lines_break_at_spaces_and_nowhere_else() {
        let long = format!("$a = {}b$", "x + ".repeat(100));
        let broken = short_source_lines(&format!("{long}\nshort\n"));
        assert!(broken.lines().all(|l| l.len() <= LONGEST_SOURCE_LINE + 8));
        // A line end is a space to TeX: the same text, line ends read as spaces.
        assert_eq!(broken.replace('\n', " "), format!("{long} short "));
        // Comments and control spaces stay as they are.
        let comment = format!("{long} % a comment\n");
        assert_eq!(short_source_lines(&comment), comment);
        let spaces = format!("{}\n", "a\\ ".repeat(100));
        assert_eq!(short_source_lines(&spaces), spaces);
    }
}
