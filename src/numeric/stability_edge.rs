//! A `stability` answer's values: each change of stability found, named by what happens
//! beyond it as the constant grows (`stable`, `unstable`) and `~` where the eigenvalue
//! crossing zero is one of an oscillation. Written by the pipeline, read by the handout.

use super::answers::Answer;
use super::quantity::Quantity;

/// One change of stability: where, what beyond it, and how the motion grows on the
/// unstable side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge {
    /// The constant's value there.
    pub value: f64,
    /// Whether the state is stable beyond it, as the constant grows.
    pub stable_above: bool,
    /// Whether the eigenvalue crossing zero there has an imaginary part (a growing
    /// oscillation on the unstable side).
    pub oscillates: bool,
}

/// The name of an edge among an answer's values: `stable` or `unstable` (beyond it),
/// with `~` where it oscillates.
pub fn name(edge: &Edge) -> String {
    let side = if edge.stable_above {
        "stable"
    } else {
        "unstable"
    };
    match edge.oscillates {
        true => format!("{side}~"),
        false => side.into(),
    }
}

/// The edges of a `stability` answer's values.
pub fn edges(answer: &Answer) -> Vec<Edge> {
    (answer.values.iter())
        .filter_map(|(q, value)| {
            let Quantity::Named(n) = q else { return None };
            let (side, oscillates) = match n.strip_suffix('~') {
                Some(side) => (side, true),
                None => (n.as_str(), false),
            };
            Some(Edge {
                value: *value,
                stable_above: side == "stable",
                oscillates,
            })
        })
        .collect()
}
