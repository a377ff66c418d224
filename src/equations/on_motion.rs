//! Rows written with the relations that hold on the motion but not identically (a gear's
//! unit line of centres has unit length wherever its distance constraint holds, see
//! [`crate::mechanics::Constraints::relations`]). The rows are evaluated
//! only there, so they give the same numbers, and read as a textbook writes them: Kane's
//! row of a disc rolling inside a ring with `(3m/2) (R − r)² ẍ/y²`, not
//! `m (1 + x²/y²) ẍ + (m/2) (R − r)² ẍ/y²`, and its Euler equation with `r F`, not
//! `r (x² + y²)/(R − r)² F`.

use crate::mechanics::Model;
use crate::plan::{unknowns_in, Equation, Groups};
use crate::symbolic::{add, simplify, Expr, Symbol};

/// `e` simplified and rewritten with `model`'s relations, if that shortens it.
fn reduced(model: &Model, e: &Expr) -> Option<Expr> {
    let relations = &model.constraints.relations;
    if relations.is_empty() {
        return None;
    }
    let simplified = simplify(e);
    let written = relations
        .iter()
        .fold(simplified.clone(), |e, (_, relation)| relation.reduce(&e));
    (written != simplified).then_some(written)
}

/// Kane's groups with the relations: `F_r` and `F_r*` each rewritten as one sum, since a
/// relation may gather terms of both of their groups (an inertia force's
/// `m (1 + x²/y²) ẍ` with an inertia torque's `(m/2) (R − r)² ẍ/y²`). A pair that no
/// relation shortens keeps its two groups.
pub(crate) fn groups(model: &Model, groups: Groups) -> Groups {
    let mut out = groups;
    if let Some(active) = reduced(model, &add([out.contact.clone(), out.distance.clone()])) {
        (out.contact, out.distance) = (active, Expr::zero());
    }
    let inertia = add([out.inertia_force.clone(), out.inertia_torque.clone()]);
    if let Some(inertia) = reduced(model, &inertia) {
        (out.inertia_force, out.inertia_torque) = (inertia, Expr::zero());
    }
    out
}

/// A row's whole expression with the relations; its groups stay as formed, so the
/// worked solution shows the relation used where the row is simplified.
pub(crate) fn row(model: &Model, row: Equation, unknowns: &[Symbol]) -> Equation {
    match reduced(model, &row.expression) {
        Some(expression) => Equation {
            unknowns: unknowns_in(&expression, unknowns),
            expression,
            ..row
        },
        None => row,
    }
}
