//! The stages every command runs, one entry each, data flowing one way:
//!
//! 1. [`load`]: the problem file → a validated [`Problem`] (the commands then apply `--set`
//!    and their size limits);
//! 2. [`derive()`]: the model (the kinematics), the free bodies, then the plan and the
//!    equations of one method, each stage called in turn, for a [`Purpose`] → a [`Derivation`];
//! 3. [`Solver::new`]: the equations compiled for numbers, with the constraints' assembly;
//!    a [`Solver`] is a [`System`] that solves, simulates and checks; [`Linearizer::new`]:
//!    their exact partial derivatives, for the small motions about any state;
//! 4. [`confirm`] checks a simulation against the other methods, and [`run`] runs each
//!    stage once for a handout, only what its [`Job`] asks (the one orchestrator); for
//!    the statics handout, [`rest`] finds the equilibrium and [`run_at_rest`] runs the
//!    stages there;
//! 5. the renderers and exporters read what the stages before them produced.
//!
//! Recovery lives here and nowhere else: where the Motion Law's plan is singular at a state
//! at which the system is not (a row's reaction term vanishing there), the solver and the
//! linearizer plan again for that state and go on, for every command alike.

mod impact;
mod memo;
mod motion;
mod rest_rows;
mod run;
mod stability;
mod stages;
mod statics;
mod statics_answers;
mod statics_handout;
mod sweep;

pub use impact::{impact, impact_at_start, ImpactSolution};
pub use motion::{frame_count, frames};
pub use run::{run, ImpactWorked, Job, Worked, NUMBERED_UNKNOWNS};
pub use stages::{derive, Purpose};
pub use statics::{Equilibrium, Stability, StabilityKind, Statics};
pub use statics_handout::{rest, run_at_rest, Rest, WorkedAtRest};
pub use sweep::{sweep, Sweep, Swept};

use crate::equations::{Derivation, Method};
use crate::error::Error;
use crate::mechanics::Form;
use crate::numeric::{
    jacobian_of, Check, Compiled, Derived, Evaluation, Jacobian, Linearization, ModalAnalysis,
    SolveError, StateSolution, System, Trajectory,
};
use crate::problem::{Problem, State};
use std::cell::RefCell;

/// Reads and validates the problem file at `path`.
///
/// # Errors
/// An unreadable file, or every error of an invalid problem with its path and hint.
pub fn load(path: &std::path::Path) -> Result<Problem, Error> {
    Ok(crate::problem::load_file(path)?)
}

/// The confirmation checks of a run of `solver` from `q0` (see
/// [`numeric::checks::confirm`](crate::numeric::confirm)), the other three methods
/// derived and solved through this pipeline, with the same recovery. Every method is
/// checked by its own rows ([`Purpose::Own`]): where Kane's system by composite bodies stood
/// in for `solver`'s method, that method's own rows are derived for the check.
pub fn confirm(
    problem: &Problem,
    solver: &Solver,
    trajectory: &Trajectory,
    q0: &[f64],
) -> Vec<Check> {
    let method = solver.method();
    let own = match solver.is_own() {
        true => None,
        false => Some(derive(problem, method, Purpose::Own).map(|d| Solver::new(problem, &d))),
    };
    let derived: Vec<(Method, Result<Derivation, Error>)> = Method::ALL
        .iter()
        .filter(|m| **m != method)
        .map(|&m| (m, derive(problem, m, Purpose::Own)))
        .collect();
    let solvers: Vec<(Method, Result<Solver, &Error>)> = derived
        .iter()
        .map(|(m, d)| (*m, d.as_ref().map(|d| Solver::new(problem, d))))
        .collect();
    let mut others: Vec<(&str, Derived)> = solvers
        .iter()
        .map(|(m, s)| {
            let system = match s {
                Ok(s) => Ok(s as &dyn System),
                Err(e) => Err(*e as &dyn std::fmt::Display),
            };
            (m.title(), system)
        })
        .collect();
    // Without its own rows the method fails the agreement, with the reason, and the run's
    // equations stand in for the other checks.
    let primary: &Solver = match &own {
        None => solver,
        Some(Ok(own)) => own,
        Some(Err(e)) => {
            others.push((method.title(), Err(e as &dyn std::fmt::Display)));
            solver
        }
    };
    // The checks name each method as a course writes it: "from the Motion Law (…)".
    crate::numeric::confirm(problem, (method.title(), primary), &others, trajectory, q0)
}

/// Runs every stage for the worked solution of `problem` by `method`: [`run`] with
/// [`Job::worked`].
///
/// # Errors
/// As for [`run`].
pub fn work(problem: &Problem, method: Method) -> Result<Worked<'_>, Error> {
    run(problem, &Job::worked(method))
}

/// The answers to the questions of `problem` (`find.questions`), in order, with the
/// equations of `method` in their numeric form: what the handout's "Answers", `mbd-tutor
/// answer` and each row of a variants key report.
///
/// # Errors
/// When the equations cannot be derived, or the first question that cannot be answered.
pub fn answers(problem: &Problem, method: Method) -> Result<Vec<crate::numeric::Answer>, Error> {
    memo::answers(problem, method, || {
        answers_from(problem, method, &derive(problem, method, Purpose::Numbers)?)
    })
}

/// As [`answers`], from `derivation`: the equations of `problem` by `method` as
/// [`derive()`] gives them, derived once for the answers, the small motions and the
/// stability alike where the problem declares no speeds of its own.
///
/// # Errors
/// As for [`answers`].
pub fn answers_from(
    problem: &Problem,
    method: Method,
    derivation: &Derivation,
) -> Result<Vec<crate::numeric::Answer>, Error> {
    let solver = Solver::fastest(problem, derivation);
    let after = match &problem.impact {
        Some(_) => Some(impact_at_start(problem, &derivation.model, &solver)?.after),
        None => None,
    };
    // At rest, and for small motions, the speeds are the rates: the equations in the
    // rates serve.
    let in_rates = problem.without_speeds();
    // The questions of statics are answered at rest, every friction site sticking; a
    // `slips` asked of a moving state is answered with the motion.
    let at_rest =
        |q: &crate::problem::Question| q.kind.is_static() && !crate::numeric::asked(problem, q);
    let mut given = vec![None; problem.questions.len()];
    if problem.questions.iter().any(at_rest) {
        let statics = statics::Statics::new(&in_rates, method)?;
        for (i, question) in problem.questions.iter().enumerate() {
            if at_rest(question) {
                match statics_answers::answer(&statics, &in_rates, question) {
                    Ok(found) => given[i] = Some(found),
                    // No equilibrium near a state at rest (a hoop let go on a slope): whether
                    // a rough site slips or tips is decided as it starts to move, below.
                    Err(_) if rough_slips(&statics, &in_rates, question) => {}
                    Err(e) => return Err(e),
                }
            }
        }
    }
    let asks_period = (problem.questions.iter()).any(|q| {
        use crate::problem::QuestionKind::{Period, Stability};
        matches!(q.kind, Period { .. } | Stability { .. })
    });
    let linearizer = match (asks_period, problem.has_speeds()) {
        (true, true) => Some(Linearizer::new(&derive(
            &in_rates,
            method,
            Purpose::Numbers,
        )?)),
        // Without declared speeds the problem in its rates is the problem itself.
        (true, false) => Some(Linearizer::new(derivation)),
        (false, _) => None,
    };
    // Where the stability changes, from the linearizations over the constant's range.
    for (i, question) in problem.questions.iter().enumerate() {
        if let (crate::problem::QuestionKind::Stability { .. }, Some(l)) =
            (&question.kind, &linearizer)
        {
            given[i] = Some(stability::answer(&in_rates, l, question)?);
        }
    }
    let linearize = |t: f64, q: &[f64], rates: &[f64]| match &linearizer {
        Some(l) => l.at(&in_rates, t, q, rates).map_err(|e| e.to_string()),
        None => Err("no linearization".to_string()),
    };
    crate::numeric::answer_all_with(problem, &solver, Some(&linearize), after.as_deref(), given)
        .map_err(|e| Error::Problem(crate::problem::ProblemErrors(vec![e])))
}

/// Whether `question` asks `slips` or `tips` of a site with friction.
fn rough_slips(
    statics: &statics::Statics,
    problem: &Problem,
    question: &crate::problem::Question,
) -> bool {
    use crate::problem::QuestionKind::{Slips, Tips};
    match question.kind {
        Slips { site } | Tips { site } => {
            let name = problem.site_name(site);
            statics.friction_sites().iter().any(|s| s == name)
        }
        _ => false,
    }
}

/// What is compiled from a derivation's plan, and from the plans made again for special
/// states where it is singular: the recovery every compiled form of the equations shares.
struct Plans<T> {
    method: Method,
    /// Whether the first plan is the Motion Law's, which a special state may make singular.
    replans: bool,
    /// Whether the equations are the method's own (see [`Solver::is_own`]).
    own: bool,
    /// The plan of the derivation first, then any plans made for special states.
    plans: RefCell<Vec<T>>,
}

impl<T> Plans<T> {
    fn new(derivation: &Derivation, first: T) -> Plans<T> {
        Plans {
            method: derivation.method,
            replans: derivation.system_method == Method::MotionLaw,
            own: derivation.system_method == derivation.method,
            plans: RefCell::new(vec![first]),
        }
    }

    fn first(&self) -> std::cell::Ref<'_, T> {
        std::cell::Ref::map(self.plans.borrow(), |plans| &plans[0])
    }

    /// Runs `f` on the newest plan; where the system is singular with the Motion Law, plans
    /// again for this state, compiles the new plan with `compile` and runs `f` on it.
    fn run<R>(
        &self,
        problem: &Problem,
        (t, q, rates): (f64, &[f64], &[f64]),
        compile: impl Fn(&Derivation) -> Option<T>,
        f: impl Fn(&T) -> Result<R, SolveError>,
    ) -> Result<R, SolveError> {
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
        if !self.replans || self.plans.borrow().len() > 8 {
            return first;
        }
        let state = State {
            t,
            q: q.to_vec(),
            rates: rates.to_vec(),
        };
        let Some(compiled) = derive(problem, self.method, Purpose::At(&[state], Form::Numeric))
            .ok()
            .and_then(|derivation| compile(&derivation))
        else {
            return first;
        };
        let result = f(&compiled);
        if result.is_ok() {
            self.plans.borrow_mut().push(compiled);
        }
        result
    }
}

/// Compiled equations that plan again where their plan is singular.
pub struct Solver<'p> {
    problem: &'p Problem,
    plans: Plans<Compiled>,
}

impl<'p> Solver<'p> {
    /// Compiles `derivation` for `problem`.
    pub fn new(problem: &'p Problem, derivation: &Derivation) -> Solver<'p> {
        Solver {
            problem,
            plans: Plans::new(derivation, Compiled::new(derivation)),
        }
    }

    /// As [`Solver::new`], with the q'' in the fastest exact form ([`Compiled::fastest`]):
    /// for `solve`, `simulate` and the answers.
    pub fn fastest(problem: &'p Problem, derivation: &Derivation) -> Solver<'p> {
        Solver {
            problem,
            plans: Plans::new(derivation, Compiled::fastest(derivation)),
        }
    }

    /// The method of the equations.
    pub fn method(&self) -> Method {
        self.plans.method
    }

    /// Whether the equations are the method's own rows, not Kane's system by composite
    /// bodies standing in for them.
    pub fn is_own(&self) -> bool {
        self.plans.own && !self.compiled().is_recursive()
    }

    /// The compiled equations of the derivation's own plan.
    pub fn compiled(&self) -> std::cell::Ref<'_, Compiled> {
        self.plans.first()
    }

    /// Runs `f` on the plan that suits the state (see [`Plans::run`]).
    fn with_plan<T>(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        f: impl Fn(&Compiled) -> Result<T, SolveError>,
    ) -> Result<T, SolveError> {
        self.plans
            .run(self.problem, (t, q, rates), |d| Some(Compiled::new(d)), f)
    }

    /// The q'', reactions and drives at a state (which must meet the constraints).
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

    fn reaction_columns(&self) -> Vec<crate::numeric::ReactionColumn> {
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

    fn friction_sites(&self) -> Vec<String> {
        self.compiled().friction_sites()
    }

    fn accelerations_held(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        held: &[crate::numeric::Held],
    ) -> Result<Vec<f64>, SolveError> {
        self.with_plan(t, q, rates, |c| {
            c.motion_held(t, q, rates, Some(held))
                .map(|m| m.accelerations)
        })
    }

    fn friction_at(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        held: Option<&[crate::numeric::Held]>,
    ) -> Result<(Vec<crate::numeric::SiteState>, Vec<f64>), SolveError> {
        self.with_plan(t, q, rates, |c| c.friction_at(t, q, rates, held))
    }
}

/// The linearization of a derivation about any state, with the same recovery as the
/// [`Solver`]: where the Motion Law's plan is singular at the state, the state matrix comes
/// from a plan made for it.
pub struct Linearizer {
    linear: ModalAnalysis,
    jacobians: Plans<Jacobian>,
}

impl Linearizer {
    /// Compiles the equations of `derivation` for their partial derivatives.
    pub fn new(derivation: &Derivation) -> Linearizer {
        Linearizer {
            linear: ModalAnalysis::new(derivation),
            jacobians: Plans::new(derivation, jacobian_of(derivation)),
        }
    }

    /// The method of the equations.
    pub fn method(&self) -> Method {
        self.jacobians.method
    }

    /// Linearizes about the state `t`, `q`, `rates` (assembled first when there are
    /// constraints), with the constants of `problem`: the problem derived from, or the
    /// same with other values of its constants (a sweep).
    ///
    /// # Errors
    /// Constraints that cannot be met, a system singular whatever the plan, a value that is
    /// not finite, or eigenvalues that do not converge.
    pub fn at(
        &self,
        problem: &Problem,
        t: f64,
        q: &[f64],
        rates: &[f64],
    ) -> Result<Linearization, Error> {
        let (q, rates) = self.linear.assemble(problem, t, q, rates)?;
        let state = self.jacobians.run(
            problem,
            (t, &q, &rates),
            |d| Some(jacobian_of(d)),
            |jacobian| jacobian.at(problem, t, &q, &rates),
        )?;
        Ok(self.linear.at(problem, t, &q, &rates, state)?)
    }
}
