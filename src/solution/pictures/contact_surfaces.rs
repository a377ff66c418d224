//! In the plane, what a point contact touches and what a collar slides on: a ladder's wall
//! and floor, each a hatched line through the contact along the surface, hatched on the
//! side away from the body (the side its normal points from); and the fixed rod of a
//! prismatic closure with the ground, a plain line along the axis through the collar.

use super::numbers::{cross, norm, scale, unit, Numbers};
use crate::mechanics::{vector_of, SiteKind};
use crate::problem::{BodyId, ConstraintKind, JointKind};
use crate::render::draw::Shape;

/// The surfaces of the point contacts and the fixed rods of the prismatic closures with
/// the ground, in a planar problem; empty in space. A body that slides on a prismatic
/// joint has its guide drawn already, and is left out.
pub fn contact_surfaces(n: &Numbers, size: f64) -> Vec<Shape> {
    let model = n.model;
    let problem = model.problem;
    if !model.is_planar() {
        return Vec::new();
    }
    let guided = |body: BodyId| {
        (problem.joints.iter()).any(|j| j.child == body && j.kind == JointKind::Prismatic)
    };
    let reach = 0.35 * size;
    let mut out = Vec::new();
    for site in &model.sites {
        match site.kind {
            SiteKind::Contact(k) => {
                let Some(ConstraintKind::Contact {
                    body, on, normal, ..
                }) = problem.constraints.get(k).map(|c| &c.kind)
                else {
                    continue;
                };
                if guided(*body) {
                    continue;
                }
                let Some(up) = unit(n.vector(&vector_of(normal))) else {
                    continue;
                };
                out.push(Shape::Surface {
                    at: n.vector(&site.point.position),
                    along: scale(cross(up, [0.0, 0.0, 1.0]), reach),
                    up,
                    fixed: *on == BodyId::GROUND,
                });
            }
            SiteKind::Closure(k) => {
                let Some(closure) = problem.closures.get(k) else {
                    continue;
                };
                let fixed = closure.parent == BodyId::GROUND;
                let Some(axis) = closure.axis.as_ref().filter(|_| fixed) else {
                    continue;
                };
                if closure.kind != JointKind::Prismatic {
                    continue;
                }
                let Some(along) = unit(n.vector(&vector_of(axis))) else {
                    continue;
                };
                let across = cross([0.0, 0.0, 1.0], along);
                if norm(across) < 1e-9 {
                    continue;
                }
                // A rod, not a floor: a plain line through the collar, out past it.
                out.push(Shape::Surface {
                    at: n.vector(&site.point.position),
                    along: scale(along, 2.5 * reach),
                    up: across,
                    fixed: false,
                });
            }
            SiteKind::Joint(_) => {}
        }
    }
    out
}
