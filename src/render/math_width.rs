//! How wide LaTeX math prints, estimated from its source, in symbols: a symbol is what a
//! letter takes at the display's size, about 6 pt at 10 pt (measured over the bundled
//! handouts: 6.0 pt on average, 6.9 pt at most).
//!
//! Scripts print smaller and a superscript stands above its subscript, so `F^{head}_{x}`
//! takes the width of `F` and 0.7 of `head`, not of `headx`. That lets a long equation be
//! broken into lines that fill the page, where counting every character the same would
//! have to leave a third of each line empty to be safe. [`printed_width`] is the rough
//! count the layout's other choices were tuned to (a table's columns, two results on one
//! line): every printed character one.

/// A script's size against its base's (TeX's 7 pt on 10 pt), and the smallest size, that of
/// a script's script (5 pt).
const SCRIPT: f64 = 0.7;
const SMALLEST: f64 = 0.5;

/// Functions print their names upright, a letter a little narrower than an italic one.
const NAMED: [&str; 15] = [
    "sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "arcsin", "arccos", "arctan",
    "sinh", "cosh", "tanh",
];
const UPRIGHT_LETTER: f64 = 0.8;

/// Commands that print nothing themselves: their argument prints as any text would.
const SILENT: [&str; 16] = [
    "mathbf",
    "boldsymbol",
    "mathrm",
    "mathit",
    "hat",
    "dot",
    "ddot",
    "tilde",
    "bar",
    "vec",
    "text",
    "operatorname",
    "displaystyle",
    "begin",
    "end",
    "limits",
];

/// Binary operators and relations written as commands, which print with space either side.
const SPACED: [&str; 12] = [
    "cdot",
    "times",
    "approx",
    "le",
    "leq",
    "ge",
    "geq",
    "neq",
    "to",
    "rightarrow",
    "equiv",
    "mapsto",
];

/// The symbols `latex` prints, at the size of a displayed equation.
pub fn symbols(latex: &str) -> f64 {
    Reader {
        text: latex.as_bytes(),
        at: 0,
    }
    .width_to_end(1.0)
}

struct Reader<'a> {
    text: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn width_to_end(&mut self, size: f64) -> f64 {
        let mut width = 0.0;
        while self.at < self.text.len() {
            width += self.next_width(size);
        }
        width
    }

    /// The width of the next item (a character, a command with its arguments, a group or a
    /// base's scripts) and moves past it.
    fn next_width(&mut self, size: f64) -> f64 {
        let byte = self.text[self.at];
        match byte {
            b'^' | b'_' => self.scripts(size),
            b'{' => {
                let group = self.group();
                symbols_at(group, size)
            }
            b'}' | b' ' | b'\n' | b'&' => {
                self.at += 1;
                0.0
            }
            b'\\' => self.command(size),
            b'+' | b'-' | b'=' | b'<' | b'>' => {
                self.at += 1;
                2.0 * size
            }
            _ => {
                // A character of several bytes (a Greek letter typed as such) is one symbol.
                self.at += 1;
                while self.at < self.text.len() && (self.text[self.at] & 0xC0) == 0x80 {
                    self.at += 1;
                }
                size
            }
        }
    }

    /// A superscript and a subscript (either order, either alone): they stand one above
    /// the other, so the wider one counts.
    fn scripts(&mut self, size: f64) -> f64 {
        let smaller = (size * SCRIPT).max(SMALLEST);
        let first = self.text[self.at];
        self.at += 1;
        let mut width = symbols_at(self.argument(), smaller);
        self.skip_spaces();
        let other = if first == b'^' { b'_' } else { b'^' };
        if self.text.get(self.at) == Some(&other) {
            self.at += 1;
            width = width.max(symbols_at(self.argument(), smaller));
        }
        width
    }

    fn command(&mut self, size: f64) -> f64 {
        let start = self.at + 1;
        let mut end = start;
        while end < self.text.len() && self.text[end].is_ascii_alphabetic() {
            end += 1;
        }
        let name = std::str::from_utf8(&self.text[start..end]).unwrap_or("");
        if name.is_empty() {
            // `\,`, `\;`, `\!` are small spaces, `\\` ends a line, `\{` `\}` `\|` print.
            self.at = (start + 1).min(self.text.len());
            return match self.text.get(start) {
                Some(b',' | b';' | b':' | b'!') => 0.3 * size,
                Some(b'\\') => 0.0,
                _ => size,
            };
        }
        self.at = end;
        match name {
            "frac" | "dfrac" | "tfrac" => {
                let numerator = symbols_at(self.argument(), size);
                let denominator = symbols_at(self.argument(), size);
                numerator.max(denominator) + size
            }
            "sqrt" => size + symbols_at(self.argument(), size),
            "left" | "right" => self.delimiter(size),
            "quad" => 2.0 * size,
            "qquad" => 4.0 * size,
            _ if NAMED.contains(&name) => name.len() as f64 * UPRIGHT_LETTER * size,
            _ if SPACED.contains(&name) => 2.0 * size,
            _ if SILENT.contains(&name) => 0.0,
            _ => size,
        }
    }

    /// The delimiter after `\left` or `\right`: `.` prints nothing.
    fn delimiter(&mut self, size: f64) -> f64 {
        self.skip_spaces();
        match self.text.get(self.at) {
            Some(b'.') => {
                self.at += 1;
                0.0
            }
            Some(b'\\') => self.command(size),
            Some(_) => {
                self.at += 1;
                size
            }
            None => 0.0,
        }
    }

    /// A command's or script's argument: a group's inside, a command, or one character.
    fn argument(&mut self) -> &[u8] {
        self.skip_spaces();
        let start = self.at;
        match self.text.get(self.at) {
            Some(b'{') => return self.group(),
            Some(b'\\') => {
                self.at += 1;
                while self.at < self.text.len() && self.text[self.at].is_ascii_alphabetic() {
                    self.at += 1;
                }
                if self.at == start + 1 {
                    self.at = (self.at + 1).min(self.text.len());
                }
            }
            Some(_) => self.at += 1,
            None => {}
        }
        &self.text[start..self.at]
    }

    /// The inside of the group that starts here, moving past its closing brace.
    fn group(&mut self) -> &[u8] {
        let start = self.at + 1;
        let mut depth = 0usize;
        while self.at < self.text.len() {
            match self.text[self.at] {
                b'\\' => self.at += 1,
                b'{' => depth += 1,
                b'}' => {
                    depth -= 1;
                    if depth == 0 {
                        self.at += 1;
                        return &self.text[start..self.at - 1];
                    }
                }
                _ => {}
            }
            self.at += 1;
        }
        &self.text[start.min(self.text.len())..]
    }

    fn skip_spaces(&mut self) {
        while self.text.get(self.at) == Some(&b' ') {
            self.at += 1;
        }
    }
}

fn symbols_at(text: &[u8], size: f64) -> f64 {
    Reader { text, at: 0 }.width_to_end(size)
}

/// Roughly how many symbols `latex` prints: command names that only shape or place
/// (`\\frac`, `\\mathbf`, `\\left`) and grouping count nothing, other commands one.
pub fn printed_width(latex: &str) -> usize {
    // Functions print their names.
    const NAMED: [&str; 16] = [
        "sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "sqrt", "arcsin", "arccos",
        "arctan", "sinh", "cosh", "tanh",
    ];
    const SILENT: [&str; 15] = [
        "left",
        "right",
        "frac",
        "mathbf",
        "boldsymbol",
        "mathrm",
        "hat",
        "dot",
        "ddot",
        "text",
        "begin",
        "end",
        "operatorname",
        "quad",
        "displaystyle",
    ];
    let mut width = 0;
    let mut chars = latex.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let name = crate::typeset::command_name(&mut chars);
                if name.is_empty() {
                    chars.next();
                    width += 1;
                } else if NAMED.contains(&name.as_str()) {
                    width += if name == "sqrt" { 1 } else { name.len() };
                } else if !SILENT.contains(&name.as_str()) {
                    width += 1;
                }
            }
            '{' | '}' | '_' | '^' | ' ' => {}
            // Binary operators and relations print with space on both sides.
            '+' | '-' | '=' => width += 2,
            _ => width += 1,
        }
    }
    width
}

#[cfg(test)]
mod tests {
    use super::{printed_width, symbols};

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    #[test]
    fn a_superscript_stands_above_its_subscript() {
        // F, then the wider of "head" and "x" at script size.
        assert!(close(symbols("F^{\\mathrm{head}}_{x}"), 1.0 + 4.0 * 0.7));
        assert!(close(symbols("F_{x}^{\\mathrm{head}}"), 1.0 + 4.0 * 0.7));
    }

    #[test]
    fn scripts_of_scripts_print_at_the_smallest_size() {
        // c, then q at 0.7, then D2 at 0.5.
        assert!(close(symbols("c_{q_{D2}}"), 1.0 + 0.7 + 2.0 * 0.5));
    }

    #[test]
    fn operators_fractions_and_functions() {
        assert!(close(symbols("a + b"), 4.0));
        // The wider of numerator and denominator, and room around the bar.
        assert!(close(symbols("\\frac{m L^{2}}{12}"), 2.0 + 0.7 + 1.0));
        assert!(close(symbols("\\sin(\\theta)"), 3.0 * 0.8 + 3.0));
        assert!(close(symbols("\\left. x \\right)"), 2.0));
        assert!(close(symbols("\\hat{\\mathbf{n}}_{z}"), 1.7));
    }

    #[test]
    fn the_rough_count_leaves_out_what_only_shapes_or_places() {
        assert_eq!(
            printed_width("\\frac{m L^{2}}{12} \\hat{\\mathbf{n}}_{z}"),
            7
        );
    }

    #[test]
    fn unbalanced_or_truncated_source_does_not_panic() {
        for text in ["{", "}", "\\", "^", "x_{", "\\frac{a}", "\\left", "θ̈_"] {
            let _ = symbols(text);
        }
    }
}
