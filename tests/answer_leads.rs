//! The Answers as an answer key reads: each answer numbered as the statement numbers its
//! items, led by the statement's own words or by no restatement at all, never by a
//! question the statement does not ask ("Find the cart's acceleration ẍ.").

use crate::support::{all_problems, explain_file};

/// `text` with its runs of white space made single spaces, in lower case (a question
/// quoted from the middle of a sentence starts with a capital).
fn spaced(text: &str) -> String {
    text.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .to_lowercase()
}

/// The Answers of a Markdown handout, line by line.
fn answer_lines(handout: &str) -> Vec<String> {
    let Some((_, answers)) = handout.split_once("## Answers") else {
        return Vec::new();
    };
    answers.lines().map(|l| l.trim().to_string()).collect()
}

/// The item number a line of the Answers opens with (`2. …`), and the rest of it.
fn numbered(line: &str) -> Option<(u32, &str)> {
    let (number, rest) = line.split_once('.')?;
    let rest = match rest.is_empty() {
        true => rest,
        false => rest.strip_prefix(' ')?,
    };
    Some((number.parse().ok()?, rest))
}

/// `line` when it opens by asking (`Find …`, `Show …`, a question), as a restated question
/// does; `None` for a value, a state or a sentence of working.
fn asking(line: &str) -> Option<&str> {
    let asks = [
        "Find ",
        "Show ",
        "Evaluate ",
        "Check ",
        "Does ",
        "When ",
        "How ",
        "At what ",
    ];
    asks.iter().any(|a| line.starts_with(a)).then_some(line)
}

/// Every bundled problem by the Motion Law: each answer line's number is an item of the
/// statement, and each question an answer restates is the statement's words.
#[test]
fn every_answer_is_numbered_and_led_by_the_statement() {
    let mut faults = Vec::new();
    for path in all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("valid");
        if problem.questions.is_empty() {
            continue;
        }
        let statement = spaced(problem.statement.as_deref().unwrap_or(""));
        let handout = explain_file(&path, &["--format", "markdown"]);
        let lines = answer_lines(&handout);
        assert!(!lines.is_empty(), "{}: no Answers", path.display());
        let mut numbers = Vec::new();
        for line in &lines {
            let lead = match numbered(line) {
                Some((n, rest)) => {
                    numbers.push(n);
                    rest
                }
                None => line.as_str(),
            };
            if let Some(asked) = asking(lead).filter(|a| !statement.contains(&spaced(a))) {
                faults.push(format!(
                    "{}: \"{asked}\" is not the statement's words",
                    path.display()
                ));
            }
        }
        let labels = mbd_tutor::solution::answer_labels(&problem);
        let wanted: Vec<u32> = labels.iter().filter_map(|l| l.parse().ok()).collect();
        if numbers != wanted {
            faults.push(format!(
                "{}: {numbers:?} against {wanted:?}",
                path.display()
            ));
        }
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

#[test]
fn an_asking_sentence_is_found_and_a_number_read() {
    assert_eq!(asking("Find $x$."), Some("Find $x$."));
    assert_eq!(asking("At t = 0 s (the initial state): $x = 1$"), None);
    assert_eq!(asking("$E = 1$ J"), None);
    assert_eq!(numbered("2. At t = 0"), Some((2, "At t = 0")));
    assert_eq!(numbered("1."), Some((1, "")));
    assert_eq!(numbered("0.5 rad"), None);
    assert_eq!(numbered("Yes. It does"), None);
}
