//! The labels of step 2's tables of forces, as a textbook labels a force: by what it is
//! (the weight of B, the reaction force at O, the contact force at the lane, a spring's
//! force), never by a category of forces.

use crate::mechanics::{Model, SiteKind};
use crate::plan::{Action, ActionKind, Source};

/// The label of `action` in its free body's table.
pub(super) fn table_label(model: &Model, action: &Action, shown: &[(String, String)]) -> String {
    let couple = matches!(action.kind, ActionKind::Couple { .. });
    match action.source {
        Source::Gravity => format!(
            "weight of {}",
            shown_name(model.problem.body_name(action.body), shown)
        ),
        Source::Reaction(site) => {
            let site = &model.sites[site];
            // A point named by a word is printed by its letter, as in the table's math.
            let tex = crate::symbolic::latex_name(&site.name);
            let place = match shown.iter().find(|(word, _)| *word == tex) {
                Some((_, letter)) => format!("${letter}$"),
                None => place_markup(&site.name),
            };
            match (&site.kind, couple) {
                (_, true) => format!("reaction couple at {place}"),
                (SiteKind::Contact(_), false) => format!("contact force at {place}"),
                (_, false) => format!("reaction force at {place}"),
            }
        }
        _ => action.label.clone(),
    }
}

/// Who exerts a joint's reaction on a body other than the ground, said after its label
/// (", of A on B"), and, where it is resolved along the exerting body's unit vectors, so
/// (", in A's unit vectors"): the pin force on rod B of a double pendulum. Empty for the
/// ground's reactions, a couple, a contact or the partner printed opposite.
pub(super) fn exerted_by(
    model: &Model,
    action: &Action,
    shown: &[(String, String)],
    vector_tex: &str,
) -> String {
    let Source::Reaction(site) = action.source else {
        return String::new();
    };
    let site = &model.sites[site];
    let plain = !matches!(action.kind, ActionKind::Couple { .. })
        && !matches!(site.kind, SiteKind::Contact(_))
        && site.parent != crate::problem::BodyId::GROUND
        && action.body == site.child
        && !vector_tex.starts_with('-');
    if !plain {
        return String::new();
    }
    let name = |b| shown_name(model.problem.body_name(b), shown);
    let (by, on) = (name(site.parent), name(site.child));
    // A letter reads as the tables print it; a longer name as the headings set it.
    let said = |n: &str| match n.chars().count() == 1 {
        true => n.to_string(),
        false => format!("${}$", crate::symbolic::latex_name(n)),
    };
    let hat = format!("\\hat{{\\mathbf{{{}}}}}", by.to_lowercase());
    let along = match by.chars().count() == 1 && vector_tex.contains(&hat) {
        true => format!(", in {by}'s unit vectors"),
        false => String::new(),
    };
    format!(", of {} on {}{along}", said(&by), said(&on))
}

/// A body's name as the handout prints it: its letter when it is named by a word.
pub(super) fn shown_name(name: &str, shown: &[(String, String)]) -> String {
    let tex = crate::symbolic::latex_name(name);
    match shown.iter().find(|(word, _)| *word == tex) {
        Some((_, letter)) => letter.clone(),
        None => name.to_string(),
    }
}

/// A point's name in a sentence: a symbol as it is (`O`, `P2`), a word with its article
/// (`the lane`, `the rear contact`).
pub(super) fn place(name: &str) -> String {
    let words = name.replace('_', " ");
    // A symbol is capitals and digits, with at most one small letter (O, OA, P2, Jb).
    let small = name.chars().filter(char::is_ascii_lowercase).count();
    if small <= 1 {
        words
    } else {
        format!("the {words}")
    }
}

/// A point's name in a line of markup: a symbol as the equations set it (`$O_{A}$`), a
/// word with its article (`the lane`).
fn place_markup(name: &str) -> String {
    match place(name) {
        words if words.starts_with("the ") => words,
        _ => format!("${}$", crate::symbolic::latex_name(name)),
    }
}

#[cfg(test)]
mod tests {
    use super::{place, place_markup};

    #[test]
    fn a_symbol_is_set_as_math_in_a_table_label() {
        assert_eq!(place_markup("OA"), "$O_{A}$");
        assert_eq!(place_markup("rear_contact"), "the rear contact");
    }

    #[test]
    fn a_symbol_stands_alone_and_a_word_takes_its_article() {
        assert_eq!(place("O"), "O");
        assert_eq!(place("P2"), "P2");
        assert_eq!(place("OA"), "OA");
        assert_eq!(place("lane"), "the lane");
        assert_eq!(place("rear_contact"), "the rear contact");
    }
}
