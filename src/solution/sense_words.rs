//! The sense of a reaction's components where no free body drawn shows them: a reaction
//! inside a free body of several bodies (the disc's contact inside cart + disc) has no
//! arrow to act "as drawn", so its sign is said in words: on which body, along which unit
//! vector.

use crate::problem::{ConstraintKind, Problem, QuestionKind};
use crate::render::context::FreeBody;
use crate::render::{AnswerStep, AnswerView};

/// How the answers say the sign rule where a free body draws the components.
pub const DRAWN_RULE: &str =
    "The free bodies draw each unknown component along its positive unit vector: ";

/// The body that site `site`'s reaction acts on (the joint's child, the rolling or touching
/// body of a contact), as the handout names it.
fn carried(problem: &Problem, site: usize, shown: &[(String, String)]) -> String {
    carried_body(problem, site).map_or("the body it carries".to_string(), |b| {
        super::force_labels::shown_name(problem.body_name(b), shown)
    })
}

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

/// Each component's unit vector (`\hat{\mathbf{c}}_{x}`) as the answer's values print
/// them: `\mathbf{F}^{U} \cdot \hat{\mathbf{c}}_{x} = …`; `None` for a moment's.
fn printed_units(view: &AnswerView) -> Option<Vec<String>> {
    let mut units = Vec::new();
    for value in &view.values_tex {
        let v = value.as_str();
        if !v.starts_with("\\mathbf{F}^{") {
            return None;
        }
        let unit = v.split("\\cdot ").nth(1)?.split(" =").next()?.trim();
        units.push(unit.to_string());
    }
    Some(units)
}

/// A step of working in the answer's markup.
fn step(text: String) -> AnswerStep {
    AnswerStep {
        text: text.into(),
        math: String::new().into(),
    }
}

/// Whether some free body drawn carries the point's reaction as a force of its own.
fn drawn(free_bodies: &[FreeBody], name: &str) -> bool {
    let mark = format!("^{{{name}}}_");
    (free_bodies.iter())
        .flat_map(|b| &b.contact)
        .any(|f| f.vector_tex.as_str().contains(&mark))
}

/// Says each component's sense in words where the answers refer to an arrow that no free
/// body draws.
pub fn say_undrawn_senses(
    problem: &Problem,
    free_bodies: &[FreeBody],
    shown: &[(String, String)],
    views: &mut [AnswerView],
) {
    for (question, view) in problem.questions.iter().zip(views.iter_mut()) {
        let QuestionKind::Reaction { site } = question.kind else {
            continue;
        };
        let Some(at) = view.note.find(DRAWN_RULE) else {
            continue;
        };
        let Some(units) = printed_units(view) else {
            continue;
        };
        let tex = crate::symbolic::latex_name(problem.site_name(site));
        if drawn(free_bodies, &tex) {
            continue;
        }
        let name = super::force_labels::shown_name(problem.site_name(site), shown);
        let name = match name.chars().all(|c| c.is_ascii_alphanumeric()) {
            true => format!("${}$", crate::symbolic::latex_name(&name)),
            false => super::force_labels::place(&name),
        };
        let body = carried(problem, site, shown);
        let before = view.note[..at].trim_end().to_string();
        let rule = view.note[at + DRAWN_RULE.len()..].to_string();
        let parts: Vec<String> = (rule.trim_end_matches('.').split("; "))
            .zip(&units)
            .map(|(part, unit)| sense_in_words(part, &body, unit))
            .collect();
        view.note = before;
        view.steps.insert(
            0,
            step(format!(
                "No free body drawn shows the force at {name} by itself: {}.",
                parts.join("; ")
            )),
        );
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

/// `the force along x is positive, so it acts as drawn` as `the force along x is positive:
/// it acts on D along $+\hat{\mathbf{c}}_{x}$`.
fn sense_in_words(part: &str, body: &str, unit: &str) -> String {
    let (what, positive) = match part.split_once(" is ") {
        Some((what, rest)) => (what, rest.starts_with("positive")),
        None => return part.to_string(),
    };
    let sign = if positive { "+" } else { "-" };
    let sign_word = if positive { "positive" } else { "negative" };
    format!("{what} is {sign_word}: it acts on {body} along ${sign}{unit}$")
}

#[cfg(test)]
mod tests {
    use super::sense_in_words;

    #[test]
    fn a_sense_is_said_on_the_body_along_its_unit_vector() {
        assert_eq!(
            sense_in_words(
                "the force along x is negative, so it acts opposite to the arrow drawn",
                "D",
                "\\hat{\\mathbf{c}}_{x}"
            ),
            "the force along x is negative: it acts on D along $-\\hat{\\mathbf{c}}_{x}$"
        );
    }
}
