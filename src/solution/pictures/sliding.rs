//! Sliding friction in a free body: a known force, drawn the way it acts. At the drawn
//! state a friction site that slips pushes against the slip, μ times the normal force, so
//! its arrow points against the slip velocity, not along the unknown's positive sense as a
//! sticking site's component is. Its label says both what it is and which unknown of the
//! rows it stands for: `−F^P_x = μ F^P_y` where it points along `−n̂_x`.

use super::numbers::{scale, Numbers, P3};
use crate::mechanics::{Model, ReactionComponent};
use crate::render::draw::Label;
use crate::symbolic::{latex, Expr};

/// A slip speed below this (m/s) is sticking: the friction is an unknown of the plan.
const STILL: f64 = 1e-9;

/// For component `c` of site `site`'s reaction, when it is the friction along a tangent of
/// a site that slips at the drawn state: its direction on the child (against the slip)
/// and its label, `-F^{lane}_{x} = μ F^{lane}_{y}`: the rows' unknown, signed as the arrow
/// points, equal to μ times the normal component.
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
    let normal = friction
        .normal
        .first()
        .map(|n| latex(&Expr::sym(n.clone())))
        .unwrap_or_else(|| "N".into());
    // The arrow points along the unknown's axis times −sign(slip): the unknown, so signed,
    // is the arrow's (positive) size.
    let unknown = latex(&Expr::sym(row.unknown.clone()));
    let sign = if slip > 0.0 { "-" } else { "" };
    let tex = format!(
        "{sign}{unknown} = {} {normal}",
        latex(&friction.coefficient)
    );
    Some((direction, Label::from_tex(&tex)))
}
