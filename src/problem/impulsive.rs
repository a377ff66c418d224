//! The problem of an impact's impulses: the same bodies, joints, closures and contacts,
//! held at the configuration of the impact, with the impulses as their only loads.
//!
//! Over the instant of an impact the configuration does not change and finite forces give
//! no impulse, so integrating a method's equations over it turns each q'' into the jump
//! of its rate, each reaction into its impulsive reaction, and each load into its impulse;
//! the velocity-product terms vanish with the rates (see docs/impact.md). Every method's
//! own equations, evaluated with zero rates, no gravity and the impulses as loads, are
//! therefore its impulse–momentum equations, with the constraints at velocity level.

use super::impact::Impact;
use super::model::*;
use super::validated::Problem;
use crate::symbolic::Expr;

/// The impulsive problem and where the collision's impulse enters it.
#[derive(Clone, Debug)]
pub struct Impulsive {
    /// The problem whose loads are the impulses.
    pub problem: Problem,
    /// The constants (indices into [`Problem::constants`]) that carry the collision's
    /// impulse along `on`'s unit vectors x, y (and z in 3D); empty without a collision.
    pub collision: Vec<usize>,
}

/// Names of the collision impulse's components: `P_x`, `P_y`, `P_z`, or with a suffix
/// when the problem already uses them.
fn component_names(problem: &Problem, count: usize) -> Vec<String> {
    let taken = |name: &str| {
        problem.constants.iter().any(|c| c.name == name)
            || problem.coordinates.iter().any(|c| c.name == name)
    };
    let stem = ["P", "Pc", "Pimp", "P_c"]
        .into_iter()
        .find(|s| (0..count).all(|k| !taken(&format!("{s}_{}", ["x", "y", "z"][k]))))
        .unwrap_or("P_impact");
    (0..count)
        .map(|k| format!("{stem}_{}", ["x", "y", "z"][k]))
        .collect()
}

impl Problem {
    /// The impulsive problem of this problem's impact at coordinates `q` (assembled): the
    /// coordinates held at `q` with zero rates, prescribed ones at their values (so that
    /// their rates do not jump), no gravity, no loads but the applied impulses and the
    /// collision's impulse (its components constants, 0 here), no friction at the joints
    /// and contacts (rough contacts hold as they roll). `on_point` is where the struck
    /// point is on the collision's `on` body (its own unit vectors), so that the opposite
    /// impulse acts on `on` when it moves. `None` without an impact.
    pub fn impulsive(&self, q: &[f64], on_point: Option<VectorExpr>) -> Option<Impulsive> {
        let impact: &Impact = self.impact.as_ref()?;
        let mut problem = self.clone();
        problem.impact = None;
        problem.gravity = None;
        problem.questions.clear();
        problem.loads.clear();
        for (c, value) in problem.coordinates.iter_mut().zip(q) {
            c.initial = *value;
            c.initial_expr = None;
            c.rate = 0.0;
            c.rate_expr = None;
            if c.motion.is_some() {
                c.motion = Some(Expr::real(*value));
            }
        }
        for joint in problem.joints.iter_mut().chain(problem.closures.iter_mut()) {
            joint.friction = None;
        }
        for constraint in &mut problem.constraints {
            constraint.friction = None;
        }
        for impulse in &impact.impulses {
            if let Some(linear) = &impulse.linear {
                problem.loads.push(force(
                    impulse.body,
                    impulse.point.clone(),
                    linear.clone(),
                    &impulse.path,
                ));
            }
            if let Some(angular) = &impulse.angular {
                problem.loads.push(Load {
                    name: Some(impulse.name.clone()),
                    kind: LoadKind::Torque {
                        on: impulse.body,
                        vector: angular.clone(),
                        reaction_on: None,
                    },
                    path: impulse.path.clone(),
                });
            }
        }
        let mut collision = Vec::new();
        if let Some(c) = &impact.collision {
            let count = if self.dimension == Dimension::Two {
                2
            } else {
                3
            };
            let names = component_names(self, count);
            let mut terms = Vec::new();
            for (axis, name) in names.iter().enumerate() {
                collision.push(problem.constants.len());
                problem.constants.push(Constant {
                    name: name.clone(),
                    value: 0.0,
                    unit: Some("N s".into()),
                    description: Some(format!("impulse of the collision {}", c.name)),
                    vary: None,
                });
                terms.push((c.on, axis as u8, Expr::constant(name)));
            }
            let impulse = VectorExpr { terms };
            if let (Some(at), true) = (on_point, c.on != BodyId::GROUND) {
                let opposite = VectorExpr {
                    terms: impulse
                        .terms
                        .iter()
                        .map(|(f, a, e)| (*f, *a, -e.clone()))
                        .collect(),
                };
                problem
                    .loads
                    .push(force(c.on, ForcePoint::Offset(at), opposite, &c.path));
            }
            problem
                .loads
                .push(force(c.body, c.point.clone(), impulse, &c.path));
        }
        Some(Impulsive { problem, collision })
    }
}

fn force(on: BodyId, at: ForcePoint, vector: VectorExpr, path: &str) -> Load {
    Load {
        name: None,
        kind: LoadKind::Force { on, at, vector },
        path: path.to_string(),
    }
}
