//! The words of the Answers for the kinds `period` and `show`: the question made from
//! what it asks, where it is asked (`about` a steady motion found above), and the sides of
//! an identity as math. Their working is in [`super::question_steps`].

use crate::numeric::{holds, Answer};
use crate::problem::{Problem, Question, QuestionKind};
use crate::symbolic::latex;

/// The question made from what it asks, when it has no `text`.
pub fn asked(problem: &Problem, question: &Question) -> String {
    match &question.kind {
        QuestionKind::Period {
            coordinate: Some(i),
        } => format!(
            "Find the period of small oscillations of ${}$ about this state.",
            latex(&problem.coordinate_expr(*i, 0))
        ),
        QuestionKind::Show { lhs, rhs, .. } => {
            format!("Show that ${} = {}$.", latex(lhs), latex(rhs))
        }
        _ => "Find the period of small oscillations about this state.".into(),
    }
}

/// Where a question `about` the steady motion of question `k` is asked, in words.
pub fn about_note(problem: &Problem, k: usize) -> String {
    let labels = super::answer_numbers::labels(problem);
    let item = labels[..=k].iter().rev().find(|l| !l.is_empty());
    match item {
        Some(item) => format!(
            "the steady motion found in answer {item}, the other coordinates as at the start"
        ),
        None => "the steady motion found above, the other coordinates as at the start".into(),
    }
}

/// The side of a `show` whose text is `text`, as math.
pub fn side_tex(question: &Question, text: &str) -> String {
    let QuestionKind::Show {
        lhs,
        rhs,
        text: all,
        ..
    } = &question.kind
    else {
        return String::new();
    };
    let left = all.split_once('=').map_or("", |(l, _)| l.trim());
    let (side, name) = match text == left {
        true => (lhs, "\\mathrm{LHS}"),
        false => (rhs, "\\mathrm{RHS}"),
    };
    // A long side is named; the question states it.
    match latex(side) {
        written if written.len() <= 40 => written,
        _ => name.into(),
    }
}

/// A sentence after the values of a `show`: whether the two sides agree.
pub fn note(_problem: &Problem, question: &Question, answer: &Answer) -> Option<String> {
    if !matches!(question.kind, QuestionKind::Show { .. }) {
        return None;
    }
    let [(_, lhs), (_, rhs)] = answer.values[..] else {
        return None;
    };
    Some(match holds(lhs, rhs) {
        true => "The two sides are equal: the identity holds at this state.".into(),
        false => "The two sides differ: the identity does not hold at this state.".into(),
    })
}
