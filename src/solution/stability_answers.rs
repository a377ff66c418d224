//! The answer of a `stability` question: the values of the constant where the state
//! changes stability, in the handout's Answers (each value, what happens beyond it, and
//! how the motion grows on the unstable side) and in `answer --format json`.

use crate::numeric::{edges, Answer, Edge};
use crate::problem::{Problem, Question, QuestionKind};
use crate::render::text::Math;
use serde_json::{Map, Value};

fn constant_of(question: &Question) -> Option<usize> {
    match question.kind {
        QuestionKind::Stability { constant, .. } => Some(constant),
        _ => None,
    }
}

/// The constant as math, and its unit as math after a thin space (or nothing).
fn constant_tex(problem: &Problem, constant: usize) -> (String, String) {
    let c = &problem.constants[constant];
    let symbol = crate::symbolic::latex(&crate::symbolic::Expr::constant(&c.name));
    let unit = crate::render::unit_tex(c.unit.as_deref().unwrap_or(""));
    let unit = if unit.is_empty() {
        unit
    } else {
        format!("\\ {unit}")
    };
    (symbol, unit)
}

/// How the motion grows where it is unstable next to `edge`.
fn growth(edge: &Edge) -> &'static str {
    match edge.oscillates {
        true => "an oscillation grows",
        false => "a motion grows without oscillating",
    }
}

/// One line per value found: `v = 4.29238 m/s: stable above, an oscillation grows below`.
pub fn values_tex(problem: &Problem, question: &Question, answer: &Answer) -> Vec<Math> {
    let Some(constant) = constant_of(question) else {
        return Vec::new();
    };
    let (symbol, unit) = constant_tex(problem, constant);
    edges(answer)
        .iter()
        .map(|edge| {
            let (stable, unstable) = match edge.stable_above {
                true => ("above", "below"),
                false => ("below", "above"),
            };
            Math::from(format!(
                "{symbol} = {}{unit} \\quad \\text{{(stable {stable} it; {unstable} it, {})}}",
                super::answer_numbers::number_tex(edge.value),
                growth(edge)
            ))
        })
        .collect()
}

/// The sentence under the values: the range where the state is stable, how it was found.
pub fn note(problem: &Problem, question: &Question, answer: &Answer) -> String {
    let Some(constant) = constant_of(question) else {
        return String::new();
    };
    let name = &problem.constants[constant].name;
    let unit = problem.constants[constant].unit.clone().unwrap_or_default();
    let found = edges(answer);
    let number = |x: f64| crate::symbolic::fixed(x);
    let range = match &found[..] {
        [low, high] if low.stable_above && !high.stable_above => format!(
            "The state is stable for {name} between {} and {} {unit}. ",
            number(low.value),
            number(high.value)
        ),
        _ => String::new(),
    };
    format!(
        "{range}Found from the eigenvalues of the linearization as functions of {name}: where the largest real part crosses zero."
    )
}

/// `answer --format json`'s fields: `"edges": [ { "value": 4.29, "stable_above": true,
/// "oscillates": true } ]` and the unit.
pub fn record(
    problem: &Problem,
    question: &Question,
    answer: &Answer,
    out: &mut Map<String, Value>,
) {
    let Some(constant) = constant_of(question) else {
        return;
    };
    let c = &problem.constants[constant];
    let list: Vec<Value> = edges(answer)
        .iter()
        .map(|e| {
            serde_json::json!({
                "value": super::answer_numbers::number(e.value),
                "stable_above": e.stable_above,
                "oscillates": e.oscillates,
            })
        })
        .collect();
    out.insert("constant".into(), c.name.clone().into());
    out.insert("edges".into(), Value::Array(list));
    out.insert("unit".into(), c.unit.clone().unwrap_or_default().into());
}
