//! Named quantities: a symbol's definition with what it stands for, and the entries of a
//! "where" list, which every step of the worked solution may give.

use crate::render::text::Math;
use serde::Serialize;

/// A named quantity and what it stands for.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Named {
    /// The definition, e.g. `\ell_{1} = \sqrt{x^{2} + y^{2}}`.
    pub definition_tex: Math,
    /// What it is (plain text; may be empty), e.g. `length of the line from A1 to P1`.
    pub note: String,
}

impl Named {
    /// `definition_tex` with its `note`.
    pub fn new(definition_tex: impl Into<Math>, note: impl Into<String>) -> Named {
        Named {
            definition_tex: definition_tex.into(),
            note: note.into(),
        }
    }
}

/// One entry of a "where" list: a definition with its note, or several of one kind (the
/// direction cosines, the partial velocities of one mass centre) under the note they share.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct WhereEntry {
    /// The definitions, e.g. `v^{B^*}_{q_{1},x} = -b s_{2}`, one or several.
    pub definitions_tex: Vec<Math>,
    /// What they are (plain text; may be empty), e.g. `partial velocities of B*`.
    pub note: String,
    /// Whether this is a group, written note first: `partial velocities of B*: …, …`.
    pub grouped: bool,
}
