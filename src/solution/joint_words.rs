//! Joints and bodies named in words, as a course names them: "the ball moves in the
//! plane", "rod A turns on the ground at pin O", "the disc rolls on the ground", never a bare joint
//! letter with the kind of joint in brackets.

use crate::problem::{BodyId, CoordinateKind, JointKind, Problem};

/// The longest description taken as a body's name in words.
const LONGEST_NAME: usize = 36;

/// A body in words: its description where it opens with a short phrase of plain words
/// ("the ball", "cart A"; nothing any format would have to escape), else "body B"; the
/// ground for `N`.
pub fn body_words(problem: &Problem, id: BodyId) -> String {
    if id == BodyId::GROUND {
        return "the ground".into();
    }
    let body = problem.body(id);
    // A body named by a plain word ("wedge", "top") is called by it.
    if body.name.len() >= 3 && body.name.chars().all(|c| c.is_ascii_lowercase()) {
        return format!("the {}", body.name);
    }
    let fallback = || format!("body {}", body.name.replace('_', " "));
    let Some(description) = body.description.as_deref() else {
        return fallback();
    };
    let head = description
        .split([',', ';', '(', ':'])
        .next()
        .unwrap_or_default()
        .trim();
    let plain = !head.is_empty()
        && head.len() <= LONGEST_NAME
        && (head.chars()).all(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '\''))
        && !head.starts_with("origin");
    if !plain {
        return fallback();
    }
    for article in ["a ", "an "] {
        if let Some(rest) = head.strip_prefix(article) {
            return format!("the {rest}");
        }
    }
    let named = head.split_whitespace().any(|w| w == body.name);
    if head.starts_with("the ") || named {
        head.to_string()
    } else {
        format!("the {head}")
    }
}

/// Whether a joint's name reads as a point's letter (`O`, `Q`, `J1`) rather than a word.
fn is_point_name(name: &str) -> bool {
    name.chars().count() <= 3
        && name.chars().next().is_some_and(char::is_uppercase)
        && name.chars().all(char::is_alphanumeric)
}

/// Joint `j` in words: what it lets its child do relative to its parent. A joint named by a
/// word is called by the letter the handout prints for it (`shown`).
pub fn joint_words(problem: &Problem, j: usize, shown: &[(String, String)]) -> String {
    let joint = &problem.joints[j];
    let child = body_words(problem, joint.child);
    let parent = body_words(problem, joint.parent);
    let name = super::force_labels::shown_name(&joint.name, shown);
    // A name with an index (OA) as the handout's math prints it everywhere else (O_A).
    let printed = match crate::symbolic::latex_name(&name) {
        tex if tex != name => format!("${tex}$"),
        _ => name.clone(),
    };
    let at = |what: &str| match is_point_name(&name) {
        true => format!(" at {what} {printed}"),
        false => String::new(),
    };
    let rolling = match joint.kind {
        JointKind::Planar | JointKind::Free => rolls_on(problem, joint.child),
        _ => None,
    };
    if let Some((on, rough, surface)) = rolling {
        // A rough contact may slide as well as roll (the skidding ball).
        let how = if rough { "rolls or slides" } else { "rolls" };
        return format!("{child} {how} on {}", surface_words(problem, on, surface));
    }
    match joint.kind {
        JointKind::Revolute => format!("{child} turns on {parent}{}", at("pin")),
        JointKind::Prismatic => format!("{child} slides on {parent}{}", at("point")),
        JointKind::Cylindrical => format!("{child} slides and turns on {parent}"),
        JointKind::Planar if joint.parent == BodyId::GROUND => {
            format!("{child} moves in the plane")
        }
        JointKind::Planar => format!("{child} moves in the plane relative to {parent}"),
        JointKind::Universal => format!("{child} turns on {parent} about two axes{}", at("point")),
        JointKind::Spherical if is_point_name(&name) => {
            format!("{child} turns freely about point {printed} of {parent}")
        }
        JointKind::Spherical => format!("{child} turns freely about a point of {parent}"),
        JointKind::Free => format!("{child} is free"),
        JointKind::Weld => format!("{child} is fixed to {parent}"),
    }
}

/// What a body rolls on in words: the ground by the surface's own name where the contact
/// has one (the lane).
fn surface_words(problem: &Problem, on: BodyId, surface: &str) -> String {
    match on == BodyId::GROUND && !is_point_name(surface) && surface != "contact" {
        true => super::force_labels::place(surface),
        false => body_words(problem, on),
    }
}

/// Coordinate `i`, after the first (`first`) of its joint, in words where the joint's
/// words do not say what it does: set by the constraints (a rolling ball's height, held
/// by the contact), or an angle beside distances (the ball turns). `None` where it moves
/// as the first does, which "as for" the first then says.
pub fn later_coordinate_words(problem: &Problem, i: usize, first: usize) -> Option<String> {
    let c = &problem.coordinates[i];
    let child = problem.joints[c.joint].child;
    if c.dependent {
        return Some(match rolls_on(problem, child) {
            Some((on, _, surface)) => format!(
                "held by the contact of {} with {}",
                body_words(problem, child),
                surface_words(problem, on, surface)
            ),
            None => "set by the constraints".into(),
        });
    }
    let turns = c.kind == CoordinateKind::Angle;
    (turns && problem.coordinates[first].kind != CoordinateKind::Angle)
        .then(|| format!("{} turns", body_words(problem, child)))
}

/// The body `body` rolls on where a rolling constraint holds it, whether that contact is
/// rough (it may slide too), and the contact's name.
fn rolls_on(problem: &Problem, body: BodyId) -> Option<(BodyId, bool, &str)> {
    problem.constraints.iter().find_map(|c| match &c.kind {
        crate::problem::ConstraintKind::Rolling { body: b, on, .. } if *b == body => {
            Some((*on, c.friction.is_some(), c.name.as_str()))
        }
        _ => None,
    })
}

/// The sentence under a reaction answered in a body's unit vectors where the question
/// chose no frame; `None` in `N`, or where the question's own words name the unit vectors.
pub fn frame_note(problem: &Problem, question_text: Option<&str>, frame: &str) -> Option<String> {
    if frame == problem.body_name(BodyId::GROUND) {
        return None;
    }
    if question_text.is_some_and(|t| t.contains("unit vectors")) {
        return None;
    }
    let id = problem
        .body_ids()
        .find(|&b| problem.body_name(b) == frame)?;
    Some(format!(
        "The components are along the unit vectors fixed in {} (frame {frame}).",
        body_words(problem, id)
    ))
}
