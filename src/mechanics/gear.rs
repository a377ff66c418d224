//! A `gear` contact: two discs with parallel axles rolling on each other without slipping
//! (pitch circles, friction wheels), `body`'s disc outside `on`'s or, `internal`, inside it.
//! Its site is at the contact point on the line of centres, with the parent `on`, so that
//! the contact force acts on both bodies; its rows are the distance between the centres
//! (`on_radius ± radius`) and no slip along the common tangent.

use super::error::MechanicsError;
use super::joints::{Axis, ComponentKind, ReactionComponent};
use super::model::Model;
use super::site::{Contact, Site};
use super::sites::{contact_site_of, offset_on, unit_direction};
use super::vector::{dot3, zero3, Components, Vector};
use crate::problem::{BodyId, ConstraintKind};
use crate::symbolic::{pow, simplify, sqrt, Expr, Relation};

/// The site of gear contact `k` and its geometry (the "height" is the distance between the
/// centres minus what the radii allow). The normal reaction is a push on `body`: along the
/// unit line of centres from `on`'s centre toward `body`'s for external discs, the
/// opposite (toward the ring's centre) for a disc inside a ring.
///
/// # Errors
/// A 3D axle that is zero, or one that turns relative to `on` (axles not parallel).
pub fn gear_site(model: &Model, k: usize) -> Result<(Site, Contact), MechanicsError> {
    let constraint = &model.problem.constraints[k];
    let ConstraintKind::Gear {
        body,
        radius,
        center,
        on,
        on_radius,
        on_center,
        internal,
        axis,
    } = &constraint.kind
    else {
        return Err(MechanicsError {
            path: constraint.path.clone(),
            message: "not a gear contact".into(),
            hint: None,
        });
    };
    let frames = &model.frames;
    let (body, on) = (*body, *on);
    let body_center = offset_on(model, center, body);
    let on_center = offset_on(model, on_center, on);
    // The line of centres, in `on`'s unit vectors, and its length.
    let between = model
        .position_on(body, &body_center)
        .minus(&model.position_on(on, &on_center))
        .components_in(on, frames);
    let distance = sqrt(dot3(&between, &between));
    let allowed = if *internal {
        on_radius - radius
    } else {
        on_radius + radius
    };
    // The unit line of centres: where the distance condition holds (after assembly, and
    // along the motion) the length is the pitch radii's sum (difference), which keeps
    // square roots out of every row but the distance itself.
    let inverse = pow(allowed.clone(), Expr::int(-1));
    let toward: Components = std::array::from_fn(|i| &between[i] * &inverse);
    let line = Vector::new(on, toward);
    let axle = match axis {
        None => Vector::unit(BodyId::GROUND, 2),
        Some(written) => Vector::new(
            body,
            unit_direction(model, written, body, || MechanicsError {
                path: format!("{}.axis", constraint.path),
                message: "the axis is zero".into(),
                hint: Some("give the common axle's direction, e.g. B.z".into()),
            })?,
        ),
    };
    if axis.is_some() && !fixed_in(model, &axle, on) {
        return Err(MechanicsError {
            path: constraint.path.clone(),
            message: format!(
                "the axles of {} and {} are not parallel: the common axle, fixed in {}, turns relative to {}",
                model.problem.body_name(body),
                model.problem.body_name(on),
                model.problem.body_name(body),
                model.problem.body_name(on)
            ),
            hint: Some(
                "spur gears and friction wheels need parallel axles: give both wheels' joints axes parallel to the gear's `axis`".into(),
            ),
        });
    }
    let tangent = axle.cross(&line, frames);
    // The contact point on the line of centres, `radius` from the disc's centre: toward
    // `on`'s centre outside it, away from it inside a ring.
    let line_in_body = line.components_in(body, frames);
    let sign = if *internal { Expr::one() } else { -Expr::one() };
    let offset: Components =
        std::array::from_fn(|i| &body_center[i] + &(&(&sign * radius) * &line_in_body[i]));
    // Where the distance row holds, the line of centres is a unit vector: the rows are
    // written with that, as a textbook writes them. Where the joints keep the distance, the
    // squared length is the constant it should be already.
    let square = simplify(&dot3(&between, &between));
    let on_motion = (!square.is_constant()).then(|| Relation::new(square, allowed.clone()));
    let gap = &distance - &allowed;
    // The normal force is a push on `body`: along the line of centres outside `on`'s disc,
    // against it (toward the ring's centre) inside a ring, so that a pressing contact
    // carries a positive normal force.
    let push = if *internal {
        line.scaled(&-Expr::one())
    } else {
        line.clone()
    };
    let reactions = vec![
        ReactionComponent {
            kind: ComponentKind::Force,
            axis: Axis::SoleTangent,
            direction: tangent.clone(),
        },
        ReactionComponent {
            kind: ComponentKind::Force,
            axis: Axis::Normal,
            direction: push,
        },
    ];
    let contact = Contact {
        offset,
        height: gap,
        tilt: Expr::one(),
        on_motion,
    };
    Ok(contact_site_of(
        model,
        k,
        (on, body),
        reactions,
        contact,
        |point| {
            point
                .position
                .minus(&model.position_on(on, &zero3()))
                .components_in(on, frames)
        },
    ))
}

/// Whether `axle` keeps the same components in `on`'s unit vectors at the sample states:
/// the two wheels' axles stay parallel whatever the coordinates.
fn fixed_in(model: &Model, axle: &Vector, on: BodyId) -> bool {
    let in_on = axle.components_in(on, &model.frames);
    let states = super::model::sample_states(model);
    let Some(first) = states.first() else {
        return true;
    };
    let eval = crate::symbolic::eval;
    in_on.iter().all(|c| {
        let reference = eval(c, first);
        (states.iter()).all(|state| (eval(c, state) - reference).abs() <= 1e-9)
    })
}
