//! The run of the statics handout (`explain --statics`): the equilibrium nearest the
//! initial configuration ([`rest`]), then the stages at it ([`run_at_rest`]): the
//! equations brought to rest, the solution there with every friction site sticking, and
//! the answers at the equilibrium. No simulation: the system stays at rest. The handout is
//! written from the [`WorkedAtRest`] alone.

use super::{answers, derive, rest_rows, Equilibrium, Purpose, Solver, Statics, Worked};
use crate::equations::{Derivation, Method};
use crate::error::Error;
use crate::numeric::{Answer, SolveError, StateSolution};
use crate::problem::Problem;

/// A problem brought to rest: the problem in its rates, its equilibrium nearest the
/// initial configuration, and the same problem placed there.
pub struct Rest {
    /// The problem in its rates: at rest the speeds are zero with the rates, so the
    /// equations in the rates serve.
    pub problem: Problem,
    /// The problem with its coordinates at the equilibrium and every rate zero (but for a
    /// prescribed motion's): the state the handout draws and solves at.
    pub at: Problem,
    /// The equilibrium nearest the initial configuration.
    pub equilibrium: Equilibrium,
    /// The free coordinates (neither dependent, held nor prescribed).
    free: Vec<usize>,
}

/// The equilibrium of `problem` by `method` nearest its initial configuration.
///
/// # Errors
/// Equations that cannot be derived, or no equilibrium near the initial configuration.
pub fn rest(problem: &Problem, method: Method) -> Result<Rest, Error> {
    let problem = problem.without_speeds();
    let (equilibrium, free) = {
        let statics = Statics::new(&problem, method)?;
        let guess = problem.initial_state().q;
        let equilibrium = statics.equilibrium(&guess, "the initial configuration")?;
        (equilibrium, statics.free().to_vec())
    };
    let at = at_equilibrium(&problem, &equilibrium);
    Ok(Rest {
        problem,
        at,
        equilibrium,
        free,
    })
}

/// The problem with its coordinates at the equilibrium, every rate zero.
fn at_equilibrium(problem: &Problem, equilibrium: &Equilibrium) -> Problem {
    let mut at = problem.clone();
    for ((c, q), rate) in at
        .coordinates
        .iter_mut()
        .zip(&equilibrium.q)
        .zip(&equilibrium.rates)
    {
        c.initial = *q;
        c.rate = *rate;
    }
    at
}

/// What the stages give the statics handout.
pub struct WorkedAtRest<'p> {
    /// The problem brought to rest.
    pub rest: &'p Rest,
    /// The equations at rest (every rate and q'' zero), their solver (the whole equations),
    /// the state (the equilibrium) and the solution there; no simulation.
    pub worked: Worked<'p>,
    /// Row by row, whether it is identically zero at rest.
    pub zero: Vec<bool>,
    /// The free coordinates whose equilibrium value the rows find.
    pub found: Vec<usize>,
    /// The answers at the equilibrium, for the worked solution of a problem with
    /// questions.
    pub answers: Option<Vec<Answer>>,
    /// For the student's version, the equations at the initial configuration (which its
    /// picture shows), where they can be derived.
    pub initial: Option<Derivation<'p>>,
}

/// Runs the stages at the equilibrium of `rest` by `method`; for the `student`'s version
/// also the equations at the initial configuration, and no answers.
///
/// # Errors
/// Equations that cannot be derived, or (for the worked solution) an answer that fails.
pub fn run_at_rest(rest: &Rest, method: Method, student: bool) -> Result<WorkedAtRest<'_>, Error> {
    let at = &rest.at;
    let equilibrium = &rest.equilibrium;
    let mut derivation = derive(at, method, Purpose::Handout)?;
    let solver = Solver::new(at, &derivation);
    let found = rest_rows::to_find(&derivation, &rest.free);
    rest_rows::replan(&mut derivation, &equilibrium.q, &equilibrium.rates, &found);
    let zero = rest_rows::rows(&mut derivation, &found);
    let state = (equilibrium.q.clone(), equilibrium.rates.clone());
    let mut worked = Worked::new(derivation, solver, state, solution_at_rest(equilibrium));
    worked.simulation = Some(Err(SolveError::BadSimulation {
        what: "the system is at rest".into(),
    }));
    let initial = match student {
        true => derive(&rest.problem, method, Purpose::Handout).ok(),
        false => None,
    };
    let answers = match student || rest.problem.questions.is_empty() {
        true => None,
        false => Some(answers(at, method)?),
    };
    Ok(WorkedAtRest {
        rest,
        worked,
        zero,
        found,
        answers,
        initial,
    })
}

/// The solution at the equilibrium, every friction site sticking, its reactions without
/// round-off.
fn solution_at_rest(equilibrium: &Equilibrium) -> StateSolution {
    let motion = &equilibrium.motion;
    StateSolution {
        accelerations: motion.accelerations.clone(),
        reactions: motion.reactions.iter().map(without_roundoff).collect(),
        drives: motion.drives.clone(),
        speeds: Vec::new(),
        friction: motion.friction.clone(),
    }
}

/// A reaction with the round-off of its solution (a component 1e-12 times the largest or
/// less) written as the zero it is.
fn without_roundoff(
    (name, force, moment): &(String, [f64; 3], [f64; 3]),
) -> (String, [f64; 3], [f64; 3]) {
    let scale = force
        .iter()
        .chain(moment)
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let clean = |v: &[f64; 3]| v.map(|x| if x.abs() <= 1e-12 * scale { 0.0 } else { x });
    (name.clone(), clean(force), clean(moment))
}
