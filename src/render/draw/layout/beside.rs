//! An inertia force along a bar is drawn beside the bar, not inside it: an arrow whose
//! line would run within a body's outline (a rod's stroke, a block's polygon, a disc) is moved across
//! its own line, just clear of the body, keeping its direction and its place along the
//! line. Likewise an arrow that would lie on an earlier one of another direction (a top's
//! Ḣ on its m a*): arrows of one line stay stacked by length.

use super::super::numbers::{dot, unit, P3};
use super::super::picture::{Item, P2};
use super::super::scene::{Arrow, Kind};
use super::super::strokes::{p2add, p2norm, p2scale};
use super::Painter;

/// How far along the arrow its line is tried, in page units from its tail.
const SAMPLES: [f64; 4] = [6.0, 12.0, 18.0, 24.0];
/// How far across its line the arrow may move, nearest first.
const ACROSS: [f64; 5] = [6.0, 8.0, 10.0, 13.0, 16.0];
/// How far across its line an arrow that would lie on another's moves, nearest first.
const APART: [f64; 4] = [16.0, 20.0, 24.0, 30.0];
/// Closer than this to another arrow's line, a point lies on it.
const ON_A_LINE: f64 = 8.0;

impl Painter {
    /// The tail of an arrow from `at` along the unit `u`: `at` itself unless most of its
    /// line runs inside a body or any of it on another arrow, else the nearest spot across
    /// the line that is clear of both (or, failing that, the least crowded one).
    pub(super) fn beside_bodies(&self, at: P2, u: P2) -> P2 {
        let (bodies, lines) = self.crowding(at, u);
        if bodies < 2 && lines == 0 {
            return at;
        }
        let score = |(bodies, lines): (usize, usize)| 10 * lines + bodies;
        let mut best = (score((bodies, lines)), at);
        let across = [-u[1], u[0]];
        // Off another arrow's line, far enough that the two heads stand apart.
        let offsets: &[f64] = if lines > 0 { &APART } else { &ACROSS };
        for &d in offsets {
            for side in [1.0, -1.0] {
                let moved = p2add(at, p2scale(across, side * d));
                let crowding = self.crowding(moved, u);
                if crowding == (0, 0) {
                    return moved;
                }
                if score(crowding) < best.0 {
                    best = (score(crowding), moved);
                }
            }
        }
        best.1
    }

    /// Whether a straight force `arrow` at `at` along the unit `u`, `length` long, is drawn
    /// ending at its point: when starting there would run it inside a body (all samples but
    /// one; an arrow along a wheel's tangent grazes it only) and
    /// ending there runs less of it inside one (a contact's normal push, a pin's force
    /// along its bar); or when starting there crosses an arrow drawn before and ending
    /// there crosses fewer (a crank's weight across its pin's force). Inertia forces keep
    /// to their mass centres.
    pub(super) fn pushes_at(&self, arrow: &Arrow, at: P2, u: P2, length: f64) -> bool {
        if arrow.couple || arrow.kind == Kind::Inertia {
            return false;
        }
        // Another arrow at the point the opposite way (a weight under a normal force)
        // takes the room the arrow would end in.
        let along = |d: P3| unit(d).map_or(0.0, |d| dot(d, unit(arrow.direction).unwrap_or(d)));
        let here = |p: P2| p2norm([p[0] - at[0], p[1] - at[1]]) < 0.5;
        if (self.straight.iter()).any(|(p, d)| here(*p) && along(*d) < -0.99) {
            return false;
        }
        // An arrow drawn before already ends at the point: two heads would meet there.
        if self.lines.iter().any(|(_, tip)| here(*tip)) {
            return false;
        }
        let (inside, _) = self.crowding(at, u);
        let (ending, _) = self.crowding(p2add(at, p2scale(u, -length)), u);
        // A weight hangs from its mass centre unless that crosses another arrow.
        if arrow.kind != Kind::Gravity && inside + 1 >= SAMPLES.len() && ending < inside {
            return true;
        }
        ending + 1 < SAMPLES.len() && self.crosses_less_ending(at, u, length)
    }

    /// How many of the sample points along the arrow fall inside a body, and how many on
    /// an earlier arrow's line of another direction.
    pub(super) fn crowding(&self, at: P2, u: P2) -> (usize, usize) {
        let points: Vec<P2> = SAMPLES.iter().map(|&t| p2add(at, p2scale(u, t))).collect();
        let bodies = points
            .iter()
            .filter(|&&p| self.items.iter().any(|item| inside(item, p)))
            .count();
        let lines = points
            .iter()
            .filter(|&&p| {
                self.lines.iter().any(|&(a, b)| {
                    let v = [b[0] - a[0], b[1] - a[1]];
                    let length = p2norm(v).max(1e-9);
                    let same_line =
                        (v[0] * u[0] + v[1] * u[1]) / length > 0.9999 && to_line(a, v, at) < 1.0;
                    !same_line && to_segment(p, a, b) < ON_A_LINE
                })
            })
            .count();
        (bodies, lines)
    }
}

/// The distance of `p` from the infinite line through `a` along `v`.
fn to_line(a: P2, v: P2, p: P2) -> f64 {
    let length = p2norm(v).max(1e-9);
    ((p[0] - a[0]) * v[1] - (p[1] - a[1]) * v[0]).abs() / length
}

/// Whether `p` lies within a body's drawn outline.
pub(super) fn inside(item: &Item, p: P2) -> bool {
    let Item::Body { items, .. } = item else {
        return false;
    };
    items.iter().any(|part| match part {
        Item::Stroke(s) if s.closed && s.points.len() > 2 => in_polygon(&s.points, p),
        Item::Stroke(s) => s
            .points
            .windows(2)
            .any(|w| to_segment(p, w[0], w[1]) < s.width / 2.0 + 1.0),
        Item::Ellipse {
            center,
            rx,
            ry,
            angle,
            ..
        } => {
            let (sin, cos) = angle.to_radians().sin_cos();
            let d = [p[0] - center[0], p[1] - center[1]];
            let (x, y) = (d[0] * cos + d[1] * sin, -d[0] * sin + d[1] * cos);
            (x / rx).powi(2) + (y / ry).powi(2) < 1.0
        }
        Item::Circle { center, radius, .. } => {
            p2norm([p[0] - center[0], p[1] - center[1]]) < *radius + 1.0
        }
        _ => false,
    })
}

/// The distance of `p` from the segment `a`–`b`.
pub(super) fn to_segment(p: P2, a: P2, b: P2) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let length2 = d[0] * d[0] + d[1] * d[1];
    let t = if length2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p2norm([p[0] - a[0] - t * d[0], p[1] - a[1] - t * d[1]])
}

/// Even–odd test of `p` against the polygon `points`.
fn in_polygon(points: &[P2], p: P2) -> bool {
    let mut inside = false;
    let mut j = points.len() - 1;
    for i in 0..points.len() {
        let (a, b) = (points[i], points[j]);
        if (a[1] > p[1]) != (b[1] > p[1])
            && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
        {
            inside = !inside;
        }
        j = i;
    }
    inside
}
