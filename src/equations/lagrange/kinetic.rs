//! The kinetic terms of Lagrange's equations for the numbers, `d/dt(∂T/∂q̇_r) − ∂T/∂q_r`,
//! by the chain rule on the named quantities of step 4 instead of by differentiating `T`.
//!
//! Per body, `∂T/∂q̇_r = m v*·∂v*/∂q̇_r + ω·I·∂ω/∂q̇_r`. Its time derivative by the chain
//! rule is `m a*·∂v*/∂q̇_r + m v*·d/dt(∂v*/∂q̇_r)` and likewise for the rotation, and
//! `∂T/∂q_r = m v*·∂v*/∂q_r + …`. Since `d/dt(∂v*/∂q̇_r) = ∂v*/∂q_r` (the velocity is linear
//! in the rates, its partial derivatives commute with d/dt), the velocity terms cancel
//! against `∂T/∂q_r`; for the rotation, what the rates of the body's unit vectors leave
//! makes up the gyroscopic term (the equivalence of Lagrange's equations with the
//! generalized inertia forces, Kane & Levinson ch. 6). What is left is
//!
//! `d/dt(∂T/∂q̇_r) − ∂T/∂q_r = Σ_bodies m a*·∂v*/∂q̇_r + (I·α + ω×I·ω)·∂ω/∂q̇_r`,
//!
//! the same expression, written with the accelerations of step 4 (named parts, three
//! products a body) instead of direction cosines multiplied out across a chain. The worked
//! solution still shows each of `∂T/∂q̇_r`, its time derivative and `∂T/∂q_r` formed by
//! differentiation ([`super::energy`]); the two agree at every state (tested).

use crate::equations::kane::partials;
use crate::mechanics::{DotSum, Form, MechanicsError, Model, Vector};
use crate::plan::{Action, Groups, Inertia};
use crate::symbolic::{add, partial, Expr, Symbol};

/// Whether the rows for `inertia`'s form are written with [`inertia_terms`]: for the
/// numbers, where the coordinates' rates are the speeds (with declared speeds, the rows
/// differentiate `T` as the worked solution does).
pub fn applies(model: &Model, inertia: &Inertia) -> bool {
    inertia.form == Form::Numeric && model.speeds.is_none()
}

/// Per coordinate, `−(d/dt(∂T/∂q̇_r) − ∂T/∂q_r)` as `(translation, rotation)`:
/// `Σ −m a*·∂v*/∂q̇_r` and `Σ −(I·α + ω×I·ω)·∂ω/∂q̇_r`, from the inertia forces and
/// torques of step 2 (which are `−m a*` and `−(I·α + ω×I·ω)`).
pub fn inertia_terms(model: &Model, inertia: &Inertia) -> Vec<(Expr, Expr)> {
    let frames = &model.frames;
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|r| problem.coordinate_symbol(r, 1))
        .collect();
    let accelerations: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|r| problem.coordinate_symbol(r, 2))
        .collect();
    // A body whose acceleration has named parts: its q̈ coefficients are ∂v*/∂q̇_r in its
    // own unit vectors, three products against −m a*. Otherwise the origin's partial
    // velocity with the lever arm to the mass centre.
    let own = |body: usize| !model.is_planar() || inertia.compact[body];
    let per_body: Vec<BodyPartials> = model
        .bodies
        .iter()
        .enumerate()
        .map(|(b, state)| {
            if own(b) {
                BodyPartials {
                    center: partials(&inertia.acceleration[b], &accelerations),
                    omega: partials(&inertia.alpha[b], &accelerations),
                }
            } else {
                let origin = partials(&state.origin.velocity, &rates);
                let omega = partials(&state.omega, &rates);
                let arm = Vector::new(crate::problem::BodyId(b), state.center_offset.clone());
                let center = origin
                    .iter()
                    .zip(&omega)
                    .map(|(o, w)| o.plus(&w.cross(&arm, frames)))
                    .collect();
                BodyPartials { center, omega }
            }
        })
        .collect();
    (0..rates.len())
        .map(|r| {
            let mut translation = DotSum::new(frames);
            let mut rotation = Vec::new();
            for &body in &model.order {
                let p = &per_body[body.0];
                translation.add(&p.center[r], &inertia.force[body.0]);
                rotation.push(inertia.torque[body.0].dot(&p.omega[r], frames));
            }
            (translation.total(), add(rotation))
        })
        .collect()
}

/// One body's `∂v*/∂q̇_r` and `∂ω/∂q̇_r`, indexed by coordinate.
struct BodyPartials {
    center: Vec<Vector>,
    omega: Vec<Vector>,
}

/// The groups of every coordinate's row for the numbers: `contact` the generalized forces
/// and the multipliers' terms, `distance` `−∂V/∂q_r`, and the inertia groups of
/// [`inertia_terms`].
///
/// # Errors
/// When a spring's potential holds a function without a derivative.
pub fn numeric_groups(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
) -> Result<Vec<Groups>, MechanicsError> {
    let problem = model.problem;
    let v = super::energy::potential(model);
    let loads = super::forces::generalized_forces(model, actions);
    inertia_terms(model, inertia)
        .into_iter()
        .zip(loads)
        .enumerate()
        .map(|(r, ((translation, rotation), (q, multipliers)))| {
            let dv = partial(&v, &problem.coordinate_symbol(r, 0)).map_err(|e| MechanicsError {
                path: "loads".into(),
                message: e.to_string(),
                hint: Some(
                    "Lagrange's equations differentiate the potential energy: use functions that have a derivative"
                        .into(),
                ),
            })?;
            Ok(Groups {
                contact: &q + &multipliers,
                distance: -dv,
                inertia_force: translation,
                inertia_torque: rotation,
            })
        })
        .collect()
}
