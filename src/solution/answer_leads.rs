//! Where each answer is asked, said once: the state is named at an answer asked at a new
//! state and not again at the answers after it at the same state; an instant the
//! question's own words give ("After 4 s:") is not written a second time.

use super::answer_numbers::{number_tex, unit_tex};
use crate::numeric::{coordinate_unit, Answer};
use crate::problem::{Problem, Question, QuestionKind};
use crate::render::text::Math;
use crate::render::AnswerView;
use crate::symbolic::{fixed, latex};

/// Marks each view asked at the same state as the one before it; a view asked at the state
/// of an earlier answer, not the one just before, names that answer instead of repeating
/// the state.
pub fn mark_repeated_states(views: &mut [AnswerView]) {
    for i in 1..views.len() {
        let (before, after) = views.split_at_mut(i);
        let view = &mut after[0];
        let key = (view.at_tex.clone(), view.at_note.clone());
        // A view whose lead its steps say already (a `show`'s conditions) keeps none.
        view.same_state |= asked_at(&before[i - 1], &key);
        // A lead said before, even one that names the answer that found its state ("found in
        // answer 2", where that answer found two), is not said again in full.
        if view.same_state || key.0.as_str().is_empty() {
            continue;
        }
        let Some(k) = before.iter().position(|v| asked_at(v, &key)) else {
            continue;
        };
        let Some(start) = (0..=k).rev().find(|&j| !before[j].label.is_empty()) else {
            continue;
        };
        let part = part_name(before, start, k);
        view.at_note = format!("at the state of answer {}{part}", before[start].label);
        view.at_tex = Math::from(String::new());
    }
    say_first_of_two_states(views);
}

/// An item whose answers are at two states ("At the start:", "After 4 s:") says the first
/// state too, even where the answer before it was at that state: otherwise its first value
/// reads as at the second.
fn say_first_of_two_states(views: &mut [AnswerView]) {
    for start in 0..views.len() {
        if views[start].label.is_empty() || !views[start].same_state {
            continue;
        }
        let end = (start + 1..views.len())
            .find(|&j| !views[j].label.is_empty())
            .unwrap_or(views.len());
        let moves = (start + 1..end).any(|j| !views[j].same_state);
        if moves && !views[start].at_tex.as_str().is_empty() {
            views[start].same_state = false;
        }
    }
}

/// The words that tell which state of answer `views[start]` the view `views[k]` is at,
/// where that answer is at more than one ("the slow precession" of slow and fast): its
/// question's own label (", during the slow precession"), or its order (", the first");
/// empty where the answer is at one state.
fn part_name(views: &[AnswerView], start: usize, k: usize) -> String {
    let end = (start + 1..views.len())
        .find(|&j| !views[j].label.is_empty())
        .unwrap_or(views.len());
    let key = |v: &AnswerView| (v.at_tex.clone(), v.at_note.clone());
    let states = (start..end)
        .filter(|&j| !views[j].same_state && !views[j].at_tex.as_str().is_empty())
        .map(|j| key(&views[j]))
        .fold(Vec::new(), |mut seen, s| {
            if !seen.contains(&s) {
                seen.push(s);
            }
            seen
        });
    if states.len() < 2 {
        return String::new();
    }
    if let Some(label) = super::answer_lines::label(views[k].question.as_str()) {
        return format!(", {label}");
    }
    let order = ["first", "second", "third", "fourth"];
    let at = states.iter().position(|s| *s == key(&views[k]));
    at.and_then(|i| order.get(i))
        .map(|o| format!(", the {o} state"))
        .unwrap_or_default()
}

/// The state of a steady motion found by `about` (a `steady` question), as the values it
/// found: the values it held are said in its own answer, not again. `None` for a question
/// of another kind.
pub fn found_tex(problem: &Problem, about: &Question, answer: &Answer) -> Option<String> {
    let QuestionKind::Steady { unknowns, .. } = &about.kind else {
        return None;
    };
    let parts: Vec<String> = (unknowns.iter())
        .filter_map(|e| {
            let x = match e.order {
                0 => answer.q.get(e.coordinate)?,
                _ => answer.rates.get(e.coordinate)?,
            };
            let symbol = latex(&problem.coordinate_expr(e.coordinate, e.order));
            let unit = coordinate_unit(problem, e.coordinate, e.order);
            Some(format!("{symbol} = {}{}", number_tex(*x), unit_tex(&unit)))
        })
        .collect();
    (!parts.is_empty()).then(|| parts.join(",\\ "))
}

/// Whether `view` is asked at the state `(at_tex, at_note)`.
fn asked_at(view: &AnswerView, key: &(Math, String)) -> bool {
    view.at_tex == key.0 && view.at_note == key.1
}

/// Whether the question's own words give the instant it is asked at (`After 4 s:`).
pub fn says_its_time(question: &Question) -> bool {
    let (Some(t), Some(text)) = (question.at.time, question.text.as_deref()) else {
        return false;
    };
    t > 0.0 && question.at.state.is_none() && text.contains(&format!("{} s", fixed(t)))
}

/// The instant left out of `view` where the question says it: only how the state was
/// reached is left ("simulated from the initial state").
pub fn drop_said_time(question: &Question, view: &mut AnswerView) {
    if says_its_time(question) {
        view.at_tex = Math::from(String::new());
    }
}

/// The instant a site that slides from the start stops: a wheel's contact (`rolling`,
/// `gear`) starts to roll, any other sticks.
pub fn stops_slipping(problem: &crate::problem::Problem, site: usize) -> String {
    use crate::problem::ConstraintKind;
    let name = problem.site_name(site);
    let rolls = (problem.constraints.iter()).any(|c| {
        c.name == name
            && matches!(
                c.kind,
                ConstraintKind::Rolling { .. } | ConstraintKind::Gear { .. }
            )
    });
    let then = if rolls { "starts to roll" } else { "sticks" };
    format!(
        "the instant the contact at {} stops slipping and {then}",
        super::force_labels::place(name)
    )
}

#[cfg(test)]
mod tests {
    use super::mark_repeated_states;
    use crate::render::text::{MarkupLine, Math};
    use crate::render::AnswerView;

    fn view(label: &str, question: &str, at: &str) -> AnswerView {
        AnswerView {
            label: label.into(),
            question: MarkupLine::from(question.to_string()),
            at_tex: Math::from(at.to_string()),
            at_note: "found".into(),
            ..AnswerView::default()
        }
    }

    #[test]
    fn a_state_of_an_answer_at_two_states_is_named_by_its_part() {
        let mut views = vec![
            view(
                "3",
                "Find F. During the slow precession:",
                "\\dot{\\psi} = 3",
            ),
            view("", "During the fast precession:", "\\dot{\\psi} = 61"),
            view("4", "Find x.", "t = 9"),
            view("5", "Find the period.", "\\dot{\\psi} = 61"),
            view("6", "Find the period.", "\\dot{\\psi} = 3"),
        ];
        mark_repeated_states(&mut views);
        assert_eq!(
            views[3].at_note,
            "at the state of answer 3, during the fast precession"
        );
        assert_eq!(
            views[4].at_note,
            "at the state of answer 3, during the slow precession"
        );
        assert!(views[4].at_tex.as_str().is_empty());
        // An answer at one state is named alone.
        let mut views = vec![
            view("1", "Find x.", "t = 1"),
            view("2", "Find y.", "t = 2"),
            view("3", "Find z.", "t = 1"),
        ];
        mark_repeated_states(&mut views);
        assert_eq!(views[2].at_note, "at the state of answer 1");
    }

    #[test]
    fn an_item_at_two_states_says_its_first_though_the_answer_before_said_it() {
        let mut views = vec![
            view("2", "Find F.", "t = 0"),
            view("3", "Find E. At the start:", "t = 0"),
            view("", "After 4 s:", "t = 4"),
        ];
        mark_repeated_states(&mut views);
        assert!(!views[1].same_state);
        assert!(!views[2].same_state);
        // An item at one state leaves it to the answer before.
        let mut views = vec![view("2", "Find F.", "t = 0"), view("3", "Find E.", "t = 0")];
        mark_repeated_states(&mut views);
        assert!(views[1].same_state);
    }
}
