//! Every bundled handout, by every method and in every format, in the words of a course
//! and with its algebra finished: no name of the program's own (a generated constraint's
//! `teeth.height`), no word of its algorithms (pivoting, Newton's iterations, a starting
//! guess, a command line, a check's tolerance and verdict), no child or parent for the
//! bodies a joint connects, no category in front of a force's label ("contact:"), no s² + c²
//! of one angle left unsimplified in a sum, a unit and a short mark (never words) beside
//! every initial value and rate of step 1, counts that agree with their nouns, and no word
//! of a body's or point's name as a subscript or superscript.

use crate::support::handouts::{handout_of, two_at_a_time};
use crate::support::METHODS;
use std::path::PathBuf;

/// Words a course does not use in a handout.
const NOT_COURSE_WORDS: [&str; 29] = [
    // Words an instructor would edit out: the program's tree of joints, a state's flag,
    // the name of a row for a condition, what the program did not write, an operation on
    // a row with its numbers.
    "joint of the tree",
    "(held)",
    "no-slip row",
    "is left out",
    "(multiplied by",
    // A bound of the simulation's rounding said in prose (10⁻⁹ J).
    "changes by less than",
    "less than 10⁻",
    // Gravity after the masses it multiplies, as textbooks write m g.
    " g m_{",
    "{g m_{",
    " g m ",
    "{g m ",
    " g m}",
    "{g m}",
    " g M",
    "{g M",
    "mesh.distance",
    "teeth.height",
    ".height left out",
    "pivoting",
    "Newton's method: ",
    "explain --verbose",
    "guess",
    "child",
    "parent",
    "dampers and friction only remove",
    "of the 2 slowest",
    "iterations;",
    // A force is labelled by what it is (weight of B), not by a category of forces.
    "contact: ",
    "distance: ",
];

/// What a program's report says and a textbook does not: a check's tolerance and verdict,
/// one method's numbers beside another's, how many candidates were tried, where a search
/// or an iteration started, and the algorithms of linear algebra.
const NOT_TEXTBOOK_WORDS: [&str; 18] = [
    "tolerance",
    "Tolerance",
    "| pass",
    ">pass<",
    "& pass",
    "constraint drift",
    "agreement between methods",
    "Candidates not used",
    "; started from",
    "As formed, already simplified",
    "too long to print whole",
    "the search",
    "Cramer",
    "where a pivot",
    "Hessian",
    "differs more",
    "differs most",
    "What each check compared",
];

/// The formats a handout is written in.
const FORMATS: [&str; 3] = ["markdown", "latex", "html"];

/// Every bundled problem (`problems/*.json`; the validation problems, some of which take
/// minutes a handout, are checked against their references elsewhere).
fn bundled() -> Vec<PathBuf> {
    crate::support::all_problems()
}

/// The signed terms of a line of math, split at ` + `, ` - ` and ` = ` outside braces, with any
/// brackets around a term taken off.
fn terms(line: &str) -> Vec<(char, String)> {
    let mut out = Vec::new();
    let (mut depth, mut sign, mut current) = (0i32, '+', String::new());
    let chars: Vec<char> = line.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '{' | '(' | '[' => depth += 1,
            '}' | ')' | ']' => depth -= 1,
            _ => {}
        }
        let split = depth <= 1
            && i + 2 < chars.len()
            && chars[i] == ' '
            && matches!(chars[i + 1], '+' | '-' | '=')
            && chars[i + 2] == ' ';
        if split {
            out.push((sign, current.clone()));
            // Each side of an equation starts with a term of its own.
            sign = if chars[i + 1] == '=' {
                '+'
            } else {
                chars[i + 1]
            };
            current.clear();
            i += 3;
            continue;
        }
        current.push(c);
        i += 1;
    }
    out.push((sign, current));
    out.into_iter()
        .map(|(s, t)| {
            let t = t
                .trim()
                .trim_start_matches(['[', '('])
                .trim_end_matches([']', ')']);
            (s, t.to_string())
        })
        .collect()
}

/// A pair of terms of `line` with one sign that differ only by s²_θ against c²_θ of one
/// angle θ, the other factors alike: their sum is the term without either. Hidden forms
/// count too: `s_θ c²_θ M + s³_θ M` is `s_θ M`.
fn pythagorean_pair(line: &str) -> Option<String> {
    let found: Vec<(char, String, Factors)> = terms(line)
        .into_iter()
        .map(|(sign, term)| {
            let factors = factors(&term);
            (sign, term, factors)
        })
        .collect();
    for (sign, term, factors) in &found {
        for (key, power) in factors {
            let Some(angle) = key.strip_prefix("s_") else {
                continue;
            };
            if *power < 2 {
                continue;
            }
            // s^n_θ → s^(n−2)_θ c²_θ
            let mut other = factors.clone();
            let cosine = format!("c_{angle}");
            adjust(&mut other, key, -2);
            adjust(&mut other, &cosine, 2);
            let partner = found
                .iter()
                .find(|(s, t, f)| s == sign && t != term && *f == other);
            if let Some((_, partner, _)) = partner {
                return Some(format!("{term} + {partner}"));
            }
        }
    }
    None
}

/// A term's factors, each with its power.
type Factors = Vec<(String, i32)>;

/// A term's factors, split where a space separates them outside braces, each with its
/// power (`s_{\theta}^{3}` is `s_{\theta}` to 3), sorted so two orders compare alike.
fn factors(term: &str) -> Factors {
    let mut out: Factors = Vec::new();
    let (mut depth, mut current) = (0i32, String::new());
    let mut pieces = Vec::new();
    for c in term.chars() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        if c == ' ' && depth == 0 {
            pieces.push(std::mem::take(&mut current));
        } else {
            current.push(c);
        }
    }
    pieces.push(current);
    for piece in pieces.into_iter().filter(|p| !p.is_empty()) {
        let (key, power) = match piece.rsplit_once("^{") {
            Some((base, p)) if !base.is_empty() => match p.trim_end_matches('}').parse() {
                Ok(n) => (base.to_string(), n),
                Err(_) => (piece.clone(), 1),
            },
            _ => (piece.clone(), 1),
        };
        adjust(&mut out, &key, power);
    }
    out.sort();
    out
}

/// `factors` with `key`'s power changed by `by`, dropped at zero.
fn adjust(factors: &mut Factors, key: &str, by: i32) {
    match factors.iter_mut().find(|(k, _)| k == key) {
        Some(entry) => entry.1 += by,
        None => factors.push((key.to_string(), by)),
    }
    factors.retain(|(_, p)| *p != 0);
    factors.sort();
}

#[test]
fn the_pythagorean_pair_is_found_and_only_it() {
    let line = "-R g m + [R m \\ddot{x} s_{\\theta}^{2} + R m \\ddot{x} c_{\\theta}^{2}] = 0";
    assert!(pythagorean_pair(line).is_some());
    // The hidden form: s c² + s³ = s, the factors in any order.
    let hidden = "-R g m + [h \\dot{\\psi}^{2} s_{\\psi} s_{\\theta} c_{\\theta}^{2} + h \\dot{\\psi}^{2} s_{\\psi} s_{\\theta}^{3}] = 0";
    assert!(pythagorean_pair(hidden).is_some(), "{hidden}");
    for fine in [
        "R m \\ddot{x} s_{\\theta}^{2} - R m \\ddot{x} c_{\\theta}^{2} = 0",
        "R m \\ddot{x} s_{\\theta}^{2} + m \\ddot{x} c_{\\theta}^{2} = 0",
        "s_{\\theta}^{2} + c_{\\phi}^{2} = 0",
        "s_{\\theta} c_{\\theta} = 0",
        "h s_{\\psi} s_{\\theta} c_{\\theta}^{2} + h s_{\\psi} s_{\\theta}^{2} = 0",
    ] {
        assert_eq!(pythagorean_pair(fine), None, "{fine}");
    }
}

/// Every handout in every format, two at a time.
#[test]
fn every_bundled_handout_speaks_a_course_and_finishes_its_algebra() {
    let paths = bundled();
    let jobs: Vec<(PathBuf, &str, &str)> = (paths.iter())
        .flat_map(|p| METHODS.iter().map(move |m| (p.clone(), *m)))
        .flat_map(|(p, m)| FORMATS.iter().map(move |f| (p.clone(), m, *f)))
        .collect();
    let wrong = two_at_a_time(&jobs, |(path, method, format)| {
        let Some(text) = handout_of(path, method, format) else {
            return Vec::new();
        };
        let text = match *format {
            "html" => visible(&text),
            _ => text,
        };
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        let mut wrong = Vec::new();
        for word in NOT_COURSE_WORDS.iter().chain(&NOT_TEXTBOOK_WORDS) {
            if let Some(line) = text.lines().find(|l| l.contains(word)) {
                let line: String = line.chars().take(200).collect();
                wrong.push(format!("{name} ({method}, {format}): `{word}` in: {line}"));
            }
        }
        if *format != "markdown" {
            return wrong;
        }
        for line in text.lines() {
            if let Some(pair) = pythagorean_pair(line) {
                wrong.push(format!("{name} ({method}, {format}): s² + c² left: {pair}"));
            }
        }
        wrong.extend(unitless_rows(&text).map(|row| format!("{name} ({method}): {row}")));
        wrong.extend(count_slips(&text).map(|slip| format!("{name} ({method}): `{slip}`")));
        if let Some(clash) = cosine_clash(path, &text) {
            wrong.push(format!("{name} ({method}): {clash}"));
        }
        if let Some(word) = word_script(&text) {
            wrong.push(format!("{name} ({method}): a word as a script: {word}"));
        }
        if let Some(words) = underscored_words(&text) {
            wrong.push(format!(
                "{name} ({method}): a name with `_` in words: {words}"
            ));
        }
        wrong
    });
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The text an HTML page shows: without its style sheet, its script and its tags.
fn visible(html: &str) -> String {
    let mut out = String::with_capacity(html.len());
    let mut rest = html;
    while let Some(at) = rest.find('<') {
        out.push_str(&rest[..at]);
        rest = &rest[at..];
        // The index just past the tag, or past the whole style sheet or script.
        let end = match ["<style", "<script"].iter().find(|o| rest.starts_with(**o)) {
            Some(open) => {
                let close = format!("</{}>", &open[1..]);
                rest.find(&close).map(|i| i + close.len())
            }
            None => rest.find('>').map(|i| i + 1),
        };
        rest = end.map_or("", |end| &rest[end..]);
    }
    out.push_str(rest);
    out
}

/// Words in math (`\\text{no slip at rear\\_contact}`) with a name's underscore in them:
/// a course writes "rear contact".
fn underscored_words(markdown: &str) -> Option<String> {
    markdown.match_indices("\\text{").find_map(|(at, _)| {
        let rest = &markdown[at + 6..];
        let words = &rest[..rest.find('}')?];
        words.contains("\\_").then(|| words.to_string())
    })
}

/// An abbreviation of a sine or cosine that reads as one of the problem's names: with a
/// rocker length `c`, `c_{1} = \\cos(q_{1})` beside `c \\cos(…)`.
fn cosine_clash(path: &std::path::Path, markdown: &str) -> Option<String> {
    let problem: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    let named = |letter: &str| {
        ["constants", "coordinates", "bodies"]
            .iter()
            .any(|key| problem[key].get(letter).is_some())
    };
    [("s", "\\sin"), ("c", "\\cos")]
        .iter()
        .filter(|(letter, _)| named(letter))
        .find_map(|(letter, f)| {
            let listed = format!("{letter}_{{");
            markdown
                .match_indices(&listed)
                .find(|(at, _)| {
                    let rest = &markdown[*at..];
                    rest.find('}')
                        .is_some_and(|end| rest[end..].starts_with(&format!("}} = {f}")))
                })
                .map(|_| format!("`{letter}` is a name of the problem and an abbreviation of {f}"))
        })
}

/// Words a handout sets upright in its own math (`v_{\\mathrm{slip}}`, `\\mathrm{max}`).
const OWN_SCRIPTS: [&str; 4] = ["slip", "max", "min", "loop"];

/// A body's or point's name as a word in a script: `\\hat{\\mathbf{x}}_{\\mathrm{top}}`,
/// `F^{\\mathrm{tip}}_{x}`, `\\mathrm{top}^*`; a textbook writes a letter there.
fn word_script(markdown: &str) -> Option<String> {
    markdown.match_indices("\\mathrm{").find_map(|(at, _)| {
        let rest = &markdown[at + 8..];
        let word = &rest[..rest.find('}')?];
        let after = &rest[word.len() + 1..];
        let before = &markdown[..at];
        let word_like = word.len() > 1 && word.chars().all(|c| c.is_ascii_lowercase());
        let scripted = ((before.ends_with("_{") || before.ends_with("^{"))
            && after.starts_with('}'))
            || after.starts_with("^*")
            || after.starts_with("^{*}");
        (word_like && scripted && !OWN_SCRIPTS.contains(&word))
            .then(|| format!("\\mathrm{{{word}}}"))
    })
}

#[test]
fn a_word_as_a_script_is_found() {
    assert!(word_script("$\\hat{\\mathbf{x}}_{\\mathrm{top}}$").is_some());
    assert!(word_script("$F^{\\mathrm{tip}}_{x}$").is_some());
    assert!(word_script("$\\mathrm{top}^*$").is_some());
    for fine in [
        "$v_{\\mathrm{slip}}$",
        "$\\hat{\\mathbf{x}}_{B}, B^*$",
        "$\\mathrm{link}_{7}^*$",
        "$12\\ \\mathrm{kg}$",
    ] {
        assert_eq!(word_script(fine), None, "{fine}");
    }
}

/// Step 1's coordinate rows whose initial value or rate has no unit: every coordinate is
/// an angle or a distance, so each carries one (`0.7 rad`, `1 rad/s`).
fn unitless_rows(markdown: &str) -> impl Iterator<Item = String> + '_ {
    let table = markdown
        .find("| Coordinate |")
        .map_or("", |at| &markdown[at..]);
    (table.lines().skip(2))
        .take_while(|l| l.starts_with('|'))
        .filter(|row| {
            let cells: Vec<&str> = row.trim_matches('|').split(" | ").collect();
            let n = cells.len();
            n < 2 || cells[n - 2..].iter().any(|cell| !has_unit(cell))
        })
        .map(|row| format!("a value without its unit in step 1: {row}"))
}

/// Whether a value cell names its unit after the number: `0.7 rad`, `-2 rad/s†`.
fn has_unit(cell: &str) -> bool {
    let mut words = cell.split_whitespace();
    words.next().is_some_and(|n| n.parse::<f64>().is_ok())
        && words
            .next()
            .is_some_and(|u| u.starts_with(|c: char| c.is_alphabetic()))
}

/// Nouns a handout counts, singular and plural.
const COUNTED: [(&str, &str); 16] = [
    ("constraint", "constraints"),
    ("coordinate", "coordinates"),
    ("row", "rows"),
    ("equation", "equations"),
    ("speed", "speeds"),
    ("body", "bodies"),
    ("unknown", "unknowns"),
    ("rate", "rates"),
    ("reaction", "reactions"),
    ("component", "components"),
    ("mode", "modes"),
    ("force", "forces"),
    ("term", "terms"),
    ("contact", "contacts"),
    ("joint", "joints"),
    ("question", "questions"),
];

/// Number and noun that disagree in a sentence: "the 1 position constraints", "the 2
/// equation"; the noun may follow one adjective.
fn count_slips(text: &str) -> impl Iterator<Item = String> + '_ {
    let words: Vec<&str> = text.split_whitespace().collect();
    let mut out = Vec::new();
    for (i, w) in words.iter().enumerate() {
        let Ok(n) = w.parse::<u32>() else { continue };
        // A number inside math or a list of numbers is not a count.
        if i == 0 || !matches!(words[i - 1], "the" | "The" | "of" | "from" | "all" | "are") {
            continue;
        }
        for noun in words.iter().skip(i + 1).take(2) {
            let noun = noun.trim_end_matches([',', '.', ':', ';', ')']);
            let slip = COUNTED.iter().any(|(one, many)| {
                (n == 1 && noun == *many) || (n > 1 && noun == *one && words[i - 1] == "the")
            });
            if slip {
                out.push(words[i - 1..=i + 2.min(words.len() - i - 1)].join(" "));
            }
        }
    }
    out.into_iter()
}

#[test]
fn a_number_and_its_noun_that_disagree_are_found() {
    assert_eq!(
        count_slips("solved from the 1 position constraints: y").count(),
        1
    );
    assert_eq!(count_slips("the 2 equation of motion").count(), 1);
    for fine in [
        "solved from the position constraint",
        "the 2 position constraints",
        "row 1 equations",
        "at t = 1 s the speeds",
    ] {
        assert_eq!(count_slips(fine).count(), 0, "{fine}");
    }
}

#[test]
fn a_value_without_its_unit_is_found() {
    assert!(has_unit("0.7 rad") && has_unit("-0.65053 rad†"));
    assert!(!has_unit("8") && !has_unit("0.829552†"));
    let table = "| Coordinate | Unit | Initial value | Initial rate |\n|---|---|---|---|\n| $x$ | m | 0 m | 8 |\n| $y$ | m | 0 m | 1 m/s |\n";
    assert_eq!(unitless_rows(table).count(), 1);
    assert!(underscored_words("$\\text{no slip at rear\\_contact}$").is_some());
    assert!(underscored_words("$\\text{no slip at rear contact} x_{1}$").is_none());
    let page =
        "<style>td:first-child { }</style><p class=\"parent\">a <em>b</em></p><script>x</script>c";
    assert_eq!(visible(page), "a bc");
}
