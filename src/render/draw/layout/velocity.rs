//! A velocity the problem names (the ball's v₀): a short black arrow from its point, apart
//! from the forces (the configuration carries none), drawn as one group
//! (`<g class="velocity">`).

use super::super::numbers::P3;
use super::super::picture::{Ink, Item, P2};
use super::super::scene::{Label, Shape};
use super::super::strokes::{head, p2add, p2scale, p2unit};
use super::Painter;

/// The arrow's length on the page.
const LENGTH: f64 = 36.0;
/// How far across its line the arrow stands from its point, on the page.
const OFF: f64 = 7.0;

impl Painter {
    /// Where the velocities among `shapes` start, on the page.
    pub(super) fn velocities(&self, shapes: &[Shape]) -> Vec<P2> {
        (shapes.iter())
            .filter_map(|s| match s {
                Shape::Velocity { at, .. } => Some(self.at(*at)),
                _ => None,
            })
            .collect()
    }

    /// The velocity `label` at `at` along `direction` (in `N`).
    pub(super) fn velocity(&mut self, at: P3, direction: P3, label: &Label) {
        let Some(u) = p2unit(self.projection.direction(direction)) else {
            return;
        };
        // A little above its point, off the spoke or bar that may start there along it.
        let across = if u[0] > 1e-9 || (u[0].abs() <= 1e-9 && u[1] < 0.0) {
            [u[1], -u[0]]
        } else {
            [-u[1], u[0]]
        };
        let o = p2add(self.at(at), p2scale(across, OFF));
        let tip = p2add(o, p2scale(u, LENGTH));
        let outside = std::mem::take(&mut self.items);
        self.stroke(vec![o, tip], 1.4, Ink::Black, None, false);
        self.stroke(
            head(tip, u).to_vec(),
            0.8,
            Ink::Black,
            Some(Ink::Black),
            true,
        );
        self.label(tip, u[1].atan2(u[0]), label, Ink::Black);
        let items = std::mem::replace(&mut self.items, outside);
        self.items.push(Item::Group {
            class: "velocity",
            items,
        });
    }
}
