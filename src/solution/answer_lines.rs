//! The worked Answers as an answer key reads: each item numbered as the statement numbers
//! it, not restated where the statement words it (a statement in prose leaves a question's
//! own words, such as a paper's values, unless it only names what it asks), and the values one item finds at one
//! state in one line (`ψ̈, θ̈, φ̈ = …` at once) where they fit.

use crate::render::text::MarkupLine;
use crate::render::AnswerView;

/// The most values one line of an answer holds, as the templates set them in a line.
const MOST_IN_LINE: usize = 6;
/// The most characters of LaTeX the values of one line take, as the templates allow.
const LONGEST_LINE: usize = 420;

/// The worked answers without their questions restated and with the values of one item at
/// one state joined; the student's (no values) are left as they are: a worksheet's blank
/// needs its question.
pub fn tighten(views: &mut Vec<AnswerView>, numbered: bool) {
    if views
        .iter()
        .all(|v| v.values_tex.is_empty() && v.steps.is_empty())
    {
        return;
    }
    let names: Vec<Vec<&str>> = views.iter().map(value_names).collect();
    let alike: Vec<bool> = (0..views.len())
        .map(|i| (0..views.len()).any(|j| j != i && names[j] == names[i]))
        .collect();
    for (view, alike) in views.iter_mut().zip(alike) {
        if !named(view) || !(numbered || bare_find(view.question.as_str())) {
            continue;
        }
        // A label that tells two answers of the same values apart ("The slow precession:")
        // is said with the state the answer is at, which is then said again.
        if let Some(label) = label(view.question.as_str()).filter(|_| alike) {
            view.at_note = match view.at_note.is_empty() {
                true => label,
                false => format!("{label}, {}", view.at_note),
            };
            view.same_state = false;
        }
        view.question = MarkupLine::from(String::new());
    }
    let mut joined: Vec<AnswerView> = Vec::with_capacity(views.len());
    for view in views.drain(..) {
        match joined.last_mut() {
            Some(last) if joins(last, &view) => {
                last.values_tex.extend(view.values_tex);
                last.note = view.note;
                last.steps = view.steps;
            }
            _ => joined.push(view),
        }
    }
    *views = joined;
}

/// Whether a question says no more than the names of what it asks (`Find $\\ddot{x}$.`):
/// its answer, which names them, restates it whole.
fn bare_find(question: &str) -> bool {
    let Some(asked) = question.trim().strip_prefix("Find ") else {
        return false;
    };
    let asked = asked.trim_end_matches('.');
    asked.starts_with('$')
        && asked.ends_with('$')
        && (asked.split('$').enumerate())
            .all(|(i, part)| i % 2 == 1 || ["", " and ", ", "].contains(&part))
}

/// The label a question ends with that names which of an item's answers it is ("The slow
/// precession:", "During the fast precession:"), lower-cased and without its colon; `None`
/// for a question, or for a time the answer's state says ("At the start:", "After 4 s:").
pub(super) fn label(question: &str) -> Option<String> {
    let last = question.trim().rsplit(". ").next()?.trim();
    let words = last.strip_suffix(':')?;
    let said = ["At ", "After ", "Find ", "Show "];
    if words.len() > LONGEST_LABEL || said.iter().any(|s| words.starts_with(s)) {
        return None;
    }
    let mut chars = words.chars();
    let first = chars.next()?;
    Some(first.to_lowercase().chain(chars).collect())
}

/// The longest label kept, in characters: a few words.
const LONGEST_LABEL: usize = 40;

/// The names of the values an answer gives (`\\dot{\\psi}` of `\\dot{\\psi} = 3 …`).
fn value_names(view: &AnswerView) -> Vec<&str> {
    (view.values_tex.iter())
        .filter_map(|v| v.as_str().split_once(" = ").map(|(name, _)| name))
        .collect()
}

/// Whether the answer says what it found without its question: every value named
/// (`E = 5.8 J`, a range `3 ≤ ψ̇ ≤ 3.8 rad/s`), or a working that leads to it; a bare
/// number needs the question's words, and so does a sum (`s̈ + ẍ = 1.1 m/s²`, which the
/// question names "the absolute acceleration of the disc's centre").
fn named(view: &AnswerView) -> bool {
    let values = &view.values_tex;
    let one = |v: &str| match v.split_once(" = ") {
        Some((name, _)) => !name.contains(" + ") && !name.contains(" - "),
        None => v.contains("\\le "),
    };
    match values.is_empty() {
        true => !view.steps.is_empty(),
        false => values.iter().all(|v| one(v.as_str())),
    }
}

/// Whether `next` goes on the line of `last`: the same item at the same state, neither
/// restated, nothing said after `last`'s values, and the line not too long.
fn joins(last: &AnswerView, next: &AnswerView) -> bool {
    let count = last.values_tex.len() + next.values_tex.len();
    let length: usize = (last.values_tex.iter().chain(&next.values_tex))
        .map(|v| v.as_str().len())
        .sum();
    next.label.is_empty()
        && next.same_state
        && next.question.as_str().is_empty()
        && last.question.as_str().is_empty()
        && last.note.is_empty()
        && last.steps.is_empty()
        && !last.values_tex.is_empty()
        && !next.values_tex.is_empty()
        && count <= MOST_IN_LINE
        && length < LONGEST_LINE
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::text::Math;

    fn view(label: &str, question: &str, values: &[&str], same_state: bool) -> AnswerView {
        AnswerView {
            label: label.into(),
            question: MarkupLine::from(question.to_string()),
            values_tex: values.iter().map(|v| Math::from(v.to_string())).collect(),
            same_state,
            ..AnswerView::default()
        }
    }

    #[test]
    fn one_item_at_one_state_is_one_line_without_its_questions() {
        let mut views = vec![
            view("1", "Find $\\ddot{x}$.", &["\\ddot{x} = 1"], false),
            view(
                "",
                "Find $\\ddot{\\theta}$.",
                &["\\ddot{\\theta} = 2"],
                true,
            ),
            view("2", "Find the force.", &["F = 3", "G = 4"], true),
        ];
        tighten(&mut views, true);
        assert_eq!(views.len(), 2);
        assert_eq!(views[0].values_tex.len(), 2);
        assert!(views.iter().all(|v| v.question.as_str().is_empty()));
        assert_eq!(views[1].label, "2");
    }

    #[test]
    fn a_label_goes_with_the_state_and_a_time_is_said_by_it() {
        assert_eq!(
            label("Find the rates. The slow precession:").as_deref(),
            Some("the slow precession")
        );
        assert_eq!(
            label("During the fast precession:").as_deref(),
            Some("during the fast precession")
        );
        assert_eq!(label("Simulate it. After 4 s:"), None);
        assert_eq!(label("Find $x$."), None);
        let mut views = vec![
            view("2", "The slow precession:", &["x = 1"], false),
            view("", "The fast precession:", &["x = 2"], true),
            view(
                "3",
                "The angle. The centre's acceleration:",
                &["y = 1"],
                false,
            ),
        ];
        views[1].at_note = "a steady motion".into();
        tighten(&mut views, true);
        assert_eq!(views[1].at_note, "the fast precession, a steady motion");
        assert!(!views[1].same_state);
        // A label of values no other answer gives says nothing the values do not.
        assert!(views[2].at_note.is_empty());
    }

    #[test]
    fn a_bare_number_keeps_its_question_and_a_new_state_its_line() {
        let mut views = vec![
            view("1", "Find the sum.", &["3.5\\ \\mathrm{N}"], false),
            view("", "Find $x$.", &["x = 1"], false),
            view("", "Then $y$.", &["y = 1"], true),
        ];
        tighten(&mut views, true);
        assert_eq!(views[0].question.as_str(), "Find the sum.");
        assert_eq!(views.len(), 2);
        assert_eq!(views[1].values_tex.len(), 2);
        // The worksheet's questions stay.
        let mut blank = vec![view("1", "Find $x$.", &[], false)];
        tighten(&mut blank, true);
        assert_eq!(blank[0].question.as_str(), "Find $x$.");
    }

    #[test]
    fn a_question_in_prose_is_kept_unless_it_only_names_what_it_asks() {
        assert!(bare_find("Find $\\ddot{x}$."));
        assert!(bare_find("Find $\\ddot{x}$ and $\\ddot{y}$."));
        assert!(!bare_find("Find the reaction at $O$."));
        assert!(!bare_find(
            "Leaned by $\\phi = 0.001$ rad: the roll acceleration."
        ));
        let mut views = vec![view(
            "1",
            "Leaned by $\\phi$: the paper's value is 3.",
            &["\\ddot{\\phi} = 3"],
            false,
        )];
        tighten(&mut views, false);
        assert!(!views[0].question.as_str().is_empty());
    }
}
