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
//! `statics` command's; the stages run at the equilibrium before ([`crate::WorkedAtRest`]),
//! and this module only writes what they gave.

mod at_rest;
mod view;

use super::Handout;
use crate::numeric::Answer;
use crate::render::{AnswerView, Solution};
use crate::{Worked, WorkedAtRest};

/// The statics handout from the stages' run at the equilibrium nearest the initial
/// configuration, or with `student` the student's version.
pub fn handout(at_rest: &WorkedAtRest, student: bool, settings: &Handout) -> Solution {
    let rest = at_rest.rest;
    let problem = &rest.problem;
    let worked = &at_rest.worked;
    let method = worked.derivation.method;
    let mut solution = super::worked(worked);
    at_rest::strip(&mut solution, &worked.derivation, &at_rest.zero);
    at_rest::draw(&mut solution, worked);
    solution.statics = Some(view::section(&rest.at, &rest.equilibrium, &at_rest.found));
    if settings.every_rejected {
        solution.plan.show_every_rejected();
    }
    if student {
        solution = at_rest::student(problem, method, at_rest.initial.as_ref(), &solution);
    }
    if !problem.questions.is_empty() {
        solution.answers = match (student, &at_rest.answers) {
            (false, Some(found)) => answers(worked, found),
            _ => super::answers::blank(problem),
        };
    }
    let numbered = problem.questions.iter().any(|q| q.item.is_some());
    super::concise::without_repeats(&mut solution, settings.every_rejected, numbered);
    super::abbreviations::keep_printed(&mut solution);
    solution
}

/// The Answers at the equilibrium, at rest: the questions answered as `answer` answers
/// them, for the problem placed at the equilibrium.
fn answers(worked: &Worked, answers: &[Answer]) -> Vec<AnswerView> {
    let at = worked.derivation.model.problem;
    let mut views = super::answers::section(at, answers);
    super::question_steps::attach(worked, answers, &mut views);
    for view in &mut views {
        if view.at_note == "the initial state" {
            view.at_note = "at rest, at the equilibrium".into();
        }
    }
    views
}
