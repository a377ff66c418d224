//! Escaping of user text, so that it is printed and never interpreted.
//!
//! Titles, statements and descriptions come from problem files, which may hold anything:
//! LaTeX commands (`\input{/etc/passwd}`), HTML (`<script>`), Tera syntax (`{{ x }}`).
//! The templates only ever receive such text as a context value, already escaped here for
//! LaTeX and Markdown (Tera escapes it for HTML), so neither Tera nor TeX nor a browser
//! can act on it.

/// Whether a text is one line (a title, a table cell) or may hold paragraphs (a statement).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lines {
    /// Every run of whitespace, newlines included, becomes one space.
    One,
    /// Blank lines separate paragraphs, and line breaks are kept (a statement may list
    /// its questions one per line).
    Paragraphs,
}

/// Splits `text` into paragraphs of non-empty lines; with [`Lines::One`] there is exactly
/// one paragraph of one line.
fn split(text: &str, lines: Lines) -> Vec<Vec<String>> {
    let collapse = |line: &str| {
        line.split(|c: char| c.is_whitespace() || c.is_control())
            .filter(|w| !w.is_empty())
            .collect::<Vec<_>>()
            .join(" ")
    };
    if lines == Lines::One {
        return vec![vec![collapse(text)]];
    }
    let normalized = text.replace("\r\n", "\n").replace('\r', "\n");
    let mut paragraphs: Vec<Vec<String>> = vec![Vec::new()];
    for line in normalized.split('\n').map(collapse) {
        match paragraphs.last_mut() {
            Some(current) if !line.is_empty() => current.push(line),
            Some(current) if !current.is_empty() => paragraphs.push(Vec::new()),
            _ => {}
        }
    }
    paragraphs.retain(|p| !p.is_empty());
    paragraphs
}

/// Characters outside ASCII that pdflatex sets with its default OT1 fonts and `utf8` input
/// without generating bitmap fonts (checked one by one with TeX Live 2022).
const LATEX_SAFE: &str = "\u{a0}¡\u{ad}¸¿ÀÁÂÃÄÅÆÇÈÉÊËÌÍÎÏÑÒÓÔÕÖØÙÚÛÜÝßàáâãäåæçèéêëìíîïñòóôõöøùúûüýÿ\
ĀāĂăĆćĈĉĊċČčĎďĒēĔĕĖėĚěĜĝĞğĠġĢģĤĥĨĩĪīĬĭİıĲĳĴĵĶķĹĺĻļĽľŁłŃńŅņŇňŌōŎŏŐőŒœŔŕŖŗŘřŚśŜŝŞşŠšŢţŤťŨũŪūŬŭŮůŰűŴŵŶŷŸŹźŻżŽž\
–—‘’“”…";

/// Greek letters, set in math mode, since a description may well say "the angle θ".
const GREEK: [(char, &str); 40] = [
    ('α', "alpha"),
    ('β', "beta"),
    ('γ', "gamma"),
    ('δ', "delta"),
    ('ε', "epsilon"),
    ('ζ', "zeta"),
    ('η', "eta"),
    ('θ', "theta"),
    ('ι', "iota"),
    ('κ', "kappa"),
    ('λ', "lambda"),
    ('μ', "mu"),
    ('ν', "nu"),
    ('ξ', "xi"),
    ('π', "pi"),
    ('ρ', "rho"),
    ('σ', "sigma"),
    ('τ', "tau"),
    ('υ', "upsilon"),
    ('φ', "phi"),
    ('χ', "chi"),
    ('ψ', "psi"),
    ('ω', "omega"),
    ('ϕ', "phi"),
    ('ϑ', "vartheta"),
    ('Γ', "Gamma"),
    ('Δ', "Delta"),
    ('Θ', "Theta"),
    ('Λ', "Lambda"),
    ('Ξ', "Xi"),
    ('Π', "Pi"),
    ('Σ', "Sigma"),
    ('Φ', "Phi"),
    ('Ψ', "Psi"),
    ('Ω', "Omega"),
    ('µ', "mu"),
    ('ς', "varsigma"),
    ('Υ', "Upsilon"),
    ('ϵ', "epsilon"),
    ('ϱ', "varrho"),
];

/// The Greek letter LaTeX names `\name` (`theta` → θ), for text that cannot hold math.
pub fn greek_letter(name: &str) -> Option<char> {
    // As LaTeX and MathML set them: `\phi` is ϕ, `\varphi` φ.
    match name {
        "phi" => return Some('ϕ'),
        "varphi" => return Some('φ'),
        _ => {}
    }
    GREEK.iter().find(|(_, n)| *n == name).map(|(c, _)| *c)
}

/// One character of user text as LaTeX text-mode source.
fn latex_char(c: char, out: &mut String) {
    // The default OT1 fonts have no `<`, `>`, `|`, `\` glyphs in text (`\textless` and
    // friends would switch to T1 fonts, which need cm-super or bitmap generation), so
    // those go through math mode.
    let replacement = match c {
        '\\' => "$\\backslash$",
        '{' => "\\{",
        '}' => "\\}",
        // `\$` in text mode takes its glyph from a TS1 font; in math it comes from OT1.
        '$' => "$\\$$",
        '&' => "\\&",
        '#' => "\\#",
        '%' => "\\%",
        '_' => "\\_",
        '~' => "\\~{}",
        '^' => "\\^{}",
        '<' => "$<$",
        '>' => "$>$",
        '|' => "$|$",
        // Break the `--`, ``` `` ```, `''`, `?``, `!`` and `<<` ligatures apart: user text is literal.
        '-' => "-{}",
        '`' => "`{}",
        '\'' => "'{}",
        '"' => "\"{}",
        '°' => "$^{\\circ}$",
        '×' => "$\\times$",
        '÷' => "$\\div$",
        '±' => "$\\pm$",
        '·' => "$\\cdot$",
        '²' => "$^{2}$",
        '³' => "$^{3}$",
        '¹' => "$^{1}$",
        '−' => "$-$",
        '₀' => "$_{0}$",
        '₁' => "$_{1}$",
        '₂' => "$_{2}$",
        '₃' => "$_{3}$",
        '₄' => "$_{4}$",
        '₅' => "$_{5}$",
        '₆' => "$_{6}$",
        '₇' => "$_{7}$",
        '₈' => "$_{8}$",
        '₉' => "$_{9}$",
        '⁰' => "$^{0}$",
        '⁴' => "$^{4}$",
        '⁵' => "$^{5}$",
        '⁶' => "$^{6}$",
        '⁷' => "$^{7}$",
        '⁸' => "$^{8}$",
        '⁹' => "$^{9}$",
        '⁻' => "$^{-}$",
        '∞' => "$\\infty$",
        '≤' => "$\\leq$",
        '≥' => "$\\geq$",
        '≈' => "$\\approx$",
        '≠' => "$\\neq$",
        '→' => "$\\rightarrow$",
        '•' => "$\\bullet$",
        '†' => "$^{\\dagger}$",
        '‡' => "$^{\\ddagger}$",
        _ => {
            if c.is_ascii_graphic() || c == ' ' || LATEX_SAFE.contains(c) {
                out.push(c);
            } else if let Some((_, name)) = GREEK.iter().find(|(g, _)| *g == c) {
                out.push_str("$\\");
                out.push_str(name);
                out.push('$');
            } else {
                // Anything else would stop pdflatex ("Unicode character not set up").
                out.push('?');
            }
            return;
        }
    };
    out.push_str(replacement);
}

/// User text as LaTeX text-mode source that prints it literally.
///
/// Every character TeX treats specially is escaped (`\ { } $ & # % _ ~ ^ < > |`), ligatures
/// are broken, characters the default fonts lack become math symbols or `?`. Paragraphs
/// are separated by a blank line, the lines of a paragraph by `\\`.
pub fn latex(text: &str, lines: Lines) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    for (i, paragraph) in split(text, lines).iter().enumerate() {
        if i > 0 {
            out.push_str("\n\n");
        }
        for (j, line) in paragraph.iter().enumerate() {
            if j > 0 {
                out.push_str(" \\\\\n");
            }
            line.chars().for_each(|c| latex_char(c, &mut out));
        }
    }
    out
}

/// User text as HTML text that prints it literally (`& < > " '` escaped).
///
/// The HTML template is escaped by Tera; this is for HTML made outside templates.
pub fn html(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// User text as Markdown (CommonMark, GitHub, pandoc) that prints it literally.
///
/// Inline markup characters are backslash-escaped, including `$` (math), `|` (tables),
/// `{ }` (pandoc attributes) and `~ ^` (pandoc sub- and superscripts); `< > &` become
/// entities so that no HTML passes; what would start a list, a heading or a thematic break
/// at the start of a line is escaped. Paragraphs are separated by a blank line, the lines of
/// a paragraph by hard line breaks.
pub fn markdown(text: &str, lines: Lines) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    for (i, paragraph) in split(text, lines).iter().enumerate() {
        if i > 0 {
            out.push_str("\n\n");
        }
        for (j, line) in paragraph.iter().enumerate() {
            if j > 0 {
                // A backslash before the newline is a hard line break (CommonMark, pandoc).
                out.push_str("\\\n");
            }
            markdown_line(line, &mut out);
        }
    }
    out
}

/// A piece of a line as Markdown that prints it literally, its whitespace kept.
pub fn markdown_inline(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 8);
    markdown_line(text, &mut out);
    out
}

/// A piece of a line as LaTeX text-mode source that prints it literally, its whitespace
/// kept.
pub fn latex_inline(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 8);
    text.chars().for_each(|c| latex_char(c, &mut out));
    out
}

fn markdown_line(line: &str, out: &mut String) {
    let marker = block_marker(line);
    for (j, c) in line.char_indices() {
        if Some(j) == marker {
            out.push('\\');
            out.push(c);
            continue;
        }
        match c {
            '\\' | '`' | '*' | '_' | '{' | '}' | '[' | ']' | '#' | '|' | '$' | '~' | '^' | '!' => {
                out.push('\\');
                out.push(c);
            }
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            _ => out.push(c),
        }
    }
}

/// The byte offset of the character that would make a paragraph a list item, a thematic
/// break or a setext underline (`- `, `---`, `+ `, `===`, `1. `, `1) `), if any. A sign
/// before a number (`-2.5`) is left alone. (`#`, `>`, `*` are escaped wherever they are.)
fn block_marker(paragraph: &str) -> Option<usize> {
    let digits = paragraph.chars().take_while(char::is_ascii_digit).count();
    let mut rest = paragraph[digits..].chars();
    let first = rest.next();
    let second = rest.next();
    let number_follows = second.is_some_and(|c| c.is_ascii_digit() || c == '.');
    match first {
        Some('-' | '+' | '=') if digits == 0 && !number_follows => Some(0),
        Some('.' | ')') if digits > 0 && second.is_none_or(|c| c == ' ') => Some(digits),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_escapes_every_special_character() {
        let cases = [
            ("100% & $5", "100\\% \\& $\\$$5"),
            ("a_b#c", "a\\_b\\#c"),
            (
                "\\input{/etc/passwd}",
                "$\\backslash$input\\{/etc/passwd\\}",
            ),
            ("~^", "\\~{}\\^{}"),
            ("<b>|", "$<$b$>$$|$"),
            ("a--b", "a-{}-{}b"),
            ("angle θ", "angle $\\theta$"),
            ("5 °C", "5 $^{\\circ}$C"),
            ("café", "café"),
            ("emoji 😀", "emoji ?"),
        ];
        for (input, expected) in cases {
            assert_eq!(latex(input, Lines::One), expected, "input {input:?}");
        }
    }

    #[test]
    fn paragraphs_are_kept_only_when_asked() {
        assert_eq!(latex("a\n b\n\n\n c", Lines::Paragraphs), "a \\\\\nb\n\nc");
        assert_eq!(latex("a\n b\n\n\n c", Lines::One), "a b c");
        assert_eq!(markdown("a\r\n\r\nb", Lines::Paragraphs), "a\n\nb");
        assert_eq!(
            markdown("Find:\n1. q1''\n2. the reaction", Lines::Paragraphs),
            "Find:\\\n1\\. q1''\\\n2\\. the reaction"
        );
    }

    #[test]
    fn markdown_escapes_markup() {
        let cases = [
            ("<script>x</script>", "&lt;script&gt;x&lt;/script&gt;"),
            (
                "{{ x }} 100% & $ # _ ~ ^",
                "\\{\\{ x \\}\\} 100% &amp; \\$ \\# \\_ \\~ \\^",
            ),
            ("- item", "\\- item"),
            ("1. first", "1\\. first"),
            ("-2.5", "-2.5"),
            ("---", "\\---"),
            ("1.5 m", "1.5 m"),
            ("a | b * c [d](e)", "a \\| b \\* c \\[d\\](e)"),
        ];
        for (input, expected) in cases {
            assert_eq!(markdown(input, Lines::One), expected, "input {input:?}");
        }
    }

    #[test]
    fn html_escapes_markup() {
        assert_eq!(
            html("<script>alert('x') & \"y\"</script>"),
            "&lt;script&gt;alert(&#39;x&#39;) &amp; &quot;y&quot;&lt;/script&gt;"
        );
    }
}
