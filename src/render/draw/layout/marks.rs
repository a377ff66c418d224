//! The marks of a picture that are not bodies' outlines: a bar, a weld, a slider's
//! sleeve, and the dimension marks (an angle's arc, a distance's arrows).

use super::super::numbers::{add, cross, scale, P3};
use super::super::picture::{Ink, Item, Stroke, P2};
use super::super::scene::Label;
use super::super::strokes::{head, p2add, p2scale, p2unit};
use super::Painter;

/// An angle smaller than this (radians) has an arc too short to carry its head.
pub const SHORT_ANGLE: f64 = 0.15;
/// The sweep of the arc that shows a small angle's positive sense (radians, 45°).
pub const SENSE: f64 = std::f64::consts::FRAC_PI_4;
/// An angle's arc's radius on the page (px), and the most it grows to for a short angle.
pub const ARC: f64 = 30.0;
const LONGEST_ARC: f64 = 45.0;
/// An arc shorter than this (px) carries a smaller head, at least [`SMALLEST_HEAD`] of the
/// full one: a full head would be most of it.
const HEADS_ARC: f64 = 30.0;
const SMALLEST_HEAD: f64 = 0.55;
/// The least length (px) of an angle's arc, its head included, where its radius allows.
const ARC_LENGTH: f64 = 28.0;
/// The most of a wheel's radius an angle's arc about its centre takes.
const INSIDE_A_WHEEL: f64 = 0.7;
/// The least radius (px) of a drawn circle that counts as a wheel an arc keeps inside
/// (not a pin's or a hub's ring).
const LEAST_WHEEL: f64 = 12.0;
/// The radius (px) of an arc about a velocity's point: past its arrow (36 px) and head.
pub const ROUND_A_VELOCITY: f64 = 48.0;

impl Painter {
    /// A bar through `points`: a black line with the body's colour inside.
    pub(super) fn bar(&mut self, points: &[P3]) {
        let points: Vec<P2> = points.iter().map(|p| self.at(*p)).collect();
        self.stroke(points.clone(), 7.0, Ink::Black, None, false);
        self.items.push(Item::Stroke(Stroke {
            points,
            closed: false,
            width: 4.6,
            ink: Ink::Body,
            fill: None,
            dashed: false,
        }));
    }

    /// A weld at `p`: a small filled square.
    pub(super) fn weld(&mut self, p: P3) {
        let c = self.at(p);
        let square = [[-4.0, -4.0], [4.0, -4.0], [4.0, 4.0], [-4.0, 4.0]]
            .map(|d| p2add(c, d))
            .to_vec();
        self.stroke(square, 1.0, Ink::Black, Some(Ink::Black), true);
    }

    /// A slider's sleeve at `at`, along `axis`.
    pub(super) fn slider(&mut self, at: P3, axis: P3) {
        let c = self.at(at);
        let u = p2unit(self.projection.direction(axis)).unwrap_or([1.0, 0.0]);
        let n = [-u[1], u[0]];
        let corner = |a: f64, b: f64| p2add(c, p2add(p2scale(u, a), p2scale(n, b)));
        let sleeve = vec![
            corner(-13.0, -6.0),
            corner(13.0, -6.0),
            corner(13.0, 6.0),
            corner(-13.0, 6.0),
        ];
        self.stroke(sleeve, 1.2, Ink::Black, None, true);
    }

    /// An angle's arc about `center` from the direction `from`, turning about `axis` by
    /// `angle`, with its head and its label. An angle too small for its arc to show which
    /// way it counts (zero at the start) is drawn as the arc of its positive sense, a
    /// fixed [`SENSE`] from `from`, its head showing the way it grows.
    pub(super) fn angle(&mut self, center: P3, (from, axis): (P3, P3), angle: f64, label: &Label) {
        let sweep = if angle.abs() < SHORT_ANGLE {
            SENSE
        } else {
            angle
        };
        // A short angle's arc further out, long enough to carry its head and be seen; one
        // about a velocity's point round outside its arrow.
        let c = self.at(center);
        let moving = (self.moving.iter()).any(|m| (m[0] - c[0]).hypot(m[1] - c[1]) < 1.0);
        let radius = if moving {
            ROUND_A_VELOCITY
        } else {
            (ARC_LENGTH / sweep.abs()).clamp(ARC, LONGEST_ARC)
        };
        // About a wheel's centre the arc stays inside the wheel, clear of its rim and of
        // what touches it there (a mesh point, a contact); one round a velocity's arrow
        // goes round outside it still.
        let radius = match wheel_about(&self.items, c) {
            Some(rim) if !moving && rim < radius / INSIDE_A_WHEEL => rim * INSIDE_A_WHEEL,
            _ => radius,
        };
        let r = radius / self.scale;
        let v = cross(axis, from);
        let steps = 24;
        let points: Vec<P2> = (0..=steps)
            .map(|k| {
                let t = sweep * k as f64 / steps as f64;
                let d = add(scale(from, t.cos()), scale(v, t.sin()));
                self.at(add(center, scale(d, r)))
            })
            .collect();
        let n = points.len();
        if let Some(u) = p2unit([
            points[n - 1][0] - points[n - 2][0],
            points[n - 1][1] - points[n - 2][1],
        ]) {
            let shrink = (radius * sweep.abs() / HEADS_ARC).clamp(SMALLEST_HEAD, 1.0);
            let tip = points[n - 1];
            let h =
                head(tip, u).map(|p| p2add(tip, p2scale([p[0] - tip[0], p[1] - tip[1]], shrink)));
            self.stroke(h.to_vec(), 0.8, Ink::Grey, Some(Ink::Grey), true);
        }
        let middle = points[n / 2];
        let toward = (middle[1] - c[1]).atan2(middle[0] - c[0]);
        self.stroke(points, 1.0, Ink::Grey, None, false);
        self.pending.push((
            middle,
            toward,
            label.clone(),
            Ink::Black,
            super::labels::Beside::Arc(c),
        ));
    }

    /// A distance from `from` to `to`: its extension lines, the arrows and the label, on
    /// the side of the measured line where the dimension line runs through fewer bodies
    /// (above a cart's top, beside a ladder rather than across it).
    pub(super) fn distance(&mut self, from: P3, to: P3, label: &Label) {
        let (a, b) = (self.at(from), self.at(to));
        let Some(u) = p2unit([b[0] - a[0], b[1] - a[1]]) else {
            return;
        };
        let covered = |n: P2| {
            (0..=10)
                .map(|k| {
                    p2add(
                        a,
                        p2add(
                            p2scale([b[0] - a[0], b[1] - a[1]], 0.1 * f64::from(k)),
                            p2scale(n, 14.0),
                        ),
                    )
                })
                .filter(|p| (self.items.iter()).any(|item| super::beside::inside(item, *p)))
                .count()
        };
        let n = [-u[1], u[0]];
        let n = match covered(p2scale(n, -1.0)) < covered(n) {
            true => p2scale(n, -1.0),
            false => n,
        };
        let (a2, b2) = (p2add(a, p2scale(n, 14.0)), p2add(b, p2scale(n, 14.0)));
        self.thin_dashed(a, p2add(a, p2scale(n, 18.0)));
        self.thin_dashed(b, p2add(b, p2scale(n, 18.0)));
        self.stroke(vec![a2, b2], 0.9, Ink::Grey, None, false);
        for (tip, d) in [(b2, u), (a2, p2scale(u, -1.0))] {
            self.stroke(head(tip, d).to_vec(), 0.8, Ink::Grey, Some(Ink::Grey), true);
        }
        let middle = p2scale(p2add(a2, b2), 0.5);
        self.label(middle, n[1].atan2(n[0]), label, Ink::Black);
    }
}

/// The radius (px) of the smallest wheel drawn face on about the page point `c`, if any.
fn wheel_about(items: &[Item], c: P2) -> Option<f64> {
    let about = |center: &P2, radius: f64| {
        (radius >= LEAST_WHEEL && (center[0] - c[0]).hypot(center[1] - c[1]) < 1.0)
            .then_some(radius)
    };
    (items.iter())
        .filter_map(|item| match item {
            Item::Body { items, .. } | Item::Group { items, .. } => wheel_about(items, c),
            // A wheel seen face on: one seen aslant (an ellipse) turns in another plane
            // than the angles marked at its centre.
            Item::Circle { center, radius, .. } => about(center, *radius),
            _ => None,
        })
        .reduce(f64::min)
}
