//! The abbreviations a handout lists are those it prints: every bundled problem's worked
//! handout and its handout at rest (`explain --statics`), by every method, lists
//! `s_θ = sin θ` only where some `s_θ` stands in its body.

use crate::support::handouts::{handout_with, two_at_a_time};
use crate::support::{all_problems, METHODS};
use std::path::{Path, PathBuf};

/// The line of a Markdown handout that lists the abbreviations.
const LEAD: &str = "Abbreviations: ";

/// The names `text`'s abbreviations line lists (`s_{1}` of `$s_{1} = \sin q_{1}$`), and
/// the text without that line.
fn listed(text: &str) -> (Vec<String>, String) {
    let mut names = Vec::new();
    let mut body = Vec::new();
    for line in text.lines() {
        let Some(rest) = line.strip_prefix(LEAD) else {
            body.push(line);
            continue;
        };
        // `$s$ and $c$ are …, as in $s_{1} = \sin q_{1}$, …`: each `$…$` with an `=`.
        for (k, piece) in rest.split('$').enumerate() {
            if k % 2 == 1 {
                if let Some((name, _)) = piece.split_once(" = ") {
                    names.push(name.trim().to_string());
                }
            }
        }
    }
    (names, body.join("\n"))
}

#[test]
fn the_listing_reads_names_and_leaves_the_body() {
    let text = "Step 1\nAbbreviations: $s_{1} = \\sin q_{1}$, $c_{12} = \\cos\\left(q_{1} + q_{2}\\right)$.\n$s_{1} m g$";
    let (names, body) = listed(text);
    assert_eq!(names, ["s_{1}", "c_{12}"]);
    assert_eq!(body, "Step 1\n$s_{1} m g$");
    let (names, _) = listed(
        "Abbreviations: $s$ and $c$ are the sine and cosine of the coordinate their subscript names, as in $s_{1} = \\sin q_{1}$.",
    );
    assert_eq!(names, ["s_{1}"]);
}

/// The Markdown handout of `path` by `method`, at rest with `statics`; `None` where it is
/// refused (other tests see to which are).
fn handout(path: &Path, method: &str, statics: bool) -> Option<String> {
    let flags: &[&str] = if statics { &["--statics"] } else { &[] };
    handout_with(path, method, "markdown", flags)
}

#[test]
fn every_abbreviation_listed_is_printed() {
    let jobs: Vec<(PathBuf, &str, bool)> = all_problems()
        .into_iter()
        .flat_map(|p| METHODS.map(|m| [(p.clone(), m, false), (p.clone(), m, true)]))
        .flatten()
        .collect();
    let mut wrong = two_at_a_time(&jobs, |(path, method, statics)| {
        let Some(text) = handout(path, method, *statics) else {
            return Vec::new();
        };
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        let at_rest = if *statics { " at rest" } else { "" };
        let (names, body) = listed(&text);
        names
            .iter()
            .filter(|n| !body.contains(n.as_str()))
            .map(|n| format!("{name} by {method}{at_rest}: {n} listed, never printed"))
            .collect()
    });
    wrong.sort();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
