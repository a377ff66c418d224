//! A vector `value` question: the position, velocity or acceleration of a point, or the
//! angular velocity or acceleration of a body, all in `N`, written as a course writes them:
//! `r(P)`, `v(P)`, `a(B*)`, `w(B)` (or `omega(B)`), `alpha(B)`. The answer gives the
//! components along the unit vectors of `N`, or of the frame the question's `in` names.

use super::model::{BodyId, PointRef};
use super::reader::Reader;
use serde_json::Value;

/// What a vector `value` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VectorQuantity {
    /// `r(P)`: the position of a point from `N`'s origin.
    Position(PointRef),
    /// `v(P)`: the velocity of a point in `N`.
    Velocity(PointRef),
    /// `a(P)`: the acceleration of a point in `N`.
    Acceleration(PointRef),
    /// `w(B)`: the angular velocity of a body in `N`.
    AngularVelocity(BodyId),
    /// `alpha(B)`: the angular acceleration of a body in `N`.
    AngularAcceleration(BodyId),
}

impl VectorQuantity {
    /// Whether it turns with a body (an angular velocity or acceleration) rather than
    /// moves a point: in a plane it then has only a z component.
    pub fn is_angular(self) -> bool {
        matches!(
            self,
            VectorQuantity::AngularVelocity(_) | VectorQuantity::AngularAcceleration(_)
        )
    }

    /// Its SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            VectorQuantity::Position(_) => "m",
            VectorQuantity::Velocity(_) => "m/s",
            VectorQuantity::Acceleration(_) => "m/s^2",
            VectorQuantity::AngularVelocity(_) => "rad/s",
            VectorQuantity::AngularAcceleration(_) => "rad/s^2",
        }
    }

    /// What it is, in words: "the velocity".
    pub fn noun(self) -> &'static str {
        match self {
            VectorQuantity::Position(_) => "the position",
            VectorQuantity::Velocity(_) => "the velocity",
            VectorQuantity::Acceleration(_) => "the acceleration",
            VectorQuantity::AngularVelocity(_) => "the angular velocity",
            VectorQuantity::AngularAcceleration(_) => "the angular acceleration",
        }
    }
}

/// The kinds a vector value is written with, each with whether it names a body (else a
/// point).
const HEADS: [(&str, bool); 6] = [
    ("r", false),
    ("v", false),
    ("a", false),
    ("w", true),
    ("omega", true),
    ("alpha", true),
];

/// `v(P)` split into `v` and `P`, when the text has that form and the head is one of the
/// vector kinds.
pub(super) fn split(text: &str) -> Option<(&'static str, bool, &str)> {
    let (head, rest) = text.trim().split_once('(')?;
    let inner = rest.trim_end().strip_suffix(')')?.trim();
    let (head, names_body) = HEADS.into_iter().find(|(h, _)| *h == head.trim())?;
    Some((head, names_body, inner))
}

impl Reader {
    /// A vector value written `v(P)`: `None` when `text` is not of that form (a scalar
    /// expression); `Some(None)` when it is but names no point or body (reported at `path`).
    pub(super) fn vector_value(
        &mut self,
        text: &str,
        path: &str,
    ) -> Option<Option<VectorQuantity>> {
        let (head, names_body, inner) = split(text)?;
        if self.names.kind_of(head).is_some() {
            // A name of the problem (a constant `a`): a scalar expression.
            return None;
        }
        if inner.is_empty() || inner.contains(['(', ')', ',']) {
            let hint = if names_body {
                format!("write {head}(B) with the name of a body")
            } else {
                format!("write {head}(P) with a point: a declared point, a joint, `B*` or `B.o`")
            };
            self.diag.hint(
                path,
                format!(
                    "`{}` should name one {}",
                    text.trim(),
                    if names_body { "body" } else { "point" }
                ),
                hint,
            );
            return Some(None);
        }
        let name = Value::String(inner.to_string());
        let quantity = if names_body {
            self.body_ref(&name, path).map(|b| match head {
                "alpha" => VectorQuantity::AngularAcceleration(b),
                _ => VectorQuantity::AngularVelocity(b),
            })
        } else {
            self.point_ref(&name, path).map(|p| match head {
                "r" => VectorQuantity::Position(p),
                "v" => VectorQuantity::Velocity(p),
                _ => VectorQuantity::Acceleration(p),
            })
        };
        Some(quantity)
    }
}
