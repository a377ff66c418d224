//! Terms a position constraint makes zero, dropped from the simplified rows: where a
//! constraint fixes one coordinate to a constant (a disc's height h − R = 0 on a cart),
//! the simplified row is written with that value (h = R), so that (h − R) F_x, zero on
//! every motion the constraints allow, is not left in it.

use crate::mechanics::Model;
use crate::symbolic::{linear_split, simplify, substitute, Expr, Symbol};

/// Each coordinate a position constraint holds at a constant, with that constant.
pub fn held_coordinates(model: &Model) -> Vec<(Symbol, Expr)> {
    let problem = model.problem;
    let coordinates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 0))
        .collect();
    let mut held = Vec::new();
    for row in &model.constraints.rows {
        let Some(position) = &row.position else {
            continue;
        };
        let Ok((coefficients, rest)) = linear_split(position, &coordinates) else {
            continue;
        };
        let present: Vec<usize> = (0..coordinates.len())
            .filter(|&i| !coefficients[i].is_zero())
            .collect();
        let [one] = present[..] else {
            continue;
        };
        let moves = |e: &Expr| e.any_symbol(&|s| matches!(s, Symbol::Coord(..) | Symbol::Time));
        let c = &coefficients[one];
        if moves(c) || moves(&rest) || c.as_number().is_none() {
            continue;
        }
        held.push((coordinates[one].clone(), simplify(&(-(&rest / c)))));
    }
    held
}

/// `e` with each held coordinate replaced by its constant, when that is shorter.
pub fn on_the_constraints(e: &Expr, held: &[(Symbol, Expr)]) -> Expr {
    if held.is_empty() || !held.iter().any(|(s, _)| e.contains(s)) {
        return e.clone();
    }
    let replaced = simplify(&substitute(e, &|s| {
        held.iter().find(|(h, _)| h == s).map(|(_, v)| v.clone())
    }));
    match replaced.operation_count() < e.operation_count() {
        true => replaced,
        false => e.clone(),
    }
}
