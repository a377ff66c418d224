//! The equations brought to rest for the statics handout: every rate and second derivative
//! zero in the rows, which free coordinates the rows find, and the Motion Law's rows
//! planned again for the unknowns of statics.
//!
//! In dynamics the Motion Law chooses its moment points so that the reactions not asked
//! for drop out of rows whose unknowns are the q'' and the reactions. At rest the q'' are
//! zero: the unknowns are the reactions and holding forces, and the equilibrium value of
//! each free coordinate that is not given. The planner then picks what a statics course
//! picks, the ladder's moments about its foot, where the floor's two components meet, and
//! a four-bar's links about their pins.

use crate::equations::{Derivation, LinearSystem, Method};
use crate::mechanics::reaction_unknowns;
use crate::plan::{candidates, choose};
use crate::symbolic::{linear_split, substitute, Expr, Symbol};

/// `e` at rest: every rate and second derivative zero.
fn at_rest(e: &Expr) -> Expr {
    let rest = |s: &Symbol| match s {
        Symbol::Coord(_, order) if *order > 0 => Some(Expr::zero()),
        Symbol::Speed(..) => Some(Expr::zero()),
        _ => None,
    };
    substitute(e, &rest)
}

/// Whether `e` vanishes at rest (a constraint differentiated in time, an inertia term).
fn is_zero_at_rest(e: &Expr) -> bool {
    crate::symbolic::simplify(&at_rest(e)).is_zero()
}

/// The rows of `derivation` at rest: every rate and second derivative zero, so that no
/// inertia force or torque is left in them. Among a row's unknowns the q'' of a coordinate
/// `found` gives way to the coordinate itself (its equilibrium value is what the row
/// finds), and the other q'' go. Returns, row by row, whether it is then identically zero,
/// which says nothing at rest: the handout leaves those out (the rows stay, numbered as the
/// system's).
pub(super) fn rows(derivation: &mut Derivation, found: &[usize]) -> Vec<bool> {
    let problem = derivation.model.problem;
    let found: Vec<Symbol> = found
        .iter()
        .map(|&i| problem.coordinate_symbol(i, 2))
        .collect();
    let rows = std::mem::take(&mut derivation.rows);
    derivation.rows = rows
        .into_iter()
        .map(|row| row.map_expressions(at_rest))
        .map(|mut row| {
            let mut unknowns = Vec::new();
            for u in &row.unknowns {
                let u = match u {
                    Symbol::Coord(name, 2) if found.contains(u) => Symbol::Coord(name.clone(), 0),
                    Symbol::Coord(..) | Symbol::Speed(..) => continue,
                    other => other.clone(),
                };
                // A row at rest may have lost it with the inertia terms.
                if !row.expression.contains(&u) {
                    continue;
                }
                if !unknowns.contains(&u) {
                    unknowns.push(u);
                }
            }
            row.unknowns = unknowns;
            row
        })
        .collect();
    derivation
        .rows
        .iter()
        .map(|row| crate::symbolic::simplify(&row.expression).is_zero())
        .collect()
}

/// The free coordinates whose equilibrium value the equations find: as many as the rows
/// that do not vanish at rest outnumber the other unknowns (none where friction or the
/// constraints fix the configuration given, as a ladder's sticking foot does).
pub(super) fn to_find(derivation: &Derivation, free: &[usize]) -> Vec<usize> {
    let rows = (derivation.rows.iter())
        .filter(|row| !is_zero_at_rest(&row.expression))
        .count();
    let others = (derivation.system.unknowns.iter())
        .filter(|u| !matches!(u, Symbol::Coord(..) | Symbol::Speed(..)))
        .count();
    let k = rows.saturating_sub(others).min(free.len());
    free[..k].to_vec()
}

/// The Motion Law's rows planned for the unknowns at rest (the reactions and holding forces
/// of the system, and the q'' of the coordinates `found`, which stand for the equilibrium
/// equations the rows give), at the state `q`, `rates`; the system is rebuilt from them so
/// that its rows are the plan's. Left as derived when no plan is found, or for the other
/// methods, which have no moment points to choose.
pub(super) fn replan(derivation: &mut Derivation, q: &[f64], rates: &[f64], found: &[usize]) {
    if derivation.method != Method::MotionLaw {
        return;
    }
    let problem = derivation.model.problem;
    let wanted: Vec<Symbol> = found
        .iter()
        .map(|&i| problem.coordinate_symbol(i, 2))
        .chain(
            (derivation.system.unknowns.iter())
                .filter(|u| !matches!(u, Symbol::Coord(..) | Symbol::Speed(..)))
                .cloned(),
        )
        .collect();
    let model = &derivation.model;
    let sites: Vec<usize> = (0..model.sites.len())
        .filter(|&j| !model.sites[j].reactions.is_empty())
        .collect();
    let reactions = reaction_unknowns(model, &sites);
    let candidates = candidates(model, &derivation.actions, &reactions);
    let required = vec![model.values_at(0.0, q, rates)];
    let choice = choose(
        model,
        &derivation.actions,
        derivation.inertia(),
        candidates,
        &wanted,
        &[],
        &required,
    );
    if choice.rows.len() != wanted.len() {
        return;
    }
    let Some(system) = system_of(&choice.rows, &wanted) else {
        return;
    };
    derivation.rows = choice.rows;
    derivation.rejected = choice.rejected;
    derivation.system = system;
}

/// `A x = b` of `rows` in `unknowns`, or `None` for a row not linear in them.
fn system_of(rows: &[crate::plan::Equation], unknowns: &[Symbol]) -> Option<LinearSystem> {
    let mut a = Vec::new();
    let mut b = Vec::new();
    for row in rows {
        let (coefficients, rest) = linear_split(&row.expression, unknowns).ok()?;
        a.push(coefficients);
        b.push(-rest);
    }
    Some(LinearSystem {
        unknowns: unknowns.to_vec(),
        a,
        b,
    })
}
