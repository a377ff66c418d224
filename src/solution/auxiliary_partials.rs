//! Kane's auxiliary speeds of the forces that enforce constraints, with independent speeds
//! (Kane and Levinson, ch. 4): the speed `u_r` lets the one constraint its force enforces
//! give way, every other constraint kept, so the dependent rates move by the column of
//! `A_D⁻¹` of that constraint. Its partial velocities and partial angular velocities are
//! shown in the table with the independent speeds', and its `F̃*_r` is formed body by body
//! with them, as the independent speeds' are.

use super::partial_rows::{body_rows, site_partial, BodyPartials};
use crate::equations::Derivation;
use crate::mechanics::{DependentSpeeds, RowOrigin};
use crate::plan::Sum;
use crate::render::context::PartialVelocity;
use crate::render::text::Math;
use crate::symbolic::{latex, Expr, Symbol};

/// What Kane's row `r` (1-based) of an auxiliary speed moves: the weights on the
/// coordinates' rates of the motion that breaks its constraint by a unit, and the
/// constraint's row (index into the model's constraint rows). `None` for a row of an
/// independent speed, of a drive, of a joint of the tree, or where the dependent rates are
/// evaluated at each state.
pub fn weights(derivation: &Derivation, r: usize) -> Option<(Vec<Expr>, usize)> {
    let speeds = derivation
        .dependent_speeds
        .as_ref()
        .filter(|s| !s.at_each_state)?;
    if r <= speeds.independent.len() {
        return None;
    }
    let model = &derivation.model;
    let row = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .nth(r - 1)?;
    let k = row.unknowns.iter().find_map(|u| speeds.row_of(model, u))?;
    let n = model.problem.coordinates.len();
    Some((speeds.violation_weights(k, n), speeds.rows[k]))
}

/// The table's lines of every auxiliary speed of a constraint force: each body that moves
/// with it, then the point where the force acts, relative to the body that exerts it.
pub fn table_rows(
    derivation: &Derivation,
    speeds: &DependentSpeeds,
    per_body: &[BodyPartials],
    rates: &[Symbol],
) -> Vec<PartialVelocity> {
    let model = &derivation.model;
    let rows = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .count();
    let mut out = Vec::new();
    for r in (speeds.independent.len() + 1)..=rows {
        let Some((weights, k)) = weights(derivation, r) else {
            continue;
        };
        let force = latex(&Expr::sym(model.constraints.rows[k].unknown.clone()));
        let speed = format!("u_{{{r}}} \\to {force}");
        let mut lines = body_rows(derivation, per_body, &weights, r - 1, speed.clone());
        if let RowOrigin::Site { site, .. } = model.constraints.rows[k].origin {
            let of_site = (model.constraints.rows.iter())
                .filter(|c| matches!(c.origin, RowOrigin::Site { site: s, .. } if s == site));
            let point = site_partial(model, site, of_site, rates, &weights, r - 1);
            if let Some(mut point) = point.filter(|p| !said_by_body(model, site, &lines, p)) {
                if lines.is_empty() {
                    point.speed_tex = Math::from(speed);
                }
                lines.push(point);
            }
        }
        out.extend(lines);
    }
    out
}

/// Whether the body's line already says the contact point's partial velocity: the body
/// moves without turning, as fast as the point, and what it touches does not move (the
/// coin lifted straight up: ṽ^{D*} = n̂_z, so ṽ^P = n̂_z too).
fn said_by_body(
    model: &crate::mechanics::Model,
    site: usize,
    lines: &[PartialVelocity],
    point: &PartialVelocity,
) -> bool {
    let value = |tex: &str| tex.rsplit(" = ").next().unwrap_or_default().to_string();
    let site = &model.sites[site];
    let parent = model.problem.body_name(site.parent);
    let parent_moves = lines.iter().any(|l| l.body == parent);
    let body_says = lines.iter().any(|l| {
        l.body == point.body
            && l.omega_tex.as_str().ends_with("= \\mathbf{0}")
            && value(l.velocity_tex.as_str()) == value(point.velocity_tex.as_str())
    });
    body_says && !parent_moves
}

/// Whether some auxiliary speed of a constraint force has lines in the table.
pub fn any(derivation: &Derivation) -> bool {
    let rows = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .count();
    (1..=rows).any(|r| weights(derivation, r).is_some())
}
