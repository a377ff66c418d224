//! A handout prints a word-named body or point by its letter (`solution::shown_names`:
//! the contact `contact` is P, the top's frame B): its pictures are laid out with the
//! letters already, so that each label takes the room of what it prints, not of the word.

use crate::render::draw::{Label, Scene, Shape};

/// `label` with each `(\mathrm{word}, letter)` of `names` replaced; its plain form follows.
fn renamed(label: &mut Label, names: &[(String, String)]) {
    let mut tex = label.tex.clone();
    for (word, letter) in names {
        tex = tex.replace(word.as_str(), letter);
    }
    if tex != label.tex {
        *label = Label::from_tex(&tex);
    }
}

/// Every label of `scene` (captions, arrows, unit vectors, gauges) with `names` replaced.
pub(super) fn rename(scene: &mut Scene, names: &[(String, String)]) {
    if names.is_empty() {
        return;
    }
    for caption in scene.markers.iter_mut().filter_map(|m| m.caption.as_mut()) {
        renamed(caption, names);
    }
    let kinetic = scene
        .kinetic
        .iter_mut()
        .flat_map(|(_, arrows)| arrows.iter_mut());
    for arrow in scene.arrows.iter_mut().chain(kinetic) {
        renamed(&mut arrow.label, names);
    }
    for shape in &mut scene.shapes {
        match shape {
            Shape::Triad { axes, .. } => axes.iter_mut().for_each(|(_, l)| renamed(l, names)),
            Shape::Angle { label, .. }
            | Shape::Distance { label, .. }
            | Shape::Velocity { label, .. } => renamed(label, names),
            _ => {}
        }
    }
}
