//! The scalar items: the q'' as expressions of the state, and Kane's generalized active
//! and inertia forces, each compared with the worked solution's at the sampled states.

use super::diagnose::{compare, slip, whole};
use super::equations::parse_message;
use super::names::Names;
use super::numbers::close;
use super::parts::{parts, scale, values};
use super::reference::Reference;
use super::report::Item;
use super::submission::Named;
use crate::plan::Sum;
use crate::symbolic::{linear_split, simplify, Expr, Symbol};
use serde_json::Value;

/// Parses one scalar entry, or the item that says why it cannot be read.
fn parse(reference: &Reference, name: &str, value: &Value) -> Result<Expr, Item> {
    let text = match value {
        Value::String(s) => s.clone(),
        Value::Number(n) => n.to_string(),
        _ => {
            return Err(Item::invalid(
                name.to_string(),
                "expected an expression as a string".into(),
            ))
        }
    };
    Names::new(reference.problem, &reference.reactions, false)
        .parse(&text)
        .map_err(|e| Item::invalid(name.to_string(), parse_message(&e)))
}

/// What is wrong with `given` against `expected` (free: with the q'' drawn at random), or
/// `None` when they are equal at every sampled state.
pub(super) fn differ(
    reference: &Reference,
    given: &Expr,
    expected: &Expr,
    free: bool,
) -> Option<String> {
    let samples = &reference.samples;
    let (g, e) = (
        values(given, samples, free),
        values(expected, samples, free),
    );
    if close(&g, &e, 0.0) {
        return None;
    }
    if !g.iter().all(|x| x.is_finite()) {
        return Some(super::equations::NOT_REAL.into());
    }
    let expected = simplify(&reference.own_symbols(expected));
    if let Some(all) = whole(&g, &e) {
        return Some(format!("{all}: {given} where {expected} was expected"));
    }
    if let Some(kind) = slip((given, &g), (&expected, &e), samples) {
        return Some(format!("it {kind}: {given} where {expected} was expected"));
    }
    let unknowns = &reference.accelerations;
    let (Some(gp), Some(ep)) = (
        parts(given, unknowns, reference),
        parts(&expected, unknowns, reference),
    ) else {
        return Some(format!("{given} where {expected} was expected"));
    };
    let size = scale(&gp).max(scale(&ep));
    let findings = compare(&gp, &ep, size, samples);
    let texts: Vec<String> = findings.into_iter().map(|f| f.text).collect();
    Some(match texts.is_empty() {
        true => format!("{given} where {expected} was expected"),
        false => texts.join("; "),
    })
}

/// Grades `accelerations`: one item per coordinate the equations determine.
pub(super) fn accelerations(reference: &Reference, given: &Named<Value>) -> Vec<Item> {
    let mut items = Vec::new();
    for (i, coordinate) in reference.problem.coordinates.iter().enumerate() {
        if coordinate.motion.is_some() {
            continue;
        }
        let name = format!("accelerations.{}", coordinate.name);
        let Some((_, value)) = given.iter().find(|(k, _)| *k == coordinate.name) else {
            items.push(Item::missing(
                name,
                format!("{}'' is not given", coordinate.name),
            ));
            continue;
        };
        let written = match parse(reference, &name, value) {
            Ok(e) => e,
            Err(item) => {
                items.push(item);
                continue;
            }
        };
        // A row with this q'' alone gives it in closed form; otherwise its values.
        let symbol = &reference.accelerations[i];
        let verdict = match closed_form(reference, symbol) {
            Some(expected) => differ(reference, &written, &expected, false),
            None => differ_in_value(reference, &written, symbol),
        };
        items.push(match verdict {
            None => Item::right(name, ""),
            Some(why) => Item::wrong(name, why),
        });
    }
    items
}

/// What is wrong with `given` against the values of the q'' `symbol` (no closed form
/// written), or `None` when they agree at every sampled state.
fn differ_in_value(reference: &Reference, given: &Expr, symbol: &Symbol) -> Option<String> {
    let samples = &reference.samples;
    let g = values(given, samples, false);
    let e: Vec<f64> = samples.iter().map(|s| s.motion.get(symbol)).collect();
    if close(&g, &e, 0.0) {
        return None;
    }
    if !g.iter().all(|x| x.is_finite()) {
        return Some(super::equations::NOT_REAL.into());
    }
    if let Some(all) = whole(&g, &e) {
        return Some(all);
    }
    let first = samples.first()?;
    let state: Vec<String> = reference
        .problem
        .coordinates
        .iter()
        .enumerate()
        .flat_map(|(i, c)| {
            [
                format!("{} = {:.4}", c.name, first.q[i]),
                format!("{}' = {:.4}", c.name, first.rates[i]),
            ]
        })
        .collect();
    Some(format!(
        "at {} it gives {:.6} where the equations of motion give {:.6}",
        state.join(", "),
        g[0],
        e[0]
    ))
}

/// The q'' `symbol` from a row of the worked solution in which it is the only unknown.
fn closed_form(reference: &Reference, symbol: &Symbol) -> Option<Expr> {
    let row = reference
        .derivation
        .rows
        .iter()
        .find(|r| r.unknowns.len() == 1 && r.unknowns[0] == *symbol)?;
    let (c, rest) = linear_split(&row.expression, std::slice::from_ref(symbol)).ok()?;
    Some(simplify(&reference.own_symbols(&(-rest / c[0].clone()))))
}

/// Grades `generalized_forces`: `active` and `inertia`, one expression per speed, against
/// Kane's F_r and F_r*.
pub(super) fn generalized(reference: &Reference, given: &Named<Vec<Value>>) -> Vec<Item> {
    let Some(kane) = reference.kane() else {
        return vec![Item::invalid(
            "generalized_forces".into(),
            "Kane's equations of this problem cannot be derived to compare with".into(),
        )];
    };
    let rows: Vec<_> = kane
        .rows
        .iter()
        .filter(|r| matches!(&r.sum, Sum::Generalized { speed } if !speed.starts_with("u(")))
        .collect();
    let mut items = Vec::new();
    for (key, entries) in given {
        for (r, row) in rows.iter().enumerate() {
            let name = format!("generalized_forces.{key}[{r}]");
            let Some(value) = entries.get(r) else {
                items.push(Item::missing(
                    name,
                    format!(
                        "the generalized {key} force for speed {} is not given",
                        r + 1
                    ),
                ));
                continue;
            };
            let written = match parse(reference, &name, value) {
                Ok(e) => e,
                Err(item) => {
                    items.push(item);
                    continue;
                }
            };
            let g = &row.groups;
            let expected = match key.as_str() {
                "active" => g.contact.clone() + g.distance.clone(),
                _ => g.inertia_force.clone() + g.inertia_torque.clone(),
            };
            items.push(match differ(reference, &written, &expected, true) {
                None => Item::right(name, ""),
                Some(why) => Item::wrong(name, why),
            });
        }
        for extra in rows.len()..entries.len() {
            items.push(Item::wrong(
                format!("generalized_forces.{key}[{extra}]"),
                format!("the problem has {} generalized speeds", rows.len()),
            ));
        }
    }
    items
}
