//! The free body of an auxiliary speed that relaxes a constraint: the bodies that move
//! when only the dependent rates it sets move. Its free body shows the forces that do work
//! with the speed (the disc on a cart: the disc alone, with the contact force at its rim),
//! as a textbook draws the body a force asked for acts on.

use crate::mechanics::Model;
use crate::problem::BodyId;
use crate::symbolic::Expr;

/// The bodies moved by the motion `weights` gives the coordinates' rates (a coordinate's
/// rate moves every body outboard of its joint), in the order of the model's bodies;
/// every body where none has a weight.
pub(super) fn moved_bodies(model: &Model, weights: &[Expr]) -> Vec<BodyId> {
    let coordinates = &model.problem.coordinates;
    let mut moved: Vec<BodyId> = Vec::new();
    for (coordinate, _) in coordinates
        .iter()
        .zip(weights)
        .filter(|(_, w)| !w.is_zero())
    {
        moved.extend(model.subtree(coordinate.joint));
    }
    let bodies: Vec<BodyId> = (model.order.iter().copied())
        .filter(|b| moved.contains(b))
        .collect();
    match bodies.is_empty() {
        true => model.order.clone(),
        false => bodies,
    }
}
