//! The constraints of a system beyond its tree of joints: closures, rolling contacts,
//! `position` and `velocity` entries and prescribed coordinates. Each becomes rows at the
//! position level (holonomic ones), at the velocity level (affine in the rates) and, once
//! differentiated, at the acceleration level, each with the unknown that enforces it: a
//! reaction component, a multiplier or a drive.

use super::constraint_rows::FrictionSite;
pub use super::constraint_rows::{
    drive_symbol, multiplier_symbol, ConstraintRow, Constraints, RowOrigin,
};
use super::error::MechanicsError;
use super::model::Model;
use super::site::{Site, SiteKind};
use super::sites::{closure_site, contact_site};
use super::vector::{cross3, zero3, Components, Vector};
use crate::mechanics::joints::ComponentKind;
use crate::problem::{BodyId, ConstraintKind, JointKind};
use crate::symbolic::{
    eval, linear_split, simplify, time_derivative, Expr, Relation, Symbol, Values,
};

fn unit(axis: usize) -> Components {
    let mut c = zero3();
    c[axis] = Expr::one();
    c
}

/// The sites of closures and contacts, and every constraint row.
///
/// # Errors
/// A zero axis or normal, or dependent coordinates marked wrongly.
pub fn build(model: &Model) -> Result<(Vec<Site>, Constraints), MechanicsError> {
    let problem = model.problem;
    let mut sites: Vec<Site> = (0..problem.joints.len())
        .map(|j| Site::of_joint(model, j))
        .collect();
    let mut found = Gathered::default();
    for (j, site) in sites.iter().enumerate() {
        found
            .friction
            .extend(super::friction::joint_site(model, j, site)?);
    }
    for c in 0..problem.closures.len() {
        let site = closure_site(model, c)?;
        let index = sites.len();
        let closure = closure_rows(model, &site, index)?;
        let (kept, frictional) =
            super::friction::split_closure_rows(model, c, (&site, index), closure);
        found.rows.extend(kept);
        found.friction.extend(frictional);
        sites.push(site);
    }
    let values = initial_values(model);
    for (k, constraint) in problem.constraints.iter().enumerate() {
        match &constraint.kind {
            ConstraintKind::Rolling { .. }
            | ConstraintKind::Gear { .. }
            | ConstraintKind::Contact { .. } => contact(model, k, &mut sites, &mut found)?,
            ConstraintKind::Position { expression } => {
                let velocity = time_derivative(expression).map_err(|e| MechanicsError {
                    path: constraint.path.clone(),
                    message: e.to_string(),
                    hint: None,
                })?;
                found.rows.push(ConstraintRow {
                    origin: RowOrigin::Position(k),
                    name: constraint.name.clone(),
                    position: Some(expression.clone()),
                    velocity,
                    unknown: multiplier_symbol(&constraint.name),
                    loop_acceleration: None,
                });
            }
            ConstraintKind::Velocity { expression } => found.rows.push(ConstraintRow {
                origin: RowOrigin::Velocity(k),
                name: constraint.name.clone(),
                position: None,
                velocity: expression.clone(),
                unknown: multiplier_symbol(&constraint.name),
                loop_acceleration: None,
            }),
        }
    }
    let total = problem.joints.len() + problem.closures.len() + problem.constraints.len();
    while sites.len() < total {
        sites.push(placeholder(model, sites.len()));
    }
    let prescribed = prescribed_rows(model, &mut found.rows)?;
    let Gathered {
        rows,
        mut dropped,
        tilts,
        relations,
        mut friction,
    } = found;
    let mut rows = drop_redundant(model, rows, &values, &mut dropped);
    // A friction site's stick rows enforce its tangential reactions as the rows do theirs.
    let kept = rows.len();
    let counts: Vec<usize> = friction.iter().map(|f| f.stick.len()).collect();
    rows.extend(friction.iter_mut().flat_map(|f| f.stick.drain(..)));
    keep_enforced_reactions(model, &mut sites, &mut rows)?;
    let mut stick = rows.split_off(kept).into_iter();
    for (f, count) in friction.iter_mut().zip(counts) {
        f.stick = stick.by_ref().take(count).collect();
    }
    super::friction::check_normals(model, &sites, &friction)?;
    let mut constraints = Constraints {
        rows,
        friction,
        dropped,
        prescribed,
        tilts,
        relations,
        ..Constraints::default()
    };
    super::dependent::choose(model, &mut constraints, &values)?;
    Ok((sites, constraints))
}

/// What the sites' constraints add up to as they are read, before the redundant rows are
/// dropped.
#[derive(Default)]
struct Gathered {
    rows: Vec<ConstraintRow>,
    /// The rows dropped, with the reason.
    dropped: Vec<(String, String)>,
    /// Each contact's tilt of its disc, by site name.
    tilts: Vec<(String, Expr)>,
    /// What holds on the motion at a contact, by site name.
    relations: Vec<(String, Relation)>,
    friction: Vec<FrictionSite>,
}

/// The site and rows of contact `k` (`rolling`, `gear` or `contact`): no slip at the
/// contact, and the height (or the distance of the centres) kept, where the joints do not
/// already keep it.
fn contact(
    model: &Model,
    k: usize,
    sites: &mut Vec<Site>,
    found: &mut Gathered,
) -> Result<(), MechanicsError> {
    let problem = model.problem;
    let constraint = &problem.constraints[k];
    let gear = matches!(constraint.kind, ConstraintKind::Gear { .. });
    let point = matches!(constraint.kind, ConstraintKind::Contact { .. });
    let (mut site, contact) = if gear {
        super::gear::gear_site(model, k)?
    } else if point {
        super::friction::contact_point_site(model, k)?
    } else {
        contact_site(model, k)?
    };
    let index = problem.joints.len() + problem.closures.len() + k;
    while sites.len() < index {
        // Keep site indices aligned with `Problem::site_name` for entries that are
        // not contacts: they carry no reaction.
        sites.push(placeholder(model, sites.len()));
    }
    if !point {
        found.tilts.push((site.name.clone(), contact.tilt.clone()));
    }
    // No slip is relative: the disc's material point at the contact moves as
    // the material point of `on` there (at rest when `on` is N).
    let velocity = &match site.parent {
        BodyId::GROUND => site.point.velocity.clone(),
        on => site
            .point
            .velocity
            .minus(&model.point_on(on, &site.parent_offset).velocity),
    };
    let keeps_height = identically_zero(&contact.height, model);
    if keeps_height {
        site.reactions.pop();
        found.dropped.push(if gear {
            (
                format!("{}.distance", site.name),
                "the joints already keep the centres at the pitch radii's distance, so the distance constraint holds identically and the joints carry the push along the line of centres".to_string(),
            )
        } else {
            (
                format!("{}.height", site.name),
                "the joints already keep the disc on the plane, so its height constraint holds identically and the joints carry the normal load".to_string(),
            )
        });
    }
    // Written with what holds where the contact does (a unit line of centres):
    // equal on the motion, where the rows are used.
    let written = |row: Expr| match &contact.on_motion {
        Some(relation) => relation.reduce(&simplify(&row)),
        None => row,
    };
    if let Some(relation) = &contact.on_motion {
        found.relations.push((site.name.clone(), relation.clone()));
    }
    let mut site_rows = Vec::new();
    for (component, reaction) in site.reactions.iter().enumerate() {
        let is_normal = !keeps_height && component + 1 == site.reactions.len();
        site_rows.push(ConstraintRow {
            origin: RowOrigin::Site {
                site: index,
                component,
            },
            name: format!("{}.{}", site.name, reaction.component()),
            position: is_normal.then(|| contact.height.clone()),
            velocity: written(velocity.dot(&reaction.direction, &model.frames)),
            unknown: reaction.unknown(&site.name),
            loop_acceleration: None,
        });
    }
    let (kept, frictional) = super::friction::split_rows(model, k, index, site_rows, keeps_height)?;
    found.rows.extend(kept);
    found.friction.extend(frictional);
    sites.push(site);
    Ok(())
}

/// The rows of the prescribed coordinates, `q − motion(t) = 0` each, added to `rows`;
/// the prescribed coordinates' indices.
fn prescribed_rows(
    model: &Model,
    rows: &mut Vec<ConstraintRow>,
) -> Result<Vec<usize>, MechanicsError> {
    let problem = model.problem;
    let mut prescribed = Vec::new();
    for (i, coordinate) in problem.coordinates.iter().enumerate() {
        let Some(motion) = &coordinate.motion else {
            continue;
        };
        prescribed.push(i);
        let q = problem.coordinate_expr(i, 0);
        let position = &q - motion;
        let velocity = time_derivative(&position).map_err(|e| MechanicsError {
            path: format!("coordinates.{}.motion", coordinate.name),
            message: e.to_string(),
            hint: None,
        })?;
        rows.push(ConstraintRow {
            origin: RowOrigin::Prescribed(i),
            name: format!("{} prescribed", coordinate.name),
            position: Some(position),
            velocity,
            unknown: drive_symbol(problem, i),
            loop_acceleration: None,
        });
    }
    Ok(prescribed)
}

/// A closure's or contact's reaction components whose rows were dropped are not unknowns:
/// such a reaction is not unique, and may not be requested.
fn keep_enforced_reactions(
    model: &Model,
    sites: &mut [Site],
    rows: &mut [ConstraintRow],
) -> Result<(), MechanicsError> {
    let problem = model.problem;
    for (index, site) in sites.iter_mut().enumerate() {
        if matches!(site.kind, SiteKind::Joint(_)) {
            continue;
        }
        let before = site.reactions.len();
        site.reactions.retain(|r| {
            let symbol = r.unknown(&site.name);
            rows.iter().any(|row| row.unknown == symbol)
        });
        if site.reactions.len() < before && problem.find_reactions.contains(&index) {
            return Err(MechanicsError {
                path: "find.reactions".into(),
                message: format!(
                    "the reaction at `{}` is not unique: some of its constraints are redundant with others, so the forces can be shared among them in many ways",
                    site.name
                ),
                hint: Some("request a reaction elsewhere, or remove the redundant constraint (for a spatial loop of revolutes, make one closure spherical)".into()),
            });
        }
    }
    for row in rows.iter_mut() {
        if let RowOrigin::Site { site, component } = &mut row.origin {
            let s = &sites[*site];
            if let Some(k) = s
                .reactions
                .iter()
                .position(|r| r.unknown(&s.name) == row.unknown)
            {
                *component = k;
            }
        }
    }
    Ok(())
}

/// A site for an entry that has no reaction (a `position` or `velocity` constraint).
fn placeholder(model: &Model, index: usize) -> Site {
    let name = model.problem.site_name(index).to_string();
    Site {
        name,
        kind: SiteKind::Contact(index),
        parent: BodyId::GROUND,
        child: BodyId::GROUND,
        child_offset: zero3(),
        parent_offset: zero3(),
        point: Default::default(),
        reactions: Vec::new(),
        across: Vec::new(),
    }
}

/// The constants with every coordinate and rate at its initial value, time 0.
pub fn initial_values(model: &Model) -> Values {
    let coordinates = &model.problem.coordinates;
    let q: Vec<f64> = coordinates.iter().map(|c| c.initial).collect();
    let rates: Vec<f64> = coordinates.iter().map(|c| c.rate).collect();
    model.values_at(0.0, &q, &rates)
}

/// Whether `e` vanishes at the initial state and at generic ones.
fn identically_zero(e: &Expr, model: &Model) -> bool {
    if e.is_zero() {
        return true;
    }
    super::model::sample_states(model)
        .iter()
        .all(|values| eval(e, values).abs() < 1e-12)
}

/// A closure's rows: one per reaction component, the relative motion that component forbids.
fn closure_rows(
    model: &Model,
    site: &Site,
    index: usize,
) -> Result<Vec<ConstraintRow>, MechanicsError> {
    let problem = model.problem;
    let frames = &model.frames;
    let SiteKind::Closure(c) = site.kind else {
        return Ok(Vec::new());
    };
    let closure = &problem.closures[c];
    let (parent, child) = (closure.parent, closure.child);
    let parent_state = &model.bodies[parent.0];
    let child_state = &model.bodies[child.0];
    let at = super::vector::own_components(&closure.at, parent);
    let parent_point = model.point_on(parent, &at);
    let gap = site.point.position.minus(&parent_point.position);
    // The parent's material point where the child's point is now.
    let parent_velocity = parent_point
        .velocity
        .plus(&parent_state.omega.cross(&gap, frames));
    let relative_velocity = site.point.velocity.minus(&parent_velocity);
    let relative_omega = child_state.omega.minus(&parent_state.omega);
    let axis = site
        .reactions
        .iter()
        .find(|r| r.kind == ComponentKind::Moment)
        .and(closure_axis(model, closure)?);
    let mut rows = Vec::new();
    for (component, reaction) in site.reactions.iter().enumerate() {
        let d = &reaction.direction;
        let (position, velocity) = if reaction.kind == ComponentKind::Force {
            (gap.dot(d, frames), relative_velocity.dot(d, frames))
        } else {
            let g = alignment(model, closure, d, axis.as_ref());
            (g, relative_omega.dot(d, frames))
        };
        // A closure that holds its point: the two material points there have the same
        // acceleration, and each row is that loop's component.
        let holds_point = matches!(
            closure.kind,
            JointKind::Revolute | JointKind::Spherical | JointKind::Universal | JointKind::Weld
        );
        let loop_acceleration = (holds_point && reaction.kind == ComponentKind::Force).then(|| {
            site.point
                .acceleration
                .minus(&parent_point.acceleration)
                .dot(d, frames)
        });
        rows.push(ConstraintRow {
            origin: RowOrigin::Site {
                site: index,
                component,
            },
            name: format!("{}.{}", site.name, reaction.component()),
            position: Some(position),
            velocity,
            unknown: reaction.unknown(&site.name),
            loop_acceleration,
        });
    }
    Ok(rows)
}

/// The unit axis of a revolute or cylindrical closure in the parent's unit vectors.
fn closure_axis(
    model: &Model,
    closure: &crate::problem::Joint,
) -> Result<Option<Components>, MechanicsError> {
    if !matches!(closure.kind, JointKind::Revolute | JointKind::Cylindrical) {
        return Ok(None);
    }
    super::joints::joint_axis(model.problem, closure, &model.frames, &model.values)
        .map(|(axis, _)| Some(axis))
}

/// A position-level row for a moment component along `d`: zero when the frames are
/// aligned about `d`, with derivative `(ω_child − ω_parent)·d` there. With `a` a direction
/// perpendicular to `d` that should have the same components in both frames, it is
/// `a_child · (d × a)_parent`.
fn alignment(
    model: &Model,
    closure: &crate::problem::Joint,
    d: &Vector,
    axis: Option<&Components>,
) -> Expr {
    let frames = &model.frames;
    let (parent, child) = (closure.parent, closure.child);
    if closure.kind == JointKind::Universal {
        let first = Vector::new(parent, unit(closure.sequence[0] as usize));
        let second = Vector::new(child, unit(closure.sequence[1] as usize));
        return first.dot(&second, frames);
    }
    let d_parent = d.components_in(parent, frames);
    let a: Components = match axis {
        Some(axis) => axis.clone(),
        None => {
            // Rotation is locked about every axis: pair d = e_i with a = e_(i+1).
            let i = (0..3).find(|&i| d_parent[i].is_one()).unwrap_or(2);
            unit((i + 1) % 3)
        }
    };
    let a_child = Vector::new(child, a.clone());
    let d_cross_a = Vector::new(parent, cross3(&d_parent, &a));
    a_child.dot(&d_cross_a, frames)
}

/// Keeps the rows whose velocity-level coefficients are independent at the initial state;
/// the others are recorded in `dropped`.
fn drop_redundant(
    model: &Model,
    rows: Vec<ConstraintRow>,
    values: &Values,
    dropped: &mut Vec<(String, String)>,
) -> Vec<ConstraintRow> {
    let rates: Vec<Symbol> = (0..model.problem.coordinates.len())
        .map(|i| model.problem.coordinate_symbol(i, 1))
        .collect();
    let mut basis = Vec::new();
    let mut kept = Vec::new();
    for row in rows {
        let coefficients: Vec<f64> = match linear_split(&row.velocity, &rates) {
            Ok((c, _)) => c.iter().map(|e| eval(e, values)).collect(),
            Err(_) => vec![f64::NAN; rates.len()],
        };
        if independent(&mut basis, &coefficients) {
            kept.push(row);
        } else {
            dropped.push((
                row.name.clone(),
                "redundant: it follows from the constraints before it".to_string(),
            ));
        }
    }
    kept
}

/// Gram–Schmidt with a tolerance loose enough for a configuration not yet assembled.
fn independent(basis: &mut Vec<Vec<f64>>, row: &[f64]) -> bool {
    let norm = row.iter().map(|x| x * x).sum::<f64>().sqrt();
    if norm.is_nan() || norm <= 1e-12 || !norm.is_finite() {
        return false;
    }
    let mut residual: Vec<f64> = row.iter().map(|x| x / norm).collect();
    for _ in 0..2 {
        for b in basis.iter() {
            let p: f64 = residual.iter().zip(b).map(|(r, b)| r * b).sum();
            residual.iter_mut().zip(b).for_each(|(r, b)| *r -= p * b);
        }
    }
    let left = residual.iter().map(|x| x * x).sum::<f64>().sqrt();
    if left < 1e-6 {
        return false;
    }
    basis.push(residual.iter().map(|x| x / left).collect());
    true
}
