//! The whole handout of `explain` (and `serve`): the worked solution or the student's
//! version, with the sections asked for — small motions about a state, the Answers, and
//! step 6's motion for the HTML page.

use crate::equations::{Derivation, Method};
use crate::pipeline;
use crate::problem::Problem;
use crate::render::text::InlineSvg;
use crate::render::Solution;
use crate::Error;

/// What goes into a handout besides the six steps.
#[derive(Clone, Debug, Default)]
pub struct Handout {
    /// The student's version: the statement and the set-up, with blank tables.
    pub student: bool,
    /// Small motions about this state (coordinates, rates); left out of the student's.
    pub linearize_at: Option<(Vec<f64>, Vec<f64>)>,
    /// Step 6's motion, animated (the HTML page).
    pub motion: bool,
    /// Every candidate row the planner did not use, not only those that teach.
    pub every_rejected: bool,
}

/// The handout of `problem` by `method`.
///
/// # Errors
/// Whatever stops the worked solution: an invalid problem, equations that cannot be
/// derived or solved, a linearization or an answer that fails.
pub fn handout(problem: &Problem, method: Method, settings: &Handout) -> Result<Solution, Error> {
    let worked = match settings.student {
        true => None,
        false => Some(pipeline::work(problem, method)?),
    };
    let mut solution = match &worked {
        None => student(problem, method),
        Some(worked) => {
            let mut solution = super::worked(worked);
            if settings.motion {
                with_motion(&mut solution, problem, &worked.derivation);
            }
            solution
        }
    };
    if settings.every_rejected {
        solution.plan.show_every_rejected();
    }
    if let Some((q, rates)) = settings.linearize_at.as_ref().filter(|_| !settings.student) {
        // Small motions are about the coordinates and their rates, whatever the speeds.
        let in_rates = problem.without_speeds();
        let linearizer = pipeline::Linearizer::new(&pipeline::derive(&in_rates, method)?);
        let l = linearizer.at(&in_rates, 0.0, q, rates)?;
        solution.linearization = Some(super::linearization::section(problem, &l));
    }
    if !problem.questions.is_empty() {
        solution.answers = match &worked {
            None => super::answers::blank(problem),
            Some(worked) => {
                let answers = pipeline::answers(problem, method)?;
                let mut views = super::answers::section(problem, &answers);
                super::question_steps::attach(problem, &worked.derivation, &answers, &mut views);
                views
            }
        };
    }
    Ok(solution)
}

/// The student's handout: the set-up, the system drawn, and as many blank rows as the
/// worked solution has free bodies and equations.
fn student(problem: &Problem, method: Method) -> Solution {
    let mut setup = super::setup(problem, method);
    // The handout shows the system; its free bodies are left to draw.
    if let Ok(worked) = pipeline::work(problem, method) {
        if let Some(drawing) = super::pictures::initial_configuration(&worked.derivation) {
            setup.configuration = drawing.figure();
        }
        let full = super::worked(&worked);
        setup.free_bodies = vec![Default::default(); full.free_bodies.len()];
        setup.plan.rows = vec![Default::default(); full.plan.rows.len()];
        // Kane's worksheet: one line per speed and body of the partial-velocity table, to fill in.
        setup.partial_velocities = (full.partial_velocities.iter())
            .map(|p| crate::render::context::PartialVelocity {
                velocity_tex: Default::default(),
                omega_tex: Default::default(),
                ..p.clone()
            })
            .collect();
        setup.kane_theory = full.kane_theory.clone();
        setup.lagrange = full.lagrange.map(super::lagrange::blank);
    }
    setup
}

/// Step 6's motion for the HTML page, over the simulation's duration at the default frame
/// rate; left out, with a note, when it cannot be made.
fn with_motion(solution: &mut Solution, problem: &Problem, derivation: &Derivation) {
    use super::pictures::motion;
    use crate::render::draw::{motion_svg, View};
    let duration = problem.simulate.duration;
    match motion::frames(problem, derivation, duration, motion::DEFAULT_FPS) {
        Ok(frames) => {
            let drawn = motion::motion(derivation, &frames, View::Isometric);
            solution.simulation.motion_duration = frames.last().map_or(duration, |f| f.t);
            solution.simulation.motion_svg_inline =
                InlineSvg::from(motion_svg::export(&drawn).trim_end().to_string());
            solution.simulation.time_axis = crate::render::plot::x_axis_span();
        }
        Err(e) => {
            let note = &mut solution.simulation.note;
            if note.is_empty() {
                *note = format!("The motion could not be animated: {}", e.one_line());
            }
        }
    }
}
