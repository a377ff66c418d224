//! A carrier (a cart, a rack) that slides on the ground along a rail is drawn on its
//! guide: its bottom face rests on the hatched ground, as a block sliding on a smooth floor
//! is drawn (no rollers: it slides), not a sleeve and hatching at the joint's point on the
//! block's top face (where another body rolls).

use super::numbers::{add, dot, scale, Numbers, P3};
use crate::problem::{BodyId, JointKind};
use crate::render::draw::{BodyKind, Shape};

/// The ground of joint `j` when it is a rail (a prismatic joint on `N`) under a body drawn
/// as a carrier block along `axis` (unit, in `N`): a hatched line along the block's bottom
/// face; `None` for any other joint.
pub fn guide(n: &Numbers, j: usize, axis: P3, size: f64) -> Option<Vec<Shape>> {
    let joint = &n.model.problem.joints[j];
    if joint.kind != JointKind::Prismatic || joint.parent != BodyId::GROUND {
        return None;
    }
    // Only a body the carrier rule draws (not one whose shape the problem declares).
    let Shape::Body {
        kind: BodyKind::Block,
        ..
    } = super::bodies::body(n, joint.child, size)
    else {
        return None;
    };
    let (_, parts) = super::carriers::carrier(n, joint.child, size)?;
    let Some(Shape::Polygon(corners)) = parts.first() else {
        return None;
    };
    // Up: across the rail, in the plane, away from the ground.
    let up = [-axis[1], axis[0], 0.0];
    let up = if up[1] < 0.0 { scale(up, -1.0) } else { up };
    let bottom = corners
        .iter()
        .map(|c| dot(*c, up))
        .fold(f64::INFINITY, f64::min);
    let (lo, hi) = corners
        .iter()
        .map(|c| dot(*c, axis))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s), hi.max(s))
        });
    let start = corners[0];
    // A point at `s` along the rail, `level` up from the ground.
    let at = |s: f64, level: f64| -> P3 {
        let p = add(start, scale(axis, s - dot(start, axis)));
        add(p, scale(up, level - dot(p, up)))
    };
    let middle = 0.5 * (lo + hi);
    Some(vec![Shape::Surface {
        at: at(middle, bottom),
        along: scale(axis, 0.5 * (hi - lo) + 0.1 * size),
        up,
        fixed: true,
    }])
}
