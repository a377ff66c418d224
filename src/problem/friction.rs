//! Reading Coulomb friction: the key `friction` (the coefficient μ ≥ 0) on `rolling`, `gear`
//! and `contact` entries and on `prismatic` joints and closures, and the `contact` entry
//! itself, a point of a body that stays on a plane fixed in another and may slide on it
//! (see constraints.md, version 3).

use super::expressions::{ConstantValues, Context};
use super::json::{check_keys, key_path, required, Diagnostics};
use super::model::*;
use super::reader::Reader;
use super::validate;
use crate::symbolic::{fixed, Expr};
use serde_json::{Map, Value};

const CONTACT_KEYS: [&str; 8] = [
    "name", "type", "body", "point", "on", "normal", "offset", "friction",
];

impl Reader {
    /// The coefficient of friction under `friction`, if given: a scalar of constants, not
    /// negative.
    pub(super) fn friction(&mut self, fields: &Map<String, Value>, path: &str) -> Option<Expr> {
        let value = fields.get("friction")?;
        let friction_path = key_path(path, "friction");
        let mu = self.scalar(
            value,
            &friction_path,
            Context::constant("a coefficient of friction"),
        )?;
        coefficient(&mu, &self.values, &friction_path, &mut self.diag);
        Some(mu)
    }

    /// A `contact` entry: `body`'s `point` stays on the plane fixed in `on`.
    pub(super) fn contact(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
    ) -> Option<ConstraintKind> {
        check_keys(fields, path, &CONTACT_KEYS, &mut self.diag);
        let body = required(fields, "body", path, &mut self.diag)
            .and_then(|v| self.body_ref(v, &key_path(path, "body")));
        if body == Some(BodyId::GROUND) {
            self.diag.hint(
                &key_path(path, "body"),
                "the body in contact may not be `N`",
                "name the body whose point touches the plane; the plane is fixed in `on`",
            );
        }
        let body_id = body.unwrap_or(BodyId::GROUND);
        let mut on = BodyId::GROUND;
        if let Some(value) = fields.get("on") {
            let on_path = key_path(path, "on");
            if let Some(b) = self.body_ref(value, &on_path) {
                if body == Some(b) {
                    self.diag.hint(
                        &on_path,
                        format!(
                            "a body cannot touch a plane fixed in itself (`{}`)",
                            self.names.body_name(b)
                        ),
                        "name the body (or N) that carries the plane",
                    );
                }
                on = b;
            }
        }
        let normal_path = key_path(path, "normal");
        let normal = required(fields, "normal", path, &mut self.diag).and_then(|v| {
            let normal = self.position(v, &normal_path, on, "the plane's normal")?;
            validate::axis(&normal, &self.values, &normal_path, &mut self.diag);
            Some(normal)
        });
        let point = self.disc_center(fields.get("point"), &key_path(path, "point"), body_id)?;
        let offset = match fields.get("offset") {
            Some(v) => self.scalar(v, &key_path(path, "offset"), Context::constant("an offset")),
            None => Some(Expr::zero()),
        };
        Some(ConstraintKind::Contact {
            body: body?,
            point,
            on,
            normal: normal?,
            offset: offset?,
        })
    }

    /// A rough prismatic joint's coordinate may not be prescribed: the drive and the friction
    /// would both act along the axis, and while the slider sticks nothing would share the
    /// force between them.
    pub(super) fn check_sliders(&mut self, joints: &[Joint], coordinates: &[Coordinate]) {
        for joint in joints.iter().filter(|j| j.friction.is_some()) {
            let prescribed = joint
                .coordinates
                .iter()
                .filter_map(|&c| coordinates.get(c))
                .find(|c| c.motion.is_some());
            if let Some(c) = prescribed {
                self.diag.hint(
                    &key_path(&joint.path, "friction"),
                    format!(
                        "joint `{}` has friction, but its coordinate `{}` is prescribed: the drive along the axis and the friction could not be told apart while it sticks",
                        joint.name, c.name
                    ),
                    "remove `friction` (the drive's force then includes it), or the coordinate's `motion`",
                );
            }
        }
    }
}

/// A coefficient of friction: finite and not negative.
pub fn coefficient(mu: &Expr, values: &ConstantValues, path: &str, diag: &mut Diagnostics) {
    if let Some(value) = validate::finite(mu, values, path, diag) {
        if value < 0.0 {
            diag.hint(
                path,
                format!(
                    "the coefficient of friction must not be negative; `{mu}` is {}",
                    fixed(value)
                ),
                "give μ ≥ 0, e.g. \"friction\": 0.3 (0 for a smooth surface)",
            );
        }
    }
}
