//! The check that a steady motion found is steady, shown rather than asserted: the rows of
//! step 5 that hold no reaction, with the rates the motion holds at zero put in, have
//! right sides that vanish, or that are zero by the identity a `show` derived; so they give
//! every second derivative zero.

use crate::equations::Derivation;
use crate::problem::{Problem, QuestionKind};
use crate::symbolic::{latex, simplify, substitute, Expr, Symbol};

/// `(1) and (3)`.
fn rows_list(rows: &[usize]) -> String {
    let names: Vec<String> = rows.iter().map(|i| format!("({})", i + 1)).collect();
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => names.concat(),
    }
}

/// The check of question `index`, a steady motion, from step 5's rows; `None` where its
/// rows are not written (Kane's by composite bodies) or no rate is held at zero.
pub fn sentence(derivation: &Derivation, problem: &Problem, index: usize) -> Option<String> {
    let question = problem.questions.get(index)?;
    let QuestionKind::Steady { zero, unknowns } = &question.kind else {
        return None;
    };
    // The rates the motion holds at zero: given so at its state, or asked to vanish.
    let given = (question.at.state.iter().flatten())
        .filter(|(e, x)| e.order == 1 && *x == 0.0 && !unknowns.contains(e))
        .map(|(e, _)| problem.coordinate_symbol(e.coordinate, 1));
    let asked = (zero.iter())
        .filter_map(|(e, _)| e.as_symbol().cloned())
        .filter(|s| matches!(s, Symbol::Coord(_, 1)));
    let held: Vec<Symbol> = given.chain(asked).collect();
    let second: Vec<String> = (zero.iter())
        .filter(|(e, _)| matches!(e.as_symbol(), Some(Symbol::Coord(_, 2))))
        .map(|(e, _)| latex(e))
        .collect();
    let system = &derivation.system;
    if held.is_empty() || second.is_empty() || system.a.len() != derivation.rows.len() {
        return None;
    }
    let reaction = |j: usize| matches!(system.unknowns[j], Symbol::Unknown(_));
    let free: Vec<usize> = (0..system.a.len())
        .filter(|&i| (0..system.unknowns.len()).all(|j| !reaction(j) || system.a[i][j].is_zero()))
        .collect();
    if free.len() != second.len() {
        return None;
    }
    let put_in = |e: &Expr| {
        simplify(&substitute(e, &|s: &Symbol| {
            held.contains(s).then(Expr::zero)
        }))
    };
    let (vanish, by_identity): (Vec<usize>, Vec<usize>) = free
        .iter()
        .copied()
        .partition(|&i| put_in(&system.b[i]).is_zero());
    let held_tex: Vec<String> = (held.iter())
        .map(|s| format!("{} = 0", latex(&Expr::sym(s.clone()))))
        .collect();
    let mut parts = Vec::new();
    if !vanish.is_empty() {
        // The rows are written `… = 0`: what vanishes is their terms without a second
        // derivative, not a right side.
        parts.push(format!(
            "the terms of {} {} without a second derivative vanish",
            if vanish.len() == 1 { "row" } else { "rows" },
            rows_list(&vanish),
        ));
    }
    if !by_identity.is_empty() {
        let shown = (problem
            .questions
            .iter()
            .position(|q| matches!(q.kind, QuestionKind::Show { .. }) && q.about == Some(index)))
        .and_then(|k| {
            let labels = super::answer_numbers::labels(problem);
            labels[..=k].iter().rev().find(|l| !l.is_empty()).cloned()
        });
        let why = match shown {
            Some(item) => format!("by the relation of answer {item}"),
            None => "at these rates".to_string(),
        };
        parts.push(format!(
            "those of {} {} add up to zero {why}",
            if by_identity.len() == 1 {
                "row"
            } else {
                "rows"
            },
            rows_list(&by_identity)
        ));
    }
    Some(format!(
        "Check: with ${}$ put in, {}. Rows {}, which hold no reaction, then give ${} = 0$: yes, the motion is steady.",
        held_tex.join(",\\ "),
        parts.join(", and "),
        rows_list(&free),
        second.join(" = ")
    ))
}
