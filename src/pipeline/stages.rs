//! The stages that derive the equations, called in turn: the model (steps 1 and 4), the
//! free bodies (step 2), then the equations of one method (steps 3 and 5).

use crate::equations::{self, Derivation, Method, Request, Rows, State};
use crate::mechanics::{Form, MechanicsError};
use crate::problem::Problem;

/// Derives the equations of `problem` by `method` for `request` (see
/// [`equations::derive`]).
///
/// # Errors
/// As for [`equations::derive`].
pub fn derive_for<'p>(
    problem: &'p Problem,
    method: Method,
    request: Request<'_>,
) -> Result<Derivation<'p>, MechanicsError> {
    equations::derive(problem, method, request)
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
