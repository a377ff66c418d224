//! Reading the loads, and the point names they use: declared points, `A*`, `A.o` and
//! joint names.

use super::expressions::Context;
use super::json::{
    self, check_keys, index_path, key_path, object, optional_string, required, string,
};
use super::model::*;
use super::names::{is_valid, suggest};
use super::reader::{Known, Reader};
use super::validate;
use crate::symbolic::Expr;
use serde_json::{Map, Value};

const TYPES: [(&str, &[&str]); 7] = [
    ("force", &["on", "at", "vector"]),
    ("torque", &["on", "vector", "reaction_on"]),
    ("spring", &["between", "stiffness", "free_length"]),
    ("damper", &["between", "coefficient"]),
    (
        "joint_spring",
        &["joint", "coordinate", "stiffness", "rest"],
    ),
    ("joint_damper", &["joint", "coordinate", "coefficient"]),
    ("joint_actuator", &["joint", "coordinate", "value"]),
];

/// Whether `text` has the shape of a point name rather than of a vector expression.
fn looks_like_point(text: &str) -> bool {
    let text = text.trim();
    let stem = text
        .strip_suffix('*')
        .or_else(|| text.strip_suffix(".o"))
        .unwrap_or(text);
    is_valid(stem)
}

/// Whether a joint's point on the child is also fixed on the parent: true for joints
/// that do not let the point slide.
fn point_fixed_on_both(kind: JointKind) -> bool {
    matches!(
        kind,
        JointKind::Revolute | JointKind::Universal | JointKind::Spherical | JointKind::Weld
    )
}

impl Reader {
    /// Every load of `loads`.
    pub fn loads(&mut self, value: &Value, known: &Known) -> Vec<Load> {
        let Some(items) = json::array(value, "loads", &mut self.diag) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let path = index_path("loads", i);
            let Some(fields) = object(item, &path, &mut self.diag) else {
                continue;
            };
            let name = optional_string(fields, "name", &path, &mut self.diag);
            let Some(type_name) = required(fields, "type", &path, &mut self.diag)
                .and_then(|v| string(v, &key_path(&path, "type"), &mut self.diag))
            else {
                continue;
            };
            let Some((_, keys)) = TYPES.iter().find(|(t, _)| *t == type_name) else {
                let types: Vec<&str> = TYPES.iter().map(|(t, _)| *t).collect();
                self.diag.hint(
                    &key_path(&path, "type"),
                    format!("unknown load type `{type_name}`"),
                    suggest(type_name, &types, "load types"),
                );
                continue;
            };
            let allowed: Vec<&str> = ["type", "name"]
                .iter()
                .chain(keys.iter())
                .copied()
                .collect();
            check_keys(fields, &path, &allowed, &mut self.diag);
            if let Some(kind) = self.load_kind(type_name, fields, &path, known) {
                out.push(Load { name, kind, path });
            }
        }
        out
    }

    fn load_kind(
        &mut self,
        type_name: &str,
        fields: &Map<String, Value>,
        path: &str,
        known: &Known,
    ) -> Option<LoadKind> {
        match type_name {
            "force" => {
                let on = self.loaded_body(fields, path);
                let vector = self.load_vector(fields, path, "a force");
                let at = match (fields.get("at"), on) {
                    (Some(v), Some(on)) => self.force_point(v, &key_path(path, "at"), on, known),
                    (None, Some(on)) => Some(ForcePoint::Point(PointRef::MassCenter(on))),
                    (_, None) => None,
                };
                Some(LoadKind::Force {
                    on: on?,
                    at: at?,
                    vector: vector?,
                })
            }
            "torque" => {
                let on = self.loaded_body(fields, path);
                let vector = self.load_vector(fields, path, "a torque");
                let reaction_path = key_path(path, "reaction_on");
                let reaction_on = match fields.get("reaction_on") {
                    Some(v) => Some(self.body_ref(v, &reaction_path)?),
                    None => None,
                };
                if reaction_on.is_some() && reaction_on == on {
                    self.diag.hint(
                        &reaction_path,
                        "a torque and its reaction on the same body cancel",
                        "name the other body, or leave `reaction_on` out",
                    );
                }
                Some(LoadKind::Torque {
                    on: on?,
                    vector: vector?,
                    reaction_on,
                })
            }
            "spring" | "damper" => {
                let between = self
                    .between(fields, path)
                    .filter(|ends| self.on_two_bodies(ends, path, known));
                let key = if type_name == "spring" {
                    "stiffness"
                } else {
                    "coefficient"
                };
                let first = self.load_scalar(fields, path, key, None);
                if type_name == "spring" {
                    let free_length =
                        self.load_scalar(fields, path, "free_length", Some(Expr::zero()));
                    Some(LoadKind::Spring {
                        between: between?,
                        stiffness: first?,
                        free_length: free_length?,
                    })
                } else {
                    Some(LoadKind::Damper {
                        between: between?,
                        coefficient: first?,
                    })
                }
            }
            _ => {
                let target = self.joint_coordinate(fields, path, known);
                let kind = match type_name {
                    "joint_spring" => {
                        let stiffness = self.load_scalar(fields, path, "stiffness", None);
                        let rest = self.load_scalar(fields, path, "rest", Some(Expr::zero()));
                        let (joint, coordinate) = target?;
                        LoadKind::JointSpring {
                            joint,
                            coordinate,
                            stiffness: stiffness?,
                            rest: rest?,
                        }
                    }
                    "joint_damper" => {
                        let coefficient = self.load_scalar(fields, path, "coefficient", None);
                        let (joint, coordinate) = target?;
                        LoadKind::JointDamper {
                            joint,
                            coordinate,
                            coefficient: coefficient?,
                        }
                    }
                    _ => {
                        let value = self.load_scalar(fields, path, "value", None);
                        let (joint, coordinate) = target?;
                        LoadKind::JointActuator {
                            joint,
                            coordinate,
                            value: value?,
                        }
                    }
                };
                Some(kind)
            }
        }
    }

    /// `on`: a declared body (a load on `N` would move nothing).
    fn loaded_body(&mut self, fields: &Map<String, Value>, path: &str) -> Option<BodyId> {
        let on_path = key_path(path, "on");
        let on = required(fields, "on", path, &mut self.diag)
            .and_then(|v| self.body_ref(v, &on_path))?;
        if on == BodyId::GROUND {
            self.diag.hint(
                &on_path,
                "a load on `N` moves nothing",
                "name the body it acts on; for the opposite torque on N use `reaction_on`",
            );
            return None;
        }
        Some(on)
    }

    fn load_vector(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        what: &'static str,
    ) -> Option<VectorExpr> {
        let vector_path = key_path(path, "vector");
        let value = required(fields, "vector", path, &mut self.diag)?;
        let v = self.vector(value, &vector_path, Context::load(what))?;
        if what == "a torque" {
            if self.dimension == Some(Dimension::Two) {
                if let Some((frame, axis, _)) = v.terms.iter().find(|(_, axis, _)| *axis != 2) {
                    let f = format!(
                        "{}.{}",
                        self.names.body_name(*frame),
                        ["x", "y", "z"][usize::from(*axis).min(2)]
                    );
                    self.diag.hint(
                        &vector_path,
                        format!("in a 2D problem a torque is about N.z, but this one has a `{f}` component"),
                        "write it as a scalar times N.z",
                    );
                }
            }
        } else {
            self.in_plane(&v, &vector_path, what);
        }
        Some(v)
    }

    /// A scalar of a load; `default` when the key may be left out.
    fn load_scalar(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        key: &str,
        default: Option<Expr>,
    ) -> Option<Expr> {
        let what = match key {
            "stiffness" => "a stiffness",
            "free_length" => "a free length",
            "coefficient" => "a damping coefficient",
            "rest" => "a rest value",
            _ => "an actuator value",
        };
        let value = match (fields.get(key), default) {
            (Some(v), _) => v,
            (None, Some(d)) => return Some(d),
            (None, None) => {
                required(fields, key, path, &mut self.diag);
                return None;
            }
        };
        let key_path = key_path(path, key);
        let e = self.scalar(value, &key_path, Context::load(what))?;
        if e.is_constant() {
            validate::finite(&e, &self.values, &key_path, &mut self.diag);
        }
        Some(e)
    }

    /// A point name: declared point, `A*`, `A.o`, or a joint.
    pub(super) fn point_ref(&mut self, value: &Value, path: &str) -> Option<PointRef> {
        let text = string(value, path, &mut self.diag)?.trim();
        let star = text.strip_suffix('*').map(|b| (b, true));
        let origin = text.strip_suffix(".o").map(|b| (b, false));
        if let Some((body, center)) = star.or(origin) {
            let Some(id) = self.names.body(body) else {
                let hint = suggest(body, &self.names.frames(), "bodies");
                self.diag
                    .hint(path, format!("unknown body `{body}` in `{text}`"), hint);
                return None;
            };
            if center && id == BodyId::GROUND {
                self.diag
                    .hint(path, "`N` has no mass center", "the fixed origin is `N.o`");
                return None;
            }
            return Some(if center {
                PointRef::MassCenter(id)
            } else {
                PointRef::Origin(id)
            });
        }
        if let Some(p) = self.names.point(text) {
            return Some(PointRef::Named(p));
        }
        if let Some(j) = self.names.joint(text) {
            return Some(PointRef::Joint(j));
        }
        let mut candidates: Vec<String> = self
            .names
            .points
            .iter()
            .chain(self.names.joints.iter().filter(|j| !j.is_empty()))
            .cloned()
            .collect();
        for frame in self.names.frames() {
            if frame != "N" {
                candidates.push(format!("{frame}*"));
            }
            candidates.push(format!("{frame}.o"));
        }
        let refs: Vec<&str> = candidates.iter().map(String::as_str).collect();
        let message = match self.names.kind_of(text) {
            Some(super::names::Kind::Body) => format!("`{text}` is a body, not a point"),
            Some(other) => format!("`{text}` is {}, not a point", other.noun()),
            None => format!("unknown point `{text}`"),
        };
        let hint = match self.names.body(text) {
            Some(_) => format!("its mass center is `{text}*`, its origin `{text}.o`"),
            None => suggest(text, &refs, "points"),
        };
        self.diag.hint(path, message, hint);
        None
    }

    /// Where a force acts: a point fixed on `on`, or a position from `on`'s origin.
    pub(super) fn force_point(
        &mut self,
        value: &Value,
        path: &str,
        on: BodyId,
        known: &Known,
    ) -> Option<ForcePoint> {
        let is_name = value.as_str().is_some_and(looks_like_point);
        if !is_name {
            let at = self.position(value, path, on, "the point of a force")?;
            validate::vector(&at, &self.values, path, &mut self.diag);
            return Some(ForcePoint::Offset(at));
        }
        let point = self.point_ref(value, path)?;
        let fixed_on_body = match point {
            PointRef::Named(p) => known.points.get(p).is_some_and(|d| d.on == on),
            PointRef::MassCenter(b) | PointRef::Origin(b) => b == on,
            PointRef::Joint(j) => known.joints.get(j).is_some_and(|joint| {
                joint.child == on || (joint.parent == on && point_fixed_on_both(joint.kind))
            }),
        };
        if !fixed_on_body {
            let body = self.names.body_name(on).to_string();
            self.diag.hint(
                path,
                format!("the force acts on `{body}`, but the point `{}` is not fixed on `{body}`", value.as_str().unwrap_or("?")),
                format!("name a point of {body}, or give the position from {body}'s origin, e.g. \"L*{body}.x\""),
            );
            return None;
        }
        Some(ForcePoint::Point(point))
    }

    fn between(&mut self, fields: &Map<String, Value>, path: &str) -> Option<[PointRef; 2]> {
        let between_path = key_path(path, "between");
        let items = json::array(
            required(fields, "between", path, &mut self.diag)?,
            &between_path,
            &mut self.diag,
        )?;
        if items.len() != 2 {
            self.diag.hint(
                &between_path,
                format!("expected two point names, found {}", items.len()),
                "e.g. [\"N.o\", \"A*\"]",
            );
            return None;
        }
        let a = self.point_ref(&items[0], &index_path(&between_path, 0));
        let b = self.point_ref(&items[1], &index_path(&between_path, 1));
        let (a, b) = (a?, b?);
        if a == b {
            self.diag
                .error(&between_path, "both ends are the same point");
            return None;
        }
        Some([a, b])
    }

    /// Whether the two ends of a spring or damper are on different bodies; if not, an
    /// error: a rigid body cannot stretch an element between two of its own points.
    fn on_two_bodies(&mut self, ends: &[PointRef; 2], path: &str, known: &Known) -> bool {
        let body = |point: PointRef| match point {
            PointRef::Named(i) => known.points.get(i).map(|p| p.on),
            PointRef::MassCenter(b) | PointRef::Origin(b) => Some(b),
            PointRef::Joint(j) => known.joints.get(j).map(|joint| joint.child),
        };
        match (body(ends[0]), body(ends[1])) {
            (Some(a), Some(b)) if a == b => {
                let name = self.names.body_name(a).to_string();
                self.diag.hint(
                    &key_path(path, "between"),
                    format!("both points are on `{name}`, so the element can never stretch"),
                    "connect points of two different bodies",
                );
                false
            }
            _ => true,
        }
    }

    /// `joint` and `coordinate` of a joint load: the coordinate must be the joint's.
    fn joint_coordinate(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        known: &Known,
    ) -> Option<(usize, usize)> {
        let joint = required(fields, "joint", path, &mut self.diag)
            .and_then(|v| self.joint_ref(v, &key_path(path, "joint")));
        let coordinate_path = key_path(path, "coordinate");
        let name = required(fields, "coordinate", path, &mut self.diag)
            .and_then(|v| string(v, &coordinate_path, &mut self.diag));
        let (joint, name) = (joint?, name?);
        let joint_name = self.names.joints[joint].clone();
        let own: Vec<&str> = known.joints[joint]
            .coordinates
            .iter()
            .map(|c| known.coordinates[*c].name.as_str())
            .collect();
        let hint = match own.as_slice() {
            [] => format!("joint `{joint_name}` has no coordinates"),
            [one] => format!("joint `{joint_name}`'s coordinate is `{one}`"),
            many => format!(
                "joint `{joint_name}`'s coordinates are {}",
                json::list(many)
            ),
        };
        match self.names.coordinate(name) {
            Some(c) if known.joints[joint].coordinates.contains(&c) => Some((joint, c)),
            Some(c) => {
                let owner = &known.joints[known.coordinates[c].joint].name;
                self.diag.hint(
                    &coordinate_path,
                    format!("`{name}` is a coordinate of joint `{owner}`, not of `{joint_name}`"),
                    hint,
                );
                None
            }
            None => {
                self.diag.hint(
                    &coordinate_path,
                    format!("unknown coordinate `{name}`"),
                    match crate::symbolic::closest(name, own.iter().copied()) {
                        Some(close) => format!("did you mean `{close}`?"),
                        None => hint,
                    },
                );
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_names_and_positions_are_told_apart() {
        for name in ["P", "A*", "B.o", "O2", " A* "] {
            assert!(looks_like_point(name), "{name}");
        }
        for vector in ["L*A.x", "A.x", "0", "-P", "2*A*"] {
            assert!(!looks_like_point(vector), "{vector}");
        }
    }
}
