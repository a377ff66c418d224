//! Which coordinates the position constraints solve for, and which rates the velocity
//! constraints solve for: those the problem marks, then the rest by pivoting on the
//! constraint Jacobian at the initial configuration (the largest pivot first, as Gaussian
//! elimination with complete pivoting picks them).

use super::constraint_rows::{Constraints, RowOrigin};
use super::error::MechanicsError;
use super::model::Model;
use crate::symbolic::{eval, linear_split, Symbol, Values};

/// A pivot smaller than this (relative to the row's largest entry) counts as zero.
const PIVOT_TOLERANCE: f64 = 1e-9;

/// Fills `dependent`, `dependent_rates` and `notes` of `constraints`.
///
/// # Errors
/// More coordinates (or rates) marked than there are constraints to solve them from, or a
/// marked set whose block of the Jacobian is singular at the initial configuration.
pub fn choose(
    model: &Model,
    constraints: &mut Constraints,
    values: &Values,
) -> Result<(), MechanicsError> {
    let problem = model.problem;
    let n = problem.coordinates.len();
    let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
    let rows: Vec<(bool, Vec<f64>)> = constraints
        .rows
        .iter()
        .filter(|r| !matches!(r.origin, RowOrigin::Prescribed(_)))
        .map(|r| {
            let coefficients = linear_split(&r.velocity, &rates)
                .map(|(c, _)| c.iter().map(|e| eval(e, values)).collect())
                .unwrap_or_else(|_| vec![f64::NAN; n]);
            (r.position.is_some(), coefficients)
        })
        .collect();
    let free: Vec<usize> = (0..n)
        .filter(|&i| problem.coordinates[i].motion.is_none())
        .collect();
    let names = |list: &[usize]| -> String {
        list.iter()
            .map(|&i| format!("`{}`", problem.coordinates[i].name))
            .collect::<Vec<_>>()
            .join(", ")
    };

    let holonomic: Vec<Vec<f64>> = rows.iter().filter(|r| r.0).map(|r| r.1.clone()).collect();
    let marked: Vec<usize> = free
        .iter()
        .copied()
        .filter(|&i| problem.coordinates[i].dependent)
        .collect();
    let dependent = pick(&holonomic, &marked, &free, &vec![1.0; n]).map_err(|why| MechanicsError {
        path: "coordinates".into(),
        message: format!("the coordinates marked dependent, {}, {why}", names(&marked)),
        hint: Some(format!(
            "the problem has {} independent position constraints; mark at most that many coordinates whose constraint Jacobian columns are independent, or mark none and let the tool choose",
            holonomic.len()
        )),
    })?;
    let all: Vec<Vec<f64>> = rows.iter().map(|r| r.1.clone()).collect();
    let mut marked_rates = dependent.clone();
    marked_rates.extend(
        free.iter()
            .copied()
            .filter(|&i| problem.coordinates[i].dependent_rate && !dependent.contains(&i)),
    );
    // A rate the problem sets is one the user means to give: prefer the others.
    let preference: Vec<f64> = problem
        .coordinates
        .iter()
        .map(|c| if c.rate != 0.0 { 1e-3 } else { 1.0 })
        .collect();
    let dependent_rates =
        pick(&all, &marked_rates, &free, &preference).map_err(|why| MechanicsError {
            path: "coordinates".into(),
            message: format!(
                "the coordinates whose rates are dependent, {}, {why}",
                names(&marked_rates)
            ),
            hint: Some(rate_hint(all.len(), constraints)),
        })?;
    if !dependent.is_empty() {
        let chosen: Vec<usize> = dependent
            .iter()
            .copied()
            .filter(|i| !marked.contains(i))
            .collect();
        let mut note = format!(
            "Dependent coordinates (solved from {}): {}",
            position_constraints(holonomic.len()),
            names(&dependent)
        );
        if !chosen.is_empty() {
            note.push_str(", which the constraints fix once the other coordinates are given");
        }
        constraints.notes.push(note + ".");
    }
    constraints
        .notes
        .extend(rates_note(model, &dependent, &dependent_rates));
    constraints.dependent = dependent;
    constraints.dependent_rates = dependent_rates;
    Ok(())
}

/// The note of step 1 on the dependent rates beyond the dependent coordinates' (with the
/// `rate`s given for them and ignored); empty where there are none.
fn rates_note(model: &Model, dependent: &[usize], dependent_rates: &[usize]) -> Vec<String> {
    let problem = model.problem;
    let names = |list: &[usize]| -> String {
        list.iter()
            .map(|&i| format!("`{}`", problem.coordinates[i].name))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut notes = Vec::new();
    let rate_only: Vec<usize> = dependent_rates
        .iter()
        .copied()
        .filter(|i| !dependent.contains(i))
        .collect();
    if rate_only.is_empty() {
        return notes;
    }
    let chosen: Vec<usize> = rate_only
        .iter()
        .copied()
        .filter(|&i| !problem.coordinates[i].dependent_rate)
        .collect();
    let ignored: Vec<usize> = rate_only
        .iter()
        .copied()
        .filter(|&i| problem.coordinates[i].rate != 0.0)
        .collect();
    if !ignored.is_empty() {
        notes.push(format!(
            "The `rate` given for {} is ignored: it is solved from the velocity constraints.",
            names(&ignored)
        ));
    }
    // Every dependent rate: a dependent coordinate's rate is one too (a disc's height
    // on a cart, ḣ = 0), beside the rates only the velocity constraints fix.
    // The rate of a dependent coordinate comes from its position constraint
    // differentiated in time, not from a velocity constraint: said apart.
    let rates = |of: &[usize]| {
        let mut listed = of.to_vec();
        listed.sort_unstable();
        (listed.iter())
            .map(|&i| format!("`{}'`", problem.coordinates[i].name))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let of_positions: Vec<usize> = (dependent_rates.iter().copied())
        .filter(|i| dependent.contains(i))
        .collect();
    let mut note = if of_positions.is_empty() {
        format!(
            "Dependent rates (solved from the velocity constraints): {}",
            rates(&rate_only)
        )
    } else {
        format!(
            "Dependent rates: {} (the position constraints differentiated in time) and {} \
             (solved from the velocity constraints)",
            rates(&of_positions),
            rates(&rate_only)
        )
    };
    if !chosen.is_empty() {
        note.push_str(", which those constraints fix once the other rates are given");
    }
    notes.push(note + ".");
    notes
}

/// Gaussian elimination on `rows` (one per constraint, one column per coordinate): the
/// `marked` columns first, in order, then the best pivots among `allowed`, each pivot's
/// size weighed by `preference` (1 for no preference).
///
/// # Errors
/// More marked columns than rows, or marked columns whose block is singular.
pub fn pick(
    rows: &[Vec<f64>],
    marked: &[usize],
    allowed: &[usize],
    preference: &[f64],
) -> Result<Vec<usize>, String> {
    if marked.len() > rows.len() {
        return Err(format!(
            "are {} but there are only {} constraints to solve them from",
            marked.len(),
            rows.len()
        ));
    }
    let mut m: Vec<Vec<f64>> = rows.to_vec();
    let mut used_rows = vec![false; m.len()];
    let mut chosen = Vec::new();
    let scale = m
        .iter()
        .flatten()
        .fold(0.0f64, |a, x| a.max(x.abs()))
        .max(f64::MIN_POSITIVE);
    let eliminate = |m: &mut Vec<Vec<f64>>, r: usize, c: usize| {
        let pivot = m[r][c];
        for k in 0..m.len() {
            if k != r {
                let f = m[k][c] / pivot;
                if f != 0.0 {
                    let row_r = m[r].clone();
                    m[k].iter_mut().zip(&row_r).for_each(|(x, y)| *x -= f * y);
                }
            }
        }
    };
    for &c in marked {
        let best = (0..m.len())
            .filter(|&r| !used_rows[r])
            .max_by(|&a, &b| m[a][c].abs().total_cmp(&m[b][c].abs()));
        match best {
            Some(r) if m[r][c].abs() > PIVOT_TOLERANCE * scale => {
                eliminate(&mut m, r, c);
                used_rows[r] = true;
                chosen.push(c);
            }
            _ => {
                return Err(
                    "have a singular block of the constraint Jacobian at the initial configuration: the constraints cannot determine them"
                        .into(),
                )
            }
        }
    }
    while chosen.len() < m.len() {
        let mut best: Option<(usize, usize, f64)> = None;
        for r in (0..m.len()).filter(|&r| !used_rows[r]) {
            for &c in allowed.iter().filter(|c| !chosen.contains(c)) {
                let v = m[r][c].abs();
                if v > PIVOT_TOLERANCE * scale && best.is_none_or(|(_, _, b)| v * preference[c] > b)
                {
                    best = Some((r, c, v * preference[c]));
                }
            }
        }
        match best {
            Some((r, c, _)) => {
                eliminate(&mut m, r, c);
                used_rows[r] = true;
                chosen.push(c);
            }
            _ => break,
        }
    }
    Ok(chosen)
}

/// The hint for too many rates marked dependent, with a clause for rough sites, whose
/// no-slip rows hold only while they stick and so make no rate dependent.
fn rate_hint(rows: usize, constraints: &Constraints) -> String {
    let mut hint = format!(
        "the problem has {rows} independent velocity constraints; mark at most that many `dependent_rate` coordinates, or mark none and let the tool choose"
    );
    if !constraints.friction.is_empty() {
        hint.push_str(&rough_sites(constraints));
    }
    hint
}

/// The clause of [`rate_hint`] for the rough sites.
fn rough_sites(constraints: &Constraints) -> String {
    let sites: Vec<String> = (constraints.friction.iter())
        .map(|f| format!("`{}`", f.name))
        .collect();
    let (has, sticks) = match sites.len() {
        1 => ("has", "it sticks"),
        _ => ("have", "they stick"),
    };
    format!(
        " (the no-slip rows of {}, which {has} friction, hold only while {sticks}, so they make no rate dependent: leave those rates independent)",
        sites.join(", ")
    )
}

/// `n` position constraints counted as a sentence counts them: "the position constraint",
/// "the 3 position constraints".
fn position_constraints(n: usize) -> String {
    match n {
        1 => "the position constraint".to_string(),
        n => format!("the {n} position constraints"),
    }
}
