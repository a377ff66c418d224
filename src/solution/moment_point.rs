//! The point a moment row is taken about, as a student names it. A joint that carries no
//! reaction (a planar or free joint) has no pin to name: where its point is a body's mass
//! centre, the row is about that mass centre, `D*`, not about the joint's name.

use crate::mechanics::{sample_states, Model, Vector};
use crate::problem::BodyId;

/// `point` (a site's name or `B*`) as the rows name it: a reaction-free joint's point by the
/// mass centre it lies at, at every sample state.
pub fn shown_point(model: &Model, point: &str, position: &Vector) -> String {
    let bare = model
        .sites
        .iter()
        .any(|s| s.name == point && s.reactions.is_empty());
    if point.ends_with('*') || !bare {
        return point.to_string();
    }
    let states = sample_states(model);
    let at = |body: usize| {
        let apart = (model.bodies[body].center.position)
            .minus(position)
            .components_in(BodyId::GROUND, &model.frames);
        states.iter().all(|state| {
            apart
                .iter()
                .all(|c| crate::symbolic::eval(c, state).abs() <= 1e-12)
        })
    };
    (1..model.bodies.len())
        .find(|&b| at(b))
        .map_or(point.to_string(), |b| {
            format!("{}*", model.problem.body_name(BodyId(b)))
        })
}
