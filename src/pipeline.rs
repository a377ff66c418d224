//! The stages every command runs, one entry each, data flowing one way:
//!
//! 1. [`load`]: the problem file and the command line's `--set` → a validated [`Problem`];
//! 2. [`derive`]: the kinematics, the free bodies, the plan and the equations of one method
//!    → a [`Derivation`];
//! 3. [`Solver::new`]: the equations compiled for numbers, with the constraints' assembly;
//!    a [`Solver`] is a [`System`] that solves, simulates and checks;
//! 4. the renderers and exporters read what the stages before them produced.
//!
//! Recovery lives here and nowhere else: where the Motion Law's plan is singular at a state
//! at which the system is not (a row's reaction term vanishing there), the solver plans
//! again for that state and goes on, for every command alike.

use crate::equations::system::{derive_at, State};
use crate::equations::{Derivation, Method};
use crate::numeric::evaluate::{Compiled, StateSolution};
use crate::numeric::system::{Evaluation, System};
use crate::numeric::SolveError;
use crate::problem::Problem;
use crate::symbolic::budget;
use crate::Error;
use std::cell::RefCell;

pub use crate::cmd::load_with_overrides as load;

/// Derives the equations of `problem` by `method`.
///
/// # Errors
/// When the model cannot be built or the method finds no complete set of equations.
pub fn derive(problem: &Problem, method: Method) -> Result<Derivation<'_>, Error> {
    derive_within_budget(problem, method, &[])
}

/// [`derive_at`] counted against the work limit ([`budget`]): past it, the overrun is the
/// error, whatever the derivation returned.
fn derive_within_budget<'p>(
    problem: &'p Problem,
    method: Method,
    states: &[State],
) -> Result<Derivation<'p>, Error> {
    budget::start();
    let derivation = derive_at(problem, method, states);
    budget::settle().map_err(|overrun| Error::TooMuchWork { overrun, method })?;
    Ok(derivation?)
}

/// Compiled equations that plan again where their plan is singular.
pub struct Solver<'p> {
    problem: &'p Problem,
    method: Method,
    /// The plan of the derivation first, then any plans made for special states.
    plans: RefCell<Vec<Compiled>>,
}

impl<'p> Solver<'p> {
    /// Compiles `derivation` for `problem`.
    pub fn new(problem: &'p Problem, derivation: &Derivation) -> Solver<'p> {
        Solver {
            problem,
            method: derivation.method,
            plans: RefCell::new(vec![Compiled::new(derivation)]),
        }
    }

    /// The method of the equations.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The compiled equations of the derivation's own plan.
    pub fn compiled(&self) -> std::cell::Ref<'_, Compiled> {
        std::cell::Ref::map(self.plans.borrow(), |plans| &plans[0])
    }

    /// Runs `f` on the newest plan; where the system is singular with the Motion Law, plans
    /// again for this state and runs `f` on the new plan.
    fn with_plan<T>(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        f: impl Fn(&Compiled) -> Result<T, SolveError>,
    ) -> Result<T, SolveError> {
        let first = {
            let plans = self.plans.borrow();
            // Each plan in turn: one made for an earlier special state may suit this one.
            let mut result = Err(SolveError::BadSimulation {
                what: String::new(),
            });
            for plan in plans.iter().rev() {
                result = f(plan);
                if !matches!(result, Err(SolveError::SingularSystem { .. })) {
                    return result;
                }
            }
            result
        };
        if self.method != Method::MotionLaw || self.plans.borrow().len() > 8 {
            return first;
        }
        let state = State {
            t,
            q: q.to_vec(),
            rates: rates.to_vec(),
        };
        let Ok(derivation) = derive_within_budget(self.problem, self.method, &[state]) else {
            return first;
        };
        let compiled = Compiled::new(&derivation);
        let result = f(&compiled);
        if result.is_ok() {
            self.plans.borrow_mut().push(compiled);
        }
        result
    }

    /// The q'', reactions, drives and energies at a state (which must meet the constraints).
    ///
    /// # Errors
    /// A system singular whatever the plan, or a value that is not finite.
    pub fn solve(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<StateSolution, SolveError> {
        self.with_plan(t, q, rates, |c| c.solve(t, q, rates))
    }
}

impl System for Solver<'_> {
    fn coordinate_names(&self) -> Vec<String> {
        self.compiled().coordinate_names()
    }

    fn reaction_columns(&self) -> Vec<String> {
        self.compiled().reaction_columns()
    }

    fn evaluate(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        self.with_plan(t, q, rates, |c| c.evaluate(t, q, rates))
    }

    fn accelerations(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Vec<f64>, SolveError> {
        self.with_plan(t, q, rates, |c| c.accelerations(t, q, rates))
    }

    fn assemble(&self, t: f64, q: &mut [f64], rates: &mut [f64]) -> Result<(), SolveError> {
        self.compiled().assemble(t, q, rates)
    }

    fn drift(&self, t: f64, q: &[f64], rates: &[f64]) -> f64 {
        self.compiled().drift(t, q, rates)
    }

    fn is_constrained(&self) -> bool {
        self.compiled().is_constrained()
    }

    fn energies(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<(f64, f64), SolveError> {
        self.compiled().energies(t, q, rates)
    }

    fn is_conservative(&self) -> bool {
        self.compiled().is_conservative()
    }

    fn has_dissipation_only(&self) -> bool {
        self.compiled().has_dissipation_only()
    }
}
