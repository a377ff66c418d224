//! In the plane, what a point contact touches and what a collar slides on: a ladder's wall
//! and floor, each a hatched line through the contact along the surface, hatched on the
//! side away from the body (the side its normal points from); and the fixed rod of a
//! prismatic closure with the ground, a plain line along the axis through the collar.

use super::numbers::{add, cross, norm, scale, sub, unit, Numbers, P3};
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
    meet_at_corners(&mut out, size);
    out
}

/// Two fixed surfaces at an angle (a wall and a floor) drawn to the corner where they
/// meet, each from there out past its contact, as a textbook draws a room's corner; a
/// corner further off than twice the system's size is left open.
fn meet_at_corners(surfaces: &mut [Shape], size: f64) {
    let lines: Vec<Option<(P3, P3)>> = (surfaces.iter())
        .map(|s| match s {
            Shape::Surface {
                at,
                along,
                fixed: true,
                ..
            } => unit(*along).map(|t| (*at, t)),
            _ => None,
        })
        .collect();
    for (i, surface) in surfaces.iter_mut().enumerate() {
        let Some((at, t)) = lines[i] else { continue };
        let Shape::Surface {
            at: centre, along, ..
        } = surface
        else {
            continue;
        };
        let reach = norm(*along);
        // The nearest corner with another fixed surface, along this one's line.
        let corner = (lines.iter().enumerate())
            .filter(|(k, _)| *k != i)
            .filter_map(|(_, l)| *l)
            .filter_map(|(p, v)| {
                // at + s t = p + r v, in the plane: s from the 2D cross products.
                let det = t[0] * v[1] - t[1] * v[0];
                if det.abs() < 1e-6 {
                    return None;
                }
                let d = sub(p, at);
                let s = (d[0] * v[1] - d[1] * v[0]) / det;
                let r = (d[0] * t[1] - d[1] * t[0]) / det;
                (s.abs() < 2.0 * size && r.abs() < 2.0 * size).then_some(s)
            })
            .min_by(|a, b| a.abs().total_cmp(&b.abs()));
        let Some(s) = corner else { continue };
        // From the corner to past the contact by the surface's reach.
        let far = -s.signum() * reach;
        let middle = add(at, scale(t, 0.5 * (s + far)));
        *centre = middle;
        *along = scale(t, 0.5 * (s - far).abs());
    }
}
