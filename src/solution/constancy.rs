//! "Check that the total mechanical energy stays constant", answered yes or no: where an
//! item of the statement asks the same quantity at the start and after a simulated time,
//! the second answer says whether it stayed constant and points to the plot; its value is
//! on the answer's lines already.

use crate::numeric::Answer;
use crate::numeric::CheckKind;
use crate::problem::{Problem, QuestionKind};
use crate::render::AnswerView;
use crate::symbolic::fixed;
use crate::Worked;

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

/// The largest change of the total energy from its start over the simulated motion, in
/// joules, where `start` (in `unit`) is that energy; `None` for another quantity or
/// without a simulation.
fn largest_change(worked: &Worked, start: f64, unit: &str) -> Option<f64> {
    let Some(Ok((trajectory, _))) = &worked.simulation else {
        return None;
    };
    let total = trajectory.series("total")?;
    let first = total.first()?.1;
    let energy = first + trajectory.potential_at_start;
    if unit != "J" || (energy - start).abs() > 1e-6 * start.abs().max(1.0) {
        return None;
    }
    Some(total.iter().fold(0.0f64, |m, p| m.max((p.1 - first).abs())))
}

/// Adds the yes or no to the later answer of each such pair (its value is on the lines).
pub fn attach(worked: &Worked, answers: &[Answer], views: &mut [AnswerView]) {
    let problem = worked.derivation.model.problem;
    let labels = super::answer_numbers::labels(problem);
    let energy_checked = match &worked.simulation {
        Some(Ok((_, checks))) => (checks.iter()).any(|c| c.kind == CheckKind::EnergyConservation),
        _ => false,
    };
    for i in 0..problem.questions.len() {
        let Some(k) = pair(problem, &labels, i) else {
            continue;
        };
        let (Some(late), Some(start)) = (answers[i].values.first(), answers[k].values.first())
        else {
            continue;
        };
        let unit = crate::numeric::answer_unit(problem, &problem.questions[k], &start.0);
        // Said in text, where `^2` would print as it is typed.
        let unit = unit.replace("^2", "²").replace("^3", "³");
        let (late, start) = (late.1, start.1);
        let measured = largest_change(worked, start, &unit).filter(|_| energy_checked);
        // The datum of V, beside the energy at the start.
        for (text, math) in super::energy_datum::steps(worked, start) {
            views[k].steps.push(crate::render::AnswerStep {
                text: text.into(),
                math: math.into(),
            });
        }
        let change = (late - start).abs();
        let relative = change / start.abs().max(1e-12);
        let time = fixed(problem.questions[i].at.time.unwrap_or(0.0));
        let symbol_tex = (views[k].values_tex.first()).and_then(|v| {
            v.as_str()
                .split_once(" = ")
                .map(|(name, _)| name.to_string())
        });
        let symbol = (symbol_tex.as_deref())
            .map(crate::render::unicode_of)
            .unwrap_or_else(|| "it".to_string());
        let spaced = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        // The change left is the simulation's rounding, not the mechanics: a course says
        // the energy stays constant, and the plot shows it.
        let note = match (relative <= 1e-6, measured) {
            (true, Some(m)) if m <= 1e-6 * start.abs().max(1.0) => {
                // Said with its evidence, which a plot cannot show: the largest change.
                views[i.max(k)].steps.push(crate::render::AnswerStep {
                    text: largest_change_words(symbol_tex.as_deref(), m).into(),
                    math: String::new().into(),
                });
                String::new()
            }
            (true, _) => format!("Yes: {symbol} is unchanged after {time} s."),
            (false, _) => format!(
                "No: after {time} s {symbol} has changed by {}{spaced} from its value at the start.",
                fixed(late - start).replace('-', "−")
            ),
        };
        let j = i.max(k);
        views[j].note = note;
    }
}

/// "Yes: E stays constant, to within the accuracy of the simulation." in the markup of an
/// answer's step: what it changes by is the integration's error, not the mechanics, and
/// is not printed.
fn largest_change_words(symbol: Option<&str>, change: f64) -> String {
    let symbol = symbol.map_or("it".to_string(), |s| format!("${s}$"));
    if change <= 0.0 {
        return format!("Yes: {symbol} stays constant; in the simulation it does not change.");
    }
    format!("Yes: {symbol} stays constant, to within the accuracy of the simulation.")
}
