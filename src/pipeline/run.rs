//! The one orchestrator of a worked solution ([`run`]): each stage called once, and only
//! for what the handout asks ([`Job`]). The worked solution and the student's version are
//! written from its [`Worked`] alone.

use super::{answers, answers_from, confirm, derive, impact, memo, Linearizer, Purpose, Solver};
use crate::equations::{Derivation, LinearSystem, Method};
use crate::error::Error;
use crate::numeric::solve_linear;
use crate::numeric::{
    simulate, Answer, Check, Frame, Linearization, SolveError, StateSolution, System, Trajectory,
    DEFAULT_FPS,
};
use crate::problem::{Problem, QuestionKind, State};
use crate::symbolic::eval;
use nalgebra::{DMatrix, DVector};

/// What a handout asks of the stages besides the derivation and the initial state.
#[derive(Clone, Debug)]
pub struct Job {
    /// The method whose equations the handout writes.
    pub method: Method,
    /// The student's version: the derivation and the initial state only (what its blank
    /// tables count and its picture shows); no simulation, checks or answers.
    pub student: bool,
    /// Small motions about this state (coordinates, rates).
    pub linearize_at: Option<(Vec<f64>, Vec<f64>)>,
    /// Step 6's motion sampled for the animation (the HTML page).
    pub motion: bool,
}

impl Job {
    /// The worked solution by `method`, without small motions or the animation.
    pub fn worked(method: Method) -> Job {
        Job {
            method,
            student: false,
            linearize_at: None,
            motion: false,
        }
    }
}

/// Everything a handout shows, from every stage: the derivation, its solver, the initial
/// state (made to meet the constraints) and the solution there, and, as the [`Job`] asked,
/// the simulation from it with its confirmation checks, the answers, the small motions and
/// the motion's frames.
pub struct Worked<'p> {
    /// The equations.
    pub derivation: Derivation<'p>,
    /// The equations compiled, with the recovery.
    pub solver: Solver<'p>,
    /// The initial coordinates, assembled.
    pub q0: Vec<f64>,
    /// The initial rates, assembled.
    pub rates0: Vec<f64>,
    /// The q'', reactions, drives and energies at the initial state.
    pub initial: StateSolution,
    /// The simulation and its checks, or why it could not start; `None` when not asked
    /// (the student's version).
    pub simulation: Option<Result<(Trajectory, Vec<Check>), SolveError>>,
    /// The impact at the initial state, if the problem has one: the simulation starts
    /// just after it.
    pub impact: Option<ImpactWorked<'p>>,
    /// The answers to the questions, when asked and the problem has questions.
    pub answers: Option<Vec<Answer>>,
    /// Kane's linear system in the rates, where a period with one degree of freedom left
    /// is answered from it (see [`Worked::answers`]).
    pub period_system: Option<LinearSystem>,
    /// For each question, where it is a `show`, the q'' at its state by the handout's
    /// equations (`None` where they cannot be solved there).
    pub show_accelerations: Vec<Option<Vec<f64>>>,
    /// The unknowns of step 5's system at the initial state, in its order, solved from its
    /// matrix and right-hand side evaluated there, where it has at most
    /// [`NUMBERED_UNKNOWNS`] unknowns (the worked solution writes the system, or the block
    /// of it solved first, with its numbers and this solution); `None` otherwise, or where
    /// it is singular there.
    pub initial_unknowns: Option<Vec<f64>>,
    /// The small motions about the state asked for.
    pub linearization: Option<Linearization>,
    /// The motion's frames over the simulation's duration at the default frame rate, or
    /// why they could not be made; `None` when not asked.
    pub frames: Option<Result<Vec<Frame>, Error>>,
}

impl<'p> Worked<'p> {
    /// The derivation, its solver, the state (coordinates and rates, assembled) and the
    /// solution there; nothing else yet.
    pub(super) fn new(
        derivation: Derivation<'p>,
        solver: Solver<'p>,
        (q0, rates0): (Vec<f64>, Vec<f64>),
        initial: StateSolution,
    ) -> Worked<'p> {
        Worked {
            derivation,
            solver,
            q0,
            rates0,
            initial,
            simulation: None,
            impact: None,
            answers: None,
            period_system: None,
            show_accelerations: Vec::new(),
            initial_unknowns: None,
            linearization: None,
            frames: None,
        }
    }
}

/// The impact at the initial state, and the method's equations of the impulsive problem
/// (or why they could not be written out).
pub struct ImpactWorked<'p> {
    /// The rates after, the impulses and the energy lost.
    pub solution: super::ImpactSolution,
    /// The impulse–momentum equations, `None` when the impulsive problem cannot be formed.
    pub equations: Option<Result<Derivation<'p>, Error>>,
}

/// Runs the stages for the handout `job` asks of `problem`, each once (see [`Worked`]).
///
/// # Errors
/// When the equations cannot be derived, the constraints cannot be met at the initial
/// state, the system cannot be solved there, or (for the worked solution) the small
/// motions or an answer fail. A simulation that cannot run is not an error: the worked
/// solution says so.
pub fn run<'p>(problem: &'p Problem, job: &Job) -> Result<Worked<'p>, Error> {
    let method = job.method;
    let derivation = derive(problem, method, Purpose::Handout)?;
    let solver = Solver::new(problem, &derivation);
    let State {
        t,
        q: mut q0,
        rates: mut rates0,
    } = problem.initial_state();
    solver.assemble(t, &mut q0, &mut rates0)?;
    let initial = solver.solve(t, &q0, &rates0)?;
    let impact = match &problem.impact {
        Some(_) => Some(impact(
            problem,
            &derivation.model,
            method,
            &q0,
            &rates0,
            &solver,
        )?),
        None => None,
    };
    let mut worked = Worked::new(derivation, solver, (q0, rates0), initial);
    if job.student {
        worked.impact = impact.map(|solution| ImpactWorked {
            solution,
            equations: None,
        });
        return Ok(worked);
    }
    worked.initial_unknowns = unknowns_at(&worked.derivation, t, &worked.q0, &worked.rates0);
    let start = impact.as_ref().map_or(&worked.rates0, |i| &i.after);
    worked.simulation = Some(
        simulate(&worked.solver, &worked.q0, start, &problem.simulate).map(|trajectory| {
            let checks = confirm(problem, &worked.solver, &trajectory, &worked.q0);
            (trajectory, checks)
        }),
    );
    worked.impact = impact.map(|solution| ImpactWorked {
        equations: impulsive_equations(problem, method, &worked.q0),
        solution,
    });
    if job.motion {
        worked.frames = Some(frames(problem, &worked));
    }
    // For numbers, derived once for the small motions and the answers where the problem
    // declares no speeds (then the problem in its rates is the problem itself).
    let mut numeric = None;
    if let Some((q, rates)) = &job.linearize_at {
        // Small motions are about the coordinates and their rates, whatever the speeds.
        let in_rates = problem.without_speeds();
        let linearizer = match problem.has_speeds() {
            true => Linearizer::new(&derive(&in_rates, method, Purpose::Numbers)?),
            false => Linearizer::new(numeric.insert(derive(problem, method, Purpose::Numbers)?)),
        };
        worked.linearization = Some(linearizer.at(&in_rates, 0.0, q, rates)?);
    }
    if !problem.questions.is_empty() {
        let found = match &numeric {
            Some(numeric) => {
                memo::answers(problem, method, || answers_from(problem, method, numeric))?
            }
            None => answers(problem, method)?,
        };
        worked.period_system = period_system(problem, &worked.derivation, &found);
        worked.show_accelerations = show_accelerations(problem, &worked.derivation, &found);
        worked.answers = Some(found);
    }
    Ok(worked)
}

/// The most unknowns a system has that the worked solution solves with its numbers (it
/// writes the matrix of at most six of them: the whole, or the block solved first).
pub const NUMBERED_UNKNOWNS: usize = 12;

/// The unknowns of `derivation`'s system at time `t`, coordinates `q` and rates `rates`:
/// its matrix and right-hand side evaluated there and solved, where it is square with at
/// most [`NUMBERED_UNKNOWNS`] unknowns and regular there.
fn unknowns_at(derivation: &Derivation, t: f64, q: &[f64], rates: &[f64]) -> Option<Vec<f64>> {
    let system = &derivation.system;
    let n = system.unknowns.len();
    if n == 0 || n > NUMBERED_UNKNOWNS || system.a.len() != n {
        return None;
    }
    let values = derivation.model.values_at(t, q, rates);
    let a = DMatrix::from_fn(n, n, |i, j| eval(&system.a[i][j], &values));
    let b = DVector::from_fn(n, |i, _| eval(&system.b[i], &values));
    let x = solve_linear(&a, &b)?;
    x.iter()
        .all(|v| v.is_finite())
        .then(|| x.iter().copied().collect())
}

/// The method's equations of the impulsive problem at `q0`, the problem kept for the rest
/// of the program (one small problem per run, which the derivation borrows).
fn impulsive_equations<'p>(
    problem: &Problem,
    method: Method,
    q0: &[f64],
) -> Option<Result<Derivation<'p>, Error>> {
    let impulsive = problem.impulsive(q0, None)?;
    let kept: &'p Problem = Box::leak(Box::new(impulsive.problem));
    Some(derive(kept, method, Purpose::Handout))
}

/// The frames of the motion over the simulation's duration at the default frame rate,
/// integrated by the handout's equations compiled afresh: the run's solver keeps the state
/// its simulation ended in (the friction sites' modes), which a new run must not start from.
fn frames(problem: &Problem, worked: &Worked) -> Result<Vec<Frame>, Error> {
    let duration = problem.simulate.duration;
    super::frames(problem, &worked.derivation, duration, DEFAULT_FPS)
}

/// Kane's linear system of the problem in its rates, where some period with one degree of
/// freedom left is answered: its working writes that coordinate's equation.
/// The run's own derivation serves where it is Kane's of a problem without declared speeds.
fn period_system(
    problem: &Problem,
    derivation: &Derivation,
    answers: &[Answer],
) -> Option<LinearSystem> {
    let one_left =
        (answers.iter().filter_map(|a| a.period.as_ref())).any(|p| p.coordinates.len() == 1);
    // A second rate asked of a problem with one degree of freedom: q̈ = b/a in symbols.
    let acceleration = (problem.questions.iter()).any(|q| {
        matches!(&q.kind, QuestionKind::Value { expression, .. }
            if matches!(expression.as_symbol(), Some(crate::symbolic::Symbol::Coord(_, 2))))
    });
    let free = (problem.coordinates.iter())
        .filter(|c| !c.dependent && !c.dependent_rate && c.motion.is_none())
        .count();
    let one_freedom = free == 1;
    if !(one_left || acceleration && one_freedom) {
        return None;
    }
    if derivation.method == Method::Kane && !problem.has_speeds() {
        return Some(derivation.system.clone());
    }
    let in_rates = problem.without_speeds();
    derive(&in_rates, Method::Kane, Purpose::Handout)
        .ok()
        .map(|d| d.system.clone())
}

/// The q'' at each `show` question's state, by the handout's equations.
fn show_accelerations(
    problem: &Problem,
    derivation: &Derivation,
    answers: &[Answer],
) -> Vec<Option<Vec<f64>>> {
    (problem.questions.iter().zip(answers))
        .map(|(question, answer)| match question.kind {
            QuestionKind::Show { .. } => Solver::new(problem, derivation)
                .solve(answer.time, &answer.q, &answer.rates)
                .ok()
                .map(|s| s.accelerations),
            _ => None,
        })
        .collect()
}
