//! Reading a `gear` entry of `constraints`: two discs (pitch circles, friction wheels) with
//! parallel axles rolling on each other, outside or inside (see constraints.md, version 3).

use super::expressions::Context;
use super::json::{check_keys, key_path, kind, required};
use super::model::*;
use super::reader::Reader;
use super::validate;
use crate::symbolic::Expr;
use serde_json::{Map, Value};

const GEAR_KEYS: [&str; 11] = [
    "name",
    "type",
    "body",
    "radius",
    "center",
    "on",
    "on_radius",
    "on_center",
    "internal",
    "axis",
    "friction",
];

impl Reader {
    pub(super) fn gear(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
    ) -> Option<ConstraintKind> {
        check_keys(fields, path, &GEAR_KEYS, &mut self.diag);
        let body = required(fields, "body", path, &mut self.diag)
            .and_then(|v| self.body_ref(v, &key_path(path, "body")));
        if body == Some(BodyId::GROUND) {
            self.diag.hint(
                &key_path(path, "body"),
                "the rolling disc may not be `N`",
                "name the body that carries the disc; `on` may be N",
            );
        }
        let on_path = key_path(path, "on");
        let on =
            required(fields, "on", path, &mut self.diag).and_then(|v| self.body_ref(v, &on_path));
        if on.is_some() && on == body {
            self.diag.hint(
                &on_path,
                "a disc cannot roll on its own body",
                "name the other disc's body, or N for a fixed circle",
            );
        }
        let body_id = body.unwrap_or(BodyId::GROUND);
        let on_id = on.unwrap_or(BodyId::GROUND);
        let radius = self.gear_radius(fields, path, "radius");
        let on_radius = self.gear_radius(fields, path, "on_radius");
        let internal = match fields.get("internal") {
            None => Some(false),
            Some(v) => match v.as_bool() {
                Some(b) => Some(b),
                None => {
                    self.diag.hint(
                        &key_path(path, "internal"),
                        format!("expected true or false, found {}", kind(v)),
                        "write \"internal\": true for a disc inside a ring",
                    );
                    None
                }
            },
        };
        if let (Some(true), Some(r), Some(big)) = (internal, &radius, &on_radius) {
            if let (Some(r), Some(big)) = (self.values.eval(r), self.values.eval(big)) {
                if big <= r {
                    self.diag.hint(
                        &key_path(path, "on_radius"),
                        format!(
                            "an internal contact needs the ring larger than the disc: `on_radius` is {big}, `radius` is {r}"
                        ),
                        "the disc rolls inside `on`'s circle: give on_radius > radius, or drop \"internal\"",
                    );
                }
            }
        }
        let center = self.disc_center(fields.get("center"), &key_path(path, "center"), body_id);
        let on_center =
            self.disc_center(fields.get("on_center"), &key_path(path, "on_center"), on_id);
        let axis = match (self.dimension, fields.get("axis")) {
            (Some(Dimension::Three), None) => {
                self.diag.hint(
                    &key_path(path, "axis"),
                    "a 3D gear needs its common axle direction",
                    "give \"axis\" in the body's unit vectors, e.g. \"B.z\"",
                );
                None
            }
            (Some(Dimension::Three), Some(v)) => {
                let axis_path = key_path(path, "axis");
                let axis = self.position(v, &axis_path, body_id, "the axle")?;
                validate::axis(&axis, &self.values, &axis_path, &mut self.diag);
                Some(Some(axis))
            }
            (_, Some(v)) => {
                let axis_path = key_path(path, "axis");
                let axis = self.vector(v, &axis_path, Context::constant("an axle"))?;
                if axis.terms.iter().any(|(_, a, _)| *a != 2) {
                    self.diag.hint(
                        &axis_path,
                        "in a 2D problem the gears' axles are parallel to N.z",
                        "write \"N.z\", or omit `axis`",
                    );
                    return None;
                }
                Some(None)
            }
            (_, None) => Some(None),
        };
        Some(ConstraintKind::Gear {
            body: body?,
            radius: radius?,
            center: center?,
            on: on?,
            on_radius: on_radius?,
            on_center: on_center?,
            internal: internal?,
            axis: axis?,
        })
    }

    /// A pitch radius: constants only, positive.
    fn gear_radius(&mut self, fields: &Map<String, Value>, path: &str, key: &str) -> Option<Expr> {
        let radius_path = key_path(path, key);
        let radius = required(fields, key, path, &mut self.diag)
            .and_then(|v| self.scalar(v, &radius_path, Context::constant("a radius")))?;
        if let Some(value) = self.values.eval(&radius) {
            if value.is_nan() || value <= 0.0 {
                self.diag.hint(
                    &radius_path,
                    format!("the radius must be positive, not {value}"),
                    "give the pitch circle's radius, e.g. \"R\"",
                );
            }
        }
        Some(radius)
    }
}
