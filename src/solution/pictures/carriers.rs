//! A body that carries the surface another rolls or rests on (a cart under a disc, a rack
//! under a pinion): drawn as a block whose face is that surface, the length of the body's
//! points along it and at least a good part of the picture, not as a particle on a line.

use super::numbers::{add, cross, dot, scale, unit, Numbers};
use super::shapes;
use crate::mechanics::own_components;
use crate::problem::{BodyId, ConstraintKind};
use crate::render::draw::{BodyKind, Shape};

/// The block of a planar body that is the `on` of a rolling contact or a contact, with its
/// face in the contact's plane; `None` for any other body.
pub fn carrier(n: &Numbers, body: BodyId, size: f64) -> Option<(BodyKind, Vec<Shape>)> {
    if body == BodyId::GROUND || !n.model.is_planar() {
        return None;
    }
    let (normal, offset, wheel) =
        n.model
            .problem
            .constraints
            .iter()
            .find_map(|c| match &c.kind {
                ConstraintKind::Rolling {
                    on,
                    normal,
                    offset,
                    radius,
                    ..
                } if *on == body => Some((normal, offset, n.scalar(radius))),
                ConstraintKind::Contact {
                    on, normal, offset, ..
                } if *on == body => Some((normal, offset, 0.0)),
                _ => None,
            })?;
    // Long and deep enough to read as a block under the wheel it carries: two wheel
    // diameters and more, more than half a wheel's radius deep.
    let wheel = if wheel.is_finite() { wheel.abs() } else { 0.0 };
    let up = unit(n.in_ground(body, &n.local(&own_components(normal, body))))?;
    let along = unit(cross(up, [0.0, 0.0, 1.0]))?;
    let origin = n.point_on(body, &[0.0; 3]);
    let face = add(origin, scale(up, n.scalar(offset)));
    // The body's points along the face; the block is centred on the mass centre (a cart's
    // middle is where its weight acts) and reaches past every point.
    let along_face = |p: super::numbers::P3| dot(add(p, scale(face, -1.0)), along);
    let reach: Vec<f64> = shapes::key_points(n, body)
        .iter()
        .map(|p| along_face(n.point_on(body, p)))
        .collect();
    let middle = along_face(n.vector(&n.model.bodies[body.0].center.position));
    let half = (reach.iter())
        .map(|r| (r - middle).abs())
        .fold(0.0, f64::max);
    // A wheel's width past its contact, and deep enough to name its points inside.
    let half = (half + (0.05 * size).max(wheel))
        .max(0.3 * size)
        .max(2.2 * wheel);
    // As deep as the problem makes it where it says: its mass centre at half its depth,
    // the joint it slides on at its underside; else deep enough to read as a block.
    let below = |p: super::numbers::P3| dot(add(p, scale(face, -1.0)), up);
    let centre = -below(n.vector(&n.model.bodies[body.0].center.position));
    let slide = shapes::key_points(n, body)
        .iter()
        .map(|p| -below(n.point_on(body, p)))
        .fold(0.0, f64::max);
    let given = (2.0 * centre).max(slide);
    let depth = match given > 1e-9 * size {
        true => given,
        false => (0.12 * size).max(0.6 * wheel),
    };
    let at = |s: f64, d: f64| add(face, add(scale(along, middle + s * half), scale(up, -d)));
    let corners = vec![at(-1.0, 0.0), at(1.0, 0.0), at(1.0, depth), at(-1.0, depth)];
    Some((BodyKind::Block, vec![Shape::Polygon(corners)]))
}
