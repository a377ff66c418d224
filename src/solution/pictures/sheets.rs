//! A body of the motion drawn as the still picture draws it: its shapes at the first frame
//! ([`super::bodies::body`]) taken into the body's own unit vectors and laid on sheets,
//! planes fixed in the body. In 2D one sheet, the plane of motion, holds them all; in 3D
//! each flat part (a disc's rim, a block's face, a bar) goes on a sheet whose plane holds
//! it, shared where parts lie in one plane.

use super::numbers::{add, cross, dot, norm, scale, sub, unit, Numbers, P3};
use crate::problem::BodyId;
use crate::render::draw::{Body, Part, Shape, Sheet};

/// A part in the body's unit vectors, before it is laid on a sheet.
enum Piece {
    Wheel {
        center: P3,
        normal: P3,
        radius: f64,
        mark: P3,
    },
    Bar(P3, P3),
    Line(P3, P3),
    Outline(Vec<P3>),
}

impl Piece {
    /// Points that fix the piece's plane.
    fn points(&self) -> Vec<P3> {
        match self {
            Piece::Wheel {
                center,
                normal,
                radius,
                mark,
            } => {
                let across = cross(*normal, *mark);
                vec![
                    *center,
                    add(*center, scale(*mark, *radius)),
                    add(*center, scale(across, *radius)),
                ]
            }
            Piece::Bar(a, b) | Piece::Line(a, b) => vec![*a, *b],
            Piece::Outline(p) => p.clone(),
        }
    }
}

/// `body` (number `index` of the motion's bodies) as drawn at the state of `n`, and its
/// sheets; `ball` is the marked point of its mass centre; `size` the system's length.
pub fn body_sheets(
    n: &Numbers,
    body: BodyId,
    index: usize,
    ball: usize,
    size: f64,
) -> (Body, Vec<Sheet>) {
    let (name, kind, parts) = match super::bodies::body(n, body, size) {
        Shape::Body { name, kind, parts } => (name, kind, parts),
        other => (
            n.model.problem.body_name(body).to_string(),
            crate::render::draw::BodyKind::Outline,
            vec![other],
        ),
    };
    let origin = n.point_on(body, &[0.0; 3]);
    let columns = [0, 1, 2].map(|k| {
        let mut e = [0.0; 3];
        e[k] = 1.0;
        n.in_ground(body, &e)
    });
    let local = |p: P3| columns.map(|c| dot(sub(p, origin), c));
    let turn = |v: P3| columns.map(|c| dot(v, c));
    let mut pieces = Vec::new();
    let mut has_ball = false;
    for part in &parts {
        match part {
            Shape::Wheel {
                center,
                normal,
                radius,
                mark,
            } => {
                let normal = turn(*normal);
                let mark = turn(*mark);
                let mark = unit(sub(mark, scale(normal, dot(mark, normal))))
                    .unwrap_or_else(|| plane_across(normal)[0]);
                pieces.push(Piece::Wheel {
                    center: local(*center),
                    normal,
                    radius: *radius,
                    mark,
                });
            }
            Shape::Bar(points) => {
                for w in points.windows(2) {
                    pieces.push(Piece::Bar(local(w[0]), local(w[1])));
                }
            }
            Shape::LightRod { from, to } => pieces.push(Piece::Line(local(*from), local(*to))),
            Shape::Polygon(points) | Shape::Outline(points) => {
                pieces.push(Piece::Outline(points.iter().map(|p| local(*p)).collect()));
            }
            Shape::Dot(_) => has_ball = true,
            _ => {}
        }
    }
    let center = n.local(&n.model.bodies[body.0].center_offset);
    let sheets = if n.model.is_planar() {
        let mut sheet = Sheet {
            body: index,
            origin: [0.0; 3],
            axes: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            parts: Vec::new(),
        };
        for piece in &pieces {
            sheet.parts.push(lay(&sheet, piece));
        }
        vec![sheet]
    } else {
        let mut sheets: Vec<Sheet> = Vec::new();
        for piece in &pieces {
            let points = piece.points();
            let holds = |s: &Sheet| {
                let normal = cross(s.axes[0], s.axes[1]);
                points
                    .iter()
                    .all(|p| dot(sub(*p, s.origin), normal).abs() <= 1e-6 * size)
            };
            let k = match sheets.iter().position(holds) {
                Some(k) => k,
                None => {
                    sheets.push(sheet_for(piece, center, index));
                    sheets.len() - 1
                }
            };
            let part = lay(&sheets[k], piece);
            sheets[k].parts.push(part);
        }
        sheets
    };
    (
        Body {
            name,
            kind,
            ball: has_ball.then_some(ball),
        },
        sheets,
    )
}

/// A new sheet whose plane holds `piece`; a bar's, through the body's centre when it can.
fn sheet_for(piece: &Piece, center: P3, body: usize) -> Sheet {
    let (origin, axes) = match piece {
        Piece::Wheel {
            center,
            normal,
            mark,
            ..
        } => (*center, [*mark, cross(*normal, *mark)]),
        Piece::Bar(a, b) | Piece::Line(a, b) => (*a, plane_through(*a, &[*b, center])),
        Piece::Outline(points) => {
            let first = points.first().copied().unwrap_or(center);
            (first, plane_through(first, points))
        }
    };
    Sheet {
        body,
        origin,
        axes,
        parts: Vec::new(),
    }
}

/// `piece` in the coordinates of `sheet`.
fn lay(sheet: &Sheet, piece: &Piece) -> Part {
    let on = |p: P3| {
        let d = sub(p, sheet.origin);
        [dot(d, sheet.axes[0]), dot(d, sheet.axes[1])]
    };
    match piece {
        Piece::Wheel {
            center,
            radius,
            mark,
            ..
        } => {
            let m = [dot(*mark, sheet.axes[0]), dot(*mark, sheet.axes[1])];
            let length = m[0].hypot(m[1]);
            Part::Wheel {
                center: on(*center),
                radius: *radius,
                mark: if length > 1e-12 {
                    [m[0] / length, m[1] / length]
                } else {
                    [1.0, 0.0]
                },
            }
        }
        Piece::Bar(a, b) => Part::Bar(vec![on(*a), on(*b)]),
        Piece::Line(a, b) => Part::Line(on(*a), on(*b)),
        Piece::Outline(points) => Part::Outline(points.iter().map(|p| on(*p)).collect()),
    }
}

/// Two unit vectors across `axis` (a disc's plane).
pub fn plane_across(axis: P3) -> [P3; 2] {
    let a = unit(axis).unwrap_or([0.0, 0.0, 1.0]);
    let helper = if a[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let e1 = unit(cross(helper, a)).unwrap_or([0.0, 1.0, 0.0]);
    [e1, cross(a, e1)]
}

/// Two unit vectors of a plane through `center` that holds the points as well as a plane
/// can: along the farthest point, then across towards the point farthest from that line.
pub fn plane_through(center: P3, points: &[P3]) -> [P3; 2] {
    let offsets: Vec<P3> = points.iter().map(|&p| sub(p, center)).collect();
    let farthest = offsets
        .iter()
        .copied()
        .max_by(|a, b| norm(*a).total_cmp(&norm(*b)));
    let Some(e1) = farthest.and_then(unit) else {
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    };
    let across = offsets
        .iter()
        .map(|&d| sub(d, scale(e1, dot(d, e1))))
        .max_by(|a, b| norm(*a).total_cmp(&norm(*b)));
    match across.and_then(|v| unit(v).filter(|_| norm(v) > 1e-6 * norm(farthest.unwrap_or(e1)))) {
        Some(e2) => [e1, e2],
        None => {
            let [_, e2] = plane_across(e1);
            [e1, e2]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sheet_across_an_axle_is_square_to_it() {
        let [e1, e2] = plane_across([0.0, 2.0, 0.0]);
        assert!(dot(e1, [0.0, 1.0, 0.0]).abs() < 1e-12);
        assert!(dot(e2, [0.0, 1.0, 0.0]).abs() < 1e-12);
        assert!(dot(e1, e2).abs() < 1e-12);
    }

    #[test]
    fn a_sheet_through_a_rim_holds_it() {
        let rim: Vec<P3> = (0..8)
            .map(|k| {
                let t = f64::from(k) * 0.7;
                [t.cos(), 0.5 * t.sin(), 0.5 * t.sin()]
            })
            .collect();
        let [e1, e2] = plane_through(rim[0], &rim);
        let normal = cross(e1, e2);
        for p in &rim {
            assert!(dot(sub(*p, rim[0]), normal).abs() < 1e-12);
        }
    }
}
