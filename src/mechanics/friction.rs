//! Coulomb friction in the model: the `contact` entry's site, and the sites where friction
//! acts (a `rolling`, `gear` or `contact` with `friction`, a rough `prismatic` joint or
//! closure).
//!
//! A friction site keeps its tangential reaction components as unknowns (the friction
//! force) and its normal one (N). Its no-slip rows are not constraints of the motion: the
//! rates they would tie stay independent, since the site may slip. They are kept apart as
//! the rows that hold while it sticks (or rolls); the numbers then choose, state by state,
//! between them and the sliding law `F = μ|N|` against the slip (see
//! [`crate::numeric::friction`]).

pub use super::constraint_rows::FrictionSite;
use super::constraint_rows::{ConstraintRow, RowOrigin};
use super::error::MechanicsError;
use super::model::Model;
use super::site::{Contact, Site};
use super::sites::{
    contact_reactions, contact_site_of, from_origin_of, offset_on, tangents_of, unit_direction,
};
use super::vector::Vector;
use crate::problem::{ConstraintKind, Dimension};
use crate::symbolic::Expr;

/// The site of `contact` entry `k`: the point of the body on the plane, with its normal
/// reaction, and its tangential ones when it has friction.
///
/// # Errors
/// A zero normal.
pub fn contact_point_site(model: &Model, k: usize) -> Result<(Site, Contact), MechanicsError> {
    let problem = model.problem;
    let constraint = &problem.constraints[k];
    let ConstraintKind::Contact {
        body,
        point,
        on,
        normal,
        offset,
    } = &constraint.kind
    else {
        return Err(MechanicsError {
            path: constraint.path.clone(),
            message: "not a contact".into(),
            hint: None,
        });
    };
    let frames = &model.frames;
    let (body, on) = (*body, *on);
    let n_in_on = unit_direction(model, normal, on, || MechanicsError {
        path: format!("{}.normal", constraint.path),
        message: "the normal is zero".into(),
        hint: Some("give a nonzero direction, e.g. \"N.y\"".into()),
    })?;
    let n_vec = Vector::new(on, n_in_on.clone());
    let offset_c = offset_on(model, point, body);
    let point_position = from_origin_of(model, on, model.position_on(body, &offset_c));
    let height = &point_position.dot(&n_vec, frames) - offset;
    let planar = problem.dimension == Dimension::Two;
    let tangents = tangents_of(&n_in_on, planar, model, on);
    // Without friction the contact holds along its normal only.
    let slides = if constraint.friction.is_some() {
        &tangents[..]
    } else {
        &[]
    };
    let reactions = contact_reactions(slides, &n_vec);
    let contact = Contact {
        offset: offset_c,
        height,
        tilt: Expr::one(),
        on_motion: None,
    };
    Ok(contact_site_of(
        model,
        k,
        (on, body),
        reactions,
        contact,
        |motion| from_origin_of(model, on, motion.position.clone()).components_in(on, frames),
    ))
}

/// Splits a friction site's rows: the no-slip rows (every component but the normal, which
/// is last) become the site's stick rows, the normal's row stays a constraint.
///
/// # Errors
/// When the joints already keep the contact (its normal row was dropped): then no normal
/// force reaches the contact, and friction has nothing to be proportional to.
pub fn split_rows(
    model: &Model,
    k: usize,
    index: usize,
    rows: Vec<ConstraintRow>,
    keeps_height: bool,
) -> Result<(Vec<ConstraintRow>, Option<FrictionSite>), MechanicsError> {
    let constraint = &model.problem.constraints[k];
    let Some(coefficient) = &constraint.friction else {
        return Ok((rows, None));
    };
    if keeps_height {
        return Err(MechanicsError {
            path: format!("{}.friction", constraint.path),
            message: format!(
                "`{}` has friction, but the joints already hold the body against the surface, so the normal force is theirs and the contact carries none for friction to be proportional to",
                constraint.name
            ),
            hint: Some("give the body a coordinate along the normal (marked `dependent`, e.g. a planar joint's y) so that the contact carries the normal force".into()),
        });
    }
    let mut rows = rows;
    let Some(normal_row) = rows.pop() else {
        return Ok((rows, None));
    };
    let site = FrictionSite {
        name: constraint.name.clone(),
        site: index,
        coefficient: coefficient.clone(),
        stick: rows,
        normal: vec![normal_row.unknown.clone()],
    };
    debug_assert!(site
        .stick
        .iter()
        .all(|r| matches!(r.origin, RowOrigin::Site { .. })));
    Ok((vec![normal_row], Some(site)))
}

/// The friction site of rough prismatic joint `j` of the tree (its site `site`), if it is
/// one: its friction force along the axis (the first reaction component) is held by the
/// row `±q' = 0` while it sticks, and its normal force is the reaction's force components
/// perpendicular to the axis (its moment does not count).
///
/// # Errors
/// An invalid axis.
pub fn joint_site(
    model: &Model,
    j: usize,
    site: &Site,
) -> Result<Option<FrictionSite>, MechanicsError> {
    let problem = model.problem;
    let joint = &problem.joints[j];
    let Some(coefficient) = &joint.friction else {
        return Ok(None);
    };
    let (_, flipped) = super::joints::joint_axis(problem, joint, &model.frames, &model.values)?;
    let rate = problem.coordinate_expr(joint.coordinates[0], 1);
    // The friction component is along the canonical axis, the coordinate along the axis as
    // written.
    let velocity = if flipped { -rate } else { rate };
    Ok(slider_site(site, j, coefficient, velocity))
}

/// Splits rough prismatic closure `c`'s rows (its site `site`, at `index`): the row along
/// the axis (the first) becomes the site's stick row, without a position level, since the
/// closure lets the child slide.
pub fn split_closure_rows(
    model: &Model,
    c: usize,
    (site, index): (&Site, usize),
    mut rows: Vec<ConstraintRow>,
) -> (Vec<ConstraintRow>, Option<FrictionSite>) {
    let Some(coefficient) = &model.problem.closures[c].friction else {
        return (rows, None);
    };
    let Some(axial) = site.reactions.first().map(|r| r.unknown(&site.name)) else {
        return (rows, None);
    };
    let Some(at) = rows.iter().position(|r| r.unknown == axial) else {
        return (rows, None);
    };
    let row = rows.remove(at);
    let friction = slider_site(site, index, coefficient, row.velocity);
    (rows, friction)
}

/// A rough slider's friction site, whose first reaction component is the friction force,
/// with the stick row's velocity (the slip velocity along that component) given.
fn slider_site(
    site: &Site,
    index: usize,
    coefficient: &Expr,
    velocity: Expr,
) -> Option<FrictionSite> {
    let (friction, rest) = site.reactions.split_first()?;
    let normal = rest
        .iter()
        .filter(|r| r.kind == super::joints::ComponentKind::Force)
        .map(|r| r.unknown(&site.name))
        .collect();
    let stick = ConstraintRow {
        origin: RowOrigin::Site {
            site: index,
            component: 0,
        },
        name: format!("{}.{}", site.name, friction.component()),
        position: None,
        velocity,
        unknown: friction.unknown(&site.name),
        loop_acceleration: None,
    };
    Some(FrictionSite {
        name: site.name.clone(),
        site: index,
        coefficient: coefficient.clone(),
        stick: vec![stick],
        normal,
    })
}

/// Every friction site keeps a normal force: a rough closure whose perpendicular rows are
/// redundant with other constraints has none of its own for friction to be proportional to.
///
/// # Errors
/// A friction site without its normal force among its reactions.
pub fn check_normals(
    model: &Model,
    sites: &[Site],
    friction: &[FrictionSite],
) -> Result<(), MechanicsError> {
    for f in friction {
        let site = &sites[f.site];
        let kept = |symbol: &crate::symbolic::Symbol| {
            site.reactions
                .iter()
                .any(|r| r.unknown(&site.name) == *symbol)
        };
        if !f.normal.is_empty() && f.normal.iter().all(kept) {
            continue;
        }
        return Err(MechanicsError {
            path: format!("{}.friction", model.problem.site_path(f.site)),
            message: format!(
                "`{}` has friction, but its normal force is not unique: the other constraints already hold the body across the axis, so friction has no normal force to be proportional to",
                f.name
            ),
            hint: Some("remove `friction` here, or the constraint that holds the body across the axis".into()),
        });
    }
    Ok(())
}
