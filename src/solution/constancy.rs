//! "Check that the total mechanical energy stays constant", answered yes or no: where an
//! item of the statement asks the same quantity at the start and after a simulated time,
//! the second answer says whether it stayed constant, and by how much
//! at most it changes over the whole motion, in its own unit, and points to the plot.

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

/// `10⁻⁹`: the smallest power of ten above `x`, as text.
fn power_above(x: f64) -> String {
    let exponent = x.log10().floor() as i32 + 1;
    let digits: String = (exponent.to_string().chars())
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect();
    format!("10{digits}")
}

/// `less than 10⁻⁹ J`: an absolute bound on a change, in the quantity's unit.
fn bound(change: f64, unit: &str) -> String {
    let unit = match unit {
        "" => String::new(),
        u => format!(" {u}"),
    };
    match change > 0.0 && change.is_finite() {
        true => format!("less than {}{unit}", power_above(change)),
        false => "nothing in the digits computed".to_string(),
    }
}

/// Adds the yes or no to the later answer of each such pair: by how much at most it
/// changes, in its own unit (its value is on the answers' lines).
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
        if let Some(datum) = super::energy_datum::sentence(worked, start) {
            views[k].steps.push(crate::render::AnswerStep {
                text: datum.into(),
                math: String::new().into(),
            });
        }
        let change = (late - start).abs();
        let relative = change / start.abs().max(1e-12);
        let time = fixed(problem.questions[i].at.time.unwrap_or(0.0));
        let symbol = (views[k].values_tex.first())
            .and_then(|v| {
                v.as_str()
                    .split_once(" = ")
                    .map(|(name, _)| name.to_string())
            })
            .map(|name| crate::render::unicode_of(&name))
            .unwrap_or_else(|| "it".to_string());
        let spaced = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        let note = match (relative <= 1e-6, measured) {
            // Its value is on the lines above: the yes says only by how little it moves.
            (true, Some(m)) => format!(
                "Yes: over the whole motion {symbol} changes by {} (the energy plot of step 6).",
                bound(m.max(change), &unit)
            ),
            (true, None) => format!(
                "Yes: after {time} s {symbol} has changed by {}.",
                bound(change, &unit)
            ),
            (false, _) => format!(
                "No: after {time} s {symbol} has changed by {}{spaced} from its value at the start.",
                fixed(late - start).replace('-', "−")
            ),
        };
        let j = i.max(k);
        views[j].note = note;
    }
}
