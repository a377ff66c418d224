//! Arrows that would cross: a force drawn from its point across (or along) an arrow drawn
//! before it is drawn ending at its point instead, when that crosses fewer (the textbook's
//! way of keeping a crank's weight off its pin's force, or one weight off another's line).

use super::super::picture::P2;
use super::super::strokes::{p2add, p2scale};
use super::beside::to_segment;
use super::Painter;

/// The part of each end of an arrow where another may meet it (px): its head, its tail.
const END: f64 = 6.0;
/// Two arrows within this angle (degrees) of one line and [`BESIDE`] of each other (px
/// at 13 px labels) read as one.
const FAN: f64 = 30.0;
const BESIDE: f64 = 20.0;

/// Whether the segments `a`–`b` and `c`–`d` cross, each one's ends on either side of the
/// other's line.
fn cross(a: P2, b: P2, c: P2, d: P2) -> bool {
    let side = |p: P2, q: P2, r: P2| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}

/// Whether the segment `a`–`b` lies along `c`–`d` over part of it: the two within 8° of
/// one line and a point of the first within 1.5 px of the second.
fn along(a: P2, b: P2, c: P2, d: P2) -> bool {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [d[0] - c[0], d[1] - c[1]]);
    let (lu, lv) = (u[0].hypot(u[1]), v[0].hypot(v[1]));
    if lu == 0.0 || lv == 0.0 {
        return false;
    }
    let cos = (u[0] * v[0] + u[1] * v[1]) / (lu * lv);
    if cos.abs() < 8f64.to_radians().cos() {
        return false;
    }
    let to_cd = |p: P2| {
        let t = (((p[0] - c[0]) * v[0] + (p[1] - c[1]) * v[1]) / (lv * lv)).clamp(0.0, 1.0);
        (p[0] - c[0] - t * v[0]).hypot(p[1] - c[1] - t * v[1])
    };
    (0..=20).any(|k| {
        let t = f64::from(k) / 20.0;
        to_cd([a[0] + t * u[0], a[1] + t * u[1]]) < 1.5
    })
}

/// The segment `a`–`b` without `END` at each end (`None` when that leaves nothing).
fn middle(a: P2, b: P2) -> Option<(P2, P2)> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let length = d[0].hypot(d[1]);
    if length <= 2.0 * END {
        return None;
    }
    let u = [d[0] / length, d[1] / length];
    Some((p2add(a, p2scale(u, END)), p2add(b, p2scale(u, -END))))
}

impl Painter {
    /// How many arrows drawn so far the arrow from `tail` to `tip` crosses or lies along.
    pub(super) fn crossings(&self, tail: P2, tip: P2) -> usize {
        let Some((a, b)) = middle(tail, tip) else {
            return 0;
        };
        // A stack of two from one tail the same way is drawn on purpose: no crossing.
        let stacked = |(p, q): &(P2, P2)| {
            let (u, v) = (
                [tip[0] - tail[0], tip[1] - tail[1]],
                [q[0] - p[0], q[1] - p[1]],
            );
            let cos = (u[0] * v[0] + u[1] * v[1]) / (u[0].hypot(u[1]) * v[0].hypot(v[1]));
            (p[0] - tail[0]).hypot(p[1] - tail[1]) < 0.5 && cos > 0.999
        };
        (self.lines.iter())
            .filter(|l| !stacked(l))
            .filter_map(|(p, q)| middle(*p, *q))
            .filter(|(c, d)| cross(a, b, *c, *d) || along(a, b, *c, *d))
            .count()
    }

    /// The tail of a moment vector (3D) at `at` along the unit `u`, `length` long: a couple
    /// is free, so it may end at its point or stand beside it, whichever of those (in
    /// that order, nearest first) crosses no arrow drawn before it; else the one that
    /// crosses fewest.
    pub(super) fn free_couple(&self, at: P2, u: P2, length: f64, inertia: bool) -> P2 {
        let across = [-u[1], u[0]];
        let mut tails = vec![at, p2add(at, p2scale(u, -length))];
        // The kinetic diagram's moment vector may go further, off its m a*.
        let offsets: &[f64] = if inertia {
            &[16.0, 24.0, 32.0, 44.0, 56.0]
        } else {
            &[16.0, 24.0, 32.0]
        };
        for &d in offsets {
            for side in [1.0, -1.0] {
                let moved = p2add(at, p2scale(across, side * d));
                tails.push(moved);
                tails.push(p2add(moved, p2scale(u, -length)));
            }
        }
        let mut best = (usize::MAX, at);
        for tail in tails {
            let tip = p2add(tail, p2scale(u, length));
            // In the kinetic diagram two arrows side by side read as one (a crossing
            // worse still); a free body's couples keep off crossings only.
            let fanned = if inertia { self.fanned(tail, tip) } else { 0 };
            let count = 2 * self.crossings(tail, tip) + fanned;
            if count == 0 {
                return tail;
            }
            if count < best.0 {
                best = (count, tail);
            }
        }
        best.1
    }

    /// How many arrows drawn so far run within [`FAN`] of the arrow from `tail` to `tip`
    /// and within [`BESIDE`] of it: two such arrows read as one (a moment vector beside
    /// `m a*` at a mass centre).
    fn fanned(&self, tail: P2, tip: P2) -> usize {
        let u = [tip[0] - tail[0], tip[1] - tail[1]];
        let lu = u[0].hypot(u[1]);
        if lu == 0.0 {
            return 0;
        }
        let close = FAN.to_radians().cos();
        let samples: Vec<P2> = (1..=4)
            .map(|k| p2add(tail, p2scale(u, f64::from(k) / 5.0)))
            .collect();
        (self.lines.iter())
            .filter(|&&(a, b)| {
                let v = [b[0] - a[0], b[1] - a[1]];
                let lv = v[0].hypot(v[1]);
                lv > 0.0
                    && ((u[0] * v[0] + u[1] * v[1]) / (lu * lv)).abs() > close
                    && samples
                        .iter()
                        .any(|&p| to_segment(p, a, b) < BESIDE * self.reach)
            })
            .count()
    }

    /// Whether an arrow `length` long along the unit `u` crosses fewer arrows drawn
    /// before it ending at `at` than starting there (and crosses some starting there).
    pub(super) fn crosses_less_ending(&self, at: P2, u: P2, length: f64) -> bool {
        let starting = self.crossings(at, p2add(at, p2scale(u, length)));
        starting > 0 && self.crossings(p2add(at, p2scale(u, -length)), at) < starting
    }
}

#[cfg(test)]
mod tests {
    use super::{along, cross};

    #[test]
    fn segments_cross_only_through_each_other() {
        assert!(cross([0.0, 0.0], [10.0, 0.0], [5.0, -5.0], [5.0, 5.0]));
        assert!(!cross([0.0, 0.0], [10.0, 0.0], [5.0, 1.0], [5.0, 5.0]));
        assert!(!cross([0.0, 0.0], [10.0, 0.0], [0.0, 1.0], [10.0, 1.0]));
        assert!(along([0.0, 0.0], [10.0, 0.0], [5.0, 1.0], [20.0, 1.0]));
        assert!(!along([0.0, 0.0], [10.0, 0.0], [0.0, 4.0], [10.0, 4.0]));
        assert!(!along([0.0, 0.0], [10.0, 0.0], [5.0, -5.0], [5.0, 5.0]));
    }
}
