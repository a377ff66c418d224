//! A `stability` question answered: the values of a constant where the question's state
//! (a bicycle's straight run at speed v) changes stability, from the linearization at
//! evenly spaced values and bisection on the largest real part of its eigenvalues between
//! two that differ ([`super::sweep`]). Each value found is named by what happens beyond
//! it as the constant grows, and by whether the eigenvalue that crosses zero there is one
//! of an oscillation (a complex pair, the weave of a bicycle) or not (a real one, its
//! capsize).

use super::{sweep, Linearizer, Sweep};
use crate::error::Error;
use crate::numeric::{edge_name as name, Answer, Edge, Quantity};
use crate::problem::{Problem, ProblemError, ProblemErrors, Question, QuestionKind};

/// The question's state for the problem with the constant set: the initial one, with the
/// question's `at.state` entries.
fn state_of(question: &Question, p: &Problem) -> (Vec<f64>, Vec<f64>) {
    let initial = p.initial_state();
    let (mut q, mut rates) = (initial.q, initial.rates);
    for (entry, value) in question.at.state.iter().flatten() {
        let target = if entry.order == 0 { &mut q } else { &mut rates };
        target[entry.coordinate] = *value;
    }
    (q, rates)
}

fn failure(question: &Question, message: String) -> Error {
    Error::Problem(ProblemErrors(vec![ProblemError {
        path: format!("{}.stability", question.path),
        column: None,
        message,
        hint: Some("widen the range, or check that the constant changes the motion".into()),
    }]))
}

/// Answers a `stability` question of `problem` (in its rates) with `linearizer`.
///
/// # Errors
/// A value the problem rejects, a singular system, or no change of stability in the range.
pub fn answer(
    problem: &Problem,
    linearizer: &Linearizer,
    question: &Question,
) -> Result<Answer, Error> {
    let QuestionKind::Stability {
        constant,
        from,
        to,
        count,
    } = question.kind
    else {
        return Err(failure(question, "not a stability question".into()));
    };
    let constant_name = problem.constants[constant].name.clone();
    let values: Vec<f64> = (0..count)
        .map(|i| from + (to - from) * i as f64 / (count - 1) as f64)
        .collect();
    let asked = Sweep {
        name: constant_name.clone(),
        values,
    };
    let t = question.at.time.unwrap_or(0.0);
    let of = |p: &Problem| -> Result<(Vec<f64>, Vec<f64>), Error> { Ok(state_of(question, p)) };
    let found = sweep(problem, linearizer, &asked, t, &of)?;
    if found.edges.is_empty() {
        return Err(failure(
            question,
            format!("the stability does not change for {constant_name} from {from} to {to}"),
        ));
    }
    let mut values = Vec::new();
    for &(value, stable_above) in &found.edges {
        // On the unstable side, just beyond: the eigenvalue with the largest real part.
        let step = 1e-3 * value.abs().max(1e-3);
        let beside = if stable_above {
            value - step
        } else {
            value + step
        };
        let mut p = problem.clone();
        crate::problem::apply_overrides(&mut p, &[(constant_name.clone(), beside)])?;
        let (q, rates) = state_of(question, &p);
        let l = linearizer.at(&p, t, &q, &rates)?;
        let oscillates = (l.eigen.iter())
            .max_by(|a, b| a.value.re.total_cmp(&b.value.re))
            .is_some_and(|e| e.value.im.abs() > 1e-6 * e.value.norm().max(1e-12));
        let edge = Edge {
            value,
            stable_above,
            oscillates,
        };
        values.push((Quantity::Named(name(&edge)), value));
    }
    Ok(Answer::at_state(values, t, state_of(question, problem)))
}
