//! A free body for every reaction asked for: where no row's free body shows the reaction
//! as a force from outside on the body it acts on (Lagrange's rows take the whole system,
//! so the disc's contact with the cart is inside it), step 2 draws that body alone, the
//! reaction's components along their positive unit vectors, as a textbook draws the body
//! a force asked for acts on.

use crate::equations::Derivation;
use crate::problem::BodyId;

/// `sets` (the rows' free bodies) with a free body of one body added for each reaction
/// asked for that none of them shows on the body it acts on.
pub(super) fn with_asked(derivation: &Derivation, mut sets: Vec<Vec<BodyId>>) -> Vec<Vec<BodyId>> {
    let model = &derivation.model;
    for &index in &model.problem.find_reactions {
        let Some(site) = model.sites.get(index) else {
            continue;
        };
        let (on, from) = (site.child, site.parent);
        if on == BodyId::GROUND {
            continue;
        }
        let shown = (sets.iter()).any(|set| set.contains(&on) && !set.contains(&from));
        if !shown {
            sets.push(vec![on]);
        }
    }
    sets
}
