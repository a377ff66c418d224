//! What an answer found, by name or as a reaction's component: the keys of an answer's
//! values, shared by every kind of answer.

use super::system::ReactionColumn;

/// What an answer found.
#[derive(Clone, Debug, PartialEq)]
pub enum Quantity {
    /// A value by name: the expression as written (`q1''`), or an unknown of a steady
    /// motion (`psi`, `psi'`).
    Named(String),
    /// A reaction component (`O.force.x`) or a drive (`theta.drive`).
    Reaction(ReactionColumn),
}

impl std::fmt::Display for Quantity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Quantity::Named(name) => f.write_str(name),
            Quantity::Reaction(column) => column.fmt(f),
        }
    }
}
