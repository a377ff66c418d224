//! Reading the bodies, points and coordinates of a problem: the declarations that come
//! first, so that expressions anywhere can name them, and then each body's mass, mass
//! center and inertia. Part of the [`Reader`](super::read) walk.

use super::expressions::Context;
use super::json::{check_keys, key_path, kind, object, optional_string, required};
use super::model::*;
use super::names::Kind;
use super::reader::Owners;
use super::validate;
use crate::symbolic::Expr;
use serde_json::Value;

impl super::reader::Reader {
    pub(super) fn declare_bodies<'v>(
        &mut self,
        value: Option<&'v Value>,
    ) -> Vec<(String, &'v Value)> {
        let Some(value) = value else {
            self.diag.hint(
                "bodies",
                "`bodies` is required",
                "declare at least one body, e.g. \"A\": { \"mass\": \"m\" }",
            );
            return Vec::new();
        };
        let Some(map) = object(value, "bodies", &mut self.diag) else {
            return Vec::new();
        };
        if map.is_empty() {
            self.diag.error("bodies", "there must be at least one body");
        }
        for name in map.keys() {
            self.names.bodies.push(name.clone());
            self.names
                .declare(name, Kind::Body, &key_path("bodies", name), &mut self.diag);
        }
        map.iter().map(|(k, v)| (k.clone(), v)).collect()
    }

    pub(super) fn declare_points<'v>(
        &mut self,
        value: Option<&'v Value>,
    ) -> Vec<(String, &'v Value)> {
        let Some(map) = value.and_then(|v| object(v, "points", &mut self.diag)) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (name, value) in map {
            if self
                .names
                .declare(name, Kind::Point, &key_path("points", name), &mut self.diag)
            {
                out.push((name.clone(), value));
            }
        }
        out
    }

    pub(super) fn coordinates(
        &mut self,
        value: Option<&Value>,
        owners: &Owners,
    ) -> Vec<Coordinate> {
        let mut out: Vec<Coordinate> = self
            .names
            .coordinates
            .iter()
            .zip(owners)
            .map(|(name, &(joint, index_in_joint, kind))| Coordinate {
                name: name.clone(),
                initial: 0.0,
                rate: 0.0,
                initial_expr: None,
                rate_expr: None,
                unit: None,
                description: None,
                joint,
                index_in_joint,
                kind,
                dependent: false,
                dependent_rate: false,
                motion: None,
                drive_symbol: None,
                held: false,
            })
            .collect();
        let Some(map) = value.and_then(|v| object(v, "coordinates", &mut self.diag)) else {
            return out;
        };
        for (name, value) in map {
            let path = key_path("coordinates", name);
            let Some(index) = self.names.coordinate(name) else {
                let message = match self.names.kind_of(name) {
                    Some(other) => format!("`{name}` is {}, not a coordinate", other.noun()),
                    None => format!("no joint names the coordinate `{name}`"),
                };
                let known: Vec<&str> = self.names.coordinates.iter().map(String::as_str).collect();
                let hint = match crate::symbolic::closest(name, known.iter().copied()) {
                    Some(close) => format!("did you mean `{close}`?"),
                    None => "coordinates are named by the joints' `coordinates` lists".to_string(),
                };
                self.diag.hint(&path, message, hint);
                continue;
            };
            let Some(fields) = object(value, &path, &mut self.diag) else {
                continue;
            };
            check_keys(
                fields,
                &path,
                &[
                    "initial",
                    "rate",
                    "unit",
                    "description",
                    "dependent",
                    "dependent_rate",
                    "motion",
                    "drive",
                    "held",
                ],
                &mut self.diag,
            );
            self.coordinate_constraint_keys(fields, &path, &mut out[index]);
            let (initial, initial_expr) = self.coordinate_value(fields, &path, "initial");
            let (rate, rate_expr) = self.coordinate_value(fields, &path, "rate");
            let entry = &mut out[index];
            (entry.initial, entry.initial_expr) = (initial, initial_expr);
            (entry.rate, entry.rate_expr) = (rate, rate_expr);
            entry.unit = optional_string(fields, "unit", &path, &mut self.diag);
            entry.description = optional_string(fields, "description", &path, &mut self.diag);
            self.held_key(fields, &path, &mut out[index]);
        }
        out
    }

    pub(super) fn body(&mut self, name: &str, value: &Value) -> Body {
        let path = key_path("bodies", name);
        let id = self.names.body(name).unwrap_or(BodyId::GROUND);
        let mut body = Body {
            name: name.to_string(),
            mass: Expr::one(),
            center: VectorExpr::default(),
            inertia: Inertia::Planar(Expr::zero()),
            description: None,
            shape: None,
            path: path.clone(),
        };
        let Some(fields) = object(value, &path, &mut self.diag) else {
            return body;
        };
        check_keys(
            fields,
            &path,
            &["mass", "center", "inertia", "description", "shape"],
            &mut self.diag,
        );
        let mass_path = key_path(&path, "mass");
        if let Some(mass) = required(fields, "mass", &path, &mut self.diag)
            .and_then(|v| self.scalar(v, &mass_path, Context::constant("a mass")))
        {
            validate::mass(&mass, &self.values, &mass_path, &mut self.diag);
            body.mass = mass;
        }
        let center_path = key_path(&path, "center");
        if let Some(center) = fields
            .get("center")
            .and_then(|v| self.position(v, &center_path, id, "the mass center"))
        {
            validate::vector(&center, &self.values, &center_path, &mut self.diag);
            body.center = center;
        }
        let inertia_path = key_path(&path, "inertia");
        if let Some(inertia) = self.inertia(fields.get("inertia"), &inertia_path) {
            validate::inertia(&inertia, &self.values, &inertia_path, &mut self.diag);
            body.inertia = inertia;
        }
        validate::massless_inertia(
            &body.mass,
            &body.inertia,
            &self.values,
            &inertia_path,
            &mut self.diag,
        );
        body.description = optional_string(fields, "description", &path, &mut self.diag);
        if let Some(shape) = fields.get("shape") {
            body.shape = self.shape(shape, &key_path(&path, "shape"), id);
        }
        body
    }

    /// The central inertia; missing means zero (a particle, or a body whose mass is all
    /// at its mass center).
    pub(super) fn inertia(&mut self, value: Option<&Value>, path: &str) -> Option<Inertia> {
        let spatial = match (self.dimension, value) {
            (Some(Dimension::Three), _) => true,
            (Some(Dimension::Two), _) => false,
            (None, Some(v)) => v.is_object(),
            (None, None) => return None,
        };
        let what = Context::constant("an inertia");
        if !spatial {
            let Some(value) = value else {
                return Some(Inertia::Planar(Expr::zero()));
            };
            if value.is_object() {
                self.diag.hint(
                    path,
                    "in a 2D problem the inertia is one scalar: the moment of inertia about the axis through the mass center parallel to N.z",
                    "write e.g. \"m*L^2/12\"",
                );
                return None;
            }
            return self.scalar(value, path, what).map(Inertia::Planar);
        }
        let zero = || Expr::zero();
        let mut m = [
            [zero(), zero(), zero()],
            [zero(), zero(), zero()],
            [zero(), zero(), zero()],
        ];
        let Some(value) = value else {
            return Some(Inertia::Spatial(m));
        };
        let Some(fields) = value.as_object() else {
            self.diag.hint(
                path,
                format!("in a 3D problem the inertia is an object, found {}", kind(value)),
                "write e.g. { \"xx\": \"I1\", \"yy\": \"I1\", \"zz\": \"I3\" }; missing components are 0",
            );
            return None;
        };
        let keys = [
            ("xx", 0, 0),
            ("yy", 1, 1),
            ("zz", 2, 2),
            ("xy", 0, 1),
            ("yz", 1, 2),
            ("zx", 2, 0),
        ];
        check_keys(fields, path, &keys.map(|(k, _, _)| k), &mut self.diag);
        let mut ok = true;
        for (key, r, c) in keys {
            let Some(v) = fields.get(key) else { continue };
            match self.scalar(v, &key_path(path, key), what) {
                Some(e) => {
                    m[r][c] = e.clone();
                    m[c][r] = e;
                }
                None => ok = false,
            }
        }
        ok.then_some(Inertia::Spatial(m))
    }

    pub(super) fn point(&mut self, name: &str, value: &Value) -> PointDef {
        let path = key_path("points", name);
        let mut point = PointDef {
            name: name.to_string(),
            on: BodyId::GROUND,
            at: VectorExpr::default(),
        };
        let Some(fields) = object(value, &path, &mut self.diag) else {
            return point;
        };
        check_keys(fields, &path, &["on", "at"], &mut self.diag);
        if let Some(on) = required(fields, "on", &path, &mut self.diag)
            .and_then(|v| self.body_ref(v, &key_path(&path, "on")))
        {
            point.on = on;
        }
        let at_path = key_path(&path, "at");
        if let Some(at) = fields
            .get("at")
            .and_then(|v| self.position(v, &at_path, point.on, "a point's position"))
        {
            validate::vector(&at, &self.values, &at_path, &mut self.diag);
            point.at = at;
        }
        point
    }
}
