//! A mass or g that no answer depends on, said once under the Answers: a gear's masses
//! and g where the axles are fixed, the pinion's mass beside a rack. Said only where every
//! answer comes from step 5's rows at the initial state and no row holds the constant, so
//! the sentence is true by the rows themselves.

use crate::equations::Derivation;
use crate::problem::{QuestionAt, QuestionKind};
use crate::render::{AnswerStep, AnswerView};
use crate::symbolic::{latex, Expr, Symbol};

/// The masses' and gravity's constants, in the problem's order.
fn candidates(derivation: &Derivation) -> Vec<String> {
    let problem = derivation.model.problem;
    let mut names: Vec<String> = Vec::new();
    let mut take = |e: &Expr| {
        e.for_each_symbol(&mut |s| {
            if let Symbol::Const(name) = s {
                if !names.iter().any(|n| n.as_str() == &**name) {
                    names.push(name.to_string());
                }
            }
        });
    };
    for body in &problem.bodies {
        take(&body.mass);
    }
    for (_, _, g) in problem.gravity.iter().flat_map(|g| &g.terms) {
        take(g);
    }
    names
}

/// Whether every question is answered from step 5's rows at the initial state: a second
/// rate or a reaction, asked at the start.
fn from_the_rows(derivation: &Derivation) -> bool {
    let problem = derivation.model.problem;
    !problem.questions.is_empty()
        && problem.questions.iter().all(|q| {
            let start = q.at == QuestionAt::default() && q.about.is_none();
            let kind = match &q.kind {
                QuestionKind::Reaction { .. } => true,
                QuestionKind::Value { expression, .. } => {
                    matches!(expression.as_symbol(), Some(Symbol::Coord(_, 2)))
                }
                _ => false,
            };
            start && kind
        })
}

/// The sentence, where some mass or g is in no row of step 5; `None` otherwise.
pub fn sentence(derivation: &Derivation) -> Option<String> {
    if !from_the_rows(derivation) {
        return None;
    }
    let system = &derivation.system;
    let in_rows = |name: &str| {
        let symbol = Symbol::Const(name.into());
        (system.a.iter().flatten().chain(&system.b)).any(|e| e.contains(&symbol))
    };
    let absent: Vec<String> = (candidates(derivation).into_iter())
        .filter(|n| !in_rows(n))
        .map(|n| format!("${}$", latex(&Expr::constant(&n))))
        .collect();
    let listed = match &absent[..] {
        [] => return None,
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    };
    let (verb, none) = match absent.len() {
        1 => ("enters", "it"),
        _ => ("enter", "any of them"),
    };
    Some(format!(
        "{listed} {verb} no answer: no row of step 5 holds {none}."
    ))
}

/// Puts the sentence under the last answer.
pub fn attach(derivation: &Derivation, views: &mut [AnswerView]) {
    let (Some(text), Some(last)) = (sentence(derivation), views.last_mut()) else {
        return;
    };
    last.steps.push(AnswerStep {
        text: text.into(),
        math: String::new().into(),
    });
}
