//! The names a problem declares: one namespace for constants, coordinates, bodies,
//! joints and points, with `N`, `t` and `pi` reserved.

use super::json::Diagnostics;
use super::model::BodyId;
use crate::symbolic::closest;
use std::collections::HashMap;

/// What a name stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A constant.
    Constant,
    /// A generalized coordinate.
    Coordinate,
    /// A body (and its frame).
    Body,
    /// A joint (and its point on the child).
    Joint,
    /// A declared point.
    Point,
    /// A loop-closing joint.
    Closure,
    /// An entry of `constraints`.
    Constraint,
    /// A declared generalized speed.
    Speed,
}

impl Kind {
    /// The noun with its article, for messages: "a constant".
    pub fn noun(self) -> &'static str {
        match self {
            Kind::Constant => "a constant",
            Kind::Coordinate => "a coordinate",
            Kind::Body => "a body",
            Kind::Joint => "a joint",
            Kind::Point => "a point",
            Kind::Closure => "a closure",
            Kind::Constraint => "a constraint",
            Kind::Speed => "a generalized speed",
        }
    }
}

/// Whether `name` matches `[A-Za-z][A-Za-z0-9_]*`.
pub fn is_valid(name: &str) -> bool {
    let mut chars = name.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Every declared name, by kind, in file order.
#[derive(Debug, Default)]
pub struct Names {
    kinds: HashMap<String, (Kind, String)>,
    /// Constant names in file order.
    pub constants: Vec<String>,
    /// Body names in file order: `BodyId(i + 1)` is `bodies[i]`.
    pub bodies: Vec<String>,
    /// Joint names by joint index (empty when a joint has no usable name).
    pub joints: Vec<String>,
    /// Point names in file order.
    pub points: Vec<String>,
    /// Coordinate names in the order the joints first name them.
    pub coordinates: Vec<String>,
    /// Closure names by closure index (empty when unusable).
    pub closures: Vec<String>,
    /// Constraint names by constraint index (empty when unusable).
    pub constraints: Vec<String>,
}

impl Names {
    /// Declares `name` as a `kind` found at `path`; records an error and returns false
    /// when the name is malformed, reserved or already taken.
    pub fn declare(&mut self, name: &str, kind: Kind, path: &str, diag: &mut Diagnostics) -> bool {
        if !is_valid(name) {
            let message = if name.is_empty() {
                "a name may not be empty".to_string()
            } else {
                format!("`{name}` is not a valid name")
            };
            diag.hint(
                path,
                message,
                "names start with a letter, then letters, digits or `_`",
            );
            return false;
        }
        let reserved = match name {
            "N" => Some(
                "`N` is the Newtonian body and frame; it is always present and may not be declared",
            ),
            "t" => Some("`t` is reserved for time"),
            "pi" => Some("`pi` is reserved for 3.14159…"),
            _ => None,
        };
        if let Some(message) = reserved {
            diag.hint(path, message, "choose another name");
            return false;
        }
        if let Some((other, other_path)) = self.kinds.get(name) {
            diag.hint(
                path,
                format!("`{name}` is already {} (at `{other_path}`)", other.noun()),
                if kind == Kind::Speed || *other == Kind::Speed {
                    "names are unique across constants, coordinates, bodies, joints, points, closures, constraints and speeds"
                } else {
                    "names are unique across constants, coordinates, bodies, joints, points, closures and constraints"
                },
            );
            return false;
        }
        self.kinds
            .insert(name.to_string(), (kind, path.to_string()));
        match kind {
            Kind::Constant => self.constants.push(name.to_string()),
            Kind::Coordinate => self.coordinates.push(name.to_string()),
            Kind::Point => self.points.push(name.to_string()),
            // Bodies and joints keep their slots by position, see `body_slot`, `joint_slot`.
            Kind::Body | Kind::Joint | Kind::Closure | Kind::Constraint | Kind::Speed => {}
        }
        true
    }

    /// What `name` was declared as.
    pub fn kind_of(&self, name: &str) -> Option<Kind> {
        self.kinds.get(name).map(|(k, _)| *k)
    }

    /// The body named `name`; `N` is the ground.
    pub fn body(&self, name: &str) -> Option<BodyId> {
        if name == "N" {
            return Some(BodyId::GROUND);
        }
        self.bodies
            .iter()
            .position(|b| b == name)
            .map(|i| BodyId(i + 1))
    }

    /// The joint named `name`.
    pub fn joint(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| !j.is_empty() && j == name)
    }

    /// The declared point named `name`.
    pub fn point(&self, name: &str) -> Option<usize> {
        self.points.iter().position(|p| p == name)
    }

    /// The coordinate named `name`.
    pub fn coordinate(&self, name: &str) -> Option<usize> {
        self.coordinates.iter().position(|c| c == name)
    }

    /// The name of a body id.
    pub fn body_name(&self, id: BodyId) -> &str {
        if id == BodyId::GROUND {
            "N"
        } else {
            self.bodies.get(id.0 - 1).map_or("?", String::as_str)
        }
    }

    /// `N` and every body, for suggestions.
    pub fn frames(&self) -> Vec<&str> {
        std::iter::once("N")
            .chain(self.bodies.iter().map(String::as_str))
            .collect()
    }
}

/// "did you mean `x`?" when a candidate is close, else a list of what exists (or `none`).
pub fn suggest(name: &str, candidates: &[&str], what: &str) -> String {
    match closest(name, candidates.iter().copied()) {
        Some(close) => format!("did you mean `{close}`?"),
        None if candidates.is_empty() => format!("there are no {what}"),
        None if candidates.len() <= 8 => {
            format!("the {what} are {}", super::json::list(candidates))
        }
        None => format!("there are {} {what}; check the spelling", candidates.len()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn declare(names: &mut Names, name: &str, kind: Kind) -> Option<String> {
        let mut diag = Diagnostics::default();
        let ok = names.declare(name, kind, "here", &mut diag);
        assert_eq!(ok, diag.is_empty());
        diag.errors.pop().map(|e| e.message)
    }

    #[test]
    fn syntax() {
        assert!(is_valid("q1"));
        assert!(is_valid("theta_dot"));
        assert!(!is_valid("1q"));
        assert!(!is_valid("_a"));
        assert!(!is_valid("a-b"));
        assert!(!is_valid(""));
        assert!(!is_valid("é"));
    }

    #[test]
    fn one_namespace_and_reserved_names() {
        let mut names = Names::default();
        assert_eq!(declare(&mut names, "m", Kind::Constant), None);
        let twice = declare(&mut names, "m", Kind::Body).unwrap();
        assert!(twice.contains("already a constant"), "{twice}");
        for reserved in ["N", "t", "pi"] {
            assert!(declare(&mut names, reserved, Kind::Constant).is_some());
        }
        assert!(declare(&mut names, "2x", Kind::Point).is_some());
        assert_eq!(names.constants, ["m"]);
    }

    #[test]
    fn suggestions() {
        assert_eq!(
            suggest("q3", &["q1", "m"], "coordinates"),
            "did you mean `q1`?"
        );
        assert_eq!(suggest("zzz", &[], "joints"), "there are no joints");
        assert_eq!(
            suggest("zzz", &["A", "B"], "bodies"),
            "the bodies are `A`, `B`"
        );
    }
}
