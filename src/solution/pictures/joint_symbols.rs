//! The symbol of a joint in a picture: a pin, a slider on its rail, a ball, a weld, the
//! ground under a joint to `N`, and the ground under a carrier on a rail (`guide.rs`).

use super::numbers::{add, cross, dot, norm, scale, sub, unit, Numbers};
use crate::problem::{BodyId, JointKind};
use crate::render::draw::Shape;

/// The symbol of joint `j` at its point, and the ground under it when its parent is `N`.
pub fn joint(n: &Numbers, j: usize, size: f64) -> Vec<Shape> {
    let model = n.model;
    let joint = &model.problem.joints[j];
    let at = n.vector(&model.joints[j].point.position);
    let axis = model.joints[j]
        .motion
        .written_axis
        .as_ref()
        .map(|a| n.in_ground(joint.parent, &n.local(a)))
        .and_then(unit)
        .unwrap_or([0.0, 0.0, 1.0]);
    if model.is_planar() {
        if let Some(shapes) = super::guide::guide(n, j, axis, size) {
            return shapes;
        }
    }
    let mut shapes = match joint.kind {
        JointKind::Revolute => vec![Shape::Pin(at)],
        JointKind::Prismatic => vec![Shape::Slider { at, axis }],
        JointKind::Cylindrical => vec![Shape::Slider { at, axis }, Shape::Pin(at)],
        JointKind::Spherical | JointKind::Universal => vec![Shape::Ball(at)],
        JointKind::Weld => vec![Shape::Weld(at)],
        JointKind::Planar | JointKind::Free => vec![],
    };
    if joint.parent == BodyId::GROUND && !matches!(joint.kind, JointKind::Planar | JointKind::Free)
    {
        let on_ground = n.point_on(BodyId::GROUND, &n.local(&model.joints[j].at));
        let child_center = n.vector(&model.bodies[joint.child.0].center.position);
        let vertical = if model.is_planar() {
            [0.0, 1.0, 0.0]
        } else {
            [0.0, 0.0, 1.0]
        };
        if matches!(joint.kind, JointKind::Prismatic | JointKind::Cylindrical) {
            // A rail along the axis, under the block.
            let across = sub(vertical, scale(axis, dot(vertical, axis)));
            let up = unit(across)
                .unwrap_or_else(|| unit(cross(axis, [0.0, 0.0, 1.0])).unwrap_or([1.0, 0.0, 0.0]));
            let middle = scale(add(on_ground, at), 0.5);
            let reach = norm(sub(at, on_ground)) / 2.0 + 0.25 * size;
            shapes.push(Shape::Ground {
                at: middle,
                along: scale(axis, reach),
                up,
            });
        } else {
            let toward = sub(child_center, on_ground);
            let up = if norm(toward) > 1e-6 * size {
                // The support sits on the side away from the body it carries.
                let v = unit(toward).unwrap_or(vertical);
                if dot(v, vertical).abs() >= 0.5 {
                    scale(vertical, dot(v, vertical).signum())
                } else {
                    v
                }
            } else {
                vertical
            };
            let along = unit(cross(up, [0.0, 0.0, 1.0]))
                .or_else(|| unit(cross(up, [1.0, 0.0, 0.0])))
                .unwrap_or([1.0, 0.0, 0.0]);
            shapes.push(Shape::Ground {
                at: on_ground,
                along: scale(along, 0.0),
                up,
            });
        }
    }
    shapes
}
