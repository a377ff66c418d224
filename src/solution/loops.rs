//! A closure's rows as a textbook writes them: first the vector loop — the two material
//! points at the closure have the same acceleration, each written down its own chain of
//! pins (a^{R_B} = a^P + α^B × r^{PR} − ω_B² r^{PR}) — then its component along each of the
//! closure's reaction directions, one row each.

use super::tex::vector_tex;
use crate::equations::Derivation;
use crate::mechanics::RowOrigin;
use crate::plan::{Equation, Sum};
use crate::render::context::Equation as EquationView;
use crate::render::text::Math;
use crate::symbolic::latex_name_of;

/// What the note says where a row is the loop's component.
const COMPONENT: &str = "The loop's component along this row's direction, simplified:";

/// The acceleration loop of a closure's force row, `a^{R_C} = a^{R_B}` with both sides
/// written out; `None` for any other row.
pub(super) fn closure_loop_tex(derivation: &Derivation, row: &Equation) -> Option<String> {
    let Sum::Constraint { name } = &row.sum else {
        return None;
    };
    let model = &derivation.model;
    let constraint = model.constraints.rows.iter().find(|r| &r.name == name)?;
    let RowOrigin::Site { site, .. } = constraint.origin else {
        return None;
    };
    let site = &model.sites[site];
    // Only a row written as the loop's component (see `ConstraintRow::loop_acceleration`).
    constraint.loop_acceleration.as_ref()?;
    let on_child = &site.point.acceleration;
    let on_parent = model
        .point_on(site.parent, &site.parent_offset)
        .acceleration;
    let side = |body| {
        format!(
            "{{}}^{{N}}\\mathbf{{a}}^{{{}}}",
            latex_name_of(&site.name, model.problem.body_name(body))
        )
    };
    Some(format!(
        "{} = {}\\colon\\; {} = {}",
        side(site.child),
        side(site.parent),
        vector_tex(model, on_child),
        vector_tex(model, &on_parent)
    ))
}

/// The note under a row written from its loop.
pub(super) fn component_note() -> String {
    COMPONENT.to_string()
}

/// A loop written once: a later row of the same closure refers to the first.
pub(super) fn refer_to_repeated_loops(views: &mut [EquationView]) {
    let mut seen: Vec<(Math, usize)> = Vec::new();
    for (i, view) in views.iter_mut().enumerate() {
        if view.simplified_note != COMPONENT || view.grouped_tex.is_empty() {
            continue;
        }
        match seen.iter().find(|(tex, _)| *tex == view.grouped_tex) {
            Some((_, first)) => {
                view.grouped_tex.clear();
                view.simplified_note =
                    format!("The loop of row {first}, along this row's direction, simplified:");
            }
            None => seen.push((view.grouped_tex.clone(), i + 1)),
        }
    }
}
