//! Lagrange's rows of a problem whose derivatives of `T` are too long to write out (a
//! spatial chain: ∂T/∂q̇_r multiplied out over the direction cosines of every link).
//!
//! Simplified, such a derivative would still be longer than a line of the worked solution,
//! which then names it only; simplifying it takes minutes. So the derivatives of `T` are
//! not formed for the worked solution: step 5 names them, and the rows' kinetic terms are
//! written from the accelerations of step 4, `d/dt(∂T/∂q̇_r) − ∂T/∂q_r =
//! Σ m a*·∂v*/∂q̇_r + (I·α + ω×I·ω)·∂ω/∂q̇_r` ([`super::kinetic`]), the same function of
//! the coordinates, their rates and second rates.

use super::energy::{bodies, raw_momentum};
use super::CoordinateTerms;
use crate::mechanics::{Form, MechanicsError, Model};
use crate::plan::{Action, Groups, Inertia};
use crate::symbolic::Expr;

/// The fewest operations of a coordinate's ∂T/∂q̇_r, as formed (multiplied out, before
/// simplifying), past which its simplified form is too long for a line of the worked
/// solution as well. Of the bundled problems, the spherical chain of three links is past
/// it in every coordinate (its shortest 672); the ten-link chain's shortest is 484, and
/// its last links' derivatives are written out.
pub const LONGEST_MOMENTUM: usize = 600;

/// Whether the worked solution's rows of `model` are written from the accelerations of
/// step 4: a handout, without declared speeds, where every coordinate's ∂T/∂q̇_r as formed
/// is longer than [`LONGEST_MOMENTUM`] (step 5 would name each of them only).
///
/// # Errors
/// When a velocity holds a function without a derivative.
pub fn applies(model: &Model, inertia: &Inertia) -> Result<bool, MechanicsError> {
    if inertia.form != Form::Handout || model.speeds.is_some() {
        return Ok(false);
    }
    let bodies = bodies(model);
    let mut all = true;
    for r in 0..model.problem.coordinates.len() {
        let momentum = raw_momentum(model, &bodies, r)?;
        if momentum.operation_count_capped(LONGEST_MOMENTUM) <= LONGEST_MOMENTUM {
            all = false;
        }
    }
    Ok(all)
}

/// The groups of every coordinate's row (the kinetic terms, translation and rotation
/// together, in `inertia_force`, as the worked solution's rows hold them), with each
/// coordinate's terms: ∂V/∂q_r, the generalized forces and the multipliers' terms; the
/// derivatives of `T` not formed (zero, `written` false).
///
/// # Errors
/// When a spring's potential holds a function without a derivative.
pub fn groups(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
) -> Result<(Vec<Groups>, Vec<CoordinateTerms>), MechanicsError> {
    let groups: Vec<Groups> = super::kinetic::numeric_groups(model, actions, inertia)?
        .into_iter()
        .map(|g| Groups {
            contact: g.contact,
            distance: g.distance,
            inertia_force: &g.inertia_force + &g.inertia_torque,
            inertia_torque: Expr::zero(),
        })
        .collect();
    let loads = super::forces::generalized_forces(model, actions);
    let terms = groups
        .iter()
        .zip(loads)
        .map(|(g, (generalized_force, multipliers))| CoordinateTerms {
            momentum: Expr::zero(),
            momentum_rate: Expr::zero(),
            kinetic_partial: Expr::zero(),
            potential_partial: -g.distance.clone(),
            generalized_force,
            multipliers,
            written: false,
        })
        .collect();
    Ok((groups, terms))
}
