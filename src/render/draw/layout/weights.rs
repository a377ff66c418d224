//! A weight that would lie on another force's line (a pin's vertical reaction at a wheel's
//! centre, the normal force under a disc, a pin force below a crank) or along a bar (an
//! upright rocker's) is drawn a clear gap to the side, a thin dashed leader joining it to
//! the mass centre it acts at: the two arrows read apart, and the point stays shown.

use super::super::picture::{Item, P2};
use super::super::scene::{Arrow, Kind};
use super::super::strokes::{p2add, p2norm, p2scale, p2unit};
use super::beside::to_segment;
use super::Painter;

/// How far to the side the weight may move, nearest first (px at 13 px labels).
const GAPS: [f64; 4] = [16.0, 22.0, 30.0, 40.0];
/// Two lines closer than this over a common stretch are one line on the page.
const ON_A_LINE: f64 = 10.0;
/// Two arrows within this angle (degrees) of one line are parallel.
const PARALLEL: f64 = 10.0;
/// Where along the weight's arrow a bar is looked for (fractions of its length).
const SAMPLES: [f64; 4] = [0.2, 0.4, 0.6, 0.8];

impl Painter {
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
            later || self.crossings(t, tip) > 0
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
        let on_bar = |p: P2| {
            self.items.iter().any(|item| match item {
                Item::Body { items, .. } => items.iter().any(|part| match part {
                    Item::Stroke(s) if !s.closed && s.width >= 4.0 => s
                        .points
                        .windows(2)
                        .any(|w| to_segment(p, w[0], w[1]) < s.width / 2.0 + 1.5),
                    _ => false,
                }),
                _ => false,
            })
        };
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
