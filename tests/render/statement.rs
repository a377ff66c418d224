//! The statement and the questions as a reader expects them: paragraphs, lists, emphasis
//! and `$…$` math in every format; math outside the allowed part of LaTeX shown as text.

use super::{problem_files, rendered};
use mbd_tutor::render::{blocks, inlines, sample, Block, Format, Inline};

/// Every piece of text in `pieces` that still holds a `$`: math that was refused.
fn refused(pieces: &[Inline], out: &mut Vec<String>) {
    for piece in pieces {
        match piece {
            Inline::Text(t) if t.contains('$') => out.push(t.clone()),
            Inline::Emphasis { inner, .. } => refused(inner, out),
            _ => {}
        }
    }
}

/// The text pieces of `text`, the math left out.
fn text_outside_math(text: &str) -> String {
    fn collect(pieces: &[Inline], out: &mut String) {
        for piece in pieces {
            match piece {
                Inline::Text(t) => out.push_str(t),
                Inline::Emphasis { inner, .. } => collect(inner, out),
                _ => {}
            }
        }
    }
    let mut out = String::new();
    for block in blocks(text) {
        match block {
            Block::Paragraph(pieces) => collect(&pieces, &mut out),
            Block::List { items, .. } => items.iter().for_each(|i| collect(i, &mut out)),
        }
        out.push('\n');
    }
    out
}

/// The bundled problems write their symbols as math, and every span of it is allowed: a
/// refused span would print as `$…$` text in the handout.
#[test]
fn bundled_statements_and_questions_are_all_allowed_math() {
    let mut checked = 0;
    for path in problem_files() {
        let text = std::fs::read_to_string(&path).expect("readable");
        let json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
        let mut texts: Vec<String> = json["statement"]
            .as_str()
            .map(String::from)
            .into_iter()
            .collect();
        if let Some(questions) = json["find"]["questions"].as_array() {
            texts.extend(
                questions
                    .iter()
                    .filter_map(|q| q["text"].as_str().map(String::from)),
            );
        }
        for text in texts {
            let mut bad = Vec::new();
            for block in blocks(&text) {
                match block {
                    Block::Paragraph(pieces) => refused(&pieces, &mut bad),
                    Block::List { items, .. } => items.iter().for_each(|i| refused(i, &mut bad)),
                }
            }
            assert!(
                bad.is_empty(),
                "{}: math shown as text: {bad:?}",
                path.display()
            );
            // No ASCII stand-ins left where math belongs, in the text outside the math.
            let words = text_outside_math(&text);
            for ascii in ["m/s^2", "kg m^2", "theta'", "q1''"] {
                assert!(
                    !words.contains(ascii),
                    "{}: `{ascii}` in {text}",
                    path.display()
                );
            }
            checked += 1;
        }
    }
    assert!(checked > 40, "only {checked} texts found");
}

#[test]
fn the_statement_is_markup_in_every_format() {
    let mut solution = sample();
    solution.statement = Some(
        "A *light* rod, $L = 0.8\\ \\mathrm{m}$:\n\n1. Find $\\ddot{\\theta}$.\n2. Find **the pull**.\n\n$\\input{x}$ costs $5."
            .into(),
    );
    let latex = rendered(&solution, Format::Latex, false);
    assert!(
        latex.contains("A \\emph{light} rod, $L = 0.8\\ \\mathrm{m}$:"),
        "{latex}"
    );
    assert!(latex.contains("\\begin{enumerate}\n\\item Find $\\ddot{\\theta}$.\n\\item Find \\textbf{the pull}.\n\\end{enumerate}"));
    assert!(latex.contains("$\\$$$\\backslash$input\\{x\\}$\\$$ costs $\\$$5."));
    let markdown = rendered(&solution, Format::Markdown, false);
    assert!(markdown.contains("A *light* rod, $L = 0.8\\ \\mathrm{m}$:\n\n1. Find $\\ddot{\\theta}$.\n2. Find **the pull**."));
    assert!(markdown.contains("\\$\\\\input\\{x\\}\\$ costs \\$5."));
    let html = rendered(&solution, Format::Html, false);
    assert!(html.contains("<p>A <em>light</em> rod, <math"), "{html}");
    assert!(html.contains("<ol>\n<li>Find <math"));
    assert!(html.contains("<li>Find <strong>the pull</strong>.</li>"));
    assert!(html.contains("$\\input{x}$ costs $5."));
}

#[test]
fn hostile_math_stays_inert_in_html() {
    let mut solution = sample();
    solution.statement = Some(
        "$</script><script>alert(1)</script>$ and </script> $<img src=x onerror=alert(2)>$".into(),
    );
    let html = rendered(&solution, Format::Html, false).to_lowercase();
    assert!(
        // The page's own pictures are `<img alt=…>`; the statement's must not be one.
        !html.contains("<script") && !html.contains("</script") && !html.contains("<img src=x"),
        "{html}"
    );
    let markdown = rendered(&solution, Format::Markdown, false).to_lowercase();
    assert!(
        !markdown.contains("<script")
            && !markdown.contains("</script")
            && !markdown.contains("<img")
    );
}

#[test]
fn math_pieces_are_found_only_where_a_reader_sees_them() {
    assert_eq!(
        inlines("from $5 to $10, and $x$"),
        vec![
            Inline::Text("from $5 to $10, and ".into()),
            Inline::Math("x".into(), false)
        ]
    );
}
