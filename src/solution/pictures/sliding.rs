//! Sliding friction in a free body: an unknown of the rows, as the plan and the table of
//! forces have it, with the sliding law its row. At the drawn state a friction site that
//! slips pushes against the slip, so its arrow points against the slip velocity, not along
//! the unknown's positive sense as a sticking site's component is, and its label is the
//! unknown signed as the arrow points: `−F^P_x` where it points along `−n̂_x`.

use super::numbers::{scale, Numbers, P3};
use crate::mechanics::{Model, ReactionComponent};
use crate::render::draw::Label;
use crate::symbolic::{latex, Expr};

/// A slip speed below this (m/s) is sticking: the friction is an unknown of the plan.
const STILL: f64 = 1e-9;

/// For component `c` of site `site`'s reaction, when it is the friction along a tangent of
/// a site that slips at the drawn state: its direction on the child (against the slip)
/// and its label, `-F^{lane}_{x}`: the rows' unknown, signed as the arrow points.
pub fn sliding(
    model: &Model,
    numbers: &Numbers,
    site: usize,
    c: &ReactionComponent,
) -> Option<(P3, Label)> {
    let name = &model.sites[site].name;
    let friction = (model.constraints.friction.iter()).find(|f| f.site == site)?;
    let row = (friction.stick.iter()).find(|r| r.unknown == c.unknown(name))?;
    // The row's velocity is the slip velocity of the child's point along the component.
    let slip = numbers.scalar(&row.velocity);
    if !slip.is_finite() || slip.abs() <= STILL {
        return None;
    }
    let direction = scale(numbers.vector(&c.direction), -slip.signum());
    // The arrow points along the unknown's axis times −sign(slip): the unknown, so signed,
    // is the arrow's (positive) size.
    let unknown = latex(&Expr::sym(row.unknown.clone()));
    let sign = if slip > 0.0 { "-" } else { "" };
    Some((direction, Label::from_tex(&format!("{sign}{unknown}"))))
}
