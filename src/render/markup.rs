//! A problem's statement and its questions' texts as a reader expects them: the small part
//! of Markdown a statement uses (paragraphs, lists, emphasis, code) and math between
//! dollars, written out for each format.
//!
//! | source | shown as |
//! |---|---|
//! | a blank line | a new paragraph (the lines of one paragraph run on) |
//! | `- item`, `* item`, `+ item` | a bulleted list |
//! | `1. item`, `1) item` | a numbered list, from that number |
//! | `*text*`, `_text_` / `**text**`, `__text__` | emphasis / strong emphasis |
//! | `` `text` `` | code |
//! | `$…$` / `$$…$$` | inline / displayed math, if [`checked_math`] allows it |
//! | `\*`, `\$`, … | the character itself |
//!
//! Everything else is text, escaped for the format, and so is math that is not allowed:
//! `$\input{x}$` prints as those characters.

use super::escape;
use super::mathml;
use super::Format;
use crate::typeset::{checked_math, for_markdown, Display};

/// A piece of a line.
#[derive(Clone, Debug, PartialEq)]
pub enum Inline {
    /// Text, unescaped.
    Text(String),
    /// Checked LaTeX math; `true` for displayed math.
    Math(String, bool),
    /// `` `code` ``, unescaped.
    Code(String),
    /// Emphasis (`strong` false) or strong emphasis.
    Emphasis {
        /// Strong emphasis (`**…**`) rather than emphasis (`*…*`).
        strong: bool,
        /// What is emphasized.
        inner: Vec<Inline>,
    },
}

/// A paragraph or a list.
#[derive(Clone, Debug, PartialEq)]
pub enum Block {
    /// One paragraph, its lines run together.
    Paragraph(Vec<Inline>),
    /// A list; `start` is the first number of a numbered list, `None` for bullets.
    List {
        /// The first number of a numbered list, `None` for bullets.
        start: Option<u32>,
        /// The items, each a line of inline pieces.
        items: Vec<Vec<Inline>>,
    },
}

/// `text` as blocks: paragraphs separated by blank lines, and lists.
pub fn blocks(text: &str) -> Vec<Block> {
    let normalized = text.replace("\r\n", "\n").replace('\r', "\n");
    let mut blocks = Vec::new();
    // The lines of the block being read, and whether it is a list (with its start).
    let mut lines: Vec<String> = Vec::new();
    let mut list: Option<(Option<u32>, Vec<String>)> = None;
    let flush_paragraph = |lines: &mut Vec<String>, blocks: &mut Vec<Block>| {
        if !lines.is_empty() {
            blocks.push(Block::Paragraph(inlines(&lines.join(" "))));
            lines.clear();
        }
    };
    let flush_list = |list: &mut Option<(Option<u32>, Vec<String>)>, blocks: &mut Vec<Block>| {
        if let Some((start, items)) = list.take() {
            let items = items.iter().map(|item| inlines(item)).collect();
            blocks.push(Block::List { start, items });
        }
    };
    for raw in normalized.split('\n') {
        let line = collapse(raw);
        if line.is_empty() {
            flush_paragraph(&mut lines, &mut blocks);
            flush_list(&mut list, &mut blocks);
            continue;
        }
        if let Some((kind, rest)) = list_item(&line) {
            flush_paragraph(&mut lines, &mut blocks);
            let same_kind = list
                .as_ref()
                .is_some_and(|(start, _)| start.is_some() == kind.is_some());
            if !same_kind {
                flush_list(&mut list, &mut blocks);
            }
            list.get_or_insert_with(|| (kind, Vec::new()))
                .1
                .push(rest.to_string());
            continue;
        }
        match &mut list {
            // A line after an item goes on with that item.
            Some((_, items)) => {
                if let Some(last) = items.last_mut() {
                    last.push(' ');
                    last.push_str(&line);
                }
            }
            None => lines.push(line),
        }
    }
    flush_paragraph(&mut lines, &mut blocks);
    flush_list(&mut list, &mut blocks);
    blocks
}

/// A line with its whitespace runs made one space and control characters dropped.
fn collapse(line: &str) -> String {
    line.split(|c: char| c.is_whitespace() || c.is_control())
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// The list marker a line starts with (`Some(number)` for a numbered item, `None` for a
/// bullet) and the rest of the line.
fn list_item(line: &str) -> Option<(Option<u32>, &str)> {
    for bullet in ["- ", "* ", "+ "] {
        if let Some(rest) = line.strip_prefix(bullet) {
            return Some((None, rest));
        }
    }
    let digits = line.chars().take_while(char::is_ascii_digit).count();
    if digits == 0 || digits > 9 {
        return None;
    }
    let rest = &line[digits..];
    let rest = rest
        .strip_prefix(". ")
        .or_else(|| rest.strip_prefix(") "))?;
    Some((line[..digits].parse().ok(), rest))
}

/// One line of text as its pieces.
pub fn inlines(text: &str) -> Vec<Inline> {
    let mut out: Vec<Inline> = Vec::new();
    let mut text_run = String::new();
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    let flush = |run: &mut String, out: &mut Vec<Inline>| {
        if !run.is_empty() {
            out.push(Inline::Text(std::mem::take(run)));
        }
    };
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '\\' && next.is_some_and(|n| n.is_ascii_punctuation()) {
            text_run.extend(next);
            i += 2;
            continue;
        }
        let found = match c {
            '$' => math(&chars, i),
            '`' => closing(&chars, i + 1, "`")
                .map(|end| (Inline::Code(chars[i + 1..end].iter().collect()), end + 1)),
            '*' | '_' => emphasis(&chars, i),
            _ => None,
        };
        match found {
            Some((piece, end)) => {
                flush(&mut text_run, &mut out);
                out.push(piece);
                i = end;
            }
            None => {
                text_run.push(c);
                i += 1;
            }
        }
    }
    flush(&mut text_run, &mut out);
    out
}

/// Where `marker` next occurs in `chars` from `from` (not after a backslash).
fn closing(chars: &[char], from: usize, marker: &str) -> Option<usize> {
    let marker: Vec<char> = marker.chars().collect();
    let mut i = from;
    while i + marker.len() <= chars.len() {
        if chars[i] == '\\' {
            i += 2;
            continue;
        }
        if chars[i..i + marker.len()] == marker[..] {
            return Some(i);
        }
        i += 1;
    }
    None
}

/// Math at `start` (a `$`), as pandoc reads it: `$` then no space, and a closing `$` after
/// no space and before no digit (so "$5 and $10" stays text); `$$…$$` is displayed.
/// Math that [`checked_math`] refuses is text, dollars and all.
fn math(chars: &[char], start: usize) -> Option<(Inline, usize)> {
    let display = chars.get(start + 1) == Some(&'$');
    let (open, marker) = if display { (2, "$$") } else { (1, "$") };
    let from = start + open;
    let end = closing(chars, from, marker)?;
    let inner: String = chars[from..end].iter().collect();
    let after = end + open;
    if !display {
        let spaced = inner.starts_with(' ') || inner.ends_with(' ');
        let digit_after = chars.get(after).is_some_and(char::is_ascii_digit);
        if inner.is_empty() || spaced || digit_after {
            return None;
        }
    }
    let piece = match checked_math(&inner) {
        Some(latex) => Inline::Math(latex, display),
        None => Inline::Text(chars[start..after].iter().collect()),
    };
    Some((piece, after))
}

/// Emphasis at `start` (`*` or `_`, once or twice), closed on the same line: after the
/// opener no space, before the closer no space; `_` only between words (not `q_1`).
fn emphasis(chars: &[char], start: usize) -> Option<(Inline, usize)> {
    let c = chars[start];
    let strong = chars.get(start + 1) == Some(&c);
    let width = if strong { 2 } else { 1 };
    let marker: String = std::iter::repeat_n(c, width).collect();
    let from = start + width;
    let word = |i: Option<&char>| i.is_some_and(|c| c.is_alphanumeric());
    if chars.get(from).is_none_or(|n| n.is_whitespace() || *n == c) {
        return None;
    }
    if c == '_' && start > 0 && word(chars.get(start - 1)) {
        return None;
    }
    let end = closing(chars, from, &marker)?;
    if chars[end - 1].is_whitespace() || (c == '_' && word(chars.get(end + width))) {
        return None;
    }
    let inner: String = chars[from..end].iter().collect();
    let inner = inlines(&inner)
        .into_iter()
        .map(|piece| match piece {
            // Emphasis inside emphasis is shown as its text.
            Inline::Emphasis { inner, .. } => Inline::Text(plain(&inner)),
            other => other,
        })
        .collect();
    Some((Inline::Emphasis { strong, inner }, end + width))
}

/// The characters of `pieces`, without markup.
fn plain(pieces: &[Inline]) -> String {
    pieces
        .iter()
        .map(|piece| match piece {
            Inline::Text(t) | Inline::Code(t) | Inline::Math(t, _) => t.clone(),
            Inline::Emphasis { inner, .. } => plain(inner),
        })
        .collect()
}

/// A statement (paragraphs and lists) written for `format`.
pub fn render_blocks(text: &str, format: Format) -> String {
    let blocks = blocks(text);
    let rendered: Vec<String> = blocks
        .iter()
        .map(|block| match block {
            Block::Paragraph(pieces) => match format {
                Format::Html => format!("<p>{}</p>", render(pieces, format)),
                Format::Latex | Format::Markdown => render(pieces, format),
            },
            Block::List { start, items } => list(*start, items, format),
        })
        .collect();
    let separator = if format == Format::Html { "\n" } else { "\n\n" };
    rendered.join(separator)
}

/// `text` as markup that reads as those characters: each character that would start markup
/// after a backslash.
pub fn literal(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if matches!(c, '\\' | '$' | '`' | '*' | '_') {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// As [`literal`], with each number in scientific notation (`1e-9`) as math, as print
/// writes it ($1 \\times 10^{-9}$).
pub fn literal_with_numbers(text: &str) -> String {
    super::numbers::with_numbers(
        text,
        |n| format!("${}$", super::numbers::math_number(n)),
        literal,
    )
}

/// One line of text (a question) written for `format`, without paragraphs or lists.
pub fn render_line(text: &str, format: Format) -> String {
    render(&inlines(&collapse(text)), format)
}

fn list(start: Option<u32>, items: &[Vec<Inline>], format: Format) -> String {
    let items = items.iter().map(|item| render(item, format));
    match (format, start) {
        (Format::Markdown, _) => items
            .enumerate()
            .map(|(i, item)| match start {
                Some(n) => format!("{}. {item}", u64::from(n) + i as u64),
                None => format!("- {item}"),
            })
            .collect::<Vec<_>>()
            .join("\n"),
        (Format::Latex, _) => {
            let environment = if start.is_some() {
                "enumerate"
            } else {
                "itemize"
            };
            let counter = match start {
                Some(n) if n != 1 => format!("\\setcounter{{enumi}}{{{}}}\n", n.saturating_sub(1)),
                _ => String::new(),
            };
            let items: Vec<String> = items.map(|item| format!("\\item {item}")).collect();
            format!(
                "\\begin{{{environment}}}\n{counter}{}\n\\end{{{environment}}}",
                items.join("\n")
            )
        }
        (Format::Html, None) => format!(
            "<ul>\n{}\n</ul>",
            items
                .map(|i| format!("<li>{i}</li>"))
                .collect::<Vec<_>>()
                .join("\n")
        ),
        (Format::Html, Some(n)) => {
            let start = if n == 1 {
                String::new()
            } else {
                format!(" start=\"{n}\"")
            };
            format!(
                "<ol{start}>\n{}\n</ol>",
                items
                    .map(|i| format!("<li>{i}</li>"))
                    .collect::<Vec<_>>()
                    .join("\n")
            )
        }
    }
}

/// Pieces of a line written for `format`; text is escaped, math checked already.
fn render(pieces: &[Inline], format: Format) -> String {
    let mut out = String::new();
    for piece in pieces {
        match (piece, format) {
            (Inline::Text(text), Format::Markdown) => out.push_str(&escape::markdown_inline(text)),
            (Inline::Text(text), Format::Latex) => out.push_str(&escape::latex_inline(text)),
            (Inline::Text(text), Format::Html) => out.push_str(&escape::html(text)),
            (Inline::Math(math, false), Format::Markdown) => {
                out.push_str(&format!("${}$", for_markdown(math)));
            }
            (Inline::Math(math, true), Format::Markdown) => {
                out.push_str(&format!("$${}$$", for_markdown(math)));
            }
            (Inline::Math(math, false), Format::Latex) => out.push_str(&format!("${math}$")),
            (Inline::Math(math, true), Format::Latex) => out.push_str(&format!("\\[{math}\\]")),
            (Inline::Math(math, display), Format::Html) => {
                let display = if *display {
                    Display::Block
                } else {
                    Display::Inline
                };
                out.push_str(&mathml::to_mathml_or_source(math, display));
            }
            (Inline::Code(code), Format::Markdown) => {
                // A run of backticks longer than any inside, with spaces so that a
                // backtick at either end stays code.
                let longest = code.split(|c| c != '`').map(str::len).max().unwrap_or(0);
                let fence = "`".repeat(longest + 1);
                let code = code.replace('<', "&lt;");
                out.push_str(&format!("{fence} {code} {fence}"));
            }
            (Inline::Code(code), Format::Latex) => {
                out.push_str(&format!("\\texttt{{{}}}", escape::latex_inline(code)));
            }
            (Inline::Code(code), Format::Html) => {
                out.push_str(&format!("<code>{}</code>", escape::html(code)));
            }
            (Inline::Emphasis { strong, inner }, _) => {
                let inner = render(inner, format);
                let wrapped = match (format, strong) {
                    (Format::Markdown, false) => format!("*{inner}*"),
                    (Format::Markdown, true) => format!("**{inner}**"),
                    (Format::Latex, false) => format!("\\emph{{{inner}}}"),
                    (Format::Latex, true) => format!("\\textbf{{{inner}}}"),
                    (Format::Html, false) => format!("<em>{inner}</em>"),
                    (Format::Html, true) => format!("<strong>{inner}</strong>"),
                };
                out.push_str(&wrapped);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(text: &str) -> Inline {
        Inline::Text(text.into())
    }

    #[test]
    fn paragraphs_lists_and_runs_of_lines() {
        let source = "A bob swings.\nIt is *light*.\n\nFind:\n1. $\\ddot\\theta$\n2. the pull\n   of the rod\n\n- a\n- b";
        assert_eq!(
            blocks(source),
            vec![
                Block::Paragraph(vec![
                    t("A bob swings. It is "),
                    Inline::Emphasis {
                        strong: false,
                        inner: vec![t("light")]
                    },
                    t("."),
                ]),
                Block::Paragraph(vec![t("Find:")]),
                Block::List {
                    start: Some(1),
                    items: vec![
                        vec![Inline::Math("\\ddot\\theta".into(), false)],
                        vec![t("the pull of the rod")],
                    ],
                },
                Block::List {
                    start: None,
                    items: vec![vec![t("a")], vec![t("b")]]
                },
            ]
        );
    }

    #[test]
    fn dollars_and_markers_that_are_not_markup_stay_text() {
        let cases = [
            ("costs $5 and $10", "costs $5 and $10"),
            ("a $ b $ c", "a $ b $ c"),
            ("q_1 and snake_case_name", "q_1 and snake_case_name"),
            ("2 * 3 * 4", "2 * 3 * 4"),
            ("\\$x\\$ and \\*", "$x$ and *"),
            ("$\\input{/etc/passwd}$", "$\\input{/etc/passwd}$"),
        ];
        for (source, text) in cases {
            assert_eq!(inlines(source), vec![t(text)], "{source}");
        }
    }

    #[test]
    fn each_format_writes_the_same_markup() {
        let source = "Given $g = 9.81\\ \\mathrm{m/s^2}$, find **all** of `x`.";
        assert_eq!(
            render_line(source, Format::Latex),
            "Given $g = 9.81\\ \\mathrm{m/s^2}$, find \\textbf{all} of \\texttt{x}."
        );
        assert_eq!(
            render_line(source, Format::Markdown),
            "Given $g = 9.81\\ \\mathrm{m/s^2}$, find **all** of ` x `."
        );
        let html = render_line(source, Format::Html);
        assert!(
            html.starts_with("Given <math display=\"inline\">"),
            "{html}"
        );
        assert!(
            html.ends_with("</math>, find <strong>all</strong> of <code>x</code>."),
            "{html}"
        );
        assert_eq!(
            render_blocks("3. c\n4. d", Format::Latex),
            "\\begin{enumerate}\n\\setcounter{enumi}{2}\n\\item c\n\\item d\n\\end{enumerate}"
        );
        assert_eq!(
            render_blocks("3. c\n4. d", Format::Html),
            "<ol start=\"3\">\n<li>c</li>\n<li>d</li>\n</ol>"
        );
    }

    #[test]
    fn refused_math_is_escaped_text() {
        let source = "$\\input{/etc/passwd}$ and $\\write18{x}$ </script>";
        assert_eq!(
            render_line(source, Format::Latex),
            "$\\$$$\\backslash$input\\{/etc/passwd\\}$\\$$ and $\\$$$\\backslash$write18\\{x\\}$\\$$ $<$/script$>$"
        );
        assert_eq!(
            render_line(source, Format::Html),
            "$\\input{/etc/passwd}$ and $\\write18{x}$ &lt;/script&gt;"
        );
        assert_eq!(
            render_line(source, Format::Markdown),
            "\\$\\\\input\\{/etc/passwd\\}\\$ and \\$\\\\write18\\{x\\}\\$ &lt;/script&gt;"
        );
    }
}
