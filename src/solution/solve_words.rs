//! The solve of step 5's linear system said in words after its matrix form: which unknowns
//! come first (the second derivatives from the rows without reactions, then the reactions),
//! and where the constraint rows cannot give the dependent second derivatives, named from
//! the determinant of their block (a four-bar's `sin(q₁ + q₂ − q₃) = 0`: coupler and
//! rocker in line).

use crate::equations::Derivation;
use crate::mechanics::Model;
use crate::plan::Sum;
use crate::problem::BodyId;
use crate::symbolic::latex_collected;
use crate::symbolic::simplify;
use crate::symbolic::substitute;
use crate::symbolic::{latex, latex_name};
use crate::symbolic::{Expr, Func, Node, Symbol};

/// The most unknowns a block whose determinant is written may have.
const LARGEST_BLOCK: usize = 3;

/// The most characters of LaTeX a determinant is written with.
const LONGEST_DETERMINANT: usize = 300;

/// The sentences, in markup (`$…$` for mathematics); empty when there is nothing to say
/// beyond the matrix form.
pub fn notes(derivation: &Derivation) -> Vec<String> {
    let mut out = Vec::new();
    out.extend(super::kane_system::rows_are_the_system(derivation));
    if let Some(order) = order(derivation) {
        out.push(order);
    }
    if let Some(singular) = singular(derivation) {
        out.push(singular);
    }
    out
}

/// Whether an unknown is a reaction (not a second derivative).
pub(super) fn is_reaction(u: &Symbol) -> bool {
    matches!(u, Symbol::Unknown(_))
}

/// `(1), (2) and (4)`.
pub(super) fn row_list(rows: &[usize]) -> String {
    let names: Vec<String> = rows.iter().map(|i| format!("({})", i + 1)).collect();
    match names.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// `$\ddot{q}_{1}$, $\ddot{q}_{2}$`.
fn unknown_list(unknowns: &[&Symbol]) -> String {
    let items: Vec<String> = unknowns
        .iter()
        .map(|u| format!("${}$", latex(&Expr::sym((*u).clone()))))
        .collect();
    match items.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// What is solved first: the rows without a reaction give the second derivatives when they
/// are as many; the other rows then give the reactions.
pub(super) fn order(derivation: &Derivation) -> Option<String> {
    let system = &derivation.system;
    let reactions: Vec<usize> = (0..system.unknowns.len())
        .filter(|&j| is_reaction(&system.unknowns[j]))
        .collect();
    if reactions.is_empty() {
        return None;
    }
    let accelerations: Vec<&Symbol> = system.unknowns.iter().filter(|u| !is_reaction(u)).collect();
    let free: Vec<usize> = (0..system.a.len())
        .filter(|&i| reactions.iter().all(|&j| system.a[i][j].is_zero()))
        .collect();
    if free.len() != accelerations.len() || free.is_empty() {
        return None;
    }
    let rest: Vec<usize> = (0..system.a.len()).filter(|i| !free.contains(i)).collect();
    let forces: Vec<&Symbol> = reactions.iter().map(|&j| &system.unknowns[j]).collect();
    let (rows, contain, give) = match free.len() {
        1 => ("Row", "contains", "gives"),
        _ => ("Rows", "contain", "give"),
    };
    let (then, then_give) = match rest.len() {
        1 => ("row", "gives"),
        _ => ("rows", "give"),
    };
    Some(format!(
        "{rows} {} {contain} no reaction and {give} {}; {then} {} then {then_give} {}.",
        row_list(&free),
        unknown_list(&accelerations),
        row_list(&rest),
        unknown_list(&forces),
    ))
}

/// The determinant of a square block of at most three rows, by cofactors.
fn determinant(block: &[Vec<Expr>]) -> Option<Expr> {
    let e = |i: usize, j: usize| block[i][j].clone();
    Some(match block.len() {
        1 => e(0, 0),
        2 => e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0),
        3 => {
            e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1))
                - e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0))
                + e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0))
        }
        _ => return None,
    })
}

/// The constraint rows of step 5 (by index), the columns of the dependent second
/// derivatives, and the determinant of that block, simplified; `None` where there are no
/// constraint rows, they are not as many as the dependent rates, or more than three.
pub fn constraint_block(derivation: &Derivation) -> Option<(Vec<usize>, Vec<usize>, Expr)> {
    let model = &derivation.model;
    let system = &derivation.system;
    let problem = model.problem;
    let rows: Vec<usize> = (0..derivation.rows.len())
        .filter(|&i| matches!(derivation.rows[i].sum, Sum::Constraint { .. }))
        .collect();
    let dependent: Vec<usize> = model.constraints.dependent_rates.clone();
    if rows.is_empty() || rows.len() != dependent.len() || rows.len() > LARGEST_BLOCK {
        return None;
    }
    let columns: Vec<usize> = dependent
        .iter()
        .map(|&c| {
            let symbol = problem.coordinate_symbol(c, 2);
            system.unknowns.iter().position(|u| *u == symbol)
        })
        .collect::<Option<_>>()?;
    let block: Vec<Vec<Expr>> = rows
        .iter()
        .map(|&i| columns.iter().map(|&j| system.a[i][j].clone()).collect())
        .collect();
    let det = simplify(&determinant(&block)?);
    Some((rows, columns, det))
}

/// The constraint rows' block in the dependent second derivatives, its determinant, and
/// the configuration where it vanishes.
fn singular(derivation: &Derivation) -> Option<String> {
    let model = &derivation.model;
    let system = &derivation.system;
    let problem = model.problem;
    let (rows, columns, det) = constraint_block(derivation)?;
    if det.is_zero() {
        return None;
    }
    // Its factors of constants alone (a radius, r/(R − r)) never vanish: the condition is
    // on the factors that move, `y ≠ 0`, not `r y/(R − r) ≠ 0`.
    let moving = crate::symbolic::mul(det.factors().iter().filter(|f| !f.is_constant()).cloned());
    let det_tex = latex_collected(&moving);
    if det_tex.len() > LONGEST_DETERMINANT {
        return None;
    }
    let names: Vec<&Symbol> = columns.iter().map(|&j| &system.unknowns[j]).collect();
    // A determinant of constants alone (a pitch radius) vanishes in no configuration: a
    // student needs no word of it.
    if det.is_constant() {
        return None;
    }
    let head = format!(
        "{} {} wherever ${det_tex} \\neq 0$.",
        rows_give(&rows),
        unknown_list(&names),
    );
    let factors = det.factors();
    let vanishing: Vec<&Expr> = factors
        .iter()
        .filter(|f| matches!(f.node(), Node::Func(Func::Sin | Func::Cos, _)))
        .collect();
    let Some(factor) = vanishing.first() else {
        return Some(head);
    };
    let line = in_line(model, factor)
        .map(|(i, j)| {
            format!(
                ", the bodies ${}$ and ${}$ in line",
                latex_name(problem.body_name(i)),
                latex_name(problem.body_name(j))
            )
        })
        .unwrap_or_default();
    // Bodies in line are a singular configuration of the mechanism itself; any other zero
    // may be the chosen coordinates' failing alone.
    let what = match line.is_empty() {
        true => "there the constraints no longer fix the dependent rates from the independent ones",
        false => {
            "a singular configuration, where the constraints no longer fix the dependent rates"
        }
    };
    Some(format!(
        "{head} This fails where ${} = 0${line}: {what}.",
        latex(factor)
    ))
}

/// "Rows (4) and (5) give", or "Row (3) gives" for one.
fn rows_give(rows: &[usize]) -> String {
    match rows.len() {
        1 => format!("Row {} gives", row_list(rows)),
        _ => format!("Rows {} give", row_list(rows)),
    }
}

/// The absolute angle of a planar body, from its angular velocity with the rates replaced
/// by their coordinates.
fn angle(model: &Model, body: BodyId) -> Expr {
    let omega = model.bodies[body.0]
        .omega
        .components_in(BodyId::GROUND, &model.frames)[2]
        .clone();
    simplify(&substitute(&omega, &|s| match s {
        Symbol::Coord(name, 1) => Some(Expr::sym(Symbol::Coord(name.clone(), 0))),
        _ => None,
    }))
}

/// The two bodies whose angles differ by the argument of `sin(x)` (in line when it
/// vanishes); none for another factor or in space.
fn in_line(model: &Model, factor: &Expr) -> Option<(BodyId, BodyId)> {
    let Node::Func(Func::Sin, args) = factor.node() else {
        return None;
    };
    if !model.is_planar() {
        return None;
    }
    let x = args.first()?;
    let bodies: Vec<BodyId> = model.order.clone();
    for (k, &i) in bodies.iter().enumerate() {
        for &j in &bodies[k + 1..] {
            let difference = angle(model, i) - angle(model, j);
            let same = simplify(&(x - &difference)).is_zero();
            let opposite = simplify(&(x + &difference)).is_zero();
            if same || opposite {
                return Some((i, j));
            }
        }
    }
    None
}
