//! q'' of an unconstrained tree in O(n): the articulated-body algorithm evaluated natively,
//! with everything that is constant for a problem (joint axes and points, masses, inertias,
//! gravity) read from the model once, so an evaluation does only the three passes.
//!
//! It covers the inertia and the weight, nothing else: a problem with loads, constraints,
//! prescribed or dependent coordinates, declared speeds or friction is left to the dense
//! form ([`Recursive::new`] gives `None`), as is any state where it finds a joint's
//! articulated inertia singular (the dense form then explains why).
//!
//! Which form `solve` and `simulate` use is decided in [`super::evaluate`]: by the rule
//! [`RECURSIVE_FROM_DOF`].

mod aba;
mod joint;
mod spatial;

use crate::mechanics::Model;
use crate::problem::BodyId;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

/// From this many degrees of freedom the recursive form is used where it applies; below it
/// the dense program and its LU. Chosen, not yet measured at the boundary: the smallest
/// chains of `tools/bench/chains.py` (revolute 6, spherical 3) already run faster
/// recursively (BENCHMARKS.md), and with one or two coordinates the dense program is a
/// handful of operations.
pub const RECURSIVE_FROM_DOF: usize = 3;

/// One body of the tree, in an order with parents first.
#[derive(Clone, Debug)]
struct Body {
    /// The parent's index in [`Recursive::bodies`]; `None` for `N`.
    parent: Option<usize>,
    /// The joint whose child it is.
    joint: joint::Geometry,
    /// Its number of coordinates.
    dof: usize,
    /// Its spatial inertia about its origin, in its own unit vectors.
    inertia: Matrix6<f64>,
}

/// An unconstrained tree ready for the articulated-body algorithm.
#[derive(Clone, Debug)]
pub struct Recursive {
    bodies: Vec<Body>,
    /// The acceleration of `N` that stands for gravity, `(0, −g)`.
    ground: Vector6<f64>,
    /// The number of coordinates.
    dof: usize,
    /// Reused between evaluations, so that one allocates only its result.
    scratch: std::cell::RefCell<aba::Scratch>,
}

impl Recursive {
    /// The tree of `model`, with the constants' values of the model; `None` where the
    /// problem has anything but joints, bodies and gravity (see the module's notes), or an
    /// expression the passes need is not constant.
    pub fn new(model: &Model) -> Option<Recursive> {
        let problem = model.problem;
        let plain = problem.loads.is_empty()
            && problem.closures.is_empty()
            && problem.constraints.is_empty()
            && problem.speeds.is_empty()
            && model.speeds.is_none()
            && model.constraints.is_empty()
            && model.constraints.friction.is_empty()
            && model.constraints.prescribed.is_empty()
            && problem
                .coordinates
                .iter()
                .all(|c| c.motion.is_none() && !c.dependent && !c.dependent_rate);
        if !plain {
            return None;
        }
        let values = &model.values;
        let mut gravity = [
            crate::symbolic::Expr::zero(),
            crate::symbolic::Expr::zero(),
            crate::symbolic::Expr::zero(),
        ];
        for (frame, axis, coefficient) in problem.gravity.iter().flat_map(|g| &g.terms) {
            if *frame != BodyId::GROUND {
                return None;
            }
            let a = *axis as usize;
            gravity[a] = &gravity[a] + coefficient;
        }
        let g = joint::numbers(&gravity, values)?;
        let mut index = vec![None; model.bodies.len()];
        let mut bodies = Vec::new();
        for &body in &model.order {
            let j = problem.joint_of(body)?;
            let declared = &problem.joints[j];
            let parent = match declared.parent {
                BodyId::GROUND => None,
                p => Some(index[p.0]?),
            };
            let geometry = joint::Geometry::new(declared, &model.joints[j], values)?;
            let state = &model.bodies[body.0];
            let mass = constant(&state.mass, values)?;
            let center = joint::numbers(&state.center_offset, values)?;
            let mut central = Matrix3::zeros();
            for r in 0..3 {
                central.set_row(r, &joint::numbers(&state.inertia[r], values)?.transpose());
            }
            index[body.0] = Some(bodies.len());
            bodies.push(Body {
                parent,
                dof: geometry.dof(),
                joint: geometry,
                inertia: spatial::inertia(mass, &center, &central),
            });
        }
        Some(Recursive {
            bodies,
            ground: spatial::join(Vector3::zeros(), -g),
            dof: problem.coordinates.len(),
            scratch: Default::default(),
        })
    }

    /// The number of coordinates.
    pub fn dof(&self) -> usize {
        self.dof
    }

    /// The q'' at coordinates `q` and rates `rates` (coordinate order); `None` where a
    /// joint's articulated inertia is singular or a value is not finite.
    pub fn accelerations(&self, q: &[f64], rates: &[f64]) -> Option<Vec<f64>> {
        if q.len() != self.dof || rates.len() != self.dof {
            return None;
        }
        let mut scratch = self.scratch.take();
        let out = aba::accelerations(self, &mut scratch, q, rates);
        self.scratch.replace(scratch);
        out
    }
}

fn constant(e: &crate::symbolic::Expr, values: &crate::symbolic::eval::Values) -> Option<f64> {
    let x = crate::symbolic::eval::eval(e, values);
    (e.is_constant() && x.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests;
