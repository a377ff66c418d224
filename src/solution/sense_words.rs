//! On which body a reaction asked for acts, and at a contact between two bodies the equal
//! and opposite force on the other (Newton's third law), said under its answer.

use crate::problem::{ConstraintKind, Problem, QuestionKind};
use crate::render::{AnswerStep, AnswerView};

/// The body that site `site`'s reaction acts on; `None` for a constraint without a body.
pub(super) fn carried_body(problem: &Problem, site: usize) -> Option<crate::problem::BodyId> {
    let (j, c) = (problem.joints.len(), problem.closures.len());
    if site < j {
        Some(problem.joints[site].child)
    } else if site < j + c {
        Some(problem.closures[site - j].child)
    } else {
        match problem.constraints.get(site - j - c).map(|k| &k.kind) {
            Some(
                ConstraintKind::Rolling { body, .. }
                | ConstraintKind::Gear { body, .. }
                | ConstraintKind::Contact { body, .. },
            ) => Some(*body),
            _ => None,
        }
    }
}

/// A step of working in the answer's markup.
fn step(text: String) -> AnswerStep {
    AnswerStep {
        text: text.into(),
        math: String::new().into(),
    }
}

/// The two bodies of a contact between bodies, the one its reaction acts on first; `None`
/// for a joint or a contact with the ground.
fn contact_bodies(
    problem: &Problem,
    site: usize,
) -> Option<(crate::problem::BodyId, crate::problem::BodyId)> {
    let (j, c) = (problem.joints.len(), problem.closures.len());
    let k = site.checked_sub(j + c)?;
    let (body, on) = match problem.constraints.get(k).map(|k| &k.kind)? {
        ConstraintKind::Rolling { body, on, .. }
        | ConstraintKind::Gear { body, on, .. }
        | ConstraintKind::Contact { body, on, .. } => (*body, *on),
        _ => return None,
    };
    let ground = crate::problem::BodyId::GROUND;
    (body != ground && on != ground).then_some((body, on))
}

/// `-15 \hat{\mathbf{n}}_{y}`: the force opposite to the printed components.
fn opposite_tex(view: &AnswerView) -> Option<String> {
    let mut terms = Vec::new();
    for value in &view.values_tex {
        let v = value.as_str();
        let unit = v.split("\\cdot ").nth(1)?.split(" =").next()?.trim();
        let number = v.split(" = ").nth(1)?.split("\\ ").next()?.trim();
        if number
            .trim_start_matches('-')
            .chars()
            .all(|c| c == '0' || c == '.')
        {
            continue;
        }
        let negated = match number.strip_prefix('-') {
            Some(positive) => positive.to_string(),
            None => format!("-{number}"),
        };
        terms.push(format!("{negated} {unit}"));
    }
    (!terms.is_empty()).then(|| terms.join(" + ").replace("+ -", "- "))
}

/// Under the answer for a contact between two bodies: which body the force found acts on,
/// and the equal and opposite force on the other (the gear's tooth force on the pinion,
/// the pinion's push on the rack).
pub fn say_third_law(problem: &Problem, shown: &[(String, String)], views: &mut [AnswerView]) {
    for (question, view) in problem.questions.iter().zip(views.iter_mut()) {
        let QuestionKind::Reaction { site } = question.kind else {
            continue;
        };
        let Some((body, on)) = contact_bodies(problem, site) else {
            continue;
        };
        let Some(opposite) = opposite_tex(view) else {
            continue;
        };
        let name = |b| super::force_labels::shown_name(problem.body_name(b), shown);
        let sentence = format!(
            "These are the components of the force on {}; {} carries the equal and opposite force, $({opposite})\\ \\mathrm{{N}}$ (Newton's third law).",
            name(body),
            name(on)
        );
        view.steps.push(step(sentence));
    }
}
