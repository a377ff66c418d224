//! Sums of many dot products `Σ a_k · b_k` where the `a_k` are short (lever arms crossed
//! with a direction, partial velocities) and the `b_k` long (inertia forces).
//!
//! Parts of the `b_k` that meet the same part of an `a_k` are added up before anything is
//! multiplied out. In a chain, every body below a joint has the same lever-arm part and the
//! same partial-velocity part along each link above it, so a row costs one product per
//! pair of frames instead of one per body and pair of frames.

use super::frames::Frames;
use super::vector::{dot3, size, Components, Vector};
use crate::problem::BodyId;
use crate::symbolic::{add, Expr};

/// An accumulating `Σ a_k · b_k`.
pub struct DotSum<'a> {
    frames: &'a Frames,
    // (frame of the short part, the short part, frame of the long part, the long part)
    parts: Vec<(BodyId, Components, BodyId, Components)>,
}

impl<'a> DotSum<'a> {
    /// An empty sum.
    pub fn new(frames: &'a Frames) -> Self {
        DotSum {
            frames,
            parts: Vec::new(),
        }
    }

    /// Adds `short · long`.
    pub fn add(&mut self, short: &Vector, long: &Vector) {
        for (short_frame, a) in short.parts() {
            for (long_frame, b) in long.parts() {
                self.parts
                    .push((*short_frame, a.clone(), *long_frame, b.clone()));
            }
        }
    }

    /// The sum, multiplied out.
    pub fn total(mut self) -> Expr {
        self.parts.sort_by(|x, y| {
            (x.0.cmp(&y.0))
                .then_with(|| x.1.cmp(&y.1))
                .then(x.2.cmp(&y.2))
        });
        let mut terms = Vec::new();
        let mut rest = self.parts.as_slice();
        while let Some((short_frame, short, long_frame, _)) = rest.first() {
            let same = rest
                .iter()
                .take_while(|p| p.0 == *short_frame && p.1 == *short && p.2 == *long_frame)
                .count();
            let (group, tail) = rest.split_at(same);
            rest = tail;
            let long: Components =
                std::array::from_fn(|k| add(group.iter().map(|p| p.3[k].clone())));
            // As `Vector::dot` does: the shorter side is expressed in the other's frame.
            terms.push(if size(short) <= size(&long) {
                dot3(
                    &self.frames.express(short, *short_frame, *long_frame),
                    &long,
                )
            } else {
                dot3(
                    short,
                    &self.frames.express(&long, *long_frame, *short_frame),
                )
            });
        }
        add(terms)
    }
}
