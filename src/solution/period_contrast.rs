//! Why a period measured in a simulation differs from one found by linearizing about a
//! state: the simulation starts elsewhere. Where a `describe` answer measures the period of
//! a coordinate's oscillation from the initial state, and a later `period` answer
//! linearizes about another state for the same coordinate, the period answer ends with the
//! two states side by side, in the statement's names where it gives them (ω₃, Ω), else in
//! the rates and coordinates, each value computed from the two states.

use crate::numeric::{coordinate_unit, described, Answer};
use crate::problem::{Problem, QuestionKind};
use crate::render::{AnswerStep, AnswerView};
use crate::symbolic::{eval, latex, latex_name, Expr, Values};
use crate::Worked;

/// A quantity compared at the two states: its LaTeX name, its expression, its unit (LaTeX).
type Compared = (String, Expr, String);

/// Adds the sentence to every `period` answer that follows a `describe` of its coordinate
/// whose simulation starts at another state.
pub fn attach(worked: &Worked, answers: &[Answer], views: &mut [AnswerView]) {
    let problem = worked.derivation.model.problem;
    for (i, question) in problem.questions.iter().enumerate() {
        let QuestionKind::Period {
            coordinate: Some(k),
        } = question.kind
        else {
            continue;
        };
        let measured = (problem.questions[..i].iter().zip(answers))
            .filter(|(q, _)| matches!(q.kind, QuestionKind::Describe { coordinate, .. } if coordinate == k))
            .find_map(|(_, a)| described(&a.values).period);
        let (Some(measured), Some(answer), Some(view)) =
            (measured, answers.get(i), views.get_mut(i))
        else {
            continue;
        };
        if let Some(text) = sentence(worked, answer, measured) {
            // The sentence says what the general remark would: it takes its place.
            view.steps
                .retain(|s| !s.text.as_str().starts_with("Oscillations that stay small"));
            view.steps.push(AnswerStep {
                text: text.into(),
                math: String::new().into(),
            });
        }
    }
}

/// "The motion simulated above starts at Ω = 3 rad/s, ω₃ = 152.633 rad/s, not at this
/// state's Ω = 3.45313 rad/s, ω₃ = 150 rad/s: …"; `None` where the two states agree.
fn sentence(worked: &Worked, answer: &Answer, measured: f64) -> Option<String> {
    let model = &worked.derivation.model;
    let problem = model.problem;
    let start = model.values_at(0.0, &worked.q0, &worked.rates0);
    let here = model.values_at(answer.time, &answer.q, &answer.rates);
    let differs = |(_, e, _): &Compared| {
        let (a, b) = (eval(e, &start), eval(e, &here));
        (a - b).abs() > 1e-9 * a.abs().max(b.abs()).max(1e-9)
    };
    let named: Vec<Compared> = statement_names(problem)
        .into_iter()
        .filter(differs)
        .collect();
    let compared = match named.is_empty() {
        false => named,
        true => state_quantities(problem)
            .into_iter()
            .filter(differs)
            .collect(),
    };
    if compared.is_empty() {
        return None;
    }
    let list = |values: &Values| {
        (compared.iter())
            .map(|(name, e, unit)| format!("${name} = {}{unit}$", number(eval(e, values))))
            .collect::<Vec<_>>()
            .join(", ")
    };
    Some(format!(
        "The motion simulated above starts at {}, not at this state's {}: it oscillates about \
         another motion, so the period measured there, $\\tau = {}\\ \\mathrm{{s}}$, differs \
         from this one.",
        list(&start),
        list(&here),
        number(measured)
    ))
}

fn number(x: f64) -> String {
    super::answer_numbers::number_tex(x)
}

/// The quantities a `show` of the statement names (`Ω = ψ̇`, `ω₃ = φ̇ + ψ̇ cos θ`) that hold
/// a rate, each with the unit of its first rate.
fn statement_names(problem: &Problem) -> Vec<Compared> {
    let mut out = Vec::new();
    for question in &problem.questions {
        let QuestionKind::Show { names, .. } = &question.kind else {
            continue;
        };
        for (name, e) in names {
            let rate = (0..problem.coordinates.len())
                .find(|&c| e.contains(&problem.coordinate_symbol(c, 1)));
            if let Some(c) = rate {
                out.push((latex_name(name), e.clone(), unit(problem, c, 1)));
            }
        }
    }
    out
}

/// Every coordinate and rate, as step 1 names them.
fn state_quantities(problem: &Problem) -> Vec<Compared> {
    (0..problem.coordinates.len())
        .flat_map(|c| {
            [0, 1].map(|order| {
                let e = Expr::sym(problem.coordinate_symbol(c, order));
                (latex(&e), e, unit(problem, c, order))
            })
        })
        .collect()
}

fn unit(problem: &Problem, c: usize, order: u8) -> String {
    super::answer_numbers::unit_tex(&coordinate_unit(problem, c, order))
}
