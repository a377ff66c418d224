//! A planar couple's curl turned so that its open quarter faces the straight arrows at its
//! point: the kinetic diagram's `m a*` leaves the mass centre through the gap of `I α`'s
//! curl, not across it, and a pin's force components leave through a reaction moment's.

use super::super::picture::P2;
use super::super::strokes::{p2add, p2norm, p2unit};
use super::beside::to_segment;
use super::Painter;

/// The curl's start when nothing is in its way (its gap then opens to the lower right).
pub(super) const START: f64 = std::f64::consts::FRAC_PI_4 * 3.0;
/// Closer than this (px) to a line, a point of the curl lies on it.
const ON: f64 = 4.0;
/// The length (px) of a curl's head along its arc, and the least room (px) between the
/// curl's ends and a line beyond [`ON`].
const HEAD: f64 = 9.0;
const CLEAR: f64 = 3.0;
/// How far along a straight arrow's line, from its point, it is expected to reach (px).
const REACH: f64 = 60.0;

impl Painter {
    /// The page directions of the panel's straight arrows that act at `at`.
    pub(super) fn rays_at(&self, at: P2) -> Vec<P2> {
        (self.straight.iter())
            .filter(|(p, _)| p2norm([p[0] - at[0], p[1] - at[1]]) < 0.5)
            .map(|(_, d)| self.projection.direction(*d))
            .collect()
    }

    /// The start angle of a curl of `radius` and `sweep` about `at` whose points meet the
    /// fewest lines: the arrows drawn so far, and the rays of the straight arrows still to be
    /// drawn from `at` (`pending`, page directions); [`START`] when it meets none there.
    pub(super) fn curl_start(&self, at: P2, radius: f64, sweep: f64, pending: &[P2]) -> f64 {
        let mut lines: Vec<(P2, P2)> = self.lines.clone();
        for u in pending.iter().filter_map(|u| p2unit(*u)) {
            lines.push((at, p2add(at, [u[0] * REACH, u[1] * REACH])));
        }
        let on_a_line = |t: f64, near: f64| {
            let p = [at[0] + radius * t.cos(), at[1] + radius * t.sin()];
            lines.iter().any(|(a, b)| to_segment(p, *a, *b) < near)
        };
        // Crossing an arrow on its way round is how a textbook draws a curl among forces;
        // its head or its tail on an arrow reads as a mark on that arrow: never, where a
        // start keeps both ends off every arrow.
        let meets = |start: f64| -> usize {
            let crossings = (0..=24)
                .map(|k| start + sweep * f64::from(k) / 24.0)
                .filter(|t| on_a_line(*t, ON))
                .count();
            let step = sweep.signum() * HEAD / radius;
            let ends = (0..=3)
                .flat_map(|k| {
                    let along = step * f64::from(k) / 3.0;
                    [start + sweep - along, start + along]
                })
                .filter(|t| on_a_line(*t, ON + CLEAR))
                .count();
            crossings + 100 * ends
        };
        let mut best = (meets(START), START);
        for k in 1..16 {
            let start = START + std::f64::consts::PI * f64::from(k) / 8.0;
            let count = meets(start);
            if count < best.0 {
                best = (count, start);
            }
        }
        best.1
    }
}

#[cfg(test)]
mod tests {
    use super::to_segment;

    #[test]
    fn distances_to_a_segment_are_measured_to_its_nearest_point() {
        assert!((to_segment([5.0, 3.0], [0.0, 0.0], [10.0, 0.0]) - 3.0).abs() < 1e-12);
        assert!((to_segment([13.0, 4.0], [0.0, 0.0], [10.0, 0.0]) - 5.0).abs() < 1e-12);
    }
}
