//! Kinetic and potential energy, for the simulation's confirmation.

use crate::mechanics::{apply, dot3, Model};
use crate::problem::{BodyId, LoadKind};
use crate::symbolic::{add, pow, Expr};

/// The kinetic energy: every body's translation and rotation.
///
/// The velocity components in `N` and the angular velocity components are named symbols,
/// so that `v·v` is not multiplied out: for a chain of n bodies that would be n² terms a body.
pub fn kinetic(model: &Model) -> Expr {
    let half = Expr::ratio(1, 2);
    let mut terms = Vec::new();
    for &body in &model.order {
        let state = &model.bodies[body.0];
        let name = model.frames.name(body);
        let v = state
            .center
            .velocity
            .components_in(BodyId::GROUND, &model.frames);
        let v: [Expr; 3] = std::array::from_fn(|axis| {
            Expr::defined(
                &format!("{name}.v.{}", ["x", "y", "z"][axis]),
                v[axis].clone(),
            )
        });
        terms.push(&half * &(&state.mass * &dot3(&v, &v)));
        let w = state.omega_named.components_in(state.frame, &model.frames);
        terms.push(&half * &dot3(&w, &apply(&state.inertia, &w)));
    }
    add(terms)
}

/// The potential energy of gravity, springs, joint springs and the forces with a potential
/// (gravity's zero at the origin's level).
pub fn potential(model: &Model) -> Expr {
    let problem = model.problem;
    let half = Expr::ratio(1, 2);
    let mut terms = Vec::new();
    if let Some(g) = &problem.gravity {
        let g = crate::mechanics::vector_of(g);
        for &body in &model.order {
            let state = &model.bodies[body.0];
            terms.push(-(&state.mass * &g.dot(&state.center.position, &model.frames)));
        }
    }
    for (index, load) in problem.loads.iter().enumerate() {
        match &load.kind {
            LoadKind::Spring {
                between,
                stiffness,
                free_length,
            } => {
                let p1 = model.position(between[0]);
                let p2 = model.position(between[1]);
                let d = p2.minus(&p1);
                let length2 = d.dot(&d, &model.frames);
                let stretch2 = if free_length.is_zero() {
                    length2
                } else {
                    // (l - l0)^2 = l^2 - 2 l0 l + l0^2
                    add([
                        length2.clone(),
                        -(Expr::int(2) * free_length.clone() * pow(length2, Expr::ratio(1, 2))),
                        free_length * free_length,
                    ])
                };
                terms.push(&half * &(stiffness * &stretch2));
            }
            LoadKind::JointSpring {
                coordinate,
                stiffness,
                rest,
                ..
            } => {
                let stretch = &problem.coordinate_expr(*coordinate, 0) - rest;
                terms.push(&half * &(stiffness * &(&stretch * &stretch)));
            }
            LoadKind::Force { .. } => {
                terms.extend(super::load_potential::force_potential(model, index));
            }
            _ => {}
        }
    }
    let _ = BodyId::GROUND;
    add(terms)
}
