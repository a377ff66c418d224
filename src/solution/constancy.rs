//! "Check that the total mechanical energy stays constant", answered yes or no: where an
//! item of the statement asks the same quantity at the start and after a simulated time,
//! the second answer says whether it stayed constant, to how many parts, over the whole
//! motion where the simulation's energy check measured it, and points to the plot.

use crate::numeric::Answer;
use crate::numeric::CheckKind;
use crate::problem::{Problem, QuestionKind};
use crate::render::AnswerView;
use crate::symbolic::fixed;
use crate::Worked;

/// `6 parts in 10¹⁰`: a small relative size to one significant digit.
pub fn parts_tex(relative: f64) -> String {
    if relative <= 0.0 || !relative.is_finite() {
        return "round-off".into();
    }
    let mut exponent = (-relative.log10()).ceil() as i32;
    let mut parts = (relative * 10f64.powi(exponent)).round() as i64;
    if parts >= 10 {
        parts /= 10;
        exponent -= 1;
    }
    let noun = if parts == 1 { "part" } else { "parts" };
    let digits: String = (exponent.to_string().chars())
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect();
    format!("{parts} {noun} in 10{digits}")
}

/// The index of the question asking the same value as question `i` in the same item at
/// the start, where `i` asks it after a simulated time.
fn pair(problem: &Problem, labels: &[String], i: usize) -> Option<usize> {
    let item = |k: usize| labels[..=k].iter().rev().find(|l| !l.is_empty()).cloned();
    let q = &problem.questions[i];
    let QuestionKind::Value { text, .. } = &q.kind else {
        return None;
    };
    let later = q.at.state.is_none() && q.at.time.is_some_and(|t| t > 0.0);
    if !later {
        return None;
    }
    (0..problem.questions.len()).find(|&k| {
        let other = &problem.questions[k];
        let same = matches!(&other.kind, QuestionKind::Value { text: t, .. } if t == text);
        let start = other.at.state.is_none()
            && other.at.time.is_none_or(|t| t == 0.0)
            && other.at.switch.is_none()
            && !other.at.after_impact;
        k != i && same && start && item(k) == item(i)
    })
}

/// Adds the yes or no to the later answer of each such pair.
pub fn attach(worked: &Worked, answers: &[Answer], views: &mut [AnswerView]) {
    let problem = worked.derivation.model.problem;
    let labels = super::answer_numbers::labels(problem);
    let measured = match &worked.simulation {
        Some(Ok((_, checks))) => (checks.iter())
            .find(|c| c.kind == CheckKind::EnergyConservation)
            .map(|c| c.value),
        _ => None,
    };
    for i in 0..problem.questions.len() {
        let Some(k) = pair(problem, &labels, i) else {
            continue;
        };
        let (Some(late), Some(start)) = (answers[i].values.first(), answers[k].values.first())
        else {
            continue;
        };
        let (late, start) = (late.1, start.1);
        // The datum of V, beside the energy at the start.
        if let Some(datum) = super::energy_datum::sentence(worked, start) {
            views[k].steps.push(crate::render::AnswerStep {
                text: datum.into(),
                math: String::new().into(),
            });
        }
        let relative = (late - start).abs() / start.abs().max(1e-12);
        let time = fixed(problem.questions[i].at.time.unwrap_or(0.0));
        let constant = relative <= 1e-6;
        let mut note = match constant {
            true => format!(
                "Yes, it stays constant: at the start and after {time} s it is the same to {}",
                parts_tex(relative)
            ),
            false => format!(
                "No: after {time} s it differs from its value at the start by {}",
                parts_tex(relative)
            ),
        };
        if let Some(m) = measured.filter(|_| constant) {
            note.push_str(&format!(
                ", and over the whole motion the total energy changes by at most {} of its scale (the plot of the energy in step 6)",
                parts_tex(m)
            ));
        }
        note.push('.');
        let j = i.max(k);
        views[j].note = note;
    }
}
