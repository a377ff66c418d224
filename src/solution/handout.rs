//! The whole handout of `explain` (and `serve`): the worked solution or the student's
//! version, with the sections asked for — small motions about a state, the Answers, and
//! step 6's motion for the HTML page — written from what the run of the stages gave
//! ([`Worked`]), nothing derived, solved or simulated here.

use crate::equations::Method;
use crate::problem::Problem;
use crate::render::text::InlineSvg;
use crate::render::Solution;
use crate::Worked;

/// What goes into a handout besides the six steps.
#[derive(Clone, Debug, Default)]
pub struct Handout {
    /// Every candidate row the planner did not use, not only those that teach.
    pub every_rejected: bool,
}

/// The worked solution from `worked`: the six steps, and the small motions, the Answers
/// and the animated motion where the run made them.
pub fn handout(worked: &Worked, settings: &Handout) -> Solution {
    let problem = worked.derivation.model.problem;
    let mut solution = super::worked(worked);
    if let Some(frames) = &worked.frames {
        with_motion(&mut solution, worked, frames);
    }
    if settings.every_rejected {
        solution.plan.show_every_rejected();
    }
    if let Some(l) = &worked.linearization {
        solution.linearization = Some(super::linearization::section(problem, l));
    }
    if let Some(answers) = &worked.answers {
        let mut views = super::answers::section(problem, answers);
        super::question_steps::attach(worked, answers, &mut views);
        let sliding = super::switch_steps::attach(problem, &worked.derivation, answers, &mut views);
        super::reaction_forms::attach(problem, &worked.derivation, answers, &mut views, sliding);
        let (bodies, shown) = (&solution.free_bodies, &solution.shown_names);
        super::sense_words::say_third_law(problem, shown, &mut views);
        super::drawn_on::point_to_free_bodies(problem, bodies, shown, &mut views);
        super::moving_axes::attach(worked, &mut views);
        super::absent_constants::attach(&worked.derivation, &mut views);
        solution.answers = views;
    }
    let numbered = problem.questions.iter().any(|q| q.item.is_some());
    super::concise::without_repeats(&mut solution, settings.every_rejected, numbered);
    super::abbreviations::keep_printed(&mut solution);
    solution
}

/// The student's handout: the set-up, the system drawn, and as many blank rows as the
/// worked solution has free bodies and equations (none drawn, no blank rows, where the
/// stages could not give the equations and the initial state: `worked` is `None`).
pub fn student(
    problem: &Problem,
    method: Method,
    worked: Option<&Worked>,
    settings: &Handout,
) -> Solution {
    let mut setup = super::setup(problem, method);
    // The handout shows the system; its free bodies are left to draw.
    if let Some(worked) = worked {
        let derivation = &worked.derivation;
        if let Some(drawing) = super::pictures::initial_configuration(derivation) {
            setup.configuration = drawing.figure();
        }
        let (free_bodies, rows, lagrange) = super::derived::blanks(derivation);
        setup.free_bodies = vec![Default::default(); free_bodies];
        setup.plan.rows = vec![Default::default(); rows];
        setup.lagrange = lagrange.map(super::lagrange::blank);
        if method == Method::Kane {
            kane_worksheet(&mut setup, worked);
        }
    }
    if settings.every_rejected {
        setup.plan.show_every_rejected();
    }
    if !problem.questions.is_empty() {
        setup.answers = super::answers::blank(problem);
    }
    setup
}

/// Step 6's motion for the HTML page, over the simulation's duration at the default frame
/// rate; left out, with a note, when it cannot be made.
fn with_motion(
    solution: &mut Solution,
    worked: &Worked,
    frames: &Result<Vec<crate::numeric::Frame>, crate::Error>,
) {
    use super::pictures::motion;
    use crate::render::draw::{motion_svg, View};
    let duration = worked.derivation.model.problem.simulate.duration;
    match frames {
        Ok(frames) => {
            let drawn = motion::motion(&worked.derivation, frames, View::Isometric);
            solution.simulation.motion_duration = frames.last().map_or(duration, |f| f.t);
            solution.simulation.motion_svg_inline =
                InlineSvg::from(motion_svg::export(&drawn).trim_end().to_string());
            solution.simulation.time_axis = crate::render::x_axis_span();
        }
        Err(e) => {
            let note = &mut solution.simulation.note;
            if note.is_empty() {
                *note = format!("The motion could not be animated: {}", e.one_line());
            }
        }
    }
}

/// Kane's worksheet: one line per speed and body of the partial-velocity table to fill in,
/// and the theory said as the worked solution says it.
fn kane_worksheet(setup: &mut Solution, worked: &Worked) {
    let full = super::worked(worked);
    setup.partial_velocities = (full.partial_velocities.iter())
        .map(|p| crate::render::context::PartialVelocity {
            velocity_tex: Default::default(),
            omega_tex: Default::default(),
            ..p.clone()
        })
        .collect();
    setup.kane_theory = full.kane_theory;
}
