//! The numerical answers: each within 0.5 % of the key (or 1e-6 absolute near zero), a
//! vector's components in the frame the student names (default the frame `answer` gives).

use super::numbers::{factor_text, percent};
use super::reference::Reference;
use super::report::Item;
use super::submission::Named;
use crate::numeric::{Answer, Quantity, ReactionColumn};
use crate::problem::{BodyId, QuestionKind};
use crate::symbolic::{eval, ComponentKind, Expr};
use serde_json::Value;

/// The relative tolerance of an answer.
const RELATIVE: f64 = 0.005;
/// The absolute tolerance of an answer near zero.
const ABSOLUTE: f64 = 1e-6;

const AXES: [&str; 3] = ["x", "y", "z"];

/// Grades the answers: one item per question of the problem.
pub(super) fn grade(reference: &Reference, given: &Named<Value>) -> Vec<Item> {
    let questions = &reference.problem.questions;
    let mut items = Vec::new();
    for (key, _) in given {
        if !key.parse::<usize>().is_ok_and(|i| i < questions.len()) {
            items.push(Item::invalid(
                format!("answers.{key}"),
                format!(
                    "the problem has no question `{key}`: its questions are numbered 0 to {}",
                    questions.len().saturating_sub(1)
                ),
            ));
        }
    }
    for i in 0..questions.len() {
        let name = format!("answers.{i}");
        let Some((_, value)) = given.iter().find(|(k, _)| k.parse::<usize>() == Ok(i)) else {
            items.push(Item::missing(name, format!("question {i} is not answered")));
            continue;
        };
        let answer = match &reference.answers {
            Ok(all) => match &all[i] {
                Some(answer) => answer,
                None => {
                    // Not worked out: the reference was made for other questions.
                    items.push(Item::invalid(
                        name,
                        format!("question {i} was not worked out"),
                    ));
                    continue;
                }
            },
            Err(why) => {
                items.push(Item::invalid(
                    name,
                    format!("the key cannot be computed: {why}"),
                ));
                continue;
            }
        };
        items.push(match one(reference, i, answer, value) {
            Ok(None) => Item::right(name, ""),
            Ok(Some(why)) => Item::wrong(name, why),
            Err(why) => Item::invalid(name, why),
        });
    }
    items
}

fn within(given: f64, expected: f64) -> bool {
    (given - expected).abs() <= (RELATIVE * expected.abs()).max(ABSOLUTE)
}

fn number(value: &Value) -> Option<f64> {
    match value {
        Value::Number(n) => n.as_f64(),
        Value::String(s) => s.trim().parse().ok(),
        _ => None,
    }
}

/// What is wrong with one number, or `None` when it is right.
fn scalar(given: f64, expected: f64) -> Option<String> {
    if within(given, expected) {
        return None;
    }
    let how = if within(-given, expected) {
        "the sign is wrong".to_string()
    } else if expected != 0.0
        && (given / expected - (given / expected).round()).abs() < 0.005
        && (given / expected).round() != 0.0
    {
        format!(
            "off by the factor {}",
            factor_text((given / expected).round())
        )
    } else if expected != 0.0 {
        let side = if given.abs() > expected.abs() {
            "too large"
        } else {
            "too small"
        };
        format!("{} {side}", percent(given, expected))
    } else {
        "should be zero".into()
    };
    Some(format!(
        "{given} where {expected} was expected ({how}; within 0.5 % is right)"
    ))
}

/// Grades one answer: `Ok(None)` right, `Ok(Some(why))` wrong, `Err(why)` unreadable.
fn one(
    reference: &Reference,
    i: usize,
    answer: &Answer,
    value: &Value,
) -> Result<Option<String>, String> {
    let question = &reference.problem.questions[i];
    match &question.kind {
        QuestionKind::Value { .. }
        | QuestionKind::Drive { .. }
        | QuestionKind::Impending { .. }
        | QuestionKind::Period { .. } => {
            let given = number(value).ok_or("expected a number")?;
            let expected = answer.values.first().map_or(f64::NAN, |(_, x)| *x);
            Ok(scalar(given, expected))
        }
        QuestionKind::Steady { .. } | QuestionKind::Describe { .. } => {
            let Value::Object(map) = value else {
                return Err("expected an object of the unknowns, e.g. { \"psi'\": 2.5 }".into());
            };
            let mut wrong = Vec::new();
            for (found, expected) in &answer.values {
                let name = found.to_string();
                match map.get(&name).and_then(number) {
                    None => wrong.push(format!("{name} is missing")),
                    Some(g) => wrong.extend(scalar(g, *expected).map(|w| format!("{name}: {w}"))),
                }
            }
            Ok((!wrong.is_empty()).then(|| wrong.join("; ")))
        }
        QuestionKind::Reaction { site } => reaction(reference, *site, answer, value),
        QuestionKind::VectorValue { .. } => vector_value(answer, value),
        QuestionKind::Slips { .. } | QuestionKind::Tips { .. } => {
            yes_or_no(&question.kind, answer, value)
        }
        QuestionKind::Show { .. } => shown(answer, value),
        QuestionKind::Stability { .. } => stability(answer, value),
    }
}

/// A vector `value`: every component along the unit vectors of the frame `answer` gives
/// them in, each within 0.5 %.
fn vector_value(answer: &Answer, value: &Value) -> Result<Option<String>, String> {
    let Value::Object(map) = value else {
        return Err("expected the components, e.g. { \"x\": 0.5, \"y\": -1.2 }".into());
    };
    let frame = answer.frame.as_deref().unwrap_or("N");
    if let Some(given) = map.get("frame") {
        if given.as_str() != Some(frame) {
            return Err(format!("give the components along {frame}'s unit vectors"));
        }
    }
    let mut wrong = Vec::new();
    for (found, expected) in &answer.values {
        let name = found.to_string();
        let axis = name.rsplit('.').next().unwrap_or("x");
        match map.get(axis).and_then(number) {
            None => wrong.push(format!("the {axis} component is missing")),
            Some(g) => wrong.extend(scalar(g, *expected).map(|w| format!("{axis}: {w}"))),
        }
    }
    Ok((!wrong.is_empty()).then(|| wrong.join("; ")))
}

/// A `stability`: the values where the stability changes, in order, each within 0.5 %.
fn stability(answer: &Answer, value: &Value) -> Result<Option<String>, String> {
    let given: Vec<f64> = match value {
        Value::Array(items) => items.iter().map(number).collect::<Option<_>>(),
        other => number(other).map(|x| vec![x]),
    }
    .ok_or("expected the values where the stability changes, e.g. [4.29, 6.02]")?;
    let expected: Vec<f64> = answer.values.iter().map(|(_, x)| *x).collect();
    if given.len() != expected.len() {
        return Ok(Some(format!(
            "{} values where {} were expected",
            given.len(),
            expected.len()
        )));
    }
    let wrong: Vec<String> = (given.iter().zip(&expected))
        .filter_map(|(g, e)| scalar(*g, *e))
        .collect();
    Ok((!wrong.is_empty()).then(|| wrong.join("; ")))
}

/// A `show`: `true` (or "yes") when the identity holds, or the common value of its sides
/// within 0.5 %.
fn shown(answer: &Answer, value: &Value) -> Result<Option<String>, String> {
    let lhs = answer.values.first().map_or(f64::NAN, |(_, x)| *x);
    match value {
        Value::Bool(true) => Ok(None),
        Value::String(s) if s.eq_ignore_ascii_case("yes") => Ok(None),
        Value::Bool(false) => Ok(Some("the identity holds: both sides are equal".into())),
        _ => number(value)
            .map(|given| scalar(given, lhs))
            .ok_or_else(|| "expected true (the identity holds) or the sides' value".into()),
    }
}

/// A yes/no question of statics: `true`/`false` (or "yes"/"no") against the decision, or
/// the deciding number (the ratio |F|/(μ|N|), the normal force) within 0.5 %.
fn yes_or_no(
    kind: &QuestionKind,
    answer: &Answer,
    value: &Value,
) -> Result<Option<String>, String> {
    let deciding = answer.values.first().map_or(f64::NAN, |(_, x)| *x);
    if let Some(given) = number(value) {
        return Ok(scalar(given, deciding));
    }
    let given = match value {
        Value::Bool(b) => *b,
        Value::String(s) if s.eq_ignore_ascii_case("yes") => true,
        Value::String(s) if s.eq_ignore_ascii_case("no") => false,
        _ => return Err("expected yes or no (true or false), or the deciding number".into()),
    };
    let expected = match kind {
        // As `answer` decides: slip where friction would need more than μ|N|, tipping where
        // the normal force would have to pull.
        QuestionKind::Tips { .. } => deciding < 0.0,
        // In motion, a contact point that slides slips (friction is then μ|N|).
        _ => {
            crate::numeric::slip_speed(&answer.values).is_some_and(|s| s > 0.0)
                || deciding > 1.0
                || crate::numeric::contact_lost(&answer.values)
        }
    };
    let word = |b: bool| if b { "yes" } else { "no" };
    Ok((given != expected)
        .then(|| format!("{} where {} was expected", word(given), word(expected))))
}

/// A reaction's components, force then moment, in the frame the answer gives them in.
fn expected_components(answer: &Answer) -> [[f64; 3]; 2] {
    let mut out = [[0.0; 3]; 2];
    for (found, x) in &answer.values {
        if let Quantity::Reaction(ReactionColumn::Component { kind, axis, .. }) = found {
            let k = usize::from(*kind == ComponentKind::Moment);
            if *axis < 3 {
                out[k][*axis] = *x;
            }
        }
    }
    out
}

fn frame_id(reference: &Reference, name: &str) -> Option<BodyId> {
    if name == "N" {
        return Some(BodyId::GROUND);
    }
    let i = reference
        .problem
        .bodies
        .iter()
        .position(|b| b.name == name)?;
    Some(BodyId(i + 1))
}

/// `v` given in `from` written in `to`, at the state of `answer`.
fn express(
    reference: &Reference,
    answer: &Answer,
    v: &[f64; 3],
    from: BodyId,
    to: BodyId,
) -> [f64; 3] {
    let model = &reference.derivation.model;
    let values = model.values_at(answer.time, &answer.q, &answer.rates);
    let components = [Expr::real(v[0]), Expr::real(v[1]), Expr::real(v[2])];
    let c = model.frames.express(&components, from, to);
    [
        eval(&c[0], &values),
        eval(&c[1], &values),
        eval(&c[2], &values),
    ]
}

fn reaction(
    reference: &Reference,
    site: usize,
    answer: &Answer,
    value: &Value,
) -> Result<Option<String>, String> {
    let Value::Object(map) = value else {
        return Err(
            "expected the components, e.g. { \"x\": 0.0, \"y\": 15.0, \"frame\": \"N\" }".into(),
        );
    };
    let model = &reference.derivation.model;
    // The frame `answer` gives the components in: the question's `in`, else the site's.
    let home = (answer.frame.as_deref())
        .and_then(|name| frame_id(reference, name))
        .unwrap_or(model.sites[site].parent);
    let frame_name = match map.get("frame") {
        None => model.frames.name(home).to_string(),
        Some(Value::String(s)) => s.clone(),
        Some(_) => return Err("`frame` is the name of a frame, e.g. \"N\"".into()),
    };
    let frame = frame_id(reference, &frame_name)
        .ok_or_else(|| format!("unknown frame `{frame_name}`: write N or a body's name"))?;
    let expected = expected_components(answer);
    let given = given_components(map)?;
    let mut wrong = Vec::new();
    for (k, what) in [(0, "force"), (1, "moment")] {
        let in_frame = express(reference, answer, &expected[k], home, frame);
        let wanted: Vec<usize> = (0..3)
            .filter(|&a| {
                given[k][a].is_some()
                    || in_frame[a].abs() > ABSOLUTE.max(RELATIVE * norm(&in_frame))
            })
            .collect();
        let mut bad = Vec::new();
        for &a in &wanted {
            match given[k][a] {
                None => bad.push(format!("the {what}'s {} component is missing", AXES[a])),
                Some(g) => bad.extend(
                    scalar(g, in_frame[a])
                        .map(|w| format!("the {what}'s {} component is {w}", AXES[a])),
                ),
            }
        }
        if bad.is_empty() {
            continue;
        }
        if let Some(other) = mislabelled(reference, answer, &expected[k], home, frame, &given[k]) {
            wrong.push(format!("the {what}'s components are those in {other}'s unit vectors, labelled {frame_name}"));
        } else {
            wrong.extend(bad);
        }
    }
    Ok((!wrong.is_empty()).then(|| wrong.join("; ")))
}

fn norm(v: &[f64; 3]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// The frame other than `frame` whose components the student's numbers are, if any.
fn mislabelled(
    reference: &Reference,
    answer: &Answer,
    expected: &[f64; 3],
    home: BodyId,
    frame: BodyId,
    given: &[Option<f64>; 3],
) -> Option<String> {
    let frames = &reference.derivation.model.frames;
    (0..frames.len())
        .map(BodyId)
        .filter(|&f| f != frame)
        .find_map(|other| {
            let c = express(reference, answer, expected, home, other);
            let fits = (0..3).all(|a| within(given[a].unwrap_or(0.0), c[a]));
            fits.then(|| frames.name(other).to_string())
        })
}

type Components = [[Option<f64>; 3]; 2];

fn given_components(map: &serde_json::Map<String, Value>) -> Result<Components, String> {
    let mut out: Components = [[None; 3]; 2];
    for (key, value) in map {
        match key.as_str() {
            "frame" => {}
            "moment" => {
                let Value::Object(m) = value else {
                    return Err("`moment` is an object of components, e.g. { \"z\": 1.5 }".into());
                };
                for (a, axis) in AXES.iter().enumerate() {
                    out[1][a] = m
                        .get(*axis)
                        .map(|v| number(v).ok_or(format!("moment.{axis} is not a number")))
                        .transpose()?;
                }
            }
            axis => {
                let a = AXES.iter().position(|x| *x == axis).ok_or(format!(
                    "unknown key `{axis}`: the components are x, y, z (and `moment`, `frame`)"
                ))?;
                out[0][a] = Some(number(value).ok_or(format!("{axis} is not a number"))?);
            }
        }
    }
    Ok(out)
}
