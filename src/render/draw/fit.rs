//! The projection that fits a scene on the page: in 2D the plane turned so that gravity
//! points down the page, in 3D the view asked for; scaled so the system spans the content
//! box, with room around it for arrows and labels.

use super::numbers::{add, scale, unit, P3};
use super::picture::{Projection, View, P2};
use super::scene::{Scene, Shape};

/// The room around the system for arrows and labels.
pub const MARGIN: f64 = 90.0;
/// The largest extent of the system in the picture, unless the scene asks for less.
pub const CONTENT: f64 = 300.0;
/// Room for the caption above.
pub const TITLE: f64 = 26.0;

/// Every point of a shape in `N`, for fitting the picture.
fn shape_points(shape: &Shape) -> Vec<P3> {
    match shape {
        Shape::Body { parts, .. } => parts.iter().flat_map(shape_points).collect(),
        Shape::Wheel {
            center,
            normal,
            radius,
            ..
        } => super::numbers::circle(*center, *normal, *radius),
        Shape::LightRod { from, to } => vec![*from, *to],
        Shape::Track {
            center,
            normal,
            radius,
            ..
        } => super::numbers::circle(*center, *normal, *radius),
        Shape::Floor { corners, .. } => corners.to_vec(),
        Shape::Surface { at, along, .. } => vec![add(*at, *along), add(*at, scale(*along, -1.0))],
        Shape::Bar(p) | Shape::Polygon(p) | Shape::Outline(p) => p.clone(),
        Shape::Dot(p) | Shape::Pin(p) | Shape::Ball(p) | Shape::Weld(p) => vec![*p],
        Shape::Slider { at, .. } => vec![*at],
        Shape::Ground { at, along, .. } => vec![add(*at, *along), add(*at, scale(*along, -1.0))],
        Shape::Spring { from, to, .. }
        | Shape::Damper { from, to, .. }
        | Shape::Distance { from, to, .. }
        | Shape::Dashed { from, to } => vec![*from, *to],
        Shape::Triad { origin, .. } => origin.iter().copied().collect(),
        Shape::Angle { center, .. } | Shape::Velocity { at: center, .. } => vec![*center],
    }
}

/// The rows of a planar picture's map with unit scale: seen from +N.z, turned so that
/// `down` (gravity) points down the page; without it N.x right and N.y up. A rotation and
/// the flip of the page's y, so counterclockwise stays counterclockwise.
pub fn planar_rows(down: Option<P3>) -> [P3; 2] {
    match down.and_then(|g| unit([g[0], g[1], 0.0])) {
        Some(g) => [[-g[1], g[0], 0.0], [g[0], g[1], 0.0]],
        None => [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0]],
    }
}

/// The projection that fits `scene` into a box `content` px across at most, with `margin`
/// px around it for arrows and labels, and the picture's size.
pub fn fit(scene: &Scene, view: View, margin: f64, content: f64) -> (Projection, P2) {
    let rows = if scene.planar {
        planar_rows(scene.down)
    } else {
        view.rows_up(scene.down.map(|g| [-g[0], -g[1], -g[2]]))
    };
    let mut points: Vec<P3> = scene.shapes.iter().flat_map(shape_points).collect();
    points.extend(scene.markers.iter().map(|m| m.at));
    let unit_map = Projection {
        a: rows,
        b: [0.0, 0.0],
    };
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in points.iter().map(|p| unit_map.point(*p)) {
        if p.iter().all(|x| x.is_finite()) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    if lo[0] > hi[0] {
        (lo, hi) = ([0.0; 2], [0.0; 2]);
    }
    let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let s = if extent > 1e-12 {
        content / extent
    } else {
        100.0
    };
    let a = [scale(rows[0], s), scale(rows[1], s)];
    let width = (hi[0] - lo[0]) * s + 2.0 * margin;
    let height = (hi[1] - lo[1]) * s + 2.0 * margin + TITLE;
    let b = [margin - lo[0] * s, margin + TITLE - lo[1] * s];
    // At least wide enough for a long label beside a tall, thin body.
    let room = 280.0f64.max(width);
    let b = [b[0] + (room - width) / 2.0, b[1]];
    (Projection { a, b }, [room, height])
}
