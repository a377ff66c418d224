//! The stages that derive the equations, called in turn: the model (steps 1 and 4), the
//! free bodies (step 2), then the equations of one method (steps 3 and 5).

use crate::equations::{self, Derivation, Method, Request, Rows, State};
use crate::mechanics::{Form, MechanicsError, Model};
use crate::plan;
use crate::problem::Problem;
use crate::symbolic::budget;

/// Derives the equations of `problem` by `method` for `request`: the model, then the free
/// bodies, then the method's rows and their linear system.
///
/// # Errors
/// When the model cannot be built, a load cannot be written, the planner finds no complete
/// set of rows, or an unknown appears nonlinearly.
pub fn derive_for<'p>(
    problem: &'p Problem,
    method: Method,
    request: Request<'_>,
) -> Result<Derivation<'p>, MechanicsError> {
    budget::step("computing the kinematics (step 4)");
    let mut model = Model::build_for(problem, request.form)?;
    if matches!(method, Method::Kane | Method::Lagrange) {
        // Kane's auxiliary speed (and Lagrange's relaxed joint) along a light rod brings in its tension alone.
        crate::mechanics::two_force::along_members(&mut model);
    }
    if method != Method::NewtonEuler {
        // A light rod's closure carries its tension alone. Newton–Euler keeps both
        // components: there every body is a free body, the rod's rows finding the
        // component across it zero.
        crate::mechanics::light_rod::closures_along_rods(&mut model);
    }
    budget::step("writing the forces, the inertia forces and torques (step 2)");
    let free_bodies = plan::free_bodies(&model, request.form)?;
    equations::write_equations(model, free_bodies, method, request)
}

/// Every row `method` writes for `problem`, for numbers ([`Form::Numeric`]): what the
/// comparisons between methods read.
///
/// # Errors
/// As for [`derive_for`].
pub fn derive_rows(problem: &Problem, method: Method) -> Result<Derivation<'_>, MechanicsError> {
    derive_at(problem, method, &[], Form::Numeric)
}

/// Every row `method` writes for `problem` in `form`, the Motion Law's plan nonsingular at
/// `states` where a plan can be.
///
/// # Errors
/// As for [`derive_for`].
pub fn derive_at<'p>(
    problem: &'p Problem,
    method: Method,
    states: &[State],
    form: Form,
) -> Result<Derivation<'p>, MechanicsError> {
    let rows = Rows::Formed;
    derive_for(problem, method, Request { form, rows, states })
}

/// As [`derive_at`] for numbers, forming only what is compiled ([`Rows::Compiled`]).
///
/// # Errors
/// As for [`derive_for`].
pub fn derive_for_numbers<'p>(
    problem: &'p Problem,
    method: Method,
    states: &[State],
) -> Result<Derivation<'p>, MechanicsError> {
    let (form, rows) = (Form::Numeric, Rows::Compiled);
    derive_for(problem, method, Request { form, rows, states })
}

/// For numbers, Kane's system by composite bodies standing in for any method's rows where
/// it is built alone ([`Rows::Fastest`]).
///
/// # Errors
/// As for [`derive_for`].
pub fn derive_fastest(problem: &Problem, method: Method) -> Result<Derivation<'_>, MechanicsError> {
    let (form, rows) = (Form::Numeric, Rows::Fastest);
    derive_for(
        problem,
        method,
        Request {
            form,
            rows,
            states: &[],
        },
    )
}
