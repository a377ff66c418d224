//! A `describe` question answered: the run simulated and described (see
//! [`super::describe`]), its numbers as named values of the answer.
//!
//! The values are `minimum`, `maximum`, `mean`, `amplitude` (the coordinate's unit),
//! `period` (s; only where two maxima are reached) and `duration` (s), then for each rate
//! asked `psi'.minimum` and `psi'.maximum`.

use super::describe::{describe, Description};
use super::quantity::Quantity;
use super::system::System;
use crate::problem::{Problem, Question, QuestionKind, SimulateSettings};

/// The named values of a `describe` question, simulated from `(q, rates)`; an error
/// message and hint where the run fails.
pub fn values(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    state: (&[f64], &[f64]),
) -> Result<Vec<(Quantity, f64)>, (String, &'static str)> {
    let QuestionKind::Describe { coordinate, rates } = &question.kind else {
        return Ok(Vec::new());
    };
    let settings = SimulateSettings {
        duration: question.at.time.unwrap_or(problem.simulate.duration),
        ..problem.simulate.clone()
    };
    let found = describe(system, state, &settings, (*coordinate, rates)).map_err(|e| {
        (
            format!("cannot describe the motion: {e}"),
            "ask over a shorter time (`at.time`), or check the initial state",
        )
    })?;
    let named = |name: &str, x: f64| (Quantity::Named(name.into()), x);
    let mut out = vec![
        named("minimum", found.minimum),
        named("maximum", found.maximum),
        named("mean", found.mean),
        named("amplitude", found.amplitude),
    ];
    if let Some(period) = found.period {
        out.push(named("period", period));
    }
    out.push(named("duration", found.duration));
    for (&j, (lo, hi)) in rates.iter().zip(&found.rates) {
        let rate = format!("{}'", problem.coordinates[j].name);
        out.push(named(&format!("{rate}.minimum"), *lo));
        out.push(named(&format!("{rate}.maximum"), *hi));
    }
    Ok(out)
}

/// The description read back from an answer's named values.
pub fn described(values: &[(Quantity, f64)]) -> Description {
    let get = |name: &str| {
        (values.iter())
            .find(|(q, _)| matches!(q, Quantity::Named(n) if n == name))
            .map(|(_, x)| *x)
    };
    let mut rates = Vec::new();
    for (q, lo) in values {
        if let Quantity::Named(n) = q {
            if let Some(rate) = n.strip_suffix(".minimum") {
                rates.push((*lo, get(&format!("{rate}.maximum")).unwrap_or(*lo)));
            }
        }
    }
    Description {
        minimum: get("minimum").unwrap_or_default(),
        maximum: get("maximum").unwrap_or_default(),
        mean: get("mean").unwrap_or_default(),
        amplitude: get("amplitude").unwrap_or_default(),
        period: get("period"),
        maxima: Vec::new(),
        rates,
        duration: get("duration").unwrap_or_default(),
    }
}

/// The unit of a value of a `describe` question of `coordinate`.
pub fn unit(problem: &Problem, coordinate: usize, name: &str) -> String {
    let rate = name.split_once("'.").map(|(c, _)| c);
    match (name, rate) {
        ("period" | "duration", _) => "s".into(),
        (_, Some(c)) => (problem.coordinates.iter())
            .position(|x| x.name == c)
            .map(|i| super::coordinate_unit(problem, i, 1))
            .unwrap_or_default(),
        _ => super::coordinate_unit(problem, coordinate, 0),
    }
}
