//! Where a body's unit vectors are drawn: beside the body, not inside it or on a pin. A
//! bar's triad stands off its middle, across it, on the side away from the other bodies.

use super::numbers::{add, cross, dot, norm, scale, sub, unit, Numbers, P3};
use super::shapes;
use crate::problem::BodyId;
use crate::render::draw::{BodyKind, Shape};

/// The triad's origin for a planar `body` that reaches over a length (a rod, a link):
/// off the middle of its two farthest points, across the line between them, `size`
/// being the picture's length; a block past its end (see `past_the_end`). `None` for a
/// body at one point, or in 3D.
pub fn beside(n: &Numbers, body: BodyId, size: f64) -> Option<P3> {
    if body == BodyId::GROUND || !n.model.is_planar() {
        return None;
    }
    // Away from the other bodies' mass centres, so that the arrows stand in the open.
    let others: Vec<P3> = (n.model.problem.body_ids())
        .filter(|&b| b != body)
        .map(|b| n.vector(&n.model.bodies[b.0].center.position))
        .collect();
    // A block another body stands on (a rack under its pinion, a cart under its disc):
    // past its end further from the others, where its arrows are not read as theirs.
    if let Some(end) = past_the_end(n, body, size, &others) {
        return Some(end);
    }
    let points: Vec<P3> = shapes::key_points(n, body)
        .iter()
        .map(|p| n.point_on(body, p))
        .collect();
    let mut far = (points.first().copied()?, points[0], 0.0);
    for (i, a) in points.iter().enumerate() {
        for b in &points[i + 1..] {
            let d = norm(sub(*b, *a));
            if d > far.2 {
                far = (*a, *b, d);
            }
        }
    }
    if far.2 <= 0.05 * size {
        return None;
    }
    let middle = scale(add(far.0, far.1), 0.5);
    let across = unit(cross([0.0, 0.0, 1.0], sub(far.1, far.0)))?;
    let toward_others = others
        .iter()
        .map(|c| dot(sub(*c, middle), across))
        .sum::<f64>();
    let side = if toward_others > 0.0 { -1.0 } else { 1.0 };
    Some(add(middle, scale(across, side * 0.09 * size)))
}

/// For a body drawn as a block or an outline: a point past the end of its longest side
/// further from the `others` (the right end where they stand over its middle), by a
/// little of the picture's `size`. `None` for another body.
fn past_the_end(n: &Numbers, body: BodyId, size: f64, others: &[P3]) -> Option<P3> {
    let Shape::Body {
        kind: BodyKind::Block | BodyKind::Outline,
        parts,
        ..
    } = super::bodies::body(n, body, size)
    else {
        return None;
    };
    let polygon = parts.into_iter().find_map(|p| match p {
        Shape::Polygon(points) => Some(points),
        _ => None,
    })?;
    let count = polygon.len();
    let along = (0..count)
        .map(|i| sub(polygon[(i + 1) % count], polygon[i]))
        .fold(
            [0.0; 3],
            |best, e| if norm(e) > norm(best) { e } else { best },
        );
    let along = unit(along)?;
    let middle = scale(
        polygon.iter().fold([0.0; 3], |s, p| add(s, *p)),
        1.0 / count as f64,
    );
    let reach = |sign: f64| {
        (polygon.iter())
            .map(|p| sign * dot(sub(*p, middle), along))
            .fold(0.0, f64::max)
    };
    let toward_others: f64 = others.iter().map(|c| dot(sub(*c, middle), along)).sum();
    let sign = if toward_others > 1e-9 * size {
        -1.0
    } else {
        1.0
    };
    Some(add(
        middle,
        scale(along, sign * (reach(sign) + 0.06 * size)),
    ))
}

/// The triad's origin for a body that [`beside`] leaves: half way from its origin to its
/// mass centre, on the body, not on the pin its origin may be (a top's tip); the picture
/// then moves it to the nearest clear spot beside the body.
pub fn within(n: &Numbers, body: BodyId) -> P3 {
    let body = &n.model.bodies[body.0];
    let origin = n.vector(&body.origin.position);
    let center = n.vector(&body.center.position);
    scale(add(origin, center), 0.5)
}
