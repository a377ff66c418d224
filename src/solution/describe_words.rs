//! A `describe` question in the Answers and in `answer --format json`: a simulated
//! coordinate's motion said as a student would say it, its least and greatest value, its
//! mean and amplitude, its period measured from the simulation, and the range of the other
//! rates asked (whether each keeps its sign).

use crate::numeric::{coordinate_unit, described, Answer, Description};
use crate::problem::{Problem, Question, QuestionKind};
use crate::render::{AnswerStep, AnswerView};
use crate::symbolic::latex;
use serde_json::{Map, Value};

fn number(x: f64) -> String {
    super::answer_numbers::number_tex(x)
}

fn unit(problem: &Problem, i: usize, order: u8) -> String {
    super::answer_numbers::unit_tex(&coordinate_unit(problem, i, order))
}

/// The values and the place of a `describe` answer in its view, and the motion in words
/// as its one step.
pub fn fill(
    problem: &Problem,
    question: &Question,
    answer: &Answer,
    view: &mut AnswerView,
) -> Vec<AnswerStep> {
    let QuestionKind::Describe { coordinate, rates } = &question.kind else {
        return Vec::new();
    };
    let k = *coordinate;
    let found = described(&answer.values);
    view.at_tex = format!(
        "0 \\le t \\le {}\\ \\mathrm{{s}}",
        crate::symbolic::fixed(found.duration)
    )
    .into();
    view.at_note = "simulated from the initial state".into();
    // The motion is said once, in words, with every value to the answers' digits.
    view.values_tex.clear();
    vec![AnswerStep {
        text: sentence(problem, (k, rates), &found).into(),
        math: String::new().into(),
    }]
}

/// The motion in words, each value to the answers' digits: "θ oscillates between … and …
/// about a mean of …, with the amplitude (θ_max − θ_min)/2 = …, once every τ = … s, measured
/// between its successive maxima. ψ̇ stays between … and … and keeps its sign: ψ never turns
/// back (no loops)."
fn sentence(problem: &Problem, (k, rates): (usize, &[usize]), found: &Description) -> String {
    let q = latex(&problem.coordinate_expr(k, 0));
    let u = unit(problem, k, 0);
    let mut words = format!(
        "${q}$ oscillates between ${}{u}$ and ${}{u}$, about a mean of ${}{u}$, with the \
         amplitude $\\frac{{{q}_{{\\max}} - {q}_{{\\min}}}}{{2}} = {}{u}$",
        number(found.minimum),
        number(found.maximum),
        number(found.mean),
        number(found.amplitude)
    );
    match found.period {
        Some(period) => words.push_str(&format!(
            ", once every $\\tau = {}\\ \\mathrm{{s}}$, measured between its successive maxima.",
            number(period)
        )),
        None => words.push_str(": it does not reach two maxima, so no period is measured."),
    }
    for (&j, (lo, hi)) in rates.iter().zip(&found.rates) {
        let rate = latex(&problem.coordinate_expr(j, 1));
        let name = latex(&problem.coordinate_expr(j, 0));
        let keeps = lo * hi > 0.0;
        words.push_str(&format!(
            " ${rate}$ stays between ${}$ and ${}{}$ and {}.",
            number(*lo),
            number(*hi),
            unit(problem, j, 1),
            match keeps {
                true => format!("keeps its sign: ${name}$ never turns back (no loops)"),
                false => format!("changes sign: ${name}$ turns back (loops)"),
            }
        ));
    }
    words
}

fn json_number(x: f64) -> Value {
    super::answer_numbers::number(x)
}

/// The fields of a `describe` answer in `answer --format json`: `coordinate`, `unit`,
/// `minimum`, `maximum`, `mean`, `amplitude`, `period` (s, or null), `duration` (s) and
/// `rates`: `{ "psi'": { "minimum", "maximum", "keeps_sign", "unit" } }`.
pub fn record(
    problem: &Problem,
    question: &Question,
    answer: &Answer,
    out: &mut Map<String, Value>,
) {
    let QuestionKind::Describe { coordinate, rates } = &question.kind else {
        return;
    };
    let found = described(&answer.values);
    let name = problem.coordinates[*coordinate].name.clone();
    out.insert("coordinate".into(), name.into());
    out.insert(
        "unit".into(),
        coordinate_unit(problem, *coordinate, 0).into(),
    );
    out.insert("minimum".into(), json_number(found.minimum));
    out.insert("maximum".into(), json_number(found.maximum));
    out.insert("mean".into(), json_number(found.mean));
    out.insert("amplitude".into(), json_number(found.amplitude));
    out.insert(
        "period".into(),
        found.period.map_or(Value::Null, json_number),
    );
    out.insert("duration".into(), json_number(found.duration));
    let mut ranges = Map::new();
    for (&j, (lo, hi)) in rates.iter().zip(&found.rates) {
        let mut range = Map::new();
        range.insert("minimum".into(), json_number(*lo));
        range.insert("maximum".into(), json_number(*hi));
        range.insert("keeps_sign".into(), (lo * hi > 0.0).into());
        range.insert("unit".into(), coordinate_unit(problem, j, 1).into());
        ranges.insert(
            format!("{}'", problem.coordinates[j].name),
            Value::Object(range),
        );
    }
    out.insert("rates".into(), Value::Object(ranges));
}
