//! LaTeX math -> MathML, so that the HTML page shows its equations with no script and no
//! network.
//!
//! The conversion is `pulldown-latex`'s. Of the two crates on crates.io it is the one that
//! handles all of our LaTeX: `\ddot{q}_{1}` (accent under the subscript), `F^{O}_{x}`,
//! `\operatorname`, `\left( \right)` and `bmatrix`. Its output is then checked by a small
//! sanitizer that lets only MathML elements through, because `pulldown-latex` writes
//! operators such as `<` unescaped and echoes the input in its error messages.

use pulldown_latex::config::{DisplayMode, RenderConfig};
use pulldown_latex::{push_mathml, Parser, Storage};
use std::fmt;

/// LaTeX that could not be converted.
#[derive(Clone, Debug, PartialEq)]
pub struct MathError {
    /// The LaTeX.
    pub latex: String,
    /// Why.
    pub message: String,
}

impl fmt::Display for MathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "cannot convert `{}` to MathML: {}",
            self.latex, self.message
        )
    }
}

impl std::error::Error for MathError {}

/// Inline (in a sentence or a table cell) or display (a line of its own).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    /// `<math>`.
    Inline,
    /// `<math display="block">`.
    Block,
}

/// Converts LaTeX math (without `$`) to one `<math>` element.
///
/// # Errors
/// When the LaTeX does not parse; the message is the parser's.
pub fn to_mathml(latex: &str, display: Display) -> Result<String, MathError> {
    let error = |message: String| MathError {
        latex: latex.to_string(),
        message,
    };
    let storage = Storage::new();
    let plain = underscores_in_text(latex);
    let events: Vec<_> = Parser::new(&plain, &storage).collect();
    if let Some(Err(e)) = events.iter().find(|e| e.is_err()) {
        // The first line of the parser's message; the rest is a drawing of the input.
        return Err(error(
            e.to_string().lines().next().unwrap_or_default().to_string(),
        ));
    }
    let display_mode = match display {
        Display::Inline => DisplayMode::Inline,
        Display::Block => DisplayMode::Block,
    };
    let config = RenderConfig {
        display_mode,
        ..RenderConfig::default()
    };
    let mut out = String::new();
    push_mathml(&mut out, events.into_iter(), config).map_err(|e| error(e.to_string()))?;
    // Our `mover`s are accents (`\hat`, `\dot`, `\ddot`): marked so, they sit close to the letter.
    let out = out.replace("<mover>", "<mover accent=\"true\">");
    let out = accents_as_operators(&out);
    // A solidus is an ordinary symbol in TeX, set close (`m/s²`, `a/2`); MathML Core's
    // dictionary spaces it as an operator (`m / s²`), so its spaces are set to none.
    let out = out.replace("<mo>/</mo>", "<mo lspace=\"0\" rspace=\"0\">/</mo>");
    // `pulldown-latex` writes the space of `\ ` as an escaped entity, which a browser would
    // print as the six characters `&nbsp;`.
    let out = out.replace("&amp;nbsp;", "&#160;");
    Ok(sanitize(&spaces_out_of_scripts(&out)))
}

/// The accents of `\hat`, `\dot` and `\ddot` as the operators MathML Core places as
/// accents (`<mo>`, not an italic identifier), the hat as the modifier circumflex `ˆ`, not
/// stretched: a browser sets the spacing circumflex `^` as the literal caret it is, and
/// the combining one (U+0302, of no width) to the left of the letter it stands over. The dots are of
/// class `dot`, which the page's style sets larger than the font's, whose dots over a
/// letter in a fraction are a pixel across at 100 %.
fn accents_as_operators(mathml: &str) -> String {
    mathml
        .replace(
            "<mi>^</mi></mover>",
            "<mo stretchy=\"false\">\u{2c6}</mo></mover>",
        )
        .replace(
            "<mi>\u{2d9}</mi></mover>",
            "<mo class=\"dot\">\u{2d9}</mo></mover>",
        )
        .replace(
            "<mi>\u{a8}</mi></mover>",
            "<mo class=\"dot\">\u{a8}</mo></mover>",
        )
}

/// `latex` with `\_` inside `\text{…}` written `_`: the parser ends the text there and
/// drops the rest (`\text{rear\_contact}` would read `rear`), while a plain underscore in
/// text mode is a character.
fn underscores_in_text(latex: &str) -> std::borrow::Cow<'_, str> {
    if !latex.contains("\\_") {
        return latex.into();
    }
    let mut out = String::with_capacity(latex.len());
    let mut rest = latex;
    while let Some(start) = rest.find("\\text{") {
        let (before, text) = rest.split_at(start + "\\text{".len());
        out.push_str(before);
        // The group's end: braces nest.
        let mut depth = 1;
        let end = text
            .char_indices()
            .find(|&(_, c)| {
                depth += match c {
                    '{' => 1,
                    '}' => -1,
                    _ => 0,
                };
                depth == 0
            })
            .map_or(text.len(), |(i, _)| i);
        out.push_str(&text[..end].replace("\\_", "_"));
        rest = &text[end..];
    }
    out.push_str(rest);
    out.into()
}

/// The elements whose children are counted: a base and one or two scripts.
const SCRIPTS: [&str; 6] = ["msup", "msub", "msubsup", "mover", "munder", "munderover"];

/// Moves an `<mspace .../>` that opens a script element to just before it.
///
/// `pulldown-latex` writes the thin space before an operator name inside the script
/// element, so `\sin^{2}` becomes `<msup><mspace/><mi>sin</mi><mn>2</mn></msup>`: three
/// children where MathML allows two, which browsers then draw wrongly.
fn spaces_out_of_scripts(markup: &str) -> String {
    let mut out = markup.to_string();
    for tag in SCRIPTS {
        let open = format!("<{tag}>");
        let mut from = 0;
        while let Some(at) = out[from..].find(&open).map(|i| i + from) {
            let inner = at + open.len();
            let space = out[inner..]
                .starts_with("<mspace")
                .then(|| out[inner..].find("/>"))
                .flatten();
            match space {
                Some(end) => {
                    let space = out[inner..inner + end + 2].to_string();
                    out.replace_range(at..inner + end + 2, &format!("{space}{open}"));
                    from = at + space.len() + open.len();
                }
                None => from = inner,
            }
        }
    }
    out
}

/// The elements `pulldown-latex` writes, all presentation MathML.
const ELEMENTS: [&str; 22] = [
    "math",
    "mi",
    "mn",
    "mo",
    "ms",
    "mtext",
    "mspace",
    "mrow",
    "mfrac",
    "msqrt",
    "mroot",
    "msub",
    "msup",
    "msubsup",
    "munder",
    "mover",
    "munderover",
    "mtable",
    "mtr",
    "mtd",
    "mstyle",
    "merror",
];

/// Keeps the tags of `ELEMENTS` (with attributes free of `<` and quotes balanced) and
/// escapes every other `<`, `>` and stray `&`, so that nothing but MathML can come out.
pub fn sanitize(markup: &str) -> String {
    let mut out = String::with_capacity(markup.len());
    let mut rest = markup;
    while let Some(c) = rest.chars().next() {
        match c {
            '<' => match allowed_tag(rest) {
                Some(length) => {
                    out.push_str(&rest[..length]);
                    rest = &rest[length..];
                    continue;
                }
                None => out.push_str("&lt;"),
            },
            '>' => out.push_str("&gt;"),
            '&' if !is_entity(rest) => out.push_str("&amp;"),
            _ => out.push(c),
        }
        rest = &rest[c.len_utf8()..];
    }
    out
}

/// The length of the tag at the start of `text` if it is an allowed MathML element.
fn allowed_tag(text: &str) -> Option<usize> {
    let inner = text.strip_prefix('<')?;
    let closing = inner.starts_with('/');
    let inner = inner.strip_prefix('/').unwrap_or(inner);
    let name_length = inner
        .find(|c: char| !c.is_ascii_alphanumeric())
        .unwrap_or(inner.len());
    if !ELEMENTS.contains(&&inner[..name_length]) {
        return None;
    }
    let end = inner.find('>')?;
    let attributes = &inner[name_length..end];
    let boundary = attributes.is_empty() || attributes.starts_with([' ', '/']);
    let quotes_balanced = attributes.matches('"').count() % 2 == 0 && !attributes.contains('\'');
    let safe = !attributes.contains('<') && !attributes.to_ascii_lowercase().contains(" on");
    (boundary && quotes_balanced && safe && (!closing || attributes.trim().is_empty()))
        .then_some(1 + usize::from(closing) + end + 1)
}

/// Whether `text` starts with a character reference such as `&amp;` or `&#x2F;`.
fn is_entity(text: &str) -> bool {
    let Some(end) = text.find(';') else {
        return false;
    };
    let body = &text[1..end];
    !body.is_empty()
        && body.len() <= 10
        && (body.chars().all(|c| c.is_ascii_alphanumeric())
            || body
                .strip_prefix('#')
                .is_some_and(|n| n.chars().all(|c| c.is_ascii_alphanumeric())))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Converts and checks that every expected fragment is present, in order.
    fn check(latex: &str, fragments: &[&str]) {
        let mathml = to_mathml(latex, Display::Inline).unwrap_or_else(|e| panic!("{e}"));
        let mut rest = mathml.as_str();
        for fragment in fragments {
            let at = rest
                .find(fragment)
                .unwrap_or_else(|| panic!("`{fragment}` not in {mathml}"));
            rest = &rest[at + fragment.len()..];
        }
    }

    #[test]
    fn our_latex_converts() {
        check(
            "\\ddot{q}_{1}",
            &[
                "<msub><mover accent=\"true\">",
                "<mi>q</mi>",
                "¨",
                "</mover>",
                "<mn>1</mn>",
            ],
        );
        check(
            "\\hat{\\mathbf{a}}_{x}",
            &[
                "<msub><mover accent=\"true\">",
                "𝐚",
                "<mo stretchy=\"false\">\u{2c6}</mo>",
                "<mi>x</mi>",
            ],
        );
        check(
            "\\frac{L^{2} m}{12}",
            &["<mfrac>", "<msup><mi>L</mi>", "<mn>12</mn>", "</mfrac>"],
        );
        check(
            "\\left(\\dot{q}_{1} + 1\\right)",
            &["<mo stretchy=\"true\">(</mo>", "<mo>+</mo>", ")</mo>"],
        );
        check(
            "\\sin(q_{1}) \\cdot x \\times y \\quad z",
            &["<mi>sin</mi>", "⋅", "×", "<mspace", "<mi>z</mi>"],
        );
        check(
            "F^{O}_{x}",
            &["<msubsup><mi>F</mi>", "<mi>x</mi>", "<mi>O</mi>"],
        );
        check(
            "\\operatorname{atan2}\\left(a, b\\right)",
            &["<mi>atan2</mi>"],
        );
        check(
            "\\begin{bmatrix} a & b \\\\ c & d \\end{bmatrix}",
            &[
                "[</mo><mtable",
                "<mtr><mtd><mi>a</mi></mtd><mtd><mi>b</mi></mtd></mtr>",
                "<mi>d</mi>",
                "]</mo>",
            ],
        );
    }

    #[test]
    fn an_underscore_in_text_is_kept() {
        let mathml = to_mathml("\\text{at rear\\_contact} \\cdot x_{1}", Display::Inline).unwrap();
        assert!(
            mathml.contains("<mtext>at rear_contact</mtext>"),
            "{mathml}"
        );
        assert!(mathml.contains("<msub>"), "{mathml}");
    }

    #[test]
    fn a_control_space_is_a_space() {
        let mathml = to_mathml("t = 2\\ \\mathrm{s}", Display::Inline).unwrap_or_default();
        assert!(mathml.contains("<mtext>&#160;</mtext>"), "{mathml}");
        assert!(!mathml.contains("&amp;"), "{mathml}");
    }

    #[test]
    fn a_squared_sine_is_a_base_and_one_script() {
        let mathml = to_mathml("\\sin^{2}(q) + \\cos^{2}{x}", Display::Inline).unwrap_or_default();
        assert!(!mathml.contains("<msup><mspace"), "{mathml}");
        // After another term the space before `sin` stays, outside the script.
        let after = to_mathml("a \\sin^{2}(q)", Display::Inline).unwrap_or_default();
        assert!(after.contains("/><msup><mi>sin</mi>"), "{after}");
        check(
            "\\sin^{2}(q)",
            &["<msup><mi>sin</mi><mrow><mn>2</mn></mrow></msup>"],
        );
    }

    #[test]
    fn bad_latex_is_an_error() {
        assert!(to_mathml("\\frac{a}{", Display::Inline).is_err());
    }

    #[test]
    fn a_solidus_is_set_close_as_in_latex() {
        let unit = to_mathml("9.81\\ \\mathrm{m/s^{2}}", Display::Inline).unwrap();
        assert!(
            unit.contains("<mo lspace=\"0\" rspace=\"0\">/</mo>"),
            "{unit}"
        );
        assert!(!unit.contains("<mo>/</mo>"), "{unit}");
    }

    #[test]
    fn sanitizer_lets_only_mathml_through() {
        assert_eq!(
            sanitize("<mo><</mo><mo>></mo>"),
            "<mo>&lt;</mo><mo>&gt;</mo>"
        );
        assert_eq!(
            sanitize("<mtext>a &amp; b & c</mtext>"),
            "<mtext>a &amp; b &amp; c</mtext>"
        );
        assert_eq!(
            sanitize("<script>x</script>"),
            "&lt;script&gt;x&lt;/script&gt;"
        );
        assert_eq!(
            sanitize("<mi onclick=\"x\">a</mi>"),
            "&lt;mi onclick=\"x\"&gt;a&lt;/mi&gt;".replace("&lt;/mi&gt;", "</mi>")
        );
        assert_eq!(
            sanitize("<mspace width=\"1em\" />"),
            "<mspace width=\"1em\" />"
        );
        let converted = to_mathml("a < b", Display::Inline).unwrap_or_default();
        assert!(converted.contains("<mo>&lt;</mo>"), "{converted}");
    }
}
