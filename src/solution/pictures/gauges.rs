//! The coordinates' marks: an arc for each angle at its joint, from where the child's line
//! lay at zero, and a dimension line for each distance. One list per problem, the same at
//! every state, so that the still picture draws it and the motion moves it frame by frame.

use super::numbers::{add, dot, norm, rotate, scale, sub, unit, Numbers, P3};
use super::shapes;
use crate::problem::{BodyId, JointKind};
use crate::render::draw::{layout, Gauge, Label, Shape};
use crate::symbolic::latex;

/// One coordinate's mark.
#[derive(Clone, Debug, PartialEq)]
pub struct Gauged {
    /// The coordinate (an index into the problem's coordinates).
    pub coordinate: usize,
    /// Its symbol.
    pub label: Label,
    /// Where it is drawn at this state; `None` where it has no direction to be drawn in
    /// (the child's line along the joint's axis).
    pub at: Option<Gauge>,
}

/// Every coordinate's mark at the state of `n`; `size` is the system's length. The list
/// depends only on the problem, not on the state.
pub fn gauges(n: &Numbers, size: f64) -> Vec<Gauged> {
    let model = n.model;
    let problem = model.problem;
    let mut out = Vec::new();
    for (j, joint) in problem.joints.iter().enumerate() {
        let jm = &model.joints[j];
        let label = |k: usize| {
            let c = joint.coordinates[k];
            Label::from_tex(&latex(&problem.coordinate_expr(c, 0)))
        };
        let value = |k: usize| {
            n.values
                .get(&problem.coordinate_symbol(joint.coordinates[k], 0))
        };
        let mut push = |k: usize, at: Option<Gauge>| {
            out.push(Gauged {
                coordinate: joint.coordinates[k],
                label: label(k),
                at,
            });
        };
        let at = n.vector(&jm.point.position);
        let base = n.point_on(joint.parent, &n.local(&jm.at));
        let axis = jm
            .motion
            .written_axis
            .as_ref()
            .map(|a| n.in_ground(joint.parent, &n.local(a)))
            .and_then(unit);
        let along = |axis: Option<P3>| {
            axis.or_else(|| unit(sub(at, base)))
                .unwrap_or([1.0, 0.0, 0.0])
        };
        match joint.kind {
            JointKind::Revolute | JointKind::Cylindrical => {
                let k = usize::from(joint.kind == JointKind::Cylindrical);
                if let Some(axis) = axis {
                    push(k, angle(n, joint.child, at, axis, value(k), size));
                }
                if k == 1 {
                    push(
                        0,
                        Some(Gauge::Distance {
                            from: base,
                            to: at,
                            along: along(axis),
                        }),
                    );
                }
            }
            JointKind::Prismatic => push(
                0,
                Some(Gauge::Distance {
                    from: base,
                    to: at,
                    along: along(axis),
                }),
            ),
            JointKind::Planar if model.is_planar() => {
                let x = n.in_ground(joint.parent, &[1.0, 0.0, 0.0]);
                let y = n.in_ground(joint.parent, &[0.0, 1.0, 0.0]);
                let corner = add(base, scale(x, value(0)));
                for (from, to, k, along) in [(base, corner, 0, x), (corner, at, 1, y)] {
                    push(k, Some(Gauge::Distance { from, to, along }));
                }
                // An angle the constraints hold at zero (a collar on its rod) has no arc:
                // its label alone would name whatever is drawn beside it.
                let held =
                    problem.coordinates[joint.coordinates[2]].dependent && value(2).abs() < 1e-9;
                push(
                    2,
                    (!held).then(|| Gauge::Angle {
                        center: at,
                        from: planar_from(n, joint.child, (x, y), size),
                        axis: [0.0, 0.0, 1.0],
                        angle: value(2),
                        reference: 0.25 * size,
                    }),
                );
            }
            JointKind::Spherical => {
                let values = [value(0), value(1), value(2)];
                for (k, gauge) in euler(n, joint, (at, at), values, size) {
                    push(k, gauge);
                }
            }
            JointKind::Free => {
                let values: [f64; 6] = std::array::from_fn(value);
                for (k, gauge) in free(n, joint, (base, at), values, size) {
                    push(k, gauge);
                }
            }
            _ => {}
        }
    }
    out
}

/// A free joint's six marks: x, y, z as the legs of a box from the parent's point
/// `base` (along x, then y, then up z to the body's point `at`), then its three turns
/// (see [`euler`]), the first (a heading about the vertical) drawn at the foot of the
/// body's point on the plane across its axis, the others at the point.
fn free(
    n: &Numbers,
    joint: &crate::problem::Joint,
    (base, at): (P3, P3),
    values: [f64; 6],
    size: f64,
) -> Vec<(usize, Option<Gauge>)> {
    let p: [P3; 3] = std::array::from_fn(|i| {
        let mut e = [0.0; 3];
        e[i] = 1.0;
        n.in_ground(joint.parent, &e)
    });
    let mut out = Vec::new();
    let mut from = base;
    for (k, along) in p.iter().enumerate() {
        let to = if k == 2 {
            at
        } else {
            add(from, scale(*along, values[k]))
        };
        out.push((
            k,
            Some(Gauge::Distance {
                from,
                to,
                along: *along,
            }),
        ));
        from = to;
    }
    let first = joint.sequence.first().map_or(2, |a| usize::from(*a));
    let foot = sub(at, scale(p[first], dot(sub(at, base), p[first])));
    let turns = [values[3], values[4], values[5]];
    for (k, gauge) in euler(n, joint, (foot, at), turns, size) {
        out.push((3 + k, gauge));
    }
    out
}

/// The parent's unit vector a planar joint's angle is drawn from: `x`, or `y` where the
/// child's line (its farthest key point from its centre) lies along its own y axis (a
/// ladder whose angle is measured from the vertical), so that the arc ends on the body as
/// drawn. A wheel's line is its spoke, along its own x axis, not the line to its contact
/// (a disc's turn is drawn at the disc, from its spoke's line, not along the line to the
/// cylinder's axis). The angle turns either into the other by the same amount.
fn planar_from(n: &Numbers, child: BodyId, (x, y): (P3, P3), size: f64) -> P3 {
    let wheel = match super::bodies::body(n, child, size) {
        Shape::Body { parts, .. } => parts.iter().any(|p| matches!(p, Shape::Wheel { .. })),
        _ => false,
    };
    if wheel {
        return x;
    }
    let center = n.local(&n.model.bodies[child.0].center_offset);
    let line = shapes::key_points(n, child)
        .into_iter()
        .map(|p| sub(p, center))
        .fold(
            [0.0; 3],
            |best, p| if norm(p) > norm(best) { p } else { best },
        );
    if line[1].abs() > line[0].abs() {
        y
    } else {
        x
    }
}

/// The three turns of a joint's body-fixed sequence `a b c` (a top's `zxz`, a coin's
/// `zxy`), each drawn as a textbook draws it: the first about the parent's `a` axis from
/// its `b` axis (a precession or heading from n̂_x to the line of nodes), at `first_at`;
/// the second about that turned `b` axis from the parent's `a` axis (a tilt or lean from
/// the vertical), at `at`; the third about the body's `c` axis from where the second left
/// the `a` axis (the `b` axis, the line of nodes, where `a` is `c`), at the point of that
/// axis nearest the body's mass centre (a top's spin at its centre, not at its tip). Each
/// with its coordinate's index in the joint; `None` where its axes leave it undrawn (a
/// sequence of other than three turns).
fn euler(
    n: &Numbers,
    joint: &crate::problem::Joint,
    (first_at, at): (P3, P3),
    values: [f64; 3],
    size: f64,
) -> Vec<(usize, Option<Gauge>)> {
    let [a, b, c] = joint.sequence.as_slice() else {
        return (0..3).map(|k| (k, None)).collect();
    };
    let [a, b, c] = [*a, *b, *c].map(usize::from);
    let parent: [P3; 3] = std::array::from_fn(|i| {
        let mut e = [0.0; 3];
        e[i] = 1.0;
        n.in_ground(joint.parent, &e)
    });
    let once = parent.map(|e| rotate(e, parent[a], values[0]));
    let twice = once.map(|e| rotate(e, once[b], values[1]));
    let third_from = if a == c { twice[b] } else { twice[a] };
    let center = n.vector(&n.model.bodies[joint.child.0].center.position);
    let spin_at = add(at, scale(twice[c], dot(sub(center, at), twice[c])));
    let turn = |center: P3, from: P3, axis: P3, angle: f64, reference: f64| {
        unit(axis).map(|axis| Gauge::Angle {
            center,
            from,
            axis,
            angle,
            reference,
        })
    };
    vec![
        (
            0,
            turn(first_at, parent[b], parent[a], values[0], 0.3 * size),
        ),
        (1, turn(at, parent[a], once[b], values[1], 0.3 * size)),
        (
            2,
            turn(spin_at, third_from, twice[c], values[2], 0.2 * size),
        ),
    ]
}

/// The arc of a relative angle `q` at a joint at `at`, from where the child's line lay at
/// zero: turned back by `q` about the axis from where it lies now.
fn angle(n: &Numbers, child: BodyId, at: P3, axis: P3, q: f64, size: f64) -> Option<Gauge> {
    let model = n.model;
    let joint = model.problem.joint_of(child).map(|j| &model.joints[j]);
    let child_at = joint.map_or([0.0; 3], |jm| n.local(&jm.child_at));
    let center = n.local(&model.bodies[child.0].center_offset);
    let mut line = sub(center, child_at);
    if norm(line) < 1e-6 * size {
        line = shapes::key_points(n, child)
            .into_iter()
            .map(|p| sub(p, child_at))
            .fold(
                [1.0, 0.0, 0.0],
                |best, p| if norm(p) > norm(best) { p } else { best },
            );
    }
    let now = n.in_ground(child, &line);
    let now = unit(sub(now, scale(axis, dot(now, axis))))?;
    Some(Gauge::Angle {
        center: at,
        from: rotate(now, axis, -q),
        axis,
        angle: q,
        reference: 0.3 * size,
    })
}

/// Angle arcs (each with its dashed line where the child lay at zero) and dimension
/// lines for the coordinates; a distance that is zero now is left out.
pub(super) fn shapes(n: &Numbers, size: f64) -> Vec<Shape> {
    let mut shapes = Vec::new();
    for gauge in gauges(n, size) {
        let value = (n.values).get(&n.model.problem.coordinate_symbol(gauge.coordinate, 0));
        let label = match gauge.at {
            // A dimension line is drawn the way it points: a coordinate below zero is
            // the length of the opposite way, −y, not y.
            Some(Gauge::Distance { .. }) if value < 0.0 => {
                Label::from_tex(&format!("-{}", gauge.label.tex))
            }
            _ => gauge.label,
        };
        match gauge.at {
            Some(Gauge::Angle {
                center,
                from,
                axis,
                angle,
                reference,
            }) => {
                shapes.push(Shape::Dashed {
                    from: center,
                    to: add(center, scale(from, reference)),
                });
                // An angle below zero is drawn the way angles count, from the child's
                // line back to where it lay at zero: the arc of −q, its head showing
                // the positive sense.
                let (from, angle, label) = if angle <= -layout::SHORT_ANGLE {
                    let minus = Label {
                        plain: format!("\u{2212}{}", label.plain),
                        tex: format!("-{}", label.tex),
                    };
                    (rotate(from, axis, angle), -angle, minus)
                } else {
                    (from, angle, label)
                };
                shapes.push(Shape::Angle {
                    center,
                    from,
                    axis,
                    angle,
                    label,
                });
            }
            Some(Gauge::Distance { from, to, .. }) if norm(sub(to, from)) > 1e-6 * size => {
                shapes.push(Shape::Distance { from, to, label });
            }
            _ => {}
        }
    }
    shapes
}

/// The lengths the statement names on a body: a mass centre written as one constant
/// along one of the body's unit vectors from its origin (a top's `h` from its tip), as a
/// dimension line from the origin to the centre named by the constant. None for a
/// centre written any other way (a rod's `L/2`, whose length the bar shows).
pub(super) fn named_lengths(n: &Numbers, size: f64) -> Vec<Shape> {
    let model = n.model;
    let problem = model.problem;
    let mut out = Vec::new();
    for body in problem.body_ids() {
        let [(frame, _, c)] = problem.body(body).center.terms.as_slice() else {
            continue;
        };
        let Some(symbol) = c.as_symbol() else {
            continue;
        };
        if *frame != body || !matches!(symbol, crate::symbolic::Symbol::Const(_)) {
            continue;
        }
        let from = n.vector(&model.bodies[body.0].origin.position);
        let to = n.vector(&model.bodies[body.0].center.position);
        if norm(sub(to, from)) > 1e-6 * size {
            out.push(Shape::Distance {
                from,
                to,
                label: Label::from_tex(&latex(c)),
            });
        }
    }
    out
}
