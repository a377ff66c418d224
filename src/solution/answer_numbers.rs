//! How the Answers write a number and a question's label, shared by every kind of answer:
//! a number as JSON and as LaTeX, a unit after it, the question's item number.

use crate::problem::Problem;
use crate::symbolic::fixed;
use serde_json::Value;

/// `x` as JSON: a number, or `null` when not finite (never, for an answer).
pub(super) fn number(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

/// Each question's number in the Answers: the statement's item it answers, written on the
/// first question of each item and left empty on the others of the same item. Without any
/// `item`, the questions are numbered in order.
pub fn labels(problem: &Problem) -> Vec<String> {
    let numbered = problem.questions.iter().any(|q| q.item.is_some());
    let mut previous = None;
    let mut out = Vec::new();
    for (i, q) in problem.questions.iter().enumerate() {
        let item = match numbered {
            true => q.item.or(previous).unwrap_or(1),
            false => i as u32 + 1,
        };
        out.push(match previous == Some(item) {
            true => String::new(),
            false => item.to_string(),
        });
        previous = Some(item);
    }
    out
}

pub(super) fn number_tex(x: f64) -> String {
    let text = fixed(x);
    match text.split_once('e') {
        Some((mantissa, exponent)) => format!(
            "{mantissa} \\times 10^{{{}}}",
            exponent.trim_start_matches('+')
        ),
        None => text,
    }
}

/// A unit as written (`rad/s^2`, `N m`) in upright LaTeX, after a thin space.
pub(super) fn unit_tex(unit: &str) -> String {
    match crate::render::unit_tex(unit) {
        tex if tex.is_empty() => tex,
        tex => format!("\\ {tex}"),
    }
}
