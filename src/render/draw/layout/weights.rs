//! A weight hangs from its mass centre, as a textbook draws it. Where it would run onto
//! another force's line (the normal force under a disc) it is drawn shorter, ending a gap
//! before that force's point; a force at the mass centre itself along its line is drawn
//! from there the other way (a pin's vertical reaction at a wheel's centre). Only where
//! even a short weight would not stand clear, or where it would run along a bar that hides
//! it, is it drawn a gap to the side, a thin dashed leader joining it to the mass centre
//! it acts at: there it keeps off the other marked points and the other forces' arrows,
//! so that it does not read as acting at them.

use super::super::picture::{DrawnArrow, Item, P2};
use super::super::scene::{Arrow, Kind};
use super::super::strokes::{p2add, p2norm, p2scale, p2unit};
use super::beside::to_segment;
use super::Painter;

/// How far to the side the weight may move, nearest first (px at 13 px labels).
const GAPS: [f64; 6] = [16.0, 22.0, 30.0, 40.0, 52.0, 64.0];
/// Two lines closer than this over a common stretch are one line on the page.
const ON_A_LINE: f64 = 10.0;
/// Two arrows within this angle (degrees) of one line are parallel.
const PARALLEL: f64 = 10.0;
/// The gap a shortened weight leaves before another force's point on its line (px at
/// 13 px labels).
const SHORT_OF: f64 = 9.0;
/// The shortest a weight is drawn, as a fraction of an arrow's length.
const SHORTEST: f64 = 0.45;
/// Two points closer than this (px) are one point on the page.
const ONE_POINT: f64 = 2.0;
/// Closer than this (px) to a bar's stroke, an arrow reads as lying along the bar.
const BESIDE_A_BAR: f64 = 3.0;
/// A weight moved aside ends no closer than this (px at 13 px labels) to another marked
/// point, where it would read as acting there.
const OFF_A_POINT: f64 = 12.0;
/// Where along the weight's arrow a bar is looked for (fractions of its length).
const SAMPLES: [f64; 4] = [0.2, 0.4, 0.6, 0.8];

impl Painter {
    /// Where a weight's arrow starts and how long it is: from its mass centre `point`
    /// (`at`, or a length above it where it `pushes`), shortened before a force ahead on
    /// its line ([`weight_length`](Self::weight_length)); only where that does not serve,
    /// a gap to the side with a dashed leader from `point` (set in `drawn`).
    pub(super) fn weight(
        &mut self,
        drawn: &mut DrawnArrow,
        (point, at): (P2, P2),
        u: P2,
        (length, pushes): (f64, bool),
    ) -> (P2, f64) {
        if !pushes {
            // Shortened before a force ahead, unless it then runs along a bar, hidden by it.
            if let Some(short) = self.weight_length(at, u, length) {
                if !self.along_a_bar(at, u, short) {
                    return (at, short);
                }
            }
        }
        let Some(moved) = self.weight_aside(at, u, length) else {
            return (at, length);
        };
        // The leader joins the point to the arrow's end nearest it.
        let end = if pushes {
            p2add(moved, p2scale(u, length))
        } else {
            moved
        };
        self.thin_dashed(point, end);
        drawn.leader = Some((point, end));
        (moved, length)
    }

    /// Where the straight forces of `arrows` other than weights act (on the page) and
    /// which way (a unit vector on the page).
    pub(super) fn other_forces(&self, arrows: &[Arrow]) -> Vec<(P2, P2)> {
        (arrows.iter())
            .filter(|a| !a.couple && a.kind != Kind::Gravity)
            .filter_map(|a| {
                let u = p2unit(self.projection.direction(a.direction))?;
                Some((self.at(a.at), u))
            })
            .collect()
    }

    /// How long a weight from its mass centre `tail` along the unit `u` is drawn, at most
    /// `length`: shorter where another force's point lies ahead on its line, ending
    /// [`SHORT_OF`] before it; `None` where that leaves less than [`SHORTEST`] of it, or it
    /// would still lie on another force's line.
    pub(super) fn weight_length(&self, tail: P2, u: P2, length: f64) -> Option<f64> {
        let parallel = PARALLEL.to_radians().cos();
        let mut reach = length;
        for &(p, v) in &self.others {
            if (u[0] * v[0] + u[1] * v[1]).abs() < parallel {
                continue;
            }
            let d = [p[0] - tail[0], p[1] - tail[1]];
            let along = d[0] * u[0] + d[1] * u[1];
            let across = (d[0] * u[1] - d[1] * u[0]).abs();
            if across >= ON_A_LINE * self.reach {
                continue;
            }
            let same_way = u[0] * v[0] + u[1] * v[1] > 0.0;
            // Whether the other force, started at its point, would run inside a body: it is
            // then drawn ending there, from outside (a contact's push).
            let pushes = self.crowding(p, v).0 + 1 >= SAMPLES.len();
            if p2norm(d) < ONE_POINT {
                // At the mass centre itself: a force the other way goes from there the
                // other way; one the same way would lie on it.
                if same_way {
                    return None;
                }
            } else if along > 0.0 && same_way != pushes {
                // Ahead on its line, drawn away from the weight: the weight stops short.
                reach = reach.min(along - SHORT_OF * self.reach);
            } else if along > 0.0 || (along > -length && same_way != pushes) {
                // Ahead and drawn towards the weight, or behind it within its reach and
                // drawn towards it (one behind drawn away from it stands clear).
                return None;
            }
        }
        let reach = reach.min(self.short_of_other_bodies(tail, u, length));
        (reach >= SHORTEST * length).then_some(reach)
    }

    /// How long a weight from `tail` along the unit `u` may be drawn, at most `length`,
    /// ending [`SHORT_OF`] before any body its mass centre is not in (a disc's weight
    /// stops above the cart it stands on, where its tip would read as a push on the cart).
    fn short_of_other_bodies(&self, tail: P2, u: P2, length: f64) -> f64 {
        let own: Vec<&Item> = (self.items.iter())
            .filter(|item| super::beside::inside(item, tail))
            .collect();
        let gap = SHORT_OF * self.reach;
        let steps = ((length + gap) / 2.0).ceil() as usize;
        (0..=steps)
            .map(|k| 2.0 * k as f64)
            .find(|&t| {
                let p = p2add(tail, p2scale(u, t));
                (self.items.iter()).any(|item| {
                    matches!(item, Item::Body { .. })
                        && !own.iter().any(|o| std::ptr::eq(*o, item))
                        && super::beside::inside(item, p)
                })
            })
            .map_or(length, |t| (t - gap).min(length))
    }

    /// How far back from `at` along `-u` an arrow's tip must stop so that it is not hidden
    /// in a bar's stroke there (0 where no bar covers `at`).
    pub(super) fn clear_of_a_bar(&self, at: P2, u: P2) -> f64 {
        (0..=12)
            .map(f64::from)
            .find(|&s| !self.on_a_bar(p2add(at, p2scale(u, -s)), 0.0))
            .map_or(0.0, |s| if s > 0.0 { s + 1.5 } else { 0.0 })
    }

    /// Whether `p` lies within `margin` of a bar's stroke (its half width).
    fn on_a_bar(&self, p: P2, margin: f64) -> bool {
        self.items.iter().any(|item| match item {
            Item::Body { items, .. } => items.iter().any(|part| match part {
                Item::Stroke(s) if !s.closed && s.width >= 4.0 => s
                    .points
                    .windows(2)
                    .any(|w| to_segment(p, w[0], w[1]) < s.width / 2.0 + margin),
                _ => false,
            }),
            _ => false,
        })
    }

    /// The tail a weight from `tail` along the unit `u`, `length` long, is drawn from
    /// instead, when from `tail` it would lie on another force's line or along a bar:
    /// the nearest spot to the side clear of both that crosses no arrow (drawn before it,
    /// or after it either way along its line); `None` when it stands clear where it is, or
    /// no spot to the side serves.
    pub(super) fn weight_aside(&self, tail: P2, u: P2, length: f64) -> Option<P2> {
        if !self.weight_blocked(tail, u, length) {
            return None;
        }
        let across = [-u[1], u[0]];
        // Arrows drawn before it, and those drawn after it from or to their points.
        let crossed = |t: P2| {
            let tip = p2add(t, p2scale(u, length));
            let reach =
                |p: P2, v: P2| (p2add(p, p2scale(v, -length)), p2add(p, p2scale(v, length)));
            let later = (self.others.iter()).any(|&(p, v)| crosses((t, tip), reach(p, v)));
            // Its shaft by another marked point reads as acting there.
            let at_a_point = (self.points.iter())
                .filter(|p| p2norm([p[0] - tail[0], p[1] - tail[1]]) > ONE_POINT)
                .any(|&p| to_segment(p, t, tip) < OFF_A_POINT * self.reach);
            // Its shaft or head by another force's arrow reads as acting on it.
            let on_a_force = (self.others.iter()).any(|&(p, v)| {
                let (a, b) = reach(p, v);
                let apart = [to_segment(t, a, b), to_segment(tip, a, b)]
                    .into_iter()
                    .chain([to_segment(a, t, tip), to_segment(b, t, tip)])
                    .fold(f64::INFINITY, f64::min);
                apart < ON_A_LINE * self.reach
            });
            later || at_a_point || on_a_force || self.crossings(t, tip) > 0
        };
        GAPS.iter()
            .flat_map(|gap| [1.0, -1.0].map(|side| side * gap * self.reach))
            .map(|d| p2add(tail, p2scale(across, d)))
            .find(|&moved| !self.weight_blocked(moved, u, length) && !crossed(moved))
    }

    /// Whether a weight from `tail` along `u`, `length` long, lies on another force's
    /// line or along a bar.
    fn weight_blocked(&self, tail: P2, u: P2, length: f64) -> bool {
        let tip = p2add(tail, p2scale(u, length));
        let parallel = PARALLEL.to_radians().cos();
        let on_a_line = self.others.iter().any(|&(p, v)| {
            if (u[0] * v[0] + u[1] * v[1]).abs() < parallel {
                return false;
            }
            // The other arrow may start or end at its point: either way along its line.
            let (a, b) = (p2add(p, p2scale(v, -length)), p2add(p, p2scale(v, length)));
            (0..=10).any(|k| {
                let s = p2add(tail, p2scale(u, length * f64::from(k) / 10.0));
                to_segment(s, a, b) < ON_A_LINE * self.reach
            }) || to_segment(p, tail, tip) < ON_A_LINE * self.reach
        });
        on_a_line || self.along_a_bar(tail, u, length)
    }

    /// Whether most of an arrow from `tail` along `u`, `length` long, runs inside a bar's
    /// stroke, where the bar would hide it.
    fn along_a_bar(&self, tail: P2, u: P2, length: f64) -> bool {
        let on_bar = |p: P2| self.on_a_bar(p, BESIDE_A_BAR);
        let inside = SAMPLES
            .iter()
            .filter(|&&t| on_bar(p2add(tail, p2scale(u, t * length))))
            .count();
        inside + 1 >= SAMPLES.len() && p2norm(u) > 0.0
    }
}

/// Whether two segments cross, each one's ends strictly on either side of the other's line
/// (a weight whose tail lies on a pin force's line hangs from it, and does not cross it).
fn crosses((a, b): (P2, P2), (c, d): (P2, P2)) -> bool {
    let side = |p: P2, q: P2, r: P2| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}
