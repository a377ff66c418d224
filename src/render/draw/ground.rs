//! The fixed things a picture hatches: the ground, a surface that something slides or
//! rolls on, and a circular track.

use super::layout::Painter;
use super::numbers::P3;
use super::picture::{Ink, Item, Stroke, P2};
use super::strokes::{p2add, p2norm, p2scale, p2unit};

/// Half the arm of the cross that marks a track's axis (px).
const AXIS_CROSS: f64 = 7.0;

impl Painter {
    /// The fixed ground at `at`: a hatched line along `along`, or a small support.
    pub(super) fn ground(&mut self, at: P3, along: P3, up: P3) {
        let c = self.at(at);
        let u = p2unit(self.projection.direction(up)).unwrap_or([0.0, -1.0]);
        let mut t = p2unit(self.projection.direction(along)).unwrap_or([-u[1], u[0]]);
        let reach = p2norm(self.projection.direction(along));
        let (line_center, half) = if reach > 1e-9 {
            (p2add(c, p2scale(u, -9.0)), reach.max(30.0))
        } else if up == [0.0; 3] {
            (c, 12.0)
        } else {
            // A small support: a triangle from the pin to the ground line.
            let base = p2add(c, p2scale(u, -14.0));
            let tri = vec![
                c,
                p2add(base, p2scale(t, 9.0)),
                p2add(base, p2scale(t, -9.0)),
            ];
            self.stroke(tri, 1.2, Ink::Black, Some(Ink::Body), true);
            (base, 14.0)
        };
        if t[0] < 0.0 {
            t = p2scale(t, -1.0);
        }
        let a = p2add(line_center, p2scale(t, -half));
        let b = p2add(line_center, p2scale(t, half));
        let outside = std::mem::take(&mut self.items);
        self.stroke(vec![a, b], 1.4, Ink::Black, None, false);
        let count = ((2.0 * half) / 6.0).floor() as usize;
        for k in 0..=count {
            let s = p2add(a, p2scale(t, k as f64 * 2.0 * half / count.max(1) as f64));
            let e = p2add(s, p2add(p2scale(u, -6.0), p2scale(t, -5.0)));
            self.hatch_tick(s, e);
        }
        self.close_ground(outside, (a, b), u);
    }

    /// The items drawn since `outside` was taken, as one group of class `ground` (which a
    /// reader of the picture finds as the ground), its line `a`–`b` remembered with the
    /// page's unit `up`: the unit vectors stand above it, not in the ground.
    fn close_ground(&mut self, outside: Vec<Item>, (a, b): (P2, P2), up: P2) {
        let items = std::mem::replace(&mut self.items, outside);
        self.items.push(Item::Group {
            class: "ground",
            items,
        });
        self.grounds.push((a, b, up));
    }

    /// How many of the nine points of `room` (corners, edges' middles, centre) lie on the
    /// ground's side of a ground line, within its length.
    pub(super) fn under_ground(&self, room: &super::place::Box2) -> usize {
        let mut count = 0;
        for i in [-1.0, 0.0, 1.0] {
            for j in [-1.0, 0.0, 1.0] {
                let p = [
                    room.center[0] + i * room.half[0],
                    room.center[1] + j * room.half[1],
                ];
                let below = self.grounds.iter().any(|&(a, b, up)| {
                    let along = [b[0] - a[0], b[1] - a[1]];
                    let length = p2norm(along).max(1e-9);
                    let s = ((p[0] - a[0]) * along[0] + (p[1] - a[1]) * along[1]) / length;
                    let height = (p[0] - a[0]) * up[0] + (p[1] - a[1]) * up[1];
                    (-2.0..=length + 2.0).contains(&s) && height < 0.0
                });
                count += usize::from(below);
            }
        }
        count
    }

    /// A patch of floor through `corners` (in order): lightly filled, its edge thin, and
    /// the two edges lowest on the page hatched outwards, as a cut through the ground is;
    /// the patch's middle stays free for the bodies on it and their labels.
    pub(super) fn floor(&mut self, corners: &[P3; 4], up: P3) {
        let _ = up;
        let points: Vec<P2> = corners.iter().map(|p| self.at(*p)).collect();
        let middle = p2scale(points.iter().fold([0.0, 0.0], |m, p| p2add(m, *p)), 0.25);
        self.stroke(points.clone(), 1.0, Ink::Grey, Some(Ink::Floor), true);
        let mut edges: Vec<(P2, P2)> = (0..4).map(|k| (points[k], points[(k + 1) % 4])).collect();
        // The lowest two on the page: the near edges seen from above.
        edges.sort_by(|a, b| (b.0[1] + b.1[1]).total_cmp(&(a.0[1] + a.1[1])));
        for &(a, b) in &edges[..2] {
            let d = [b[0] - a[0], b[1] - a[1]];
            let (Some(t), length) = (p2unit(d), p2norm(d)) else {
                continue;
            };
            let mut n = [-t[1], t[0]];
            let mid = p2scale(p2add(a, b), 0.5);
            if (mid[0] - middle[0]) * n[0] + (mid[1] - middle[1]) * n[1] < 0.0 {
                n = p2scale(n, -1.0);
            }
            let count = (length / 7.0).floor().max(1.0) as usize;
            for k in 0..=count {
                let s = p2add(a, p2scale(t, k as f64 * length / count as f64));
                let e = p2add(s, p2add(p2scale(n, 6.0), p2scale(t, -4.0)));
                self.hatch_tick(s, e);
            }
        }
    }

    /// One thin tick of a hatching, from `s` to `e`, which labels keep clear of.
    fn hatch_tick(&mut self, s: P2, e: P2) {
        self.obstacles.segment(s, e);
        self.items.push(Item::Stroke(Stroke {
            points: vec![s, e],
            closed: false,
            width: 0.8,
            ink: Ink::Black,
            fill: None,
            dashed: false,
        }));
    }

    /// A hatched line through `at` along `along` (its half length), hatched away from `up`.
    pub(super) fn surface(&mut self, at: P3, along: P3, up: P3, fixed: bool) {
        let c = self.at(at);
        let u = p2unit(self.projection.direction(up)).unwrap_or([0.0, -1.0]);
        let t = p2unit(self.projection.direction(along)).unwrap_or([-u[1], u[0]]);
        let half = p2norm(self.projection.direction(along)).max(30.0);
        let (a, b) = (p2add(c, p2scale(t, -half)), p2add(c, p2scale(t, half)));
        if !fixed {
            self.stroke(vec![a, b], 1.4, Ink::Black, None, false);
            return;
        }
        let outside = std::mem::take(&mut self.items);
        self.stroke(vec![a, b], 1.4, Ink::Black, None, false);
        // The hatching's normal side, `n`, is the page's side away from `up`.
        let n = p2scale(u, -1.0);
        let count = ((2.0 * half) / 7.0).floor().max(1.0) as usize;
        for k in 0..=count {
            let s = p2add(a, p2scale(t, k as f64 * 2.0 * half / count as f64));
            let e = p2add(s, p2add(p2scale(n, 6.0), p2scale(t, -5.0)));
            self.hatch_tick(s, e);
        }
        self.close_ground(outside, (a, b), u);
    }

    /// A fixed circular track that a disc rolls on, hatched on the side away from it, its
    /// axis marked by a centre cross.
    pub(super) fn track(&mut self, center: P3, normal: P3, radius: f64, inside: bool) {
        let c = self.at(center);
        let rim: Vec<P2> = super::numbers::circle(center, normal, radius)
            .iter()
            .map(|p| self.at(*p))
            .collect();
        self.stroke(rim.clone(), 1.4, Ink::Black, None, true);
        // Its axis, which coordinates of what rolls on it may be measured from: a centre
        // cross, as a drawing marks a circle's centre.
        for arm in [[AXIS_CROSS, 0.0], [0.0, AXIS_CROSS]] {
            let (a, b) = (p2add(c, p2scale(arm, -1.0)), p2add(c, arm));
            self.stroke(vec![a, b], 0.8, Ink::Grey, None, false);
        }
        // A tick every 8 px along the rim, away from the disc: outward when it rolls
        // inside, inward when outside.
        let away = if inside { 1.0 } else { -1.0 };
        let mut to_next_tick = 0.0;
        for (k, &p) in rim.iter().enumerate() {
            let q = rim[(k + 1) % rim.len()];
            let (Some(along), length) = (
                p2unit([q[0] - p[0], q[1] - p[1]]),
                p2norm([q[0] - p[0], q[1] - p[1]]),
            ) else {
                continue;
            };
            while to_next_tick < length {
                let s = p2add(p, p2scale(along, to_next_tick));
                to_next_tick += 8.0;
                let Some(out) = p2unit([s[0] - c[0], s[1] - c[1]]) else {
                    continue;
                };
                let e = p2add(s, p2add(p2scale(out, 6.0 * away), p2scale(along, -4.0)));
                self.hatch_tick(s, e);
            }
            to_next_tick -= length;
        }
    }
}
