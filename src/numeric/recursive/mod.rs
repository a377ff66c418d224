//! q'' of an unconstrained tree in O(n): the articulated-body algorithm evaluated natively,
//! with everything that is constant for a problem (joint axes and points, masses, inertias,
//! gravity) read from the model once, so an evaluation does only the three passes.
//!
//! Gravity is the ground's acceleration. The loads (springs, dampers, applied forces and
//! torques, joint springs, dampers and actuators) enter as the joint forces τ: their
//! generalized active forces `Q_r = Σ F · ∂v/∂q̇_r + T · ∂ω/∂q̇_r`, formed in symbols once
//! from Kane's partial velocities ([`crate::equations::kane_generalized_forces`]) and compiled into one
//! program of the constants, q, q' and t, run before the passes at each state (`loads`).
//!
//! A problem with constraints, prescribed or dependent coordinates, declared speeds or
//! friction is left to the dense form ([`Recursive::new`] gives `None`), as is any state
//! where it finds a joint's articulated inertia singular (the dense form then explains
//! why). [`super::evaluate`] leaves to it too a problem that asks for reactions, which the
//! passes do not give.
//!
//! Which form `solve` and `simulate` use is decided in [`super::evaluate`]: by the rule
//! [`is_faster`], from the measured [`RECURSIVE_FROM_DOF`] and [`RECURSIVE_FROM_DOF_PLANAR`].

mod aba;
mod joint;
mod loads;
mod spatial;

use crate::equations::Derivation;
use crate::problem::BodyId;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

/// From this many coordinates a spatial problem takes the recursive form where it applies;
/// below it the dense program and its LU. Measured (2026-11-28, the fastest of 2 runs of
/// `cargo bench --bench evaluate -- F kane`, which times the two forms taking turns, on
/// `python3 tools/bench/chains.py write KIND N F` and the same `--springs`): revolute chains
/// of 2, 3 and 4 coordinates tie (0.88 / 0.85, 1.35 / 1.35, 1.39 / 1.38 µs dense /
/// recursive), and from 6 the recursive form wins (revolute 6: 3.74 / 2.26 µs, spherical 2:
/// 1.70 / 1.03 µs); with a spring and damper on every coordinate the loads' program makes
/// the recursive form lose to 4 coordinates (revolute 4: 1.76 / 1.85 µs) and tie at 6
/// (3.0 / 2.82 µs). The machine's speed varied by up to 2× between runs.
pub const RECURSIVE_FROM_DOF: usize = 6;

/// As [`RECURSIVE_FROM_DOF`], for a planar problem: the passes work in space, while the
/// dense program of a planar chain is short, so the dense form wins longer. Measured as
/// there on planar chains: dense faster at 2 to 10 coordinates (planar 2: 0.55 / 0.84 µs,
/// planar 6: 1.97 / 2.94 µs, planar 10: 4.00 / 4.67 µs), a tie at 12 (6.42 / 7.14 and
/// 5.34 / 5.26 µs in two runs), the recursive from 14 (planar 14: 6.28 / 5.97 µs, planar 16:
/// 8.70 / 8.20 µs, planar 20: 12.01 / 10.22 µs); with a spring and damper on every
/// coordinate the dense form wins at every size measured, to 10.
pub const RECURSIVE_FROM_DOF_PLANAR: usize = 14;

/// Whether the recursive form is the faster for `dof` coordinates, in the plane or not
/// (see `RECURSIVE_FROM_DOF` and `RECURSIVE_FROM_DOF_PLANAR`).
pub fn is_faster(dof: usize, planar: bool) -> bool {
    let from = if planar {
        RECURSIVE_FROM_DOF_PLANAR
    } else {
        RECURSIVE_FROM_DOF
    };
    dof >= from
}

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
    /// The loads' generalized forces, the joint forces τ; `None` without loads.
    loads: Option<loads::Loads>,
    /// Reused between evaluations, so that one allocates only its result.
    scratch: std::cell::RefCell<aba::Scratch>,
}

impl Recursive {
    /// The tree of `derivation`'s model, with the constants' values of the model and its
    /// loads compiled; `None` where the problem has anything but joints, bodies, gravity and
    /// loads (see the module's notes), or an expression the passes need is not constant.
    pub fn new(derivation: &Derivation) -> Option<Recursive> {
        let model = &derivation.model;
        let problem = model.problem;
        // The passes take each joint's coordinate as its relative motion: an absolute angle
        // is not one.
        let plain = problem.closures.is_empty()
            && problem.joints.iter().all(|j| j.angle_from.is_none())
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
            loads: loads::Loads::new(derivation),
            scratch: Default::default(),
        })
    }

    /// The number of operations of one evaluation of the loads' generalized forces (zero
    /// without loads).
    pub fn load_operation_count(&self) -> usize {
        self.loads.as_ref().map_or(0, loads::Loads::operation_count)
    }

    /// The q'' at time `t`, coordinates `q` and rates `rates` (coordinate order); `None`
    /// where a joint's articulated inertia is singular or a value is not finite.
    pub fn accelerations(&self, t: f64, q: &[f64], rates: &[f64]) -> Option<Vec<f64>> {
        if q.len() != self.dof || rates.len() != self.dof {
            return None;
        }
        let mut scratch = self.scratch.take();
        scratch.tau.clear();
        scratch.tau.resize(self.dof, 0.0);
        if let Some(loads) = &self.loads {
            loads.run(t, q, rates, &mut scratch.tau);
        }
        let out = aba::accelerations(self, &mut scratch, q, rates);
        self.scratch.replace(scratch);
        out
    }
}

fn constant(e: &crate::symbolic::Expr, values: &crate::symbolic::Values) -> Option<f64> {
    let x = crate::symbolic::eval(e, values);
    (e.is_constant() && x.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests;
