//! Reading `impact` (constraints.md, version 4): applied impulses and a collision at the
//! initial state.
//!
//! What needs the kinematics (whether the struck point approaches the surface) is checked
//! when the impact is solved; here every name, point, vector and coefficient.

use super::expressions::Context;
use super::json::{self, check_keys, index_path, key_path, object, required, string};
use super::model::*;
use super::reader::{Known, Reader};
use super::validate;
use crate::symbolic::{fixed, Expr};
use serde_json::{Map, Value};

const IMPACT_KEYS: [&str; 2] = ["impulses", "collision"];
const IMPULSE_KEYS: [&str; 5] = ["name", "body", "point", "impulse", "angular"];
const COLLISION_KEYS: [&str; 7] = [
    "name",
    "body",
    "point",
    "on",
    "normal",
    "restitution",
    "friction",
];

/// An impact at the initial state: the rates jump, the configuration stays.
#[derive(Clone, Debug, PartialEq)]
pub struct Impact {
    /// Applied impulses (blows and impulsive couples).
    pub impulses: Vec<Impulse>,
    /// A point of a body striking a surface, if any.
    pub collision: Option<Collision>,
}

/// An applied impulse: a blow at a point of a body, an impulsive couple, or both.
#[derive(Clone, Debug, PartialEq)]
pub struct Impulse {
    /// Its name (`impulses[i]`'s path when none is given).
    pub name: String,
    /// The body struck.
    pub body: BodyId,
    /// Where the blow acts (default the mass centre).
    pub point: ForcePoint,
    /// The linear impulse (N s), a vector of constants.
    pub linear: Option<VectorExpr>,
    /// The impulsive couple (N m s), a vector of constants.
    pub angular: Option<VectorExpr>,
    /// The JSON path, e.g. `impact.impulses[0]`.
    pub path: String,
}

/// A point of `body` striking a surface fixed in `on`.
#[derive(Clone, Debug, PartialEq)]
pub struct Collision {
    /// Its name: the key of its impulse in the output.
    pub name: String,
    /// The striking body.
    pub body: BodyId,
    /// The point that strikes.
    pub point: ForcePoint,
    /// The body the surface is fixed in.
    pub on: BodyId,
    /// The surface's normal in `on`'s unit vectors, towards the body (as written).
    pub normal: VectorExpr,
    /// The coefficient of restitution e, 0 ≤ e ≤ 1.
    pub restitution: Expr,
    /// The coefficient of friction μ at the impact; `None` for a smooth surface.
    pub friction: Option<Expr>,
    /// The JSON path, `impact.collision`.
    pub path: String,
}

impl Reader {
    /// The `impact` object.
    pub(super) fn impact(&mut self, value: &Value, known: &Known) -> Option<Impact> {
        let path = "impact";
        let fields = object(value, path, &mut self.diag)?;
        check_keys(fields, path, &IMPACT_KEYS, &mut self.diag);
        if fields.is_empty() {
            self.diag.hint(
                path,
                "an impact needs `impulses`, a `collision`, or both",
                "give e.g. \"impulses\": [{ \"body\": \"B\", \"point\": \"L*B.x\", \"impulse\": \"J*N.x\" }]",
            );
            return None;
        }
        let mut impulses = Vec::new();
        if let Some(list) = fields.get("impulses") {
            let ipath = key_path(path, "impulses");
            for (i, item) in json::array(list, &ipath, &mut self.diag)
                .unwrap_or(&[])
                .iter()
                .enumerate()
            {
                if let Some(impulse) = self.impulse(item, &index_path(&ipath, i), known) {
                    impulses.push(impulse);
                }
            }
        }
        let collision = match fields.get("collision") {
            Some(v) => Some(self.collision(v, &key_path(path, "collision"), known)?),
            None => None,
        };
        Some(Impact {
            impulses,
            collision,
        })
    }

    fn impulse(&mut self, value: &Value, path: &str, known: &Known) -> Option<Impulse> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(fields, path, &IMPULSE_KEYS, &mut self.diag);
        let name = match fields.get("name") {
            Some(v) => string(v, &key_path(path, "name"), &mut self.diag)?.to_string(),
            None => path.to_string(),
        };
        let body = self.struck_body(fields, path)?;
        let point = self.struck_point(fields.get("point"), path, body, known)?;
        let linear = match fields.get("impulse") {
            Some(v) => Some(self.impulse_vector(v, &key_path(path, "impulse"), false)?),
            None => None,
        };
        let angular = match fields.get("angular") {
            Some(v) => Some(self.impulse_vector(v, &key_path(path, "angular"), true)?),
            None => None,
        };
        if linear.is_none() && angular.is_none() {
            self.diag.hint(
                path,
                "an impulse needs `impulse` (a blow, N s) or `angular` (an impulsive couple, N m s)",
                "give e.g. \"impulse\": \"J*N.x\"",
            );
            return None;
        }
        Some(Impulse {
            name,
            body,
            point,
            linear,
            angular,
            path: path.to_string(),
        })
    }

    fn collision(&mut self, value: &Value, path: &str, known: &Known) -> Option<Collision> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(fields, path, &COLLISION_KEYS, &mut self.diag);
        let name = required(fields, "name", path, &mut self.diag)
            .and_then(|v| string(v, &key_path(path, "name"), &mut self.diag))
            .map(str::to_string);
        if let Some(name) = &name {
            if let Some(kind) = self.names.kind_of(name) {
                self.diag.hint(
                    &key_path(path, "name"),
                    format!("`{name}` is already {}", kind.noun()),
                    "give the collision a name of its own, e.g. \"ledge\"",
                );
            }
        }
        let body = self.struck_body(fields, path);
        let on = match fields.get("on") {
            Some(v) => self.body_ref(v, &key_path(path, "on")),
            None => Some(BodyId::GROUND),
        };
        if body.is_some() && body == on {
            self.diag.hint(
                &key_path(path, "on"),
                "a body cannot strike a surface fixed in itself",
                "name the body (or N) that carries the surface",
            );
            return None;
        }
        let point = match (fields.get("point"), body) {
            (Some(v), Some(b)) => self.struck_point(Some(v), path, b, known),
            (None, _) => {
                self.diag.hint(
                    &key_path(path, "point"),
                    "`point` is required",
                    "name the point of the body that strikes, or give it from the body's origin, e.g. \"L*B.x\"",
                );
                None
            }
            _ => None,
        };
        let normal_path = key_path(path, "normal");
        let normal = required(fields, "normal", path, &mut self.diag).and_then(|v| {
            let n = self.position(v, &normal_path, on?, "the surface's normal")?;
            validate::axis(&n, &self.values, &normal_path, &mut self.diag);
            Some(n)
        });
        let restitution = required(fields, "restitution", path, &mut self.diag)
            .and_then(|v| self.restitution(v, &key_path(path, "restitution")));
        let friction = self.friction(fields, path);
        Some(Collision {
            name: name?,
            body: body?,
            point: point?,
            on: on?,
            normal: normal?,
            restitution: restitution?,
            friction,
            path: path.to_string(),
        })
    }

    fn struck_body(&mut self, fields: &Map<String, Value>, path: &str) -> Option<BodyId> {
        let body_path = key_path(path, "body");
        let body = required(fields, "body", path, &mut self.diag)
            .and_then(|v| self.body_ref(v, &body_path))?;
        if body == BodyId::GROUND {
            self.diag.hint(
                &body_path,
                "an impulse on `N` moves nothing",
                "name the body that is struck",
            );
            return None;
        }
        Some(body)
    }

    fn struck_point(
        &mut self,
        value: Option<&Value>,
        path: &str,
        body: BodyId,
        known: &Known,
    ) -> Option<ForcePoint> {
        match value {
            Some(v) => self.force_point(v, &key_path(path, "point"), body, known),
            None => Some(ForcePoint::Point(PointRef::MassCenter(body))),
        }
    }

    fn impulse_vector(&mut self, value: &Value, path: &str, angular: bool) -> Option<VectorExpr> {
        let what = if angular {
            "an impulsive couple"
        } else {
            "an impulse"
        };
        let v = self.vector(value, path, Context::constant(what))?;
        validate::vector(&v, &self.values, path, &mut self.diag);
        if !angular {
            self.in_plane(&v, path, what);
        } else if self.dimension == Some(Dimension::Two) && v.terms.iter().any(|t| t.1 != 2) {
            self.diag.hint(
                path,
                "in a 2D problem an impulsive couple is about N.z",
                "write it as a scalar times N.z",
            );
            return None;
        }
        Some(v)
    }

    fn restitution(&mut self, value: &Value, path: &str) -> Option<Expr> {
        let e = self.scalar(
            value,
            path,
            Context::constant("a coefficient of restitution"),
        )?;
        if let Some(x) = validate::finite(&e, &self.values, path, &mut self.diag) {
            if !(0.0..=1.0).contains(&x) {
                self.diag.hint(
                    path,
                    format!(
                        "the coefficient of restitution must lie in [0, 1]; `{e}` is {}",
                        fixed(x)
                    ),
                    "give 0 for a plastic impact (the point stays on the surface), 1 for an elastic one",
                );
                return None;
            }
        }
        Some(e)
    }
}
