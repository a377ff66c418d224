//! The conditions a `show` puts into the equations of step 5.
//!
//! A `show` with `assuming` states the motion it is asked of (steady precession: θ̇ = 0,
//! θ̈ = 0, ψ̈ = φ̈ = 0) and is derived from those conditions in symbols alone; the state of
//! the question (`about` a steady motion) only checks it, last, and is named there. A
//! `show` without them takes as conditions the second rates that vanish at its state and
//! the rates that are zero there.

use crate::problem::{Question, QuestionKind};
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
