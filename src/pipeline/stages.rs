//! The one entry for a derivation: [`derive`] turns what the caller needs ([`Purpose`])
//! into an `equations::Request` and calls `equations::derive`, which builds the model
//! (steps 1 and 4), the free bodies (step 2) and one method's rows (steps 3 and 5), counted
//! against the work limit.

use crate::equations::{self, Derivation, Method, Request, Rows};
use crate::error::Error;
use crate::mechanics::{Form, MechanicsError};
use crate::numeric::Compiled;
use crate::problem::{Problem, State};
use crate::symbolic::budget;

/// What a derivation is for, which says the rows formed and their form.
#[derive(Clone, Copy, Debug)]
pub enum Purpose<'s> {
    /// The worked solution: every row as a student writes it ([`Form::Handout`]).
    Handout,
    /// The numbers, in the fastest exact form ([`Form::Numeric`]): Kane's system by
    /// composite bodies wherever it stands in for the method's own rows ([`Rows::Fastest`]),
    /// the method's own rows elsewhere, as for [`Purpose::Own`]. The q'' and the reactions
    /// are the same to rounding; the derivation keeps the method, so what is printed names
    /// the method asked for.
    Numbers,
    /// The method's own rows for numbers, forming no row that is not compiled
    /// ([`Rows::Compiled`]), in their most compact form: what the confirmation checks
    /// compare.
    Own,
    /// Every row the method writes, for numbers: what the comparisons between methods read.
    Rows,
    /// Every row the method writes in `form`, the Motion Law's plan nonsingular at `states`
    /// where a plan can be: where the plan is made again at a singular state.
    At(&'s [State], Form),
}

/// Derives the equations of `problem` by `method` for `purpose`.
///
/// # Errors
/// When the model cannot be built, the method finds no complete set of equations, or the
/// work passes the limit ([`budget`]).
pub fn derive<'p>(
    problem: &'p Problem,
    method: Method,
    purpose: Purpose<'_>,
) -> Result<Derivation<'p>, Error> {
    within_budget(method, || match purpose {
        Purpose::Handout => formed(problem, method, &[], Form::Handout),
        Purpose::Rows => formed(problem, method, &[], Form::Numeric),
        Purpose::At(states, form) => formed(problem, method, states, form),
        Purpose::Own => most_compact(problem, numeric(problem, method, Rows::Compiled)?),
        Purpose::Numbers => {
            let fastest = numeric(problem, method, Rows::Fastest)?;
            if fastest.system_method != method {
                return Ok(fastest);
            }
            most_compact(problem, fastest)
        }
    })
}

/// Every row in `form`, the plan nonsingular at `states`.
fn formed<'p>(
    problem: &'p Problem,
    method: Method,
    states: &[State],
    form: Form,
) -> Result<Derivation<'p>, MechanicsError> {
    let rows = Rows::Formed;
    equations::derive(problem, method, Request { form, rows, states })
}

/// The rows `rows` says, for numbers.
fn numeric(
    problem: &Problem,
    method: Method,
    rows: Rows,
) -> Result<Derivation<'_>, MechanicsError> {
    let form = Form::Numeric;
    equations::derive(
        problem,
        method,
        Request {
            form,
            rows,
            states: &[],
        },
    )
}

/// The Motion Law's planar rows whole or by names, whichever compiles shorter; any other
/// derivation as it is.
fn most_compact<'p>(
    problem: &'p Problem,
    numeric: Derivation<'p>,
) -> Result<Derivation<'p>, MechanicsError> {
    let method = numeric.method;
    // Asked last: reading the inertia forces writes them.
    if method != Method::MotionLaw
        || !numeric.model.is_planar()
        || !numeric.inertia().compact.iter().any(|&c| c)
    {
        return Ok(numeric);
    }
    // The Motion Law's moments multiply each lever arm out against the named parts,
    // where whole the trigonometric identities collect them: a chain of equal links
    // comes out smaller whole (3,911 operations against 8,380 for ten), one of unequal
    // links smaller by names (11,837 against 17,559). Keep the smaller program.
    let whole = formed(problem, method, &[], Form::Handout)?;
    let size = |d: &Derivation| Compiled::new(d).operation_count();
    Ok(if size(&whole) < size(&numeric) {
        whole
    } else {
        numeric
    })
}

/// A derivation counted against the work limit ([`budget`]): past it, the overrun is the
/// error, whatever the derivation returned.
fn within_budget<T>(
    method: Method,
    derivation: impl FnOnce() -> Result<T, MechanicsError>,
) -> Result<T, Error> {
    budget::start();
    let derived = derivation();
    budget::settle().map_err(|overrun| Error::TooMuchWork { overrun, method })?;
    Ok(derived?)
}
