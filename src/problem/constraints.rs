//! Reading what closes loops and constrains motion: `closures`, `constraints`, and the
//! coordinate keys `dependent`, `dependent_rate` and `motion` (see constraints.md).

use super::expressions::Context;
use super::joints::{has_axis, has_friction, has_sequence, NO_FRICTION_HINT};
use super::json::{array, check_keys, index_path, key_path, kind, object, required, string};
use super::model::*;
use super::names::Kind;
use super::reader::Reader;
use super::validate;
use crate::symbolic::{Expr, Symbol};
use serde_json::{Map, Value};

const CLOSURE_KEYS: [&str; 9] = [
    "name", "type", "parent", "child", "axis", "sequence", "at", "child_at", "friction",
];

impl Reader {
    /// Declares the names of the closures and constraints, so that `find` can name them.
    pub fn declare_constrained(&mut self, closures: &[Value], constraints: &[Value]) {
        for (list, key, kind) in [
            (closures, "closures", Kind::Closure),
            (constraints, "constraints", Kind::Constraint),
        ] {
            for (i, value) in list.iter().enumerate() {
                let path = index_path(key, i);
                let name = value
                    .as_object()
                    .and_then(|f| required(f, "name", &path, &mut self.diag))
                    .and_then(|v| string(v, &key_path(&path, "name"), &mut self.diag))
                    .filter(|name| {
                        self.names
                            .declare(name, kind, &key_path(&path, "name"), &mut self.diag)
                    })
                    .unwrap_or("")
                    .to_string();
                match kind {
                    Kind::Closure => self.names.closures.push(name),
                    _ => self.names.constraints.push(name),
                }
            }
        }
    }

    /// The list under `key`, or nothing (with an error when it is not an array).
    pub fn list<'v>(&mut self, top: &'v Map<String, Value>, key: &str) -> &'v [Value] {
        top.get(key)
            .and_then(|v| array(v, key, &mut self.diag))
            .unwrap_or(&[])
    }

    /// The closures: joints that add no coordinates.
    pub fn closures(&mut self, values: &[Value]) -> Vec<Joint> {
        let mut out = Vec::new();
        for (i, value) in values.iter().enumerate() {
            let path = index_path("closures", i);
            let Some(fields) = object(value, &path, &mut self.diag) else {
                continue;
            };
            if fields.contains_key("coordinates") {
                self.diag.hint(
                    &key_path(&path, "coordinates"),
                    "a closure has no coordinates: it closes a loop and adds no degree of freedom",
                    "remove `coordinates`; the joints of the tree carry the coordinates",
                );
            }
            let rest: Map<String, Value> = fields
                .iter()
                .filter(|(k, _)| k.as_str() != "coordinates")
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect();
            check_keys(&rest, &path, &CLOSURE_KEYS, &mut self.diag);
            let kind = required(fields, "type", &path, &mut self.diag)
                .and_then(|v| self.closure_type(v, &key_path(&path, "type")));
            let body = |key: &str, r: &mut Reader| {
                required(fields, key, &path, &mut r.diag)
                    .and_then(|v| r.body_ref(v, &key_path(&path, key)))
            };
            let (parent, child) = (body("parent", self), body("child", self));
            if let (Some(p), Some(c)) = (parent, child) {
                if p == c {
                    self.diag.hint(
                        &key_path(&path, "child"),
                        "a closure joins two different bodies",
                        "name the two bodies whose points the loop joins",
                    );
                }
            }
            let (Some(kind), Some(parent), Some(child)) = (kind, parent, child) else {
                continue;
            };
            let mut joint = Joint {
                name: self.names.closures.get(i).cloned().unwrap_or_default(),
                kind,
                parent,
                child,
                coordinates: Vec::new(),
                axis: None,
                sequence: Vec::new(),
                at: VectorExpr::default(),
                child_at: VectorExpr::default(),
                friction: None,
                angle_from: None,
                path: path.clone(),
            };
            if has_friction(kind) {
                joint.friction = self.friction(fields, &path);
            } else if fields.contains_key("friction") {
                self.diag.hint(
                    &key_path(&path, "friction"),
                    format!("a {} closure cannot have friction", kind.name()),
                    NO_FRICTION_HINT,
                );
            }
            if has_axis(kind) {
                joint.axis = self.axis(fields.get("axis"), &key_path(&path, "axis"), kind, parent);
            } else if fields.contains_key("axis") {
                self.diag.hint(
                    &key_path(&path, "axis"),
                    format!("a {} closure has no `axis`", kind.name()),
                    "remove it",
                );
            }
            if kind == JointKind::Universal {
                joint.sequence =
                    self.sequence(fields.get("sequence"), &key_path(&path, "sequence"), kind);
            } else if fields.contains_key("sequence") && !has_sequence(kind) {
                self.diag.hint(
                    &key_path(&path, "sequence"),
                    format!("a {} closure has no `sequence`", kind.name()),
                    "remove it",
                );
            }
            for (key, body) in [("at", parent), ("child_at", child)] {
                let p = key_path(&path, key);
                if let Some(v) = fields
                    .get(key)
                    .and_then(|v| self.position(v, &p, body, "the closure's point"))
                {
                    validate::vector(&v, &self.values, &p, &mut self.diag);
                    if key == "at" {
                        joint.at = v;
                    } else {
                        joint.child_at = v;
                    }
                }
            }
            out.push(joint);
        }
        out
    }

    fn closure_type(&mut self, value: &Value, path: &str) -> Option<JointKind> {
        let kind = self.joint_type(value, path)?;
        let two_d = self.dimension == Some(Dimension::Two);
        let allowed: &[JointKind] = if two_d {
            &[JointKind::Revolute, JointKind::Prismatic, JointKind::Weld]
        } else {
            &[
                JointKind::Revolute,
                JointKind::Prismatic,
                JointKind::Cylindrical,
                JointKind::Universal,
                JointKind::Spherical,
                JointKind::Weld,
            ]
        };
        if allowed.contains(&kind) {
            return Some(kind);
        }
        let names: Vec<&str> = allowed.iter().map(|k| k.name()).collect();
        self.diag.hint(
            path,
            format!("a closure may not be {}", kind.name()),
            format!(
                "a closure must remove some motion; the types allowed here are {}",
                names.join(", ")
            ),
        );
        None
    }

    /// The `constraints` entries.
    pub fn constraints(&mut self, values: &[Value]) -> Vec<Constraint> {
        let mut out = Vec::new();
        for (i, value) in values.iter().enumerate() {
            let path = index_path("constraints", i);
            let Some(fields) = object(value, &path, &mut self.diag) else {
                continue;
            };
            let Some(kind_name) = required(fields, "type", &path, &mut self.diag)
                .and_then(|v| string(v, &key_path(&path, "type"), &mut self.diag))
            else {
                continue;
            };
            let kind = match kind_name {
                "rolling" => self.rolling(fields, &path),
                "gear" => self.gear(fields, &path),
                "contact" => self.contact(fields, &path),
                "position" | "velocity" => self.general_constraint(fields, &path, kind_name),
                other => {
                    self.diag.hint(
                        &key_path(&path, "type"),
                        format!("unknown constraint type `{other}`"),
                        super::names::suggest(
                            other,
                            &["rolling", "gear", "contact", "position", "velocity"],
                            "constraint types",
                        ),
                    );
                    None
                }
            };
            let friction = match kind_name {
                "rolling" | "gear" | "contact" => self.friction(fields, &path),
                _ => None,
            };
            if let Some(kind) = kind {
                out.push(Constraint {
                    name: self.names.constraints.get(i).cloned().unwrap_or_default(),
                    kind,
                    friction,
                    path,
                });
            }
        }
        out
    }

    fn rolling(&mut self, fields: &Map<String, Value>, path: &str) -> Option<ConstraintKind> {
        check_keys(
            fields,
            path,
            &[
                "name", "type", "body", "radius", "axis", "center", "on", "normal", "offset",
                "friction",
            ],
            &mut self.diag,
        );
        let two_d = self.dimension == Some(Dimension::Two);
        let body = required(fields, "body", path, &mut self.diag)
            .and_then(|v| self.body_ref(v, &key_path(path, "body")));
        if body == Some(BodyId::GROUND) {
            self.diag.hint(
                &key_path(path, "body"),
                "the rolling body may not be `N`",
                "name the body that carries the wheel",
            );
        }
        // The plane is fixed in `on`: `N` (the default) or a moving body, not the disc's own.
        let mut on_id = BodyId::GROUND;
        if let Some(on) = fields.get("on") {
            let on_path = key_path(path, "on");
            if let Some(b) = self.body_ref(on, &on_path) {
                if body.is_some_and(|own| own == b) {
                    self.diag.hint(
                        &on_path,
                        format!(
                            "a disc cannot roll on its own body `{}`",
                            self.names.body_name(b)
                        ),
                        "name the body (or N) that carries the plane",
                    );
                }
                on_id = b;
            }
        }
        let radius_path = key_path(path, "radius");
        let radius = required(fields, "radius", path, &mut self.diag)
            .and_then(|v| self.scalar(v, &radius_path, Context::constant("a radius")));
        if let Some(r) = &radius {
            if let Some(value) = self.values.eval(r) {
                if value.is_nan() || value <= 0.0 {
                    self.diag.hint(
                        &radius_path,
                        format!("the radius must be positive, not {value}"),
                        "give the wheel's radius, e.g. \"R\"",
                    );
                }
            }
        }
        let body_id = body.unwrap_or(BodyId::GROUND);
        let axis_path = key_path(path, "axis");
        let axis = required(fields, "axis", path, &mut self.diag).and_then(|v| {
            let axis = if two_d {
                let axis = self.vector(v, &axis_path, Context::constant("an axle"))?;
                self.fixed_in(&axis, body_id, &axis_path, "the axle");
                if axis.terms.iter().any(|(_, a, _)| *a != 2) {
                    self.diag.hint(
                        &axis_path,
                        "in a 2D problem a wheel's axle is parallel to N.z",
                        "write \"N.z\" or the body's z",
                    );
                    return None;
                }
                axis
            } else {
                self.position(v, &axis_path, body_id, "the axle")?
            };
            validate::axis(&axis, &self.values, &axis_path, &mut self.diag);
            Some(axis)
        });
        let normal_path = key_path(path, "normal");
        let normal = required(fields, "normal", path, &mut self.diag).and_then(|v| {
            let normal = self.position(v, &normal_path, on_id, "the plane's normal")?;
            validate::axis(&normal, &self.values, &normal_path, &mut self.diag);
            Some(normal)
        });
        let center = self.disc_center(fields.get("center"), &key_path(path, "center"), body_id)?;
        let offset = match fields.get("offset") {
            Some(v) => self.scalar(v, &key_path(path, "offset"), Context::constant("an offset")),
            None => Some(Expr::zero()),
        };
        Some(ConstraintKind::Rolling {
            body: body?,
            on: on_id,
            radius: radius?,
            axis: axis?,
            center,
            normal: normal?,
            offset: offset?,
        })
    }

    /// A disc's centre on `body`: a point name, or a vector from its origin in its unit
    /// vectors; missing, the origin.
    pub(super) fn disc_center(
        &mut self,
        value: Option<&Value>,
        path: &str,
        body: BodyId,
    ) -> Option<ForcePoint> {
        match value {
            Some(v)
                if v.as_str().is_some_and(|s| {
                    self.names.point(s.trim()).is_some()
                        || s.trim().ends_with('*')
                        || s.trim().ends_with(".o")
                }) =>
            {
                self.named_point(v, path, body)
            }
            Some(v) => {
                let at = self.position(v, path, body, "the disc's centre")?;
                validate::vector(&at, &self.values, path, &mut self.diag);
                Some(ForcePoint::Offset(at))
            }
            None => Some(ForcePoint::Point(PointRef::Origin(body))),
        }
    }

    /// `A*`, `A.o` or a declared point, which must be on `body`.
    fn named_point(&mut self, value: &Value, path: &str, body: BodyId) -> Option<ForcePoint> {
        let text = value.as_str()?.trim();
        let point = if let Some(p) = self.names.point(text) {
            PointRef::Named(p)
        } else if let Some(b) = text.strip_suffix('*').and_then(|b| self.names.body(b)) {
            PointRef::MassCenter(b)
        } else if let Some(b) = text.strip_suffix(".o").and_then(|b| self.names.body(b)) {
            PointRef::Origin(b)
        } else {
            self.diag.hint(
                path,
                format!("unknown point `{text}`"),
                "name a point of the rolling body, or give the centre as a vector from its origin",
            );
            return None;
        };
        let wrong_body = match point {
            PointRef::MassCenter(b) | PointRef::Origin(b) => (b != body).then_some(b),
            _ => None,
        };
        if let Some(b) = wrong_body {
            self.diag.hint(
                path,
                format!(
                    "the centre `{text}` is on `{}`, not on the rolling body `{}`",
                    self.names.body_name(b),
                    self.names.body_name(body)
                ),
                "the disc's centre is a point of the rolling body",
            );
            return None;
        }
        Some(ForcePoint::Point(point))
    }

    fn general_constraint(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        kind: &str,
    ) -> Option<ConstraintKind> {
        check_keys(
            fields,
            path,
            &["name", "type", "expression"],
            &mut self.diag,
        );
        let expression_path = key_path(path, "expression");
        let what = if kind == "position" {
            "a position constraint"
        } else {
            "a velocity constraint"
        };
        let expression = required(fields, "expression", path, &mut self.diag)
            .and_then(|v| self.scalar(v, &expression_path, Context::load(what)))?;
        let has_rate = expression.any_symbol(&|s| matches!(s, Symbol::Coord(_, k) if *k > 0));
        if kind == "position" {
            if has_rate {
                self.diag.hint(
                    &expression_path,
                    "a position constraint may not use rates",
                    "write rates in a \"velocity\" constraint",
                );
                return None;
            }
            return Some(ConstraintKind::Position { expression });
        }
        let rates: Vec<Symbol> = self
            .names
            .coordinates
            .iter()
            .map(|c| Symbol::Coord(c.as_str().into(), 1))
            .collect();
        let affine =
            crate::symbolic::linear_split(&expression, &rates).is_ok_and(|(coefficients, _)| {
                coefficients
                    .iter()
                    .all(|c| !c.any_symbol(&|s| matches!(s, Symbol::Coord(_, k) if *k > 0)))
            });
        if !affine {
            self.diag.hint(
                &expression_path,
                "a velocity constraint must be affine in the rates (like x' - v0*t), but this one is not",
                "a constraint nonlinear in the rates cannot be written as B(q) q' + b = 0",
            );
            return None;
        }
        Some(ConstraintKind::Velocity { expression })
    }

    /// The coordinate keys of constrained systems on one `coordinates` entry.
    pub fn coordinate_constraint_keys(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        entry: &mut Coordinate,
    ) {
        for key in ["dependent", "dependent_rate"] {
            let Some(v) = fields.get(key) else { continue };
            match v.as_bool() {
                Some(b) if key == "dependent" => entry.dependent = b,
                Some(b) => entry.dependent_rate = b,
                None => self.diag.hint(
                    &key_path(path, key),
                    format!("expected true or false, found {}", kind(v)),
                    format!("write \"{key}\": true"),
                ),
            }
        }
        let Some(v) = fields.get("motion") else {
            if super::held::is_held(fields) {
                entry.drive_symbol = self.drive_symbol(fields, path);
            } else if fields.contains_key("drive") {
                self.diag.hint(
                    &key_path(path, "drive"),
                    "only a prescribed coordinate has a drive",
                    "give the coordinate a `motion` or `\"held\": true`, or remove `drive`",
                );
            }
            return;
        };
        let motion_path = key_path(path, "motion");
        for key in ["initial", "rate"] {
            if fields.contains_key(key) {
                self.diag.hint(
                    &key_path(path, key),
                    format!("a prescribed coordinate has no `{key}`: its `motion` gives it"),
                    format!("remove `{key}`"),
                );
            }
        }
        if entry.dependent || entry.dependent_rate {
            self.diag.hint(
                &motion_path,
                "a prescribed coordinate cannot also be dependent",
                "remove `dependent` or `motion`",
            );
        }
        let Some(motion) = self.scalar(v, &motion_path, Context::load("a prescribed motion"))
        else {
            return;
        };
        if motion.any_symbol(&|s| matches!(s, Symbol::Coord(..))) {
            self.diag.hint(
                &motion_path,
                "a prescribed motion may use constants and `t` only",
                "e.g. \"w*t\" for a constant rate w",
            );
            return;
        }
        entry.motion = Some(motion);
        entry.drive_symbol = self.drive_symbol(fields, path);
    }

    /// `drive.symbol` of a prescribed coordinate: the name its drive goes by.
    fn drive_symbol(&mut self, fields: &Map<String, Value>, path: &str) -> Option<String> {
        let drive = fields.get("drive")?;
        let drive_path = key_path(path, "drive");
        let drive = object(drive, &drive_path, &mut self.diag)?;
        check_keys(drive, &drive_path, &["symbol"], &mut self.diag);
        let symbol_path = key_path(&drive_path, "symbol");
        let symbol = drive.get("symbol")?;
        let name = symbol.as_str().filter(|s| {
            let mut chars = s.chars();
            chars.next().is_some_and(|c| c.is_ascii_alphabetic())
                && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        });
        if name.is_none() {
            self.diag.hint(
                &symbol_path,
                format!("expected a name such as \"tau\" or \"M_m\", found {symbol}"),
                "letters, digits and underscores, starting with a letter; Greek letters by name",
            );
        }
        name.map(str::to_string)
    }

    /// A `find.reactions` name: a joint, a closure or a rolling contact, as a site index.
    pub fn site_ref(&mut self, value: &Value, path: &str, constraints: &[Value]) -> Option<usize> {
        let name = value.as_str().map(str::trim);
        let joints = self.names.joints.len();
        if let Some(c) = name.and_then(|n| self.names.closures.iter().position(|c| c == n)) {
            return Some(joints + c);
        }
        if let Some(k) = name.and_then(|n| self.names.constraints.iter().position(|c| c == n)) {
            let rolling = constraints[k]
                .get("type")
                .and_then(Value::as_str)
                .is_some_and(|t| matches!(t, "rolling" | "gear" | "contact"));
            if !rolling {
                self.diag.hint(
                    path,
                    format!("`{}` is a position or velocity constraint, which has no reaction to report", name.unwrap_or("")),
                    "request joints, closures, rolling contacts, gears and contacts",
                );
                return None;
            }
            return Some(joints + self.names.closures.len() + k);
        }
        self.joint_ref(value, path)
    }
}
