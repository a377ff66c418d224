//! The answers to a problem's `find.questions`: values at a state or at a time, reactions,
//! and steady motions or equilibria.
//!
//! - At a state (`at.state`, others initial) at `at.time` (default 0): the state is
//!   assembled (constraints) and the system evaluated there.
//! - At a time alone: the motion is simulated from the initial state up to that time, with
//!   the problem's tolerance, and the state reached is evaluated.
//! - At a switch (`at.switch`, a site with friction): simulated likewise up to the first
//!   instant that site switches between sticking and slipping (a skidding ball rolls).
//! - A drive: the generalized force of a prescribed coordinate's motion, solved with the
//!   reactions.
//! - A steady motion: Newton's method (Gauss-Newton where there are more second derivatives
//!   to make zero than unknowns) on the evaluated q'', with central-difference Jacobians and
//!   a halving line search, from the state given as the guess. Which root it finds depends
//!   on the guess: the slow and the fast precession of a top are two questions with two
//!   guesses.

use super::answer_frame;
use super::simulate::simulate;
use super::steady::{state_values, steady};
use super::system::{Evaluation, ReactionColumn, System};
use crate::problem::{Problem, ProblemError, Question, QuestionKind, SimulateSettings};
use crate::symbolic::{eval, ComponentKind};

pub use super::answer_units::{coordinate_unit, entry_name, is_free_moment, unit};
pub use super::quantity::Quantity;

/// One question answered.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    /// What was found, each with its value in SI units (or the problem's).
    pub values: Vec<(Quantity, f64)>,
    /// The time, seconds.
    pub time: f64,
    /// The state where the answer holds (for a steady motion, the one found).
    pub q: Vec<f64>,
    /// The rates at that state.
    pub rates: Vec<f64>,
    /// True when the state was reached by simulating from the initial state.
    pub simulated: bool,
    /// A steady motion: the largest |q''| of the `zero` coordinates left, and the
    /// iterations taken.
    pub residual: Option<(f64, usize)>,
    /// The frame whose unit vectors a vector answer's components are along (a reaction's:
    /// its site's parent's, or the question's `in`); `None` for a scalar.
    pub frame: Option<String>,
    /// A `period` question: the oscillation found.
    pub period: Option<super::period::Period>,
}

impl Answer {
    /// The answer `values` at one state `(q, rates)` at time `time`, reached without
    /// simulating: no steady motion's residual, no frame, no oscillation.
    pub fn at_state(
        values: Vec<(Quantity, f64)>,
        time: f64,
        (q, rates): (Vec<f64>, Vec<f64>),
    ) -> Answer {
        Answer {
            values,
            time,
            q,
            rates,
            simulated: false,
            residual: None,
            frame: None,
            period: None,
        }
    }
}

/// What answering one question may draw on: the answers of the steady motions (for
/// `about`) and the linearization (for `period`).
#[derive(Clone, Copy, Default)]
pub struct Context<'a> {
    /// The answers found so far, by question index.
    pub earlier: &'a [Option<Answer>],
    /// The linearization about a state; without it a `period` cannot be answered.
    pub linearize: Option<&'a super::period::Linearize<'a>>,
    /// The rates just after the problem's impact, if it has one (see [`answer_all_with`]).
    pub after: Option<&'a [f64]>,
}

/// Whether the two sides of a `show` agree: to 1e-6 of the larger, or both below 1e-9.
pub fn holds(lhs: f64, rhs: f64) -> bool {
    (lhs - rhs).abs() <= 1e-6 * lhs.abs().max(rhs.abs()).max(1e-3)
}

/// Answers every question of `problem` with `system`, in order.
///
/// # Errors
/// The first question that cannot be answered, with its JSON path and a hint.
pub fn answer_all(problem: &Problem, system: &dyn System) -> Result<Vec<Answer>, ProblemError> {
    answer_all_with(problem, system, None, None, Vec::new())
}

/// As [`answer_all`], with the linearization that `period` questions need, the rates just
/// after an impact, and the answers `given` already (by question index: the questions of
/// statics, answered at rest), which are kept as they are.
///
/// # Errors
/// As for [`answer_all`].
pub fn answer_all_with(
    problem: &Problem,
    system: &dyn System,
    linearize: Option<&super::period::Linearize>,
    after: Option<&[f64]>,
    given: Vec<Option<Answer>>,
) -> Result<Vec<Answer>, ProblemError> {
    // The questions without `about` first: those with it are asked at a steady motion
    // that another question finds, before or after them.
    let mut answers = given;
    answers.resize(problem.questions.len(), None);
    for pass in [false, true] {
        for (i, q) in problem.questions.iter().enumerate() {
            if q.about.is_some() != pass || answers[i].is_some() {
                continue;
            }
            let context = Context {
                earlier: &answers,
                linearize,
                after,
            };
            let found = answer_in(problem, system, q, context)?;
            answers[i] = Some(found);
        }
    }
    Ok(answers.into_iter().flatten().collect())
}

fn failure(question: &Question, message: String, hint: &str) -> ProblemError {
    ProblemError {
        path: question.path.clone(),
        column: None,
        message,
        hint: Some(hint.to_string()),
    }
}

/// As [`failure`], naming the question's `key` (its site): `find.questions[2].slips`.
fn site_failure(question: &Question, key: &str, message: String, hint: &str) -> ProblemError {
    ProblemError {
        path: format!("{}.{key}", question.path),
        ..failure(question, message, hint)
    }
}

/// Answers one question with what it may draw on (see [`Context`]).
///
/// # Errors
/// A system that cannot be solved at the state, a simulation that stops before the time,
/// or a steady motion that Newton's method does not find, each naming the question's path; also a `period` without the linearization, about an unstable state
/// or one where nothing oscillates.
pub fn answer_in(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    context: Context,
) -> Result<Answer, ProblemError> {
    let (t, mut q, mut rates) = starting_state(problem, system, question, &context)?;
    if matches!(question.kind, QuestionKind::Describe { .. }) {
        return described_answer(problem, system, question, (q, rates));
    }
    let simulated = question.about.is_none() && question.at.state.is_none() && t > 0.0;
    if let Some(state) = &question.at.state {
        for (entry, value) in state {
            let target = if entry.order == 0 { &mut q } else { &mut rates };
            target[entry.coordinate] = *value;
        }
    }
    if simulated {
        simulate_to(problem, system, question, t, (&mut q, &mut rates))?;
    }
    // A `slips` or `tips` question at rest that statics left (no equilibrium near it) is
    // answered as the motion starts; an `impending` one only at rest.
    if matches!(question.kind, QuestionKind::Impending { .. }) {
        return Err(failure(
            question,
            "a question of statics is answered at rest, with the friction sites sticking".into(),
            "ask it through the answers of the problem (`mbd-tutor answer`)",
        ));
    }
    let mut residual = None;
    if let QuestionKind::Steady { unknowns, zero } = &question.kind {
        let found = steady(problem, system, t, &mut q, &mut rates, unknowns, zero)
            .map_err(|(message, hint)| failure(question, message, hint))?;
        residual = Some(found);
    }
    system
        .assemble(t, &mut q, &mut rates)
        .map_err(|e| solve_failed(question, e))?;
    let evaluation = system
        .evaluate(t, &q, &rates)
        .map_err(|e| solve_failed(question, e))?;
    let names = system.coordinate_names();
    let mut frame = None;
    let mut period = None;
    let values = match &question.kind {
        QuestionKind::Value { expression, text } => {
            let v = state_values(problem, t, &q, &rates, &evaluation.accelerations);
            vec![(
                Quantity::Named(text.clone()),
                finite(question, text, eval(expression, &v))?,
            )]
        }
        QuestionKind::VectorValue { quantity, text } => {
            let at = (t, &q[..], &rates[..], &evaluation.accelerations[..]);
            let (found, to) = vector_values(problem, question, (*quantity, text), at)?;
            frame = Some(to);
            found
        }
        QuestionKind::Reaction { site: index } => {
            let (found, to) = reaction_values(
                problem,
                system,
                question,
                &evaluation,
                (*index, t, &q, &rates),
            )?;
            frame = Some(to);
            found
        }
        QuestionKind::Drive { coordinate } => {
            drive_values(problem, system, question, &evaluation, *coordinate)?
        }
        QuestionKind::Steady { unknowns, .. } => unknowns
            .iter()
            .map(|e| {
                let name = &names[e.coordinate];
                if e.order == 0 {
                    (Quantity::Named(name.clone()), q[e.coordinate])
                } else {
                    (Quantity::Named(format!("{name}'")), rates[e.coordinate])
                }
            })
            .collect(),
        // In motion: whether the site slides there.
        QuestionKind::Slips { site } => {
            super::moving_slip::values(problem, system, *site, (t, &q[..], &rates[..]))
                .map_err(|(message, hint)| site_failure(question, "slips", message, &hint))?
        }
        // Left by statics (no equilibrium near): the normal force as the motion starts.
        QuestionKind::Tips { site } => {
            super::moving_slip::normal(problem, system, *site, (t, &q[..], &rates[..]))
                .map_err(|(message, hint)| site_failure(question, "tips", message, &hint))?
        }
        // Answered by statics, or over the constant's range, before this point.
        QuestionKind::Impending { .. }
        | QuestionKind::Stability { .. }
        | QuestionKind::Describe { .. } => Vec::new(),
        QuestionKind::Period { coordinate } => {
            let coordinate = coordinate.map(|i| names[i].as_str());
            let found =
                super::period::asked(question, context.linearize, (t, &q, &rates), coordinate)?;
            let value = found.period;
            period = Some(found);
            vec![(Quantity::Named("T".into()), value)]
        }
        QuestionKind::Show { lhs, rhs, text, .. } => {
            let v = state_values(problem, t, &q, &rates, &evaluation.accelerations);
            let (l, r) = (
                finite(question, text, eval(lhs, &v))?,
                finite(question, text, eval(rhs, &v))?,
            );
            let (left, right) = text.split_once('=').unwrap_or((text, ""));
            vec![
                (Quantity::Named(left.trim().into()), l),
                (Quantity::Named(right.trim().into()), r),
            ]
        }
    };
    Ok(Answer {
        values,
        time: t,
        q,
        rates,
        simulated,
        residual,
        frame,
        period,
    })
}

/// `x`, or an error naming the question when `text` is not finite at its state.
fn finite(question: &Question, text: &str, x: f64) -> Result<f64, ProblemError> {
    if x.is_finite() {
        return Ok(x);
    }
    Err(failure(
        question,
        format!("`{text}` is not finite at this state"),
        "ask at a state where the expression is defined",
    ))
}

/// A `describe` question: the run from `(q, rates)` described (see [`super::describe`]).
fn described_answer(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    (q, rates): (Vec<f64>, Vec<f64>),
) -> Result<Answer, ProblemError> {
    let values = super::describe_answer::values(problem, system, question, (&q, &rates))
        .map_err(|(message, hint)| failure(question, message, hint))?;
    Ok(Answer::at_state(values, 0.0, (q, rates)))
}

/// The names of the axes, as the components of a vector answer are named.
pub const AXES: [&str; 3] = ["x", "y", "z"];

/// The axes a vector value has components along: in a plane, x and y for a point's
/// position, velocity or acceleration and z alone for a body's angular velocity or
/// acceleration; in space all three.
pub fn vector_axes(
    problem: &Problem,
    quantity: crate::problem::VectorQuantity,
) -> std::ops::Range<usize> {
    match (problem.dimension, quantity.is_angular()) {
        (crate::problem::Dimension::Two, false) => 0..2,
        (crate::problem::Dimension::Two, true) => 2..3,
        _ => 0..3,
    }
}

/// The time and state a question starts from, before its own `state` and any simulation:
/// the initial state (the rates just after the impact where it is asked after it), or an
/// earlier steady question's state (`about`), at the time asked or at the first switch of
/// a friction site.
fn starting_state(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    context: &Context,
) -> Result<(f64, Vec<f64>, Vec<f64>), ProblemError> {
    let initial = problem.initial_state();
    let (mut q, mut rates) = (initial.q, initial.rates);
    let at = &question.at;
    let from_after = at.after_impact
        || (at.state.is_none() && (at.switch.is_some() || at.time.is_some_and(|t| t > 0.0)));
    match context.after {
        Some(after) if from_after => rates.copy_from_slice(after),
        None if at.after_impact => {
            return Err(failure(
                question,
                "the question is asked after the impact, but the problem has no `impact`".into(),
                "remove `after_impact`, or give the problem an `impact`",
            ))
        }
        _ => {}
    }
    let t = match (question.about, question.at.switch) {
        (Some(k), _) => {
            let Some(Some(steady)) = context.earlier.get(k) else {
                return Err(failure(
                    question,
                    format!("question {k} does not find a steady motion to ask about"),
                    "`about` names a `steady` question of find.questions, by its index from 0",
                ));
            };
            q.clone_from(&steady.q);
            rates.clone_from(&steady.rates);
            steady.time
        }
        (None, Some(site)) => first_switch(problem, system, question, site, &q, &rates)?,
        (None, None) => question.at.time.unwrap_or(0.0),
    };
    Ok((t, q, rates))
}

/// The state at `t`, simulated from the state in `q` and `rates`, written into them.
fn simulate_to(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    t: f64,
    (q, rates): (&mut [f64], &mut [f64]),
) -> Result<(), ProblemError> {
    let settings = SimulateSettings {
        duration: t,
        output_step: t,
        tolerance: problem.simulate.tolerance,
    };
    let trajectory =
        simulate(system, q, rates, &settings).map_err(|e| solve_failed(question, e))?;
    if let Some(stopped) = trajectory.stopped {
        return Err(failure(
            question,
            format!("the simulation stopped before t = {t}: {stopped}"),
            "ask at an earlier time",
        ));
    }
    let n = q.len();
    let Some(last) = trajectory.rows.last().filter(|r| r[0] == t) else {
        return Err(failure(
            question,
            format!("the simulation did not reach t = {t}"),
            "ask at an earlier time",
        ));
    };
    q.copy_from_slice(&last[1..=n]);
    rates.copy_from_slice(&last[n + 1..=2 * n]);
    Ok(())
}

/// The components of the reaction at site `index`, in the frame the question asks for
/// (the parent's unless `in` says otherwise), with that frame's name.
fn reaction_values(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    evaluation: &Evaluation,
    (index, t, q, rates): (usize, f64, &[f64], &[f64]),
) -> Result<(Vec<(Quantity, f64)>, String), ProblemError> {
    let site = problem.site_name(index);
    let planar = problem.dimension == crate::problem::Dimension::Two;
    // In the plane: the force along x and y, the moment about z.
    let in_plane = |column: &ReactionColumn| {
        matches!(
            column,
            ReactionColumn::Component {
                kind: ComponentKind::Force,
                axis: 0 | 1,
                ..
            } | ReactionColumn::Component {
                kind: ComponentKind::Moment,
                axis: 2,
                ..
            }
        )
    };
    let mut found: Vec<(ReactionColumn, f64)> = system
        .reaction_columns()
        .into_iter()
        .zip(evaluation.reactions.iter().copied())
        .filter(|(column, _)| column.site() == Some(site))
        .collect();
    let own = answer_frame::reaction_frame(problem, index);
    let to = question.frame.unwrap_or(own);
    if to != own {
        let m = answer_frame::rotation_between(problem, (to, own), t, q, rates).map_err(|e| {
            failure(
                question,
                format!(
                    "cannot rotate the reaction into {}: {e}",
                    problem.body_name(to)
                ),
                "ask for the reaction in its parent's unit vectors (remove `in`)",
            )
        })?;
        answer_frame::rotate_columns(&m, &mut found);
    }
    let found = found
        .into_iter()
        .filter(|(column, _)| !planar || in_plane(column))
        .map(|(column, x)| (Quantity::Reaction(column), x))
        .collect();
    Ok((found, problem.body_name(to).to_string()))
}

/// The components of a vector value along the unit vectors of the frame the question asks
/// for (`N` unless `in` says otherwise), each named `v(P).x`, with that frame's name.
fn vector_values(
    problem: &Problem,
    question: &Question,
    (quantity, text): (crate::problem::VectorQuantity, &str),
    (t, q, rates, accelerations): (f64, &[f64], &[f64], &[f64]),
) -> Result<(Vec<(Quantity, f64)>, String), ProblemError> {
    let to = question.frame.unwrap_or(crate::problem::BodyId::GROUND);
    let at = super::VectorAt {
        t,
        q,
        rates,
        accelerations,
    };
    let found = super::vector_components(problem, quantity, to, at).map_err(|e| {
        failure(
            question,
            format!("cannot find `{text}`: {e}"),
            "ask for the vector in N (remove `in`)",
        )
    })?;
    let values = vector_axes(problem, quantity)
        .map(|axis| {
            (
                Quantity::Named(format!("{text}.{}", AXES[axis])),
                found[axis],
            )
        })
        .collect();
    Ok((values, problem.body_name(to).to_string()))
}

/// The generalized force that drives prescribed coordinate `coordinate`.
fn drive_values(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    evaluation: &Evaluation,
    coordinate: usize,
) -> Result<Vec<(Quantity, f64)>, ProblemError> {
    let name = &problem.coordinates[coordinate].name;
    let column = ReactionColumn::Drive {
        coordinate: name.clone(),
    };
    let found = system
        .reaction_columns()
        .iter()
        .zip(&evaluation.reactions)
        .find(|(c, _)| **c == column)
        .map(|(_, &x)| x);
    let Some(x) = found else {
        return Err(failure(
            question,
            format!("`{name}` is not prescribed, so nothing drives it"),
            "ask for the drive of a coordinate with a `motion`; a joint load's value is a `value` question",
        ));
    };
    Ok(vec![(Quantity::Reaction(column), x)])
}

/// A question that cannot be answered because the equations failed at its state.
fn solve_failed(question: &Question, e: super::SolveError) -> ProblemError {
    failure(
        question,
        format!("cannot answer: {e}"),
        "ask at another state, or check the problem's initial state",
    )
}

/// The first instant that friction site `site` switches between sticking and slipping,
/// simulating from the initial state over the problem's `simulate.duration`.
fn first_switch(
    problem: &Problem,
    system: &dyn System,
    question: &Question,
    site: usize,
    q: &[f64],
    rates: &[f64],
) -> Result<f64, ProblemError> {
    let name = problem.site_name(site);
    let path = format!("{}.at.switch", question.path);
    let fail = |message: String, hint: String| ProblemError {
        path: path.clone(),
        column: None,
        message,
        hint: Some(hint),
    };
    let sites = system.friction_sites();
    if !sites.iter().any(|s| s == name) {
        return Err(fail(
            format!("`{name}` has no friction to switch"),
            match sites.is_empty() {
                true => "give a site a `friction` coefficient, or ask at a `time`".into(),
                false => format!("name a site with friction: {}", sites.join(", ")),
            },
        ));
    }
    let duration = problem.simulate.duration;
    let settings = SimulateSettings {
        duration,
        output_step: duration,
        tolerance: problem.simulate.tolerance,
    };
    let trajectory = simulate(system, q, rates, &settings).map_err(|e| {
        fail(
            format!("cannot simulate to find the switch: {e}"),
            "check the problem's initial state".into(),
        )
    })?;
    (trajectory.switches.iter())
        .find(|s| s.site == name)
        .map(|s| s.t)
        .ok_or_else(|| {
            fail(
                format!(
                    "`{name}` does not switch between sticking and slipping within the simulation's {} s",
                    crate::symbolic::fixed(duration)
                ),
                "lengthen simulate.duration, or ask at a `time`".into(),
            )
        })
}
