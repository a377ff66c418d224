//! The equations of motion: each one checked against the motion (does it hold with the
//! worked solution's q'' and reactions?), the set checked for how many q'' it determines,
//! and a wrong one matched to the worked row it was meant to be and diagnosed.

use super::contributions::{rows, Kind, Row};
use super::diagnose::{compare, Finding};
use super::names::Names;
use super::numbers::{close, factor_expr, factor_text, is_zero, ratio};
use super::parts::{parts, scale, Key, Part};
use super::reference::{Reference, Sample};
use super::report::Item;
use crate::symbolic::{eval, linear_split, Expr, ParseError, Symbol};
use nalgebra::DMatrix;
use serde_json::Value;
use std::cmp::Reverse;

/// One equation as written, parsed into `residual = 0`.
struct Written {
    residual: Expr,
    /// Whether it holds for the motion at every sampled state (`None`: it uses a reaction
    /// whose value is not known).
    holds: Option<bool>,
}

/// Grades the equations of a submission.
pub(super) fn grade(reference: &Reference, entries: &[Value]) -> Vec<Item> {
    let unknowns: Vec<Symbol> = reference
        .accelerations
        .iter()
        .chain(&reference.reactions)
        .cloned()
        .collect();
    let mut items = Vec::new();
    let mut written: Vec<(usize, Written)> = Vec::new();
    for (i, entry) in entries.iter().enumerate() {
        let name = format!("equations[{i}]");
        match read(reference, entry, &unknowns) {
            Err(item) => items.push(item.named(name)),
            Ok(Err(why)) => items.push(Item::wrong(name, why)),
            Ok(Ok(w)) => {
                written.push((i, w));
                items.push(Item::right(name, ""));
            }
        }
    }
    let mut table: Option<Vec<Row>> = None;
    for (i, w) in &written {
        if w.holds == Some(false) {
            let rows = table.get_or_insert_with(|| rows(reference));
            items[*i] = Item::wrong(
                format!("equations[{i}]"),
                diagnose(reference, rows, &w.residual),
            );
        }
    }
    let all: Vec<&Expr> = written.iter().map(|(_, w)| &w.residual).collect();
    let (determined, _) = determined(reference, &all, &unknowns);
    let unsure: Vec<&Expr> = written
        .iter()
        .filter(|(_, w)| w.holds != Some(false))
        .map(|(_, w)| &w.residual)
        .collect();
    if !determined_consistently(reference, &unsure, &unknowns) {
        for (i, w) in &written {
            if w.holds.is_none() {
                items[*i] = Item::wrong(
                    format!("equations[{i}]"),
                    "with the other equations it gives q'' that are not the worked solution's"
                        .into(),
                );
            }
        }
    }
    let dof = reference.degrees_of_freedom();
    let names: Vec<String> = reference
        .accelerations
        .iter()
        .map(|s| Expr::sym(s.clone()).to_string())
        .collect();
    for k in 0..dof.saturating_sub(determined) {
        let more = dof - determined;
        let diagnosis = format!(
            "the equations determine {determined} of the {dof} second derivatives ({}); {more} more independent equation{} needed",
            names.join(", "),
            if more == 1 { " is" } else { "s are" }
        );
        items.push(Item::missing(
            format!("equations[{}]", entries.len() + k),
            diagnosis,
        ));
    }
    items
}

/// Reads one entry: an item when it cannot be graded as an equation (not a string, a
/// syntax error); otherwise the equation, or why it is wrong as written.
fn read(
    reference: &Reference,
    entry: &Value,
    unknowns: &[Symbol],
) -> Result<Result<Written, String>, Item> {
    let Value::String(text) = entry else {
        return Err(Item::invalid(
            String::new(),
            "expected the equation as a string, e.g. \"m*L^2/3*theta'' + m*g*L/2*sin(theta) = 0\""
                .into(),
        ));
    };
    let names = Names::new(reference.problem, &reference.reactions, false);
    let residual = parse_equation(&names, text)
        .map_err(|e| Item::invalid(String::new(), parse_message(&e)))?;
    if residual.is_zero() {
        return Ok(Err("it says 0 = 0".into()));
    }
    let Ok((coefficients, rest)) = linear_split(&residual, unknowns) else {
        return Ok(Err("an equation of motion is linear in the second derivatives and the reactions; this one is not".into()));
    };
    if !real_everywhere(reference, &coefficients, &rest) {
        return Ok(Err(NOT_REAL.into()));
    }
    Ok(Ok(Written {
        holds: holds(reference, &coefficients, &rest, unknowns),
        residual,
    }))
}

/// Why an expression with no value at a sampled state is wrong.
pub(super) const NOT_REAL: &str =
    "it has no real value at some states of the motion (a division by zero or the root of a negative number)";

/// Whether the coefficients and the rest of an equation have finite values at every
/// sampled state.
fn real_everywhere(reference: &Reference, coefficients: &[Expr], rest: &Expr) -> bool {
    reference.samples.iter().all(|sample| {
        std::iter::once(rest)
            .chain(coefficients)
            .all(|e| eval(e, &sample.motion).is_finite())
    })
}

/// The parser's message with its column and hint.
pub(super) fn parse_message(e: &ParseError) -> String {
    match &e.hint {
        Some(hint) => format!("column {}: {} (hint: {hint})", e.column, e.message),
        None => format!("column {}: {}", e.column, e.message),
    }
}

/// `LHS = RHS` (or an expression equal to zero) as `LHS - RHS`.
fn parse_equation(names: &Names, text: &str) -> Result<Expr, ParseError> {
    let sides: Vec<&str> = text.split('=').collect();
    match sides.as_slice() {
        [whole] => names.parse(whole),
        [left, right] => {
            let offset = left.chars().count() + 1;
            let l = names.parse(left)?;
            let r = names.parse(right).map_err(|mut e| {
                e.column += offset;
                e
            })?;
            Ok(l - r)
        }
        _ => {
            let column = sides[0].chars().count() + sides[1].chars().count() + 2;
            Err(ParseError::new(column, "a second `=`")
                .with_hint("write one equation per entry: LHS = RHS"))
        }
    }
}

/// Whether `Σ c_k x_k + rest` vanishes at every sampled state with the motion's q'' and
/// reactions; `None` when a reaction it uses has no known value.
fn holds(
    reference: &Reference,
    coefficients: &[Expr],
    rest: &Expr,
    unknowns: &[Symbol],
) -> Option<bool> {
    let mut trivial = true;
    for sample in &reference.samples {
        let mut total = eval(rest, &sample.motion);
        let mut size = total.abs();
        for (c, u) in coefficients.iter().zip(unknowns) {
            if c.is_zero() {
                continue;
            }
            let x = sample.motion.get(u);
            let term = eval(c, &sample.motion) * x;
            total += term;
            size += term.abs();
        }
        if !total.is_finite() {
            return None;
        }
        trivial &= size == 0.0;
        if total.abs() > 1e-6 * size + 1e-12 {
            return Some(false);
        }
    }
    Some(!trivial)
}

/// How many q'' the equations determine once their reactions are eliminated, at the
/// state where they determine fewest; and whether the q'' they give are the motion's.
fn determined(reference: &Reference, equations: &[&Expr], unknowns: &[Symbol]) -> (usize, bool) {
    let n = reference.accelerations.len();
    let split: Vec<(Vec<Expr>, Expr)> = equations
        .iter()
        .filter_map(|e| linear_split(e, unknowns).ok())
        .collect();
    if split.is_empty() {
        return (0, true);
    }
    let used: Vec<usize> = (n..unknowns.len())
        .filter(|&k| split.iter().any(|(c, _)| !c[k].is_zero()))
        .collect();
    let mut fewest = n;
    let mut consistent = true;
    for sample in &reference.samples {
        let m = split.len();
        let value = |e: &Expr| eval(e, &sample.motion);
        let a = DMatrix::from_fn(m, n + used.len(), |i, j| {
            let k = if j < n { j } else { used[j - n] };
            value(&split[i].0[k])
        });
        let reactions = a.columns(n, used.len()).into_owned();
        fewest = fewest.min(rank(&a).saturating_sub(rank(&reactions)));
        // The motion's q'' must leave a right side the reactions can balance.
        let known = DMatrix::from_fn(m, 1, |i, _| {
            let mut r = value(&split[i].1);
            for (j, s) in reference.accelerations.iter().enumerate() {
                r += value(&split[i].0[j]) * sample.motion.get(s);
            }
            r
        });
        let mut augmented = reactions.clone().insert_columns(used.len(), 1, 0.0);
        augmented.set_column(used.len(), &known.column(0));
        consistent &= rank(&augmented) == rank(&reactions);
    }
    (fewest, consistent)
}

/// Whether the equations that hold or cannot be checked alone give the motion's q''.
fn determined_consistently(
    reference: &Reference,
    equations: &[&Expr],
    unknowns: &[Symbol],
) -> bool {
    determined(reference, equations, unknowns).1
}

/// The rank of `a`, its rows and columns scaled to one first.
fn rank(a: &DMatrix<f64>) -> usize {
    // A value that is not a number (a root of a negative number at a state) has no rank.
    if a.ncols() == 0 || a.nrows() == 0 || !a.iter().all(|x| x.is_finite()) {
        return 0;
    }
    let mut b = a.clone();
    for mut row in b.row_iter_mut() {
        let size = row.amax();
        if size > 0.0 {
            row /= size;
        }
    }
    for mut column in b.column_iter_mut() {
        let size = column.amax();
        if size > 0.0 {
            column /= size;
        }
    }
    b.rank(1e-8)
}

/// The worked row `residual` matches best, the factor between them, and what differs.
fn diagnose(reference: &Reference, rows: &[Row], residual: &Expr) -> String {
    let unknowns: Vec<Symbol> = reference
        .accelerations
        .iter()
        .chain(&reference.reactions)
        .cloned()
        .collect();
    let samples = &reference.samples;
    let Some(given) = parts(residual, &unknowns, reference) else {
        return "it is not linear in the second derivatives and the reactions".into();
    };
    let mut best: Option<(usize, f64, (usize, usize))> = None;
    let mut row_parts = Vec::new();
    for (r, row) in rows.iter().enumerate() {
        let Some(expected) = parts(&row.expr, &unknowns, reference) else {
            row_parts.push(None);
            continue;
        };
        let (k, score) = factor(&given, &expected);
        let better = match best {
            None => true,
            Some((_, _, s)) => (score.0, Reverse(score.1)) > (s.0, Reverse(s.1)),
        };
        if better {
            best = Some((r, k, score));
        }
        row_parts.push(Some(expected));
    }
    let Some((r, k, _)) = best else {
        return "it matches no row of the worked solution".into();
    };
    let Some(expected) = &row_parts[r] else {
        return "it matches no row of the worked solution".into();
    };
    let by = factor_of(&given, expected, k, samples);
    let scaled: Vec<Part> = expected.iter().map(|p| scale_part(p, &by, k)).collect();
    let size = scale(&given).max(scale(&scaled));
    let findings = compare(&given, &scaled, size, samples);
    let row = &rows[r];
    let times = if (k - 1.0).abs() < 1e-9 {
        String::new()
    } else {
        format!(" (multiplied by {by})")
    };
    let mut sentences: Vec<String> = Vec::new();
    for finding in findings.iter().take(3) {
        let mut text = finding.text.clone();
        let short = shortfall_of(&given, &scaled, &finding.key);
        let kind = velocity_kind(reference, &short);
        if let Some(why) = attribute(reference, row, finding, (k, kind), &unknowns, size) {
            text.push_str(": ");
            text.push_str(&why);
        }
        sentences.push(text);
    }
    if sentences.is_empty() {
        sentences.push("it differs from it at the sampled states".into());
    }
    format!(
        "compared with {}{times}: {}",
        row.label,
        sentences.join("; ")
    )
}

fn scale_part(p: &Part, by: &Expr, k: f64) -> Part {
    Part {
        key: p.key.clone(),
        expr: crate::symbolic::simplify(&(p.expr.clone() * by.clone())),
        values: p.values.iter().map(|v| v * k).collect(),
    }
}

/// The factor `k` between `given` and `expected` as the problem writes it: the ratio of
/// the first two parts that are not zero, where it holds constants alone and is `k`
/// (`-1/(R*m)` for an equation divided by m R), else `k` as a number or a fraction.
fn factor_of(given: &[Part], expected: &[Part], k: f64, samples: &[Sample]) -> Expr {
    let size = scale(given).max(scale(expected));
    let symbolic = (given.iter().zip(expected))
        .filter(|(g, e)| !is_zero(&g.values, size) && !is_zero(&e.values, size))
        .map(|(g, e)| crate::symbolic::simplify(&(g.expr.clone() / e.expr.clone())))
        .find(|ratio| {
            let value = samples.first().map(|s| eval(ratio, &s.free));
            ratio.is_constant() && value.is_some_and(|v| close(&[v], &[k], 0.0))
        });
    symbolic.unwrap_or_else(|| factor_expr(k))
}

/// The factor `k` for which most parts of `given` are `k` times those of `expected`
/// (ties: the factor nearest ±1, then the one of the first q''), with the parts that
/// agree and those that do not.
fn factor(given: &[Part], expected: &[Part]) -> (f64, (usize, usize)) {
    let size = scale(given).max(scale(expected));
    let candidates: Vec<f64> = given
        .iter()
        .zip(expected)
        .filter(|(g, e)| !is_zero(&g.values, size) && !is_zero(&e.values, size))
        .filter_map(|(g, e)| ratio(&g.values, &e.values))
        .collect();
    let mut best: (f64, (usize, usize)) = (1.0, (0, usize::MAX));
    for &k in candidates.iter().chain(std::iter::once(&1.0)) {
        let mut agree = 0;
        let mut differ = 0;
        for (g, e) in given.iter().zip(expected) {
            if is_zero(&g.values, size) && is_zero(&e.values, size) {
                continue;
            }
            let scaled: Vec<f64> = e.values.iter().map(|v| v * k).collect();
            if close(&g.values, &scaled, size) {
                agree += 1;
            } else {
                differ += 1;
            }
        }
        let better = (agree, Reverse(differ)) > (best.1 .0, Reverse(best.1 .1))
            || ((agree, differ) == best.1 && k.abs().ln().abs() < best.0.abs().ln().abs() - 1e-9);
        if better {
            best = (k, (agree, differ));
        }
    }
    best
}

/// Which contribution of the worked row the difference of `finding` is.
fn attribute(
    reference: &Reference,
    row: &Row,
    finding: &Finding,
    (k, kind): (f64, &str),
    unknowns: &[Symbol],
    size: f64,
) -> Option<String> {
    let shortfall = &finding.shortfall;
    let mut found = Vec::new();
    for c in &row.contributions {
        let parts = parts(&c.expr, unknowns, reference)?;
        let part = parts.iter().find(|p| p.key == finding.key)?;
        let values: Vec<f64> = part.values.iter().map(|v| v * k).collect();
        if !is_zero(&values, size) {
            found.push((
                c,
                label(c.kind.clone(), &c.label, &finding.key, kind),
                values,
            ));
        }
    }
    // The whole of one contribution missing, then one with its sign wrong, then one off
    // by a factor; otherwise the contributions the part is made of.
    if let Some((c, label, _)) = found.iter().find(|(_, _, v)| close(shortfall, v, size)) {
        return Some(missing(&c.kind, label, &finding.key, row.point.as_deref()));
    }
    let doubled = |v: &Vec<f64>| -> Vec<f64> { v.iter().map(|x| 2.0 * x).collect() };
    if let Some((_, label, _)) = found
        .iter()
        .find(|(_, _, v)| close(shortfall, &doubled(v), size))
    {
        return Some(format!("the sign of {label} is wrong"));
    }
    if found.len() == 1 {
        let (_, label, v) = &found[0];
        if let Some(r) = ratio(shortfall, v) {
            return Some(format!(
                "{label} is off by the factor {}",
                factor_text(1.0 - r)
            ));
        }
    }
    let labels: Vec<&str> = found.iter().map(|(_, l, _)| l.as_str()).collect();
    (!labels.is_empty()).then(|| {
        format!(
            "in the worked solution this comes from {}",
            labels.join(" and ")
        )
    })
}

fn label(kind: Kind, label: &str, key: &Key, velocity: &str) -> String {
    match (kind, key) {
        (Kind::InertiaForce(body), Key::Rates) => {
            format!("the {velocity} of {body}'s acceleration (in {label})")
        }
        // Without rates or second rates: what a motion prescribed in time adds (the bead
        // on a hoop spun at W: m R W² sin θ cos θ).
        (Kind::InertiaForce(body), Key::Free) => {
            format!("the terms of {body}'s acceleration from the prescribed motion (in {label})")
        }
        (Kind::InertiaTorque(body), Key::Free) => {
            format!("the terms of {body}'s inertia torque from the prescribed motion (in {label})")
        }
        _ => label.to_string(),
    }
}

/// The expected part `key` less the given one, as an expression.
fn shortfall_of(given: &[Part], expected: &[Part], key: &Key) -> Expr {
    let of = |parts: &[Part]| parts.iter().find(|p| p.key == *key).map(|p| p.expr.clone());
    let (g, e) = (
        of(given).unwrap_or_else(Expr::zero),
        of(expected).unwrap_or_else(Expr::zero),
    );
    crate::symbolic::simplify(&(e - g))
}

/// What terms in the rates `e` is: the square of one combination of rates (a
/// centripetal term), products of different rates only (a Coriolis term), or both.
fn velocity_kind(reference: &Reference, e: &Expr) -> &'static str {
    let rates = &reference.rates;
    let Some(sample) = reference.samples.first() else {
        return "centripetal and Coriolis terms";
    };
    let n = rates.len();
    let second = |a: &Symbol, b: &Symbol| {
        crate::symbolic::partial(e, a)
            .and_then(|d| crate::symbolic::partial(&d, b))
            .map_or(f64::NAN, |d| eval(&d, &sample.free))
    };
    let q: Vec<Vec<f64>> = rates
        .iter()
        .map(|a| rates.iter().map(|b| second(a, b)).collect())
        .collect();
    let size = q.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let diagonal = (0..n).all(|i| q[i][i].abs() <= 1e-9 * size);
    let rank_one = (0..n).all(|i| {
        (0..n).all(|j| (q[i][i] * q[j][j] - q[i][j] * q[j][i]).abs() <= 1e-9 * size * size)
    });
    match (diagonal, rank_one) {
        (true, _) => "Coriolis term",
        (false, true) => "centripetal term",
        _ => "centripetal and Coriolis terms",
    }
}

fn missing(kind: &Kind, label: &str, key: &Key, point: Option<&str>) -> String {
    match (kind, key, point) {
        (Kind::InertiaForce(body), Key::Unknown(_), Some(p)) => format!(
            "the moment of inertia of {body} about its mass centre was used where the one about {p} was expected; the parallel-axis term m d² ({label}) is missing"
        ),
        (Kind::InertiaTorque(body), Key::Unknown(_), _) => {
            format!("the inertia torque of {body} (-I* α) is missing")
        }
        _ if label.contains(" terms of ") => format!("{label} are missing"),
        _ => format!("{label} is missing"),
    }
}
