//! The names a handout prints in math for a problem's bodies and points named by words. A
//! problem may call its body `top` and the fixed point `tip`; a textbook writes x̂_B, B*
//! and F^O, never a word as a subscript. Each body or point whose name is one word gets a
//! capital letter, the same in every step and format:
//!
//! - a point the statement names (`point O`) keeps the statement's letter; a joint to the
//!   ground at its origin is O;
//! - otherwise the word's first letter, else the first letter free of a list;
//!
//! never a letter the problem already uses (a constant, a coordinate, another body or
//! point), nor a capital matrix's (A, C), nor one a handout gives a meaning of its own (N, the energies T, V, E, the
//! Lagrangian L, forces F, moments M, inertia I, generalized forces Q). Prose keeps the
//! problem's words; only the math changes, at rendering (see `render::prepare`).

use crate::mechanics::Model;
use crate::problem::BodyId;
use crate::render::context::Solution;
use crate::symbolic::latex_name;

/// Letters with a meaning of their own in a handout.
const RESERVED: [&str; 10] = ["N", "T", "V", "E", "L", "F", "M", "I", "Q", "O"];

/// Letters tried for a body after its word's first letter.
const BODY_LETTERS: &str = "BDGHJKPRSUWXYZACO";

/// Letters tried for a point after the statement's and its word's first letter.
const POINT_LETTERS: &str = "PRSUWXYZABCDGHJK";

/// Units and words the handout sets upright in math itself: never a name to replace.
const OWN_WORDS: [&str; 8] = ["rad", "kg", "deg", "slip", "max", "min", "loop", "const"];

/// Each word-named body and point as `(\mathrm{word}, letter)`, in the problem's order.
pub fn shown_names(model: &Model) -> Vec<(String, String)> {
    let problem = model.problem;
    let word = |name: &str| -> Option<String> {
        let tex = latex_name(name);
        let inner = tex.strip_prefix("\\mathrm{")?.strip_suffix('}')?;
        let plain = inner.chars().all(|c| c.is_ascii_lowercase());
        (plain && !OWN_WORDS.contains(&inner)).then_some(tex)
    };
    let bodies: Vec<&str> = problem.body_ids().map(|b| problem.body_name(b)).collect();
    let sites: Vec<&str> = model.sites.iter().map(|s| s.name.as_str()).collect();
    let mut taken: Vec<String> = (problem.constants.iter().map(|c| c.name.as_str()))
        .chain(problem.coordinates.iter().map(|c| c.name.as_str()))
        .chain(bodies.iter().copied())
        .chain(sites.iter().copied())
        .filter(|n| word(n).is_none())
        .map(latex_name)
        .collect();
    // The handout's capital matrices: the system's A of A x = b, the C of q̇_D = C q̇_I.
    let matrices = crate::problem::MatrixNames::of(problem);
    taken.extend([matrices.a, matrices.c]);
    let mut out = Vec::new();
    let mut claim = |tex: String, candidates: Vec<String>, taken: &mut Vec<String>| {
        if out.iter().any(|(t, _)| *t == tex) {
            return;
        }
        if let Some(letter) = candidates.into_iter().find(|c| !taken.contains(c)) {
            taken.push(letter.clone());
            out.push((tex, letter));
        }
    };
    let free = |letters: &str, skip: &[&str]| -> Vec<String> {
        (letters.chars().map(String::from))
            .filter(|l| !skip.contains(&l.as_str()))
            .collect()
    };
    let initial = |name: &str| name[..1].to_uppercase();
    let statement = statement_points(problem.statement.as_deref().unwrap_or_default());
    for (k, site) in model.sites.iter().enumerate() {
        let Some(tex) = word(&site.name) else {
            continue;
        };
        let mut candidates = Vec::new();
        let at_origin =
            site.parent == BodyId::GROUND && site.parent_offset.iter().all(|e| e.is_zero());
        if at_origin && k < problem.joints.len() {
            candidates.push("O".to_string());
        }
        candidates.extend(statement.iter().cloned());
        candidates.push(initial(&site.name));
        candidates.extend(free(POINT_LETTERS, &RESERVED));
        candidates.retain(|c| c == "O" || !RESERVED.contains(&c.as_str()));
        claim(tex, candidates, &mut taken);
    }
    for name in &bodies {
        let Some(tex) = word(name) else { continue };
        let mut candidates = vec![initial(name)];
        candidates.extend(free(BODY_LETTERS, &RESERVED));
        candidates.retain(|c| !RESERVED.contains(&c.as_str()));
        claim(tex, candidates, &mut taken);
    }
    out
}

/// Step 1 says which letter stands for which word: the frame of the top is B, fixed in
/// "the top (B)"; a word-named joint is called by its letter in the coordinates' table.
pub fn name_in_step_one(solution: &mut Solution, names: &[(String, String)]) {
    let letter = |name: &str| {
        let tex = latex_name(name);
        names
            .iter()
            .find(|(w, _)| *w == tex)
            .map(|(_, l)| l.clone())
    };
    for frame in &mut solution.frames {
        if let Some(l) = letter(&frame.parent) {
            frame.parent = l;
        }
        if let Some(l) = letter(&frame.name) {
            frame.fixed_in = format!("the {} ({l})", frame.name);
            frame.name = l;
        }
    }
}

/// A note for each point of a contact or closure printed by a letter (a joint's is named in
/// the coordinate table): "P is the point of contact at the lane."; "R is the pin joining
/// the coupler B and the rocker C, where the loop closes."; and for each point the problem
/// names by a letter where a spring or damper is attached: "F is where the dashpot is
/// attached to the ground."
pub fn point_notes(model: &Model, names: &[(String, String)]) -> Vec<String> {
    let mut notes = site_notes(model, names);
    notes.extend(attachment_notes(model.problem));
    notes.extend(particle_notes(model, names));
    notes
}

/// "B is the bob, a particle: all its mass at one point.": each particle, which the
/// figures name by its letter alone (no mass centre's star).
fn particle_notes(model: &Model, names: &[(String, String)]) -> Vec<String> {
    let problem = model.problem;
    (problem.body_ids())
        .filter(|b| !crate::mechanics::is_massless(model, *b))
        .filter(|b| crate::mechanics::is_point_particle(model, *b))
        .filter_map(|b| {
            let name = problem.body_name(b);
            let tex = latex_name(name);
            let letter = match names.iter().find(|(w, _)| *w == tex) {
                Some((_, l)) => l.clone(),
                None if is_letter(name) => name.to_string(),
                None => return None,
            };
            let words = super::joint_words::body_words(problem, b);
            let what = match words.strip_prefix("body ") {
                Some(_) => "a particle".to_string(),
                None => format!("{words}, a particle"),
            };
            Some(format!("{letter} is {what}: all its mass at one point."))
        })
        .collect()
}

/// Whether a name reads as a point's letter (`R`, `P2`), not a word.
fn is_letter(name: &str) -> bool {
    name.chars().count() <= 3
        && name.chars().next().is_some_and(|c| c.is_ascii_uppercase())
        && name.chars().all(|c| c.is_ascii_alphanumeric())
}

/// "F is where the dashpot is attached to the ground.": each point the problem names by a
/// letter that a spring or damper is attached to, with the loads by their names.
fn attachment_notes(problem: &crate::problem::Problem) -> Vec<String> {
    use crate::problem::{LoadKind, PointRef};
    let body = |id| super::joint_words::body_words(problem, id);
    (problem.points.iter().enumerate())
        .filter(|(_, point)| is_letter(&point.name))
        .filter_map(|(k, point)| {
            let loads: Vec<String> = (problem.loads.iter())
                .filter_map(|load| {
                    let (between, what) = match &load.kind {
                        LoadKind::Spring { between, .. } => (between, "spring"),
                        LoadKind::Damper { between, .. } => (between, "damper"),
                        _ => return None,
                    };
                    between
                        .contains(&PointRef::Named(k))
                        .then(|| format!("the {}", load.name.as_deref().unwrap_or(what)))
                })
                .collect();
            let loads = match loads.as_slice() {
                [] => return None,
                [one] => format!("{one} is"),
                [rest @ .., last] => format!("{} and {last} are", rest.join(", ")),
            };
            Some(format!(
                "{} is where {loads} attached to {}.",
                point.name,
                body(point.on)
            ))
        })
        .collect()
}

/// The notes of the contacts and closures after the tree's joints.
fn site_notes(model: &Model, names: &[(String, String)]) -> Vec<String> {
    let problem = model.problem;
    let joints = problem.joints.len();
    (model.sites.iter().enumerate())
        .filter(|(k, _)| *k >= joints)
        .filter_map(|(_, site)| {
            let tex = latex_name(&site.name);
            let Some((_, letter)) = names.iter().find(|(w, _)| *w == tex) else {
                // A closure named by its letter: the pin (or joint) that closes the loop.
                let crate::mechanics::SiteKind::Closure(c) = site.kind else {
                    return None;
                };
                if !is_letter(&site.name) {
                    return None;
                }
                let words = |id| super::joint_words::body_words(problem, id);
                let joint = match problem.closures.get(c).map(|j| j.kind) {
                    Some(crate::problem::JointKind::Revolute) => "pin",
                    _ => "joint",
                };
                return Some(format!(
                    "{} is the {joint} joining {} and {}, where the loop closes.",
                    site.name,
                    words(site.parent),
                    words(site.child)
                ));
            };
            let name = site.name.as_str();
            Some(match site.kind {
                crate::mechanics::SiteKind::Contact(_) if name == "contact" => {
                    format!("{letter} is the point of contact.")
                }
                crate::mechanics::SiteKind::Contact(_) => {
                    format!("{letter} is the point of contact at the {name}.")
                }
                _ if super::row_names::is_guide(model, site) => format!(
                    "{letter} is the point of {} on the {name}.",
                    super::joint_words::body_words(model.problem, site.child)
                ),
                _ => format!("{letter} is the point where the loop closes, the {name}."),
            })
        })
        .collect()
}

/// The capital letters a statement names points by: `point O`, `point $O$`.
fn statement_points(statement: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for (at, _) in statement.match_indices("point ") {
        let rest = statement[at + 6..].trim_start_matches('$');
        let mut chars = rest.chars();
        let (Some(letter), next) = (chars.next(), chars.next()) else {
            continue;
        };
        let alone = next.is_none_or(|c| !c.is_alphanumeric());
        if letter.is_ascii_uppercase() && alone && !out.contains(&letter.to_string()) {
            out.push(letter.to_string());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::statement_points;

    #[test]
    fn the_statement_names_its_points_by_letters() {
        let text =
            "spins on a fixed, frictionless point O on the floor; the point $A$ and a point Pa";
        assert_eq!(statement_points(text), ["O", "A"]);
        assert!(statement_points("the points of contact").is_empty());
    }
}
