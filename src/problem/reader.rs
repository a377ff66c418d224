//! The state shared by the parts of reading a problem ([`Reader`]), what a section needs
//! to know of the others ([`Known`]), and the readers of an expression, a position and a
//! name that every section uses. [`read`](super::read) walks the sections; each section's
//! file adds its own methods to [`Reader`].

use super::expressions::{self, ConstantValues, Context};
use super::graph::Orientation;
use super::json::{string, Diagnostics};
use super::model::{BodyId, Coordinate, CoordinateKind, Dimension, Joint, PointDef, VectorExpr};
use super::names::{suggest, Names};
use crate::symbolic::Expr;
use serde_json::Value;

/// What a load needs to know of the rest of the problem.
pub struct Known<'a> {
    /// The joints.
    pub joints: &'a [Joint],
    /// The declared points.
    pub points: &'a [PointDef],
    /// The coordinates.
    pub coordinates: &'a [Coordinate],
}

/// The state shared by the parts of reading.
pub struct Reader {
    /// Every error so far.
    pub diag: Diagnostics,
    /// Every declared name.
    pub names: Names,
    /// `None` when `dimension` itself is wrong: the checks that depend on it are skipped.
    pub dimension: Option<Dimension>,
    /// The constants' values, for the value checks.
    pub values: ConstantValues,
    /// Which frames stay aligned; known once the joints are read.
    pub orientation: Option<Orientation>,
}

impl Reader {
    /// A scalar expression.
    pub fn scalar(&mut self, value: &Value, path: &str, context: Context) -> Option<Expr> {
        expressions::scalar(value, path, &self.names, context, &mut self.diag)
    }

    /// A vector expression.
    pub fn vector(&mut self, value: &Value, path: &str, context: Context) -> Option<VectorExpr> {
        expressions::vector(value, path, &self.names, context, &mut self.diag)
    }

    /// A constant vector fixed in `body`: its unit vectors must not turn relative to the
    /// body, and in 2D it lies in the plane.
    pub fn position(
        &mut self,
        value: &Value,
        path: &str,
        body: BodyId,
        what: &'static str,
    ) -> Option<VectorExpr> {
        let v = self.vector(value, path, Context::constant(what))?;
        self.fixed_in(&v, body, path, what);
        self.in_plane(&v, path, what);
        Some(v)
    }

    /// Records an error when a term of `v` uses unit vectors that turn relative to `body`.
    pub fn fixed_in(&mut self, v: &VectorExpr, body: BodyId, path: &str, what: &str) {
        let Some(orientation) = &self.orientation else {
            return;
        };
        let two_d = self.dimension == Some(Dimension::Two);
        // In 2D every frame shares its z with N.z.
        let turning = v
            .terms
            .iter()
            .find(|(f, axis, _)| !(orientation.aligned(*f, body) || (two_d && *axis == 2)));
        if let Some((frame, axis, _)) = turning {
            let (b, f) = (
                self.names.body_name(body).to_string(),
                self.names.body_name(*frame).to_string(),
            );
            let letter = ["x", "y", "z"][usize::from(*axis).min(2)];
            self.diag.hint(
                path,
                format!("{what} is fixed in `{b}`, but `{f}.{letter}` turns relative to `{b}`"),
                format!("write it with {b}.x, {b}.y, {b}.z"),
            );
        }
    }

    /// In 2D, records an error when `v` has a component along z.
    pub fn in_plane(&mut self, v: &VectorExpr, path: &str, what: &str) {
        if self.dimension != Some(Dimension::Two) {
            return;
        }
        if let Some((frame, _, _)) = v.terms.iter().find(|(_, axis, _)| *axis == 2) {
            let f = self.names.body_name(*frame).to_string();
            self.diag.hint(
                path,
                format!("in a 2D problem {what} lies in the plane of N.x and N.y, but it has a `{f}.z` component"),
                "drop the z term, or make the problem 3D with \"dimension\": 3",
            );
        }
    }

    /// A body name (`N` included).
    pub fn body_ref(&mut self, value: &Value, path: &str) -> Option<BodyId> {
        let name = string(value, path, &mut self.diag)?;
        if let Some(id) = self.names.body(name) {
            return Some(id);
        }
        let message = match self.names.kind_of(name) {
            Some(other) => format!("`{name}` is {}, not a body", other.noun()),
            None => format!("unknown body `{name}`"),
        };
        let hint = suggest(name, &self.names.frames(), "bodies");
        self.diag.hint(path, message, hint);
        None
    }

    /// A joint name.
    pub fn joint_ref(&mut self, value: &Value, path: &str) -> Option<usize> {
        let name = string(value, path, &mut self.diag)?;
        if let Some(index) = self.names.joint(name) {
            return Some(index);
        }
        let known: Vec<&str> = self
            .names
            .joints
            .iter()
            .filter(|j| !j.is_empty())
            .map(String::as_str)
            .collect();
        let message = match self.names.kind_of(name) {
            Some(other) => format!("`{name}` is {}, not a joint", other.noun()),
            None => format!("unknown joint `{name}`"),
        };
        let hint = suggest(name, &known, "joints");
        self.diag.hint(path, message, hint);
        None
    }
}

/// The owner of each coordinate, in coordinate order: `(joint, index in joint, kind)`.
pub type Owners = Vec<(usize, usize, CoordinateKind)>;
