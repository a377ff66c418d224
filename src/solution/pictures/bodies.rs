//! Each body drawn as what it is, in one group: its `shape` when the problem gives one,
//! else the first rule that fits (cli.md, version 3, `draw`): a rolling body is a wheel of
//! its contact's radius, a uniform rod pinned at one end reaches its far end, a body
//! without inertia is a particle on a light rod, and anything else a rod or outline through
//! its points ([`shapes::body`]).

use super::numbers::{add, cross, dot, norm, scale, sub, unit, Numbers, P3};
use super::shapes;
use crate::mechanics::own_components;
use crate::problem::{BodyId, BodyShape, ConstraintKind, ForcePoint, Inertia, VectorExpr};
use crate::render::draw::{BodyKind, Shape};

/// The group of `body`'s shapes; `size` is the picture's characteristic length.
pub fn body(n: &Numbers, body: BodyId, size: f64) -> Shape {
    let (kind, parts) = declared(n, body, size)
        .or_else(|| wheel(n, body, size))
        .or_else(|| uniform_rod(n, body))
        .or_else(|| super::carriers::carrier(n, body, size))
        .or_else(|| particle(n, body, size))
        .unwrap_or_else(|| outline(n, body, size));
    Shape::Body {
        name: n.model.problem.body_name(body).to_string(),
        kind,
        parts,
    }
}

/// A point of `body` written from its origin, in `N`.
fn point(n: &Numbers, body: BodyId, v: &VectorExpr) -> P3 {
    n.point_on(body, &n.local(&own_components(v, body)))
}

/// A direction of `body` written in its unit vectors, in `N`, unit.
fn direction(n: &Numbers, body: BodyId, v: &VectorExpr) -> Option<P3> {
    unit(n.in_ground(body, &n.local(&own_components(v, body))))
}

fn center_of(n: &Numbers, body: BodyId) -> P3 {
    n.vector(&n.model.bodies[body.0].center.position)
}

/// A unit vector fixed in `body` across `normal`: the wheel's spoke.
fn spoke(n: &Numbers, body: BodyId, normal: P3) -> P3 {
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
        .iter()
        .filter_map(|e| {
            let d = n.in_ground(body, e);
            unit(sub(d, scale(normal, dot(d, normal))))
        })
        .next()
        .unwrap_or([1.0, 0.0, 0.0])
}

/// The body's `shape`.
fn declared(n: &Numbers, body: BodyId, size: f64) -> Option<(BodyKind, Vec<Shape>)> {
    let shape = n.model.problem.body(body).shape.as_ref()?;
    let planar = n.model.is_planar();
    Some(match shape {
        BodyShape::Rod { from, to } => (
            BodyKind::Rod,
            vec![Shape::Bar(vec![point(n, body, from), point(n, body, to)])],
        ),
        BodyShape::Disc {
            radius,
            center,
            axis,
        } => {
            let center = center
                .as_ref()
                .map_or_else(|| center_of(n, body), |c| point(n, body, c));
            let normal = match (planar, axis) {
                (false, Some(a)) => direction(n, body, a),
                _ => None,
            }
            .unwrap_or_else(|| {
                unit(n.in_ground(body, &[0.0, 0.0, 1.0])).unwrap_or([0.0, 0.0, 1.0])
            });
            let radius = n.scalar(radius);
            let mark = spoke(n, body, normal);
            (
                BodyKind::Disc,
                vec![Shape::Wheel {
                    center,
                    normal,
                    radius,
                    mark,
                }],
            )
        }
        BodyShape::Block {
            size: sides,
            center,
        } => {
            let half: Vec<f64> = sides.iter().map(|s| n.scalar(s) / 2.0).collect();
            let c = n.local(&own_components(center, body));
            let corner = |x: f64, y: f64, z: f64| {
                n.point_on(
                    body,
                    &add(
                        c,
                        [x * half[0], y * half[1], z * half.get(2).unwrap_or(&0.0)],
                    ),
                )
            };
            let mut parts = vec![Shape::Polygon(vec![
                corner(-1.0, -1.0, 1.0),
                corner(1.0, -1.0, 1.0),
                corner(1.0, 1.0, 1.0),
                corner(-1.0, 1.0, 1.0),
            ])];
            if half.len() == 3 {
                // A box: its other faces as outlines too.
                for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    parts.push(Shape::Bar(vec![corner(a, b, 1.0), corner(a, b, -1.0)]));
                }
                parts.push(Shape::Polygon(vec![
                    corner(-1.0, -1.0, -1.0),
                    corner(1.0, -1.0, -1.0),
                    corner(1.0, 1.0, -1.0),
                    corner(-1.0, 1.0, -1.0),
                ]));
                parts.retain(|s| !matches!(s, Shape::Bar(_)));
            }
            (BodyKind::Block, parts)
        }
        BodyShape::Particle => (BodyKind::Particle, particle_parts(n, body, size)),
        BodyShape::Polygon { points } => (
            BodyKind::Outline,
            vec![Shape::Polygon(
                points.iter().map(|p| point(n, body, p)).collect(),
            )],
        ),
    })
}

/// Where a body's disc is, from the contact that makes it one: its radius, its centre
/// and the axle's direction (N.z in 2D).
struct Disc {
    radius: f64,
    center: P3,
    normal: P3,
}

/// A place given as a point or as an offset from `body`'s origin, in `N`.
fn place(n: &Numbers, body: BodyId, at: &ForcePoint) -> P3 {
    match at {
        ForcePoint::Point(p) => n.vector(&n.model.position(*p)),
        ForcePoint::Offset(v) => point(n, body, v),
    }
}

/// The axle of a contact whose axis is written in `body`'s unit vectors (N.z in 2D).
fn axle(n: &Numbers, body: BodyId, axis: Option<&VectorExpr>) -> Option<P3> {
    match axis {
        _ if n.model.is_planar() => Some([0.0, 0.0, 1.0]),
        Some(axis) => direction(n, body, axis),
        None => None,
    }
}

/// `body`'s disc: a rolling body's wheel, a gear, or the disc a gear rolls on outside.
fn disc_of(n: &Numbers, body: BodyId) -> Option<Disc> {
    n.model
        .problem
        .constraints
        .iter()
        .find_map(|c| match &c.kind {
            ConstraintKind::Rolling {
                body: b,
                radius,
                axis,
                center,
                ..
            } if *b == body => Some(Disc {
                radius: n.scalar(radius),
                center: place(n, body, center),
                normal: axle(n, body, Some(axis))?,
            }),
            ConstraintKind::Gear {
                body: b,
                radius,
                center,
                axis,
                ..
            } if *b == body => Some(Disc {
                radius: n.scalar(radius),
                center: place(n, body, center),
                normal: axle(n, body, axis.as_ref())?,
            }),
            // A ring that a gear rolls inside is not a disc: its other rules draw it.
            ConstraintKind::Gear {
                body: gear,
                on,
                on_radius,
                on_center,
                axis,
                internal: false,
                ..
            } if *on == body => Some(Disc {
                radius: n.scalar(on_radius),
                center: place(n, body, on_center),
                normal: axle(n, *gear, axis.as_ref())?,
            }),
            _ => None,
        })
}

/// Rule 1: a body with a rolling contact or a gear is a wheel of the contact's radius
/// about its centre; points of the body beyond the rim hang on it by bars.
fn wheel(n: &Numbers, body: BodyId, size: f64) -> Option<(BodyKind, Vec<Shape>)> {
    let Disc {
        radius,
        center,
        normal,
    } = disc_of(n, body)?;
    let mut parts = vec![Shape::Wheel {
        center,
        normal,
        radius,
        mark: spoke(n, body, normal),
    }];
    for p in shapes::key_points(n, body) {
        let p = n.point_on(body, &p);
        if norm(sub(p, center)) > 1.05 * radius + 1e-6 * size {
            parts.push(Shape::Bar(vec![center, p]));
        }
    }
    Some((BodyKind::Disc, parts))
}

/// The points of the joints that hold `body`, as child and as parent, in `N` (a closure
/// counts too, at the body's origin: it only makes the body held at more than one point).
fn joint_points(n: &Numbers, body: BodyId) -> Vec<P3> {
    let model = n.model;
    let problem = model.problem;
    let touches = |j: &crate::problem::Joint| j.child == body || j.parent == body;
    let mut out: Vec<P3> = problem
        .joints
        .iter()
        .zip(&model.joints)
        .filter(|(j, _)| touches(j))
        .map(|(_, jm)| n.vector(&jm.point.position))
        .collect();
    for _ in problem.closures.iter().filter(|j| touches(j)) {
        out.push(center_of(n, body));
    }
    out
}

/// Rule 2: a planar body on one joint whose central inertia is m d²/3 (within 1 %) is a
/// uniform rod of length 2d, from the joint through the mass centre.
fn uniform_rod(n: &Numbers, body: BodyId) -> Option<(BodyKind, Vec<Shape>)> {
    if !n.model.is_planar() {
        return None;
    }
    let declared = n.model.problem.body(body);
    let (Inertia::Planar(izz), joints) = (&declared.inertia, joint_points(n, body)) else {
        return None;
    };
    let [pin] = joints.as_slice() else {
        return None;
    };
    let (m, i) = (n.scalar(&declared.mass), n.scalar(izz));
    let center = center_of(n, body);
    let d = norm(sub(center, *pin));
    let rod = m * d * d / 3.0;
    if !(d > 0.0 && rod > 0.0 && (i - rod).abs() <= 0.01 * rod) {
        return None;
    }
    let far = add(*pin, scale(sub(center, *pin), 2.0));
    Some((BodyKind::Rod, vec![Shape::Bar(vec![*pin, far])]))
}

/// Rule 3: a body without inertia is a ball at its mass centre.
fn particle(n: &Numbers, body: BodyId, size: f64) -> Option<(BodyKind, Vec<Shape>)> {
    let zero = match &n.model.problem.body(body).inertia {
        Inertia::Planar(i) => n.scalar(i) == 0.0,
        Inertia::Spatial(m) => m.iter().flatten().all(|e| n.scalar(e) == 0.0),
    };
    zero.then(|| (BodyKind::Particle, particle_parts(n, body, size)))
}

/// A ball at the mass centre, with a thin line from each of the body's other points.
fn particle_parts(n: &Numbers, body: BodyId, size: f64) -> Vec<Shape> {
    let center = center_of(n, body);
    let mut parts: Vec<Shape> = shapes::key_points(n, body)
        .iter()
        .map(|p| n.point_on(body, p))
        .filter(|p| norm(sub(*p, center)) > 1e-6 * size)
        .map(|from| Shape::LightRod { from, to: center })
        .collect();
    parts.push(Shape::Dot(center));
    parts
}

/// Rule 4: a rod or an outline through the body's points (a sliding block, a disc from
/// its inertia where the body is all at one point).
fn outline(n: &Numbers, body: BodyId, size: f64) -> (BodyKind, Vec<Shape>) {
    let parts = shapes::body(n, body, size);
    let kind = if parts.iter().any(|s| matches!(s, Shape::Polygon(_))) {
        let slides = n.model.problem.joint_of(body).is_some_and(|j| {
            matches!(
                n.model.problem.joints[j].kind,
                crate::problem::JointKind::Prismatic | crate::problem::JointKind::Cylindrical
            )
        });
        if slides {
            BodyKind::Block
        } else {
            BodyKind::Outline
        }
    } else if parts.iter().any(|s| matches!(s, Shape::Outline(_))) {
        BodyKind::Disc
    } else if parts.iter().all(|s| matches!(s, Shape::Dot(_))) {
        BodyKind::Particle
    } else {
        BodyKind::Rod
    };
    (kind, parts)
}

/// What rolling contacts run on: in 2D a line along the plane through the contact, long
/// enough to read as a floor or an incline (hatched when fixed in `N`, plain on a moving
/// body); in 3D a plane fixed in `N` is a patch of floor around its contacts, one per plane,
/// and one on a moving body a line; and the circle fixed in `N` that a gear rolls on or in,
/// hatched.
pub fn surfaces(n: &Numbers, size: f64) -> Vec<Shape> {
    let mut out = Vec::new();
    // Planes fixed in N in 3D: the normal, the contacts on it, the widest wheel's radius.
    let mut floors: Vec<(P3, Vec<P3>, f64)> = Vec::new();
    for c in &n.model.problem.constraints {
        match &c.kind {
            ConstraintKind::Rolling {
                body,
                on,
                normal,
                axis,
                ..
            } => {
                let (Some(up), Some(disc)) = (direction(n, *on, normal), disc_of(n, *body)) else {
                    continue;
                };
                let planar = n.model.is_planar();
                let (along, toward) = if planar {
                    (cross(up, [0.0, 0.0, 1.0]), scale(up, -1.0))
                } else {
                    let a = direction(n, *body, axis).unwrap_or([0.0, 0.0, 1.0]);
                    let rolling = unit(cross(a, up)).unwrap_or([1.0, 0.0, 0.0]);
                    // From the centre to the contact: down the disc's plane.
                    let w = sub(up, scale(a, dot(up, a)));
                    (rolling, scale(unit(w).unwrap_or(up), -1.0))
                };
                let contact = add(disc.center, scale(toward, disc.radius));
                if !planar && *on == BodyId::GROUND {
                    let same = |(u, points, _): &&mut (P3, Vec<P3>, f64)| {
                        dot(*u, up) > 1.0 - 1e-9
                            && dot(sub(contact, points[0]), up).abs() < 1e-6 * size
                    };
                    match floors.iter_mut().find(same) {
                        Some((_, points, radius)) => {
                            points.push(contact);
                            *radius = radius.max(disc.radius);
                        }
                        None => floors.push((up, vec![contact], disc.radius)),
                    }
                    continue;
                }
                // A block that carries the wheel shows the surface as its face.
                let carried = *on != BodyId::GROUND
                    && matches!(
                        self::body(n, *on, size),
                        Shape::Body {
                            kind: BodyKind::Block,
                            ..
                        }
                    );
                if planar && carried {
                    continue;
                }
                let reach = (3.0 * disc.radius).max(0.35 * size);
                out.push(Shape::Surface {
                    at: contact,
                    along: scale(along, reach),
                    up,
                    fixed: *on == BodyId::GROUND,
                });
            }
            ConstraintKind::Gear {
                body,
                on,
                on_radius,
                on_center,
                internal,
                axis,
                ..
            } if *on == BodyId::GROUND => {
                let Some(normal) = axle(n, *body, axis.as_ref()) else {
                    continue;
                };
                out.push(Shape::Track {
                    center: place(n, BodyId::GROUND, on_center),
                    normal,
                    radius: n.scalar(on_radius),
                    inside: *internal,
                });
            }
            _ => {}
        }
    }
    for (up, points, radius) in floors {
        out.push(Shape::Floor {
            corners: patch(&points, up, (2.0 * radius).max(0.25 * size)),
            up,
        });
    }
    out
}

/// The normal of the plane fixed in `N` that constraint `c` rolls a disc on, and the
/// disc's radius; `None` for any other constraint.
pub fn floor_of(n: &Numbers, c: usize) -> Option<(P3, f64)> {
    match &n.model.problem.constraints.get(c)?.kind {
        ConstraintKind::Rolling {
            body, on, normal, ..
        } if *on == BodyId::GROUND => Some((direction(n, *on, normal)?, disc_of(n, *body)?.radius)),
        _ => None,
    }
}

/// A patch of the plane through `points` with the unit normal `up`: the rectangle along
/// the plane's own directions (N.x where it lies in the plane) around the points, `pad`
/// wider on every side; its corners in order.
pub fn patch(points: &[P3], up: P3, pad: f64) -> [P3; 4] {
    let e1 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
        .iter()
        .find_map(|e| unit(sub(*e, scale(up, dot(*e, up)))).filter(|_| dot(*e, up).abs() < 0.9))
        .unwrap_or([1.0, 0.0, 0.0]);
    let e2 = cross(up, e1);
    let origin = points.first().copied().unwrap_or([0.0; 3]);
    let (mut lo, mut hi) = ([0.0f64; 2], [0.0f64; 2]);
    for p in points {
        let d = sub(*p, origin);
        let uv = [dot(d, e1), dot(d, e2)];
        if uv.iter().all(|x| x.is_finite()) {
            for k in 0..2 {
                lo[k] = lo[k].min(uv[k]);
                hi[k] = hi[k].max(uv[k]);
            }
        }
    }
    let at = |u: f64, v: f64| add(origin, add(scale(e1, u), scale(e2, v)));
    [
        at(lo[0] - pad, lo[1] - pad),
        at(hi[0] + pad, lo[1] - pad),
        at(hi[0] + pad, hi[1] + pad),
        at(lo[0] - pad, hi[1] + pad),
    ]
}

/// Gravity's direction, which the pictures draw down the page (in 3D, in the isometric view).
pub fn down(n: &Numbers) -> Option<P3> {
    let gravity = n.model.problem.gravity.as_ref()?;
    let g = n.local(&own_components(gravity, BodyId::GROUND));
    g.iter().all(|x| x.is_finite()).then(|| unit(g)).flatten()
}
