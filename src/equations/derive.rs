//! The entry of the stage: [`derive`], from a problem to the equations of one method.

use super::method::Method;
use super::system::{Derivation, Request};
use crate::mechanics::{MechanicsError, Model};
use crate::problem::Problem;
use crate::symbolic::budget;

/// Derives the equations of `problem` by `method` for `request`: the model (steps 1 and
/// 4) as the method sees it, the free bodies (step 2), then the method's rows and their
/// linear system (steps 3 and 5).
///
/// # Errors
/// When the model cannot be built, a load cannot be written, the planner finds no complete
/// set of rows, or an unknown appears nonlinearly.
pub fn derive<'p>(
    problem: &'p Problem,
    method: Method,
    request: Request<'_>,
) -> Result<Derivation<'p>, MechanicsError> {
    budget::step("computing the kinematics (step 4)");
    let mut model = Model::build_for(problem, request.form)?;
    match method {
        // A light rod's closure keeps both components for Newton–Euler: every body is a
        // free body, the rod's rows finding the component across it zero.
        Method::NewtonEuler => {}
        Method::MotionLaw => super::motion_law::view(&mut model),
        Method::Kane => super::kane::view(&mut model),
        Method::Lagrange => super::lagrange::view(&mut model),
    }
    budget::step("writing the forces, the inertia forces and torques (step 2)");
    let free_bodies = crate::plan::free_bodies(&model, request.form)?;
    super::write::write_equations(model, free_bodies, method, request)
}
