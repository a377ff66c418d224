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
        let item = (before[..=k].iter().rev()).find(|v| !v.label.is_empty());
        if let Some(item) = item {
            view.at_note = format!("at the state of answer {}", item.label);
            view.at_tex = Math::from(String::new());
        }
    }
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
