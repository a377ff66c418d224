//! The worked solution of a problem at rest (`explain --statics`), in the six steps of the
//! dynamic one: step 1 the frames, coordinates and the configuration sought; step 2 the
//! free bodies without kinetic diagrams; step 3 the planner's table; step 4 only what
//! statics needs of the kinematics; step 5 the equilibrium equations (every rate and
//! second derivative zero), their solution, the reactions, holding forces, friction and
//! the stability; step 6 no motion.
//!
//! The equations are the dynamic ones with every rate and second derivative set to zero:
//! the Motion Law with the inertia forces zero, Newton–Euler with every body free, Kane's
//! generalized active forces equal to zero, Lagrange's ∂V/∂q_r = Q_r. The numbers are the
//! `statics` command's ([`crate::pipeline::statics`]).

mod at_rest;
mod plan;
mod view;

use super::Handout;
use crate::equations::Method;
use crate::numeric::{SolveError, StateSolution};
use crate::pipeline::{self, Solver, Worked};
use crate::pipeline::{Equilibrium, Statics};
use crate::problem::Problem;
use crate::render::{AnswerView, Solution};
use crate::Error;

/// The statics handout of `problem` by `method`: the worked solution at the equilibrium
/// nearest the initial configuration, or with `settings.student` the student's version.
///
/// # Errors
/// An invalid problem, equations that cannot be derived, no equilibrium near the initial
/// configuration, or an answer that fails.
pub fn handout(
    problem: &Problem,
    method: Method,
    student: bool,
    settings: &Handout,
) -> Result<Solution, Error> {
    // At rest the speeds are zero with the rates: the equations in the rates serve.
    let problem = problem.without_speeds();
    let statics = Statics::new(&problem, method)?;
    let guess: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let equilibrium = statics.equilibrium(&guess, "the initial configuration")?;
    let at = at_equilibrium(&problem, &equilibrium);
    let free = statics.free().to_vec();
    let (worked, zero, found) = worked_at_rest(&at, method, &equilibrium, &free)?;
    let mut solution = super::worked(&worked);
    at_rest::strip(&mut solution, &worked.derivation, &zero);
    at_rest::draw(&mut solution, &worked);
    solution.statics = Some(view::section(&at, &equilibrium, &found));
    if settings.every_rejected {
        solution.plan.show_every_rejected();
    }
    if student {
        solution = at_rest::student(&problem, method, &solution);
    }
    if !problem.questions.is_empty() {
        solution.answers = match student {
            true => super::answers::blank(&problem),
            false => answers(&at, method, &worked)?,
        };
    }
    super::concise::without_repeats(&mut solution, settings.every_rejected);
    Ok(solution)
}

/// The problem with its coordinates at the equilibrium, every rate zero: the state the
/// handout draws and solves at.
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

/// What the stages give at rest: the equations, the state (the equilibrium) and the
/// solution there with every friction site sticking; no simulation. The rows are those
/// at rest ([`at_rest::rows`]), with which of them are identically zero, and the free
/// coordinates whose equilibrium value they find; the solver keeps the whole equations.
fn worked_at_rest<'p>(
    at: &'p Problem,
    method: Method,
    equilibrium: &Equilibrium,
    free: &[usize],
) -> Result<(Worked<'p>, Vec<bool>, Vec<usize>), Error> {
    let mut derivation = pipeline::derive(at, method, pipeline::Purpose::Handout)?;
    let solver = Solver::new(at, &derivation);
    let found = plan::to_find(&derivation, free);
    plan::replan(&mut derivation, &equilibrium.q, &equilibrium.rates, &found);
    let zero = at_rest::rows(&mut derivation, &found);
    let motion = &equilibrium.motion;
    let initial = StateSolution {
        accelerations: motion.accelerations.clone(),
        reactions: motion.reactions.iter().map(without_roundoff).collect(),
        drives: motion.drives.clone(),
        speeds: Vec::new(),
        friction: motion.friction.clone(),
    };
    let worked = Worked {
        derivation,
        solver,
        q0: equilibrium.q.clone(),
        rates0: equilibrium.rates.clone(),
        initial,
        simulation: Some(Err(SolveError::BadSimulation {
            what: "the system is at rest".into(),
        })),
        impact: None,
        answers: None,
        period_system: None,
        show_accelerations: Vec::new(),
        linearization: None,
        frames: None,
    };
    Ok((worked, zero, found))
}

/// The Answers at the equilibrium, at rest: the questions answered as `answer` answers
/// them, for the problem placed at the equilibrium.
fn answers(at: &Problem, method: Method, worked: &Worked) -> Result<Vec<AnswerView>, Error> {
    let answers = pipeline::answers(at, method)?;
    let mut views = super::answers::section(at, &answers);
    super::question_steps::attach(worked, &answers, &mut views);
    for view in &mut views {
        if view.at_note == "the initial state" {
            view.at_note = "at rest, at the equilibrium".into();
        }
    }
    Ok(views)
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
