//! The conditions a `show` puts into the equations of step 5, and where its identity is
//! checked with numbers.
//!
//! A `show` with `assuming` states the motion it is asked of (steady precession: θ̇ = 0,
//! θ̈ = 0, ψ̈ = φ̈ = 0) and is derived from those conditions in symbols alone; the state of
//! the question (`about` a steady motion) only checks it, last, and is named there. A
//! `show` without them takes as conditions the second rates that vanish at its state and
//! the rates that are zero there.

use crate::numeric::{coordinate_unit, Answer};
use crate::problem::{Problem, Question, QuestionKind};
use crate::symbolic::{eval, latex, simplify, substitute, Expr, Symbol, Values};

/// A condition: a coordinate, rate or second rate and the value put in for it.
pub type Condition = (Symbol, Expr);

/// The conditions a question states (`assuming`), as symbols and values.
pub fn assumed(question: &Question) -> Vec<Condition> {
    let QuestionKind::Show { assuming, .. } = &question.kind else {
        return Vec::new();
    };
    (assuming.iter())
        .filter_map(|(s, v)| Some((s.as_symbol()?.clone(), v.clone())))
        .collect()
}

/// `e` with the conditions put in.
pub fn put_in(e: &Expr, conditions: &[Condition]) -> Expr {
    simplify(&substitute(e, &|s| {
        (conditions.iter())
            .find(|(c, _)| c == s)
            .map(|(_, v)| v.clone())
    }))
}

/// `\dot{\theta} = 0,\ \ddot{\theta} = 0`: the conditions as math.
pub fn conditions_tex(conditions: &[Condition]) -> String {
    (conditions.iter())
        .map(|(s, v)| format!("{} = {}", latex(&Expr::sym(s.clone())), latex(v)))
        .collect::<Vec<_>>()
        .join(",\\ ")
}

/// The sentence before the equation with the conditions put in: the conditions, and
/// those of them the equation does not hold (said, so that none is assumed silently).
pub fn put_in_sentence(row: &Expr, conditions: &[Condition], assumed: bool) -> String {
    let all = conditions_tex(conditions);
    if !assumed {
        return format!("At this state ${all}$; put in, the equation becomes");
    }
    let absent: Vec<Condition> = (conditions.iter())
        .filter(|(s, _)| !row.contains(s))
        .cloned()
        .collect();
    let names: Vec<String> = (absent.iter())
        .map(|(s, _)| format!("${}$", latex(&Expr::sym(s.clone()))))
        .collect();
    let absent_words = match names.len() {
        0 => String::new(),
        1 => format!(" ({} does not appear in it)", names[0]),
        _ => format!(" ({} do not appear in it)", join_words(&names)),
    };
    format!("With the conditions ${all}$ put in{absent_words}, the equation becomes")
}

fn join_words(parts: &[String]) -> String {
    match parts {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// The values that the proportionality test holds: each condition's value at `v`.
pub fn held_values(conditions: &[Condition], v: &Values) -> Vec<(Symbol, f64)> {
    (conditions.iter())
        .map(|(s, e)| (s.clone(), eval(e, v)))
        .collect()
}

/// Where a derived `show` is checked with numbers: "at the steady motion found in answer 2
/// below, where θ = 0.5 rad, ψ̇ = 3.45 rad/s, φ̇ = 147 rad/s", the coordinates and rates
/// of its identity and names at the answer's state.
pub fn check_sentence(problem: &Problem, index: usize, answer: &Answer) -> String {
    let question = &problem.questions[index];
    let QuestionKind::Show {
        lhs, rhs, names, ..
    } = &question.kind
    else {
        return String::new();
    };
    let mut used: Vec<(usize, u8)> = Vec::new();
    let mut collect = |e: &Expr| {
        e.for_each_symbol(&mut |s| {
            if let Symbol::Coord(name, order @ 0..=1) = s {
                let i = problem.coordinates.iter().position(|c| c.name == **name);
                if let Some(i) = i.filter(|i| !used.contains(&(*i, *order))) {
                    used.push((i, *order));
                }
            }
        })
    };
    collect(lhs);
    collect(rhs);
    names.iter().for_each(|(_, e)| collect(e));
    used.sort();
    let parts: Vec<String> = (used.iter())
        .map(|&(i, order)| {
            let x = if order == 0 {
                answer.q[i]
            } else {
                answer.rates[i]
            };
            format!(
                "${} = {}{}$",
                latex(&problem.coordinate_expr(i, order)),
                super::answer_numbers::number_tex(x),
                super::answer_numbers::unit_tex(&coordinate_unit(problem, i, order))
            )
        })
        .collect();
    let place = match question.about {
        Some(k) => format!(
            "at {}{}",
            super::question_answers::about_note(problem, k),
            if k > index { " below" } else { "" }
        ),
        None => "at the state of the question".into(),
    };
    match parts.is_empty() {
        true => format!("Checked with numbers {place}:"),
        false => format!(
            "Checked with numbers {place}, where {}:",
            join_words(&parts)
        ),
    }
}
