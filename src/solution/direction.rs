//! A direction written in the frame that makes it simplest: a gear's tangent, built as
//! s_{q_A} â_x + c_{q_A} â_y in the pinion's frame, is n̂_y.

use super::tex::vector_tex;
use crate::mechanics::{Model, Vector};
use crate::problem::BodyId;

/// The most rotations between the frame a direction is built in and a frame it is tried
/// in: beyond it the matrix is composed from named entries, never shorter.
const MOST_ROTATIONS: usize = 3;

/// `v` in LaTeX, written in whichever frame gives the shortest text (its own first, then
/// N, then the bodies in order; the first of equal lengths).
pub fn simplest_tex(model: &Model, v: &Vector) -> String {
    let written = vector_tex(model, v);
    let [(own, _)] = v.parts() else {
        return written;
    };
    let frames = &model.frames;
    let mut best = written;
    for index in 0..frames.len() {
        let frame = BodyId(index);
        if frame == *own || frames.rotations_between(frame, *own).len() > MOST_ROTATIONS {
            continue;
        }
        let turned = Vector::new(frame, v.components_in(frame, frames));
        let tex = vector_tex(model, &turned);
        if tex.len() < best.len() {
            best = tex;
        }
    }
    best
}
