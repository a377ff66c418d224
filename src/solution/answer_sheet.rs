//! The answers of `find.questions` without a handout: JSON and text for `mbd-tutor
//! answer`, and the columns of a variants key. The numbers are the f64s computed, printed
//! in full (the shortest text that reads back as the same f64), not rounded as a handout
//! prints them.

use super::answer_numbers::number;
use crate::numeric::{answer_unit, holds, is_free_moment, Answer, Quantity, ReactionColumn};
use crate::problem::{Problem, Question, QuestionKind};
use crate::symbolic::ComponentKind;
use serde_json::{Map, Value};
use std::fmt::Write;

/// What a question asks for, as `answer --format json` names it.
fn kind_name(question: &Question) -> &'static str {
    match question.kind {
        QuestionKind::Value { .. } | QuestionKind::VectorValue { .. } => "value",
        QuestionKind::Reaction { .. } => "reaction",
        QuestionKind::Drive { .. } => "drive",
        QuestionKind::Steady { .. } => "steady",
        QuestionKind::Slips { .. } => "slips",
        QuestionKind::Tips { .. } => "tips",
        QuestionKind::Impending { .. } => "impending",
        QuestionKind::Period { .. } => "period",
        QuestionKind::Show { .. } => "show",
        QuestionKind::Stability { .. } => "stability",
        QuestionKind::Describe { .. } => "describe",
    }
}

/// `x` in full precision: the shortest decimal that reads back as the same f64 (as JSON
/// prints it, so that a key's cell and `answer --format json` agree character for character).
pub fn full(x: f64) -> String {
    number(x).to_string()
}

/// A reaction value's place: whether it is a moment, and its axis `x`, `y` or `z`.
fn reaction_part(found: &Quantity) -> (bool, &'static str) {
    match found {
        Quantity::Reaction(ReactionColumn::Component { kind, axis, .. }) => (
            *kind == ComponentKind::Moment,
            ["x", "y", "z"].get(*axis).copied().unwrap_or("x"),
        ),
        _ => (false, "x"),
    }
}

/// The values of an answer worth reporting: all but a reaction's moments about free axes.
fn reported<'a>(
    question: &'a Question,
    answer: &'a Answer,
) -> impl Iterator<Item = (&'a Quantity, f64)> {
    answer
        .values
        .iter()
        .filter(|(found, x)| !is_free_moment(question, found, *x))
        .map(|(found, x)| (found, *x))
}

/// One question's answer as JSON (see `docs/answer-and-variants.md`).
fn record(problem: &Problem, index: usize, question: &Question, answer: &Answer) -> Value {
    let mut out = Map::new();
    out.insert("index".into(), index.into());
    let text = question
        .text
        .clone()
        .unwrap_or_else(|| super::answers::asked(problem, question));
    out.insert("text".into(), text.into());
    out.insert("kind".into(), kind_name(question).into());
    let unit_of = |found: &Quantity| answer_unit(problem, question, found);
    match &question.kind {
        QuestionKind::Value { .. } | QuestionKind::Drive { .. } => {
            if let Some((name, x)) = answer.values.first() {
                out.insert("value".into(), number(*x));
                out.insert("unit".into(), unit_of(name).into());
            }
        }
        QuestionKind::VectorValue { .. } => {
            super::vector_answers::record(problem, question, answer, &mut out);
        }
        QuestionKind::Reaction { .. } => {
            let mut components = Map::new();
            let mut moment = Map::new();
            for (found, x) in reported(question, answer) {
                match reaction_part(found) {
                    (true, axis) => moment.insert(axis.into(), number(x)),
                    (false, axis) => components.insert(axis.into(), number(x)),
                };
            }
            // In the plane the force's z is 0, given so that every reaction has x, y, z.
            for axis in ["x", "y", "z"] {
                components.entry(axis).or_insert_with(|| number(0.0));
            }
            out.insert("unit".into(), "N".into());
            if !moment.is_empty() {
                components.insert("moment".into(), Value::Object(moment));
                out.insert("moment_unit".into(), "N m".into());
            }
            out.insert("components".into(), Value::Object(components));
            if let Some(frame) = &answer.frame {
                out.insert("frame".into(), frame.as_str().into());
            }
        }
        QuestionKind::Steady { .. } => {
            let unknowns = answer
                .values
                .iter()
                .map(|(found, x)| (found.to_string(), number(*x)))
                .collect();
            let units = answer
                .values
                .iter()
                .map(|(found, _)| (found.to_string(), Value::from(unit_of(found))))
                .collect();
            out.insert("unknowns".into(), Value::Object(unknowns));
            out.insert("units".into(), Value::Object(units));
            if let Some((left, iterations)) = answer.residual {
                out.insert("residual".into(), number(left));
                out.insert("iterations".into(), iterations.into());
            }
        }
        QuestionKind::Slips { .. } | QuestionKind::Tips { .. } | QuestionKind::Impending { .. } => {
            super::static_answers::record(problem, question, answer, &mut out);
        }
        QuestionKind::Period { .. } => {
            if let Some(found) = &answer.period {
                out.insert("value".into(), number(found.period));
                out.insert("unit".into(), "s".into());
                out.insert("angular_frequency".into(), number(found.damped));
                out.insert("natural_frequency".into(), number(found.natural));
                out.insert("damping_ratio".into(), number(found.damping_ratio));
            }
        }
        QuestionKind::Show { .. } => {
            if let [(_, lhs), (_, rhs)] = answer.values[..] {
                out.insert("holds".into(), holds(lhs, rhs).into());
                out.insert("lhs".into(), number(lhs));
                out.insert("rhs".into(), number(rhs));
                if let Some(unit) = &question.unit {
                    out.insert("unit".into(), unit.as_str().into());
                }
            }
        }
        QuestionKind::Stability { .. } => {
            super::stability_answers::record(problem, question, answer, &mut out);
        }
        QuestionKind::Describe { .. } => {
            super::describe_words::record(problem, question, answer, &mut out);
        }
    }
    out.insert("state".into(), Value::Object(state(problem, answer)));
    out.insert("time".into(), number(answer.time));
    if let Some(site) = question.at.switch {
        // The instant was found, not given: say where it comes from.
        out.insert("switch".into(), Value::from(problem.site_name(site)));
    }
    Value::Object(out)
}

/// The state where an answer holds: every coordinate, then every rate (`theta'`).
fn state(problem: &Problem, answer: &Answer) -> Map<String, Value> {
    let coordinates = problem.coordinates.iter().zip(&answer.q);
    let rates = problem.coordinates.iter().zip(&answer.rates);
    coordinates
        .map(|(c, x)| (c.name.clone(), number(*x)))
        .chain(rates.map(|(c, x)| (format!("{}'", c.name), number(*x))))
        .collect()
}

/// `{ "answers": [ … ] }`, pretty-printed, with a final newline.
pub fn json(problem: &Problem, answers: &[Answer]) -> String {
    let records: Vec<Value> = problem
        .questions
        .iter()
        .zip(answers)
        .enumerate()
        .map(|(i, (question, answer))| record(problem, i, question, answer))
        .collect();
    let mut map = Map::new();
    map.insert("answers".into(), Value::Array(records));
    let mut text = serde_json::to_string_pretty(&Value::Object(map)).unwrap_or_default();
    text.push('\n');
    text
}

/// The answers for a reader: each question's index, kind and where it is asked, its text,
/// then each value found with its unit.
pub fn text(problem: &Problem, answers: &[Answer]) -> String {
    let mut out = String::new();
    for (i, (question, answer)) in problem.questions.iter().zip(answers).enumerate() {
        let how = match question.at.switch {
            Some(site) => format!(
                ", where {} first switches between sticking and slipping, simulated from the initial state",
                problem.site_name(site)
            ),
            None if answer.simulated => ", simulated from the initial state".into(),
            None => String::new(),
        };
        let _ = writeln!(
            out,
            "[{i}] {} at t = {} s{how}",
            kind_name(question),
            full(answer.time)
        );
        let text = question
            .text
            .clone()
            .unwrap_or_else(|| super::answers::asked(problem, question));
        let _ = writeln!(out, "    {}", text.replace('\n', " "));
        if let Some(frame) = &answer.frame {
            let _ = writeln!(out, "    components along {frame}'s unit vectors");
        }
        for (found, x) in reported(question, answer) {
            let unit = answer_unit(problem, question, found);
            let _ = writeln!(out, "    {found} = {} {unit}", full(x));
        }
        if let Some(verdict) = super::static_answers::verdict_words(question, answer) {
            let _ = writeln!(out, "    {verdict}");
        }
    }
    out
}

/// The key's answer columns of one problem: each question's values named by its `symbol`,
/// else its index; a reaction's components as `NAME.x@A`, `NAME.moment.z@A` (`A` the frame
/// whose unit vectors they are along), a steady motion's unknowns as `NAME.psi'`. The same
/// numbers as [`json`] gives.
pub fn key_columns(problem: &Problem, answers: &[Answer]) -> Vec<(String, f64)> {
    let mut columns = Vec::new();
    for (i, (question, answer)) in problem.questions.iter().zip(answers).enumerate() {
        let base = question.symbol.clone().unwrap_or_else(|| i.to_string());
        for (found, x) in reported(question, answer) {
            let column = match &question.kind {
                QuestionKind::Value { .. }
                | QuestionKind::Drive { .. }
                | QuestionKind::Period { .. } => base.clone(),
                QuestionKind::Show { .. } => format!("{base}.{found}"),
                QuestionKind::VectorValue { .. } => {
                    let at = answer.frame.as_deref().unwrap_or("N");
                    format!("{base}.{}@{at}", super::vector_answers::axis_of(found))
                }
                QuestionKind::Reaction { .. } => {
                    let at = answer.frame.as_deref().unwrap_or("N");
                    match reaction_part(found) {
                        (true, axis) => format!("{base}.moment.{axis}@{at}"),
                        (false, axis) => format!("{base}.{axis}@{at}"),
                    }
                }
                QuestionKind::Steady { .. } => format!("{base}.{found}"),
                QuestionKind::Slips { .. } | QuestionKind::Tips { .. } => format!("{base}.{found}"),
                QuestionKind::Impending { .. } => base.clone(),
                QuestionKind::Stability { .. } | QuestionKind::Describe { .. } => {
                    format!("{base}.{found}")
                }
            };
            columns.push((column, x));
        }
    }
    columns
}

/// A CSV cell: quoted when it holds a comma, a quote or a line break (RFC 4180); a text
/// that a spreadsheet would take for a formula (beginning with `=`, `+`, `-`, `@`, a tab or
/// a carriage return, and not a number) begins with `'`, as spreadsheets expect.
pub fn csv_cell(text: &str) -> String {
    let formula =
        text.starts_with(['=', '+', '-', '@', '\t', '\r']) && text.parse::<f64>().is_err();
    if formula {
        return csv_cell(&format!("'{text}"));
    }
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}
