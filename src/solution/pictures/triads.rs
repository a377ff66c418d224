//! Where a body's unit vectors are drawn: beside the body, not inside it or on a pin. A
//! bar's triad stands off its middle, across it, on the side away from the other bodies.

use super::numbers::{add, cross, dot, norm, scale, sub, unit, Numbers, P3};
use super::shapes;
use crate::problem::BodyId;

/// The triad's origin for a planar `body` that reaches over a length (a rod, a link):
/// off the middle of its two farthest points, across the line between them, `size`
/// being the picture's length. `None` for a body at one point, or in 3D.
pub fn beside(n: &Numbers, body: BodyId, size: f64) -> Option<P3> {
    if body == BodyId::GROUND || !n.model.is_planar() {
        return None;
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
    // Away from the other bodies' mass centres, so that the arrows stand in the open.
    let others: Vec<P3> = (n.model.problem.body_ids())
        .filter(|&b| b != body)
        .map(|b| n.vector(&n.model.bodies[b.0].center.position))
        .collect();
    let toward_others = others
        .iter()
        .map(|c| dot(sub(*c, middle), across))
        .sum::<f64>();
    let side = if toward_others > 0.0 { -1.0 } else { 1.0 };
    Some(add(middle, scale(across, side * 0.09 * size)))
}
