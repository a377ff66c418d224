//! The [`Solution`] as a Tera context for one format, and the filters the templates use.
//!
//! Strings are treated by their kind (see [`super::text`]): plain text is escaped here for
//! LaTeX and Markdown (Tera escapes HTML itself), math is left for the template, the
//! problem's markup is written out, and what a format cannot show is removed.

use super::escape::{self, Lines};
use super::line_break::{break_into_lines, displays, HTML_WIDTH, LINE_SYMBOLS, MEASURED_AT_MOST};
use super::markup;
use super::mathml;
use super::numbers::{
    is_number, keeping_spaces, latex_number, unicode_number, with_negatives, with_numbers,
};
use super::text::key;
use super::{Format, Solution};
use crate::typeset::Display;
use serde_json::Value;
use std::collections::HashMap;

/// The context for `format`.
///
/// # Errors
/// Only if the solution cannot be serialized, which plain strings and numbers always can.
pub fn context(
    solution: &Solution,
    format: Format,
    student: bool,
) -> Result<tera::Context, tera::Error> {
    let mut value = serde_json::to_value(solution).map_err(tera::Error::json)?;
    super::shown_names::rename(&mut value, &solution.shown_names);
    walk(&mut value, format);
    if let Value::Object(map) = &mut value {
        map.insert("student".into(), Value::Bool(student));
        map.insert("format".into(), Value::String(format.extension().into()));
    }
    tera::Context::from_value(value)
}

fn walk(value: &mut Value, format: Format) {
    if let Some(prepared) = kind_of(value).map(|(kind, text)| typed(text, kind, format)) {
        *value = Value::String(prepared);
        return;
    }
    match value {
        Value::Object(map) => {
            map.values_mut().for_each(|item| walk(item, format));
        }
        Value::Array(items) => items.iter_mut().for_each(|item| walk(item, format)),
        Value::String(text) => *text = plain(text, format),
        _ => {}
    }
}

/// A typed string of [`super::text`], as it serializes: its kind's key and the string.
fn kind_of(value: &Value) -> Option<(&str, &str)> {
    let Value::Object(map) = value else {
        return None;
    };
    let (kind, text) = map.iter().next()?;
    (map.len() == 1 && kind.starts_with('\0')).then_some((kind.as_str(), text.as_str()?))
}

/// One typed string of the context, by its kind (see [`super::text`]).
fn typed(text: &str, kind: &str, format: Format) -> String {
    let kept_in = |formats: &[Format]| {
        if formats.contains(&format) {
            text.to_string()
        } else {
            String::new()
        }
    };
    match kind {
        key::MATH => {
            let math = text.split_whitespace().collect::<Vec<_>>().join(" ");
            match format {
                // `|` would end a Markdown table cell, even inside `$…$` on GitHub.
                Format::Markdown => super::flat_brackets::flat_brackets(&math)
                    .replace("\\|", "\\Vert ")
                    .replace('|', "\\vert "),
                Format::Latex | Format::Html => math,
            }
        }
        // The statement, the questions and the notes written in it are the problem's own
        // markup (see `markup`), written out here for every format; in HTML they are
        // markup the template marks `safe`.
        key::MARKUP => markup::render_blocks(text, format),
        key::MARKUP_LINE => markup::render_line(text, format),
        key::LATEX_CODE => kept_in(&[Format::Latex]),
        key::INLINE_SVG => kept_in(&[Format::Markdown, Format::Html]),
        key::SVG_DOCUMENT if format == Format::Html && !text.is_empty() => {
            format!("data:image/svg+xml;base64,{}", base64(text.as_bytes()))
        }
        key::SVG_DOCUMENT => String::new(),
        key::FILE_NAME if format == Format::Markdown => percent_encode(text),
        key::FILE_NAME => text.to_string(),
        _ => plain(text, format),
    }
}

/// One plain-text string of the context: user text, names, numbers.
fn plain(text: &str, format: Format) -> String {
    match format {
        Format::Latex if is_number(text) => latex_number(text),
        // Numbers written `1e-9` in a sentence read as powers of ten, as in print.
        // A negative number prints with a minus sign, not a hyphen.
        Format::Latex => with_numbers(text, latex_number, |p| {
            with_negatives(p, latex_number, |p| {
                keeping_spaces(p, |p| escape::latex(p, Lines::One))
            })
        }),
        Format::Markdown => with_numbers(text, unicode_number, |p| {
            keeping_spaces(p, |p| escape::markdown(p, Lines::One))
        }),
        // Tera escapes the HTML template's output.
        Format::Html => with_numbers(text, unicode_number, |p| {
            with_negatives(p, |n| n.replace('-', "−"), str::to_string)
        }),
    }
}

/// A file name as a URL path segment, for Markdown links.
fn percent_encode(text: &str) -> String {
    let mut out = String::new();
    for byte in text.bytes() {
        if byte.is_ascii_alphanumeric() || b"-._~".contains(&byte) {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

/// Standard base64 with padding, for `data:` URIs (a dozen lines, not worth a crate).
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(ALPHABET[((n >> (18 - 6 * i)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Registers `mathml` (LaTeX math -> a sanitized `<math>` element; `display=true` for a
/// block), `tex_wrap` (LaTeX math -> `$…$` that can break after commas and in brackets) and `tex_display` (LaTeX math -> a displayed equation: `\\[…\\]`, or `multline*`
/// broken into lines when it is long).
pub fn register_filters(tera: &mut tera::Tera) {
    tera.register_filter("mathml", |value: &Value, args: &HashMap<String, Value>| {
        let latex = tera::try_get_value!("mathml", "value", String, value);
        let block = args
            .get("display")
            .and_then(Value::as_bool)
            .unwrap_or(false);
        let display = if block {
            Display::Block
        } else {
            Display::Inline
        };
        if block {
            // A wide equation is broken into lines, each its own block, so that the page
            // wraps it instead of clipping it or making the reader scroll far.
            let lines: Vec<String> = break_into_lines(&latex, HTML_WIDTH)
                .iter()
                .map(|line| mathml::to_mathml_or_source(line, display))
                .collect();
            return Ok(Value::String(lines.join("\n")));
        }
        Ok(Value::String(mathml::to_mathml_or_source(&latex, display)))
    });
    // LaTeX math -> inline math that a table cell or a list can wrap (see `tex_wrap`).
    tera.register_filter("tex_wrap", |value: &Value, _: &HashMap<String, Value>| {
        let latex = tera::try_get_value!("tex_wrap", "value", String, value);
        Ok(Value::String(super::tex_wrap::wrap(&latex)))
    });
    // An aligned block's rows as the second column pair of `alignat*{2}`, whose first
    // holds the words that open it (see `labelled_rows`).
    tera.register_filter(
        "tex_labelled_rows",
        |value: &Value, _: &HashMap<String, Value>| {
            let latex = tera::try_get_value!("tex_labelled_rows", "value", String, value);
            Ok(Value::String(super::labelled_rows::labelled_rows(&latex)))
        },
    );
    tera.register_filter(
        "tex_display",
        |value: &Value, args: &HashMap<String, Value>| {
            let latex = tera::try_get_value!("tex_display", "value", String, value);
            let width = args
                .get("width")
                .and_then(Value::as_f64)
                .unwrap_or(LINE_SYMBOLS);
            let lead = args.get("lead").and_then(Value::as_str).unwrap_or("");
            let (latex, above) = lead_into(&latex, lead, width);
            let lines = break_into_lines(&latex, width);
            let broken = displays(&lines);
            if lines.len() > 1 && latex.len() <= MEASURED_AT_MOST {
                // The count of symbols is a guess: LaTeX measures whether the equation fits
                // one line after all, and sets it whole if so.
                return Ok(Value::String(format!(
                    "{above}\\fitdisplay{{{latex}}}{{\n{broken}\n}}"
                )));
            }
            Ok(Value::String(format!("{above}{broken}")))
        },
    );
}

/// The most of a display's line that words opening it may take: a longer heading leaves
/// too little beside it for the first term.
const LEAD_AT_MOST: f64 = 0.45;

/// A display's math with `lead` (text: a row's heading, "Simplified:") opening its first
/// line, so that the words do not take a line of their own above it; or, when the words
/// would take too much of the line, the math as it is and the words to set above it.
fn lead_into(latex: &str, lead: &str, width: f64) -> (String, String) {
    if lead.is_empty() {
        return (latex.to_string(), String::new());
    }
    let words = format!("\\text{{{lead}}}");
    if super::math_width::symbols(&words) > LEAD_AT_MOST * width {
        return (latex.to_string(), format!("{lead}\n"));
    }
    (format!("{words}\\quad {latex}"), String::new())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_lead_opens_the_display_and_a_long_one_stands_above_it() {
        let (math, above) = lead_into("x = 0", "Simplified:", 70.0);
        assert_eq!(math, "\\text{Simplified:}\\quad x = 0");
        assert_eq!(above, "");
        // 40 letters of a constraint's heading: more than 0.45 of a 70-symbol line.
        let heading = "rolling constraint at the front contact x";
        let (math, above) = lead_into("x = 0", heading, 70.0);
        assert_eq!(math, "x = 0");
        assert_eq!(above, format!("{heading}\n"));
        assert_eq!(
            lead_into("x = 0", "", 70.0),
            ("x = 0".to_string(), String::new())
        );
    }

    #[test]
    fn base64_matches_the_rfc_4648_vectors() {
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (input, expected) in cases {
            assert_eq!(base64(input.as_bytes()), expected);
        }
    }

    #[test]
    fn numbers_become_math_in_latex() {
        assert_eq!(plain("-12.5", Format::Latex), "$-12.5$");
        assert_eq!(plain("1e-9", Format::Latex), "$10^{-9}$");
        assert_eq!(plain("-2.5e7", Format::Latex), "$-2.5 \\times 10^{7}$");
        assert_eq!(plain("1-2", Format::Latex), "1-{}2");
    }

    /// `value` as the context holds it once prepared for `format`.
    fn prepared(value: impl serde::Serialize, format: Format) -> Value {
        let mut value = serde_json::to_value(value).unwrap();
        walk(&mut value, format);
        value
    }

    #[test]
    fn strings_are_treated_by_kind() {
        use crate::render::text::*;
        assert_eq!(prepared("a_b", Format::Latex), "a\\_b");
        assert_eq!(prepared(MarkupLine::from("a_b"), Format::Latex), "a\\_b");
        assert_eq!(
            prepared(Math::from("\\left|x\\right|"), Format::Markdown),
            "\\left\\vert x\\right\\vert "
        );
        assert_eq!(
            prepared(Math::from("\\frac{a}{b}"), Format::Latex),
            "\\frac{a}{b}"
        );
        // A plain string that looks like math is still text.
        assert_eq!(
            prepared("\\frac{a}{b}", Format::Latex),
            "$\\backslash$frac\\{a\\}\\{b\\}"
        );
        assert_eq!(prepared(LatexCode::from("\\draw"), Format::Html), "");
        assert_eq!(prepared(LatexCode::from("\\draw"), Format::Latex), "\\draw");
        assert_eq!(prepared(InlineSvg::from("<svg/>"), Format::Latex), "");
        assert_eq!(
            prepared(SvgDocument::from("<svg/>"), Format::Html),
            "data:image/svg+xml;base64,PHN2Zy8+"
        );
        assert_eq!(
            prepared(FileName::from("a b.svg"), Format::Markdown),
            "a%20b.svg"
        );
        assert_eq!(prepared("<b>", Format::Html), "<b>");
        // Typed strings inside lists and structs.
        assert_eq!(
            prepared(vec![Math::from("x"), Math::from("a|b")], Format::Markdown),
            serde_json::json!(["x", "a\\vert b"])
        );
    }

    #[test]
    fn scientific_numbers_in_text_read_as_powers_of_ten() {
        let latex = plain("tolerance 1e-9, hold to -1.77636e-15.", Format::Latex);
        assert_eq!(
            latex,
            "tolerance $10^{-9}$, hold to $-1.77636 \\times 10^{-15}$."
        );
        let html = plain("value 5.99959e-10 of q1e2 and 3e8m", Format::Html);
        assert_eq!(html, "value 5.99959×10⁻¹⁰ of q1e2 and 3e8m");
        assert_eq!(plain("1e-6", Format::Markdown), "10⁻⁶");
    }
}
