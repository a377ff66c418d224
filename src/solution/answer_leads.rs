//! Where each answer is asked, said once: the state is named at an answer asked at a new
//! state and not again at the answers after it at the same state; an instant the
//! question's own words give ("After 4 s:") is not written a second time.

use crate::problem::Question;
use crate::render::text::Math;
use crate::render::AnswerView;
use crate::symbolic::fixed;

/// Marks each view asked at the same state as the one before it.
pub fn mark_repeated_states(views: &mut [AnswerView]) {
    for i in 1..views.len() {
        let (before, after) = views.split_at_mut(i);
        let last = &before[i - 1];
        after[0].same_state = last.at_tex == after[0].at_tex && last.at_note == after[0].at_note;
    }
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
        name.replace('_', " ")
    )
}
