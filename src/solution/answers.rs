//! The handout's "Answers": each question of `find.questions` restated, then answered with
//! its units (the numbers come from [`crate::numeric::answers`]). The student's handout
//! restates the questions and leaves the answers blank.

use super::answer_numbers::{labels, number_tex, unit_tex};
use crate::numeric::{coordinate_unit, Answer, Quantity, ReactionColumn};
use crate::problem::{Dimension, Problem, Question, QuestionAt, QuestionKind, StateEntry};
use crate::render::text::{MarkupLine, Math};
use crate::render::AnswerView;
use crate::symbolic::{fixed, latex, latex_unit_vector, ComponentKind};

/// The questions with their answers, in order.
pub fn section(problem: &Problem, answers: &[Answer]) -> Vec<AnswerView> {
    let labels = labels(problem);
    let mut noted: Vec<String> = Vec::new();
    // A force's words, said once: two answers of the same force at two states read alike.
    let mut said: Vec<String> = Vec::new();
    problem
        .questions
        .iter()
        .zip(answers)
        .zip(labels)
        .map(|((question, answer), label)| {
            let mut view = blank_one(problem, question);
            view.label = label;
            if let Some(k) = question.about {
                let found = super::answer_leads::found_tex(problem, &problem.questions[k], answer);
                view.at_tex = Math::from(found.unwrap_or_else(|| found_state_tex(problem, answer)));
            }
            if let Some(site) = question.at.switch {
                // The instant itself asked: its value is the answer, not where it is asked.
                let instant = matches!(&question.kind, QuestionKind::Value { expression, .. }
                    if matches!(expression.as_symbol(), Some(crate::symbolic::Symbol::Time)));
                // The instant itself asked: the lead says only which instant.
                view.at_tex = match instant {
                    true => Math::from(String::new()),
                    false => Math::from(time_tex(answer.time)),
                };
                view.at_note = switch_note(problem, site);
            }
            // A reaction's moment about a free axis is no unknown at all: exactly 0, and not
            // worth a line; the note says the others are zero.
            let shown: Vec<&(Quantity, f64)> = answer
                .values
                .iter()
                .filter(|(found, value)| !crate::numeric::is_free_moment(question, found, *value))
                .collect();
            if let QuestionKind::Reaction { site } = question.kind {
                let frame = answer.frame.clone().unwrap_or_else(|| {
                    let id = crate::numeric::reaction_frame(problem, site);
                    problem.body_name(id).to_string()
                });
                let text = question.text.as_deref();
                // Said at the first answer in that frame only.
                if let Some(note) = super::joint_words::frame_note(problem, text, &frame) {
                    if !noted.contains(&frame) {
                        view.note = note;
                        noted.push(frame);
                    }
                }
            }
            // Each force found said once in words: what it is, its size, its sense and
            // the body it acts on.
            let words = super::force_words::note(problem, question, answer);
            if let Some(words) = words.filter(|w| !said.contains(w)) {
                said.push(words.clone());
                view.steps.push(crate::render::AnswerStep {
                    text: MarkupLine::from(words),
                    math: Math::from(String::new()),
                });
            }
            view.values_tex = shown
                .iter()
                .map(|(found, value)| value_tex(problem, question, answer, found, *value))
                .map(Math::from)
                .collect();
            if question.kind.is_static() {
                if super::static_answers::slip_speed(answer).is_none() {
                    view.at_note = "at rest, every friction site sticking".into();
                }
                let index = problem
                    .questions
                    .iter()
                    .position(|q| std::ptr::eq(q, question));
                view.values_tex = vec![
                    Math::from(super::static_answers::value_tex(problem, question, answer)),
                    Math::from(super::static_answers::verdict_tex(
                        problem, question, answer,
                    )),
                ];
                view.note = index
                    .map(|i| super::static_answers::note(problem, i, answers))
                    .unwrap_or_default();
            }
            if matches!(question.kind, QuestionKind::Stability { .. }) {
                view.values_tex = super::stability_answers::values_tex(problem, question, answer);
                view.note = super::stability_answers::note(problem, question, answer);
            }
            if let Some(words) = super::question_answers::note(problem, question, answer) {
                view.note = words;
            }
            if let Some((left, _)) = answer.residual {
                view.note = steady_check(question, left);
            }
            view
        })
        .collect::<Vec<AnswerView>>()
        .into_iter()
        .enumerate()
        .fold(Vec::new(), |mut done, (i, mut view)| {
            // A second steady motion held at the same values is said under the first's
            // state, which is not said again (the question's words name which motion).
            let steady = matches!(problem.questions[i].kind, QuestionKind::Steady { .. });
            // The same check said once: the second time, briefly.
            if steady && !view.note.is_empty() && done.iter().any(|v| v.note == view.note) {
                view.note = "The same check holds here: the motion is steady.".into();
            }
            done.push(view);
            done
        })
}

/// The questions without answers, for the student's handout.
pub fn blank(problem: &Problem) -> Vec<AnswerView> {
    let mut views: Vec<AnswerView> = (problem.questions.iter())
        .zip(labels(problem))
        .map(|(q, label)| {
            let mut view = AnswerView {
                label,
                ..blank_one(problem, q)
            };
            super::answer_leads::drop_said_time(q, &mut view);
            view
        })
        .collect();
    super::answer_leads::mark_repeated_states(&mut views);
    views
}

/// The state a question `about` a steady motion is asked at: the time, then every
/// coordinate and rate of the steady motion found.
fn found_state_tex(problem: &Problem, answer: &Answer) -> String {
    let mut parts = vec![time_tex(answer.time)];
    for i in 0..problem.coordinates.len() {
        for (order, x) in [(0, answer.q[i]), (1, answer.rates[i])] {
            let symbol = latex(&problem.coordinate_expr(i, order));
            let unit = coordinate_unit(problem, i, order);
            let x = if x.abs() < ROUND_OFF { 0.0 } else { x };
            parts.push(format!("{symbol} = {}{}", number_tex(x), unit_tex(&unit)));
        }
    }
    parts.join(",\\ ")
}

fn blank_one(problem: &Problem, question: &Question) -> AnswerView {
    let (at_tex, at_note) = at(problem, question);
    AnswerView {
        question: MarkupLine::from(
            question
                .text
                .clone()
                .unwrap_or_else(|| asked(problem, question)),
        ),
        at_tex: Math::from(at_tex),
        at_note,
        values_tex: Vec::new(),
        note: String::new(),
        label: String::new(),
        steps: Vec::new(),
        blank_lines: blank_lines(problem, &question.kind),
        same_state: false,
    }
}

/// The lines a student's answer takes: one a value, one a component of a reaction (two in
/// a plane, three in space), one an unknown of a steady motion; 0 (a box to work in) for a
/// derivation.
fn blank_lines(problem: &Problem, kind: &QuestionKind) -> usize {
    match kind {
        QuestionKind::Show { .. } => 0,
        QuestionKind::Reaction { .. } if problem.dimension == Dimension::Two => 2,
        QuestionKind::Reaction { .. } => 3,
        QuestionKind::VectorValue { quantity, .. } => {
            crate::numeric::vector_axes(problem, *quantity).len()
        }
        QuestionKind::Steady { unknowns, .. } => unknowns.len().max(1),
        QuestionKind::Stability { .. } => 2,
        QuestionKind::Describe { .. } => 4,
        _ => 1,
    }
}

/// The question made from what it asks, when it has no `text`, its expressions as math.
pub fn asked(problem: &Problem, question: &Question) -> String {
    match &question.kind {
        QuestionKind::Value { expression, .. } => format!("Find ${}$.", latex(expression)),
        QuestionKind::VectorValue { .. } => super::vector_answers::asked(problem, question),
        QuestionKind::Reaction { site } => {
            format!("Find the reaction at {}.", problem.site_name(*site))
        }
        QuestionKind::Drive { coordinate } => format!(
            "Find the generalized force ${}$ that drives ${}$.",
            drive_tex(problem, *coordinate),
            latex(&problem.coordinate_expr(*coordinate, 0))
        ),
        QuestionKind::Period { .. } | QuestionKind::Show { .. } => {
            super::question_answers::asked(problem, question)
        }
        QuestionKind::Describe { coordinate, .. } => format!(
            "Describe the motion of ${}$.",
            latex(&problem.coordinate_expr(*coordinate, 0))
        ),
        QuestionKind::Steady { unknowns, zero } => {
            let unknowns: Vec<String> = unknowns
                .iter()
                .map(|e| {
                    format!(
                        "${}$",
                        latex(&problem.coordinate_expr(e.coordinate, e.order))
                    )
                })
                .collect();
            let zero: Vec<String> = zero.iter().map(|(expr, _)| latex(expr)).collect();
            format!(
                "Find {} for a steady motion: ${} = 0$.",
                unknowns.join(", "),
                zero.join(" = ")
            )
        }
        _ => super::static_answers::asked(problem, question),
    }
}

fn at(problem: &Problem, question: &Question) -> (String, String) {
    let QuestionAt {
        time,
        state,
        switch,
        after_impact,
    } = &question.at;
    if let Some(site) = switch {
        // The instant is what the student finds: the blank handout names it `t`.
        return ("t".into(), switch_note(problem, *site));
    }
    if let Some(k) = question.about {
        return (
            time_tex(0.0),
            super::question_answers::about_note(problem, k),
        );
    }
    let t = time.unwrap_or(0.0);
    let time_tex = time_tex(t);
    match state {
        None if t > 0.0 && problem.impact.is_some() => (
            time_tex,
            "simulated from the state just after the impact".into(),
        ),
        None if t > 0.0 => (time_tex, "simulated from the initial state".into()),
        None if *after_impact => (time_tex, "just after the impact".into()),
        None => (time_tex, "the initial state".into()),
        Some(entries) => {
            let steady = match &question.kind {
                QuestionKind::Steady { unknowns, .. } => unknowns.as_slice(),
                _ => &[],
            };
            // The time only where it matters (a forced or time-varying problem).
            let mut parts = Vec::new();
            if t != 0.0 || entries.iter().all(|(e, _)| steady.contains(e)) {
                parts.push(time_tex);
            }
            for (e, value) in entries.iter().filter(|(e, _)| !steady.contains(e)) {
                let symbol = latex(&problem.coordinate_expr(e.coordinate, e.order));
                let unit = coordinate_unit(problem, e.coordinate, e.order);
                parts.push(format!(
                    "{symbol} = {}{}",
                    number_tex(*value),
                    unit_tex(&unit)
                ));
            }
            let note = match question.kind {
                QuestionKind::Steady { .. } => "a steady motion",
                QuestionKind::Period { .. } => "the state the small oscillations are about",
                _ => "the other coordinates and rates as at the start",
            };
            (parts.join(",\\ "), note.into())
        }
    }
}

/// The check of a steady motion found: the second rates asked to vanish do, to `left`.
fn steady_check(question: &Question, left: f64) -> String {
    let QuestionKind::Steady { zero, .. } = &question.kind else {
        return String::new();
    };
    let second: Vec<String> = (zero.iter())
        .filter(|(e, _)| matches!(e.as_symbol(), Some(crate::symbolic::Symbol::Coord(_, 2))))
        .map(|(e, _)| latex(e))
        .collect();
    if second.is_empty() || left > 1e-6 {
        return String::new();
    }
    format!(
        "Check: with these rates the equations of step 5 give ${} = 0$: yes, the motion is steady.",
        second.join(" = ")
    )
}

/// `t = 1.2\ \mathrm{s}`.
pub(super) fn time_tex(t: f64) -> String {
    format!("t = {}\\ \\mathrm{{s}}", fixed(t))
}

/// The instant a `switch` question is asked at, in words.
fn switch_note(problem: &Problem, site: usize) -> String {
    format!(
        "the instant the friction at {} first switches between sticking and slipping",
        problem.site_name(site)
    )
}

fn value_tex(
    problem: &Problem,
    question: &Question,
    answer: &Answer,
    found: &Quantity,
    value: f64,
) -> String {
    let unit = crate::numeric::answer_unit(problem, question, found);
    let symbol = match &question.kind {
        QuestionKind::Value { expression, .. } => {
            // The question's own symbol, else the expression when it reads at a glance; a
            // long expression is restated by the question, so the answer is its number.
            let written = latex(expression);
            match question
                .symbol
                .as_deref()
                .and_then(crate::typeset::checked_math)
            {
                Some(symbol) => symbol,
                None if written.len() <= LONGEST_RESTATED => written,
                None => String::new(),
            }
        }
        QuestionKind::VectorValue { quantity, .. } => {
            super::vector_answers::component_tex(problem, *quantity, answer, found)
        }
        QuestionKind::Reaction { site } => {
            // `O.force.x`: the component along a unit vector of the answer's frame.
            let (kind, axis_index) = match found {
                Quantity::Reaction(ReactionColumn::Component { kind, axis, .. }) => (*kind, *axis),
                _ => (ComponentKind::Force, 0),
            };
            let frame = answer.frame.clone().unwrap_or_else(|| {
                problem
                    .body_name(crate::numeric::reaction_frame(problem, *site))
                    .to_string()
            });
            let letter = kind.letter();
            format!(
                "\\mathbf{{{letter}}}^{{\\mathrm{{{}}}}} \\cdot {}",
                problem.site_name(*site).replace('_', "\\_"),
                latex_unit_vector(&frame, axis_index as u8)
            )
        }
        QuestionKind::Drive { coordinate } => drive_tex(problem, *coordinate),
        // τ: T is the kinetic energy of step 6 (or a constant of the problem).
        QuestionKind::Period { .. } => "\\tau".into(),
        QuestionKind::Show { .. } => match found {
            Quantity::Named(text) => super::question_answers::side_tex(question, text),
            Quantity::Reaction(_) => String::new(),
        },
        QuestionKind::Steady { unknowns, .. } => {
            let entry = unknowns
                .iter()
                .find(|e| {
                    matches!(found, Quantity::Named(name) if crate::numeric::entry_name(problem, e) == *name)
                })
                .copied()
                .unwrap_or(StateEntry {
                    coordinate: 0,
                    order: 0,
                });
            latex(&problem.coordinate_expr(entry.coordinate, entry.order))
        }
        // Written by the statics answers.
        _ => String::new(),
    };
    // Round-off of a zero (1e-13 rad/s²) is answered as the zero it is.
    let value = if value.abs() < ROUND_OFF { 0.0 } else { value };
    let number = format!("{}{}", number_tex(value), unit_tex(&unit));
    if symbol.is_empty() {
        number
    } else {
        format!("{symbol} = {number}")
    }
}

/// The longest expression (characters of LaTeX) an answer restates before its number.
const LONGEST_RESTATED: usize = 40;
/// An answer smaller than this is round-off of zero in the SI units of a teaching problem.
const ROUND_OFF: f64 = 1e-10;

/// The drive of prescribed coordinate `i`, `Q_{\theta}`, as step 5 writes it.
fn drive_tex(problem: &Problem, i: usize) -> String {
    latex(&crate::symbolic::Expr::sym(crate::mechanics::drive_symbol(
        problem, i,
    )))
}
