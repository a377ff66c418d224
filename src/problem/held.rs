//! A coordinate's `"held": true` (constraints.md, version 4): a support keeps it at its
//! initial value and takes the generalized force it needs. It is read as `motion`'s
//! constant case, so that every stage that knows prescribed coordinates (the assembly,
//! the drives, the answers) holds it without a path of its own.

use super::expressions::Context;
use super::json::key_path;
use super::model::Coordinate;
use super::reader::Reader;
use crate::symbolic::Expr;
use serde_json::{Map, Value};

/// Whether the coordinate's fields say `"held": true`.
pub fn is_held(fields: &Map<String, Value>) -> bool {
    fields.get("held").and_then(Value::as_bool) == Some(true)
}

impl Reader {
    /// Reads `held` on one `coordinates` entry (after its `initial`): a held coordinate
    /// gets the constant motion `q = initial`. `held` with `motion`, `rate` or `dependent`
    /// is refused at its path.
    pub(super) fn held_key(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        entry: &mut Coordinate,
    ) {
        let Some(v) = fields.get("held") else { return };
        let held_path = key_path(path, "held");
        let Some(held) = v.as_bool() else {
            self.diag.hint(
                &held_path,
                format!("expected true or false, found {v}"),
                "write \"held\": true",
            );
            return;
        };
        if !held {
            return;
        }
        let refused = [
            (
                "motion",
                "a held coordinate keeps its initial value; `motion` would move it",
                "remove `held` (a constant `motion` holds it too), or remove `motion`",
            ),
            (
                "rate",
                "a held coordinate is at rest: it has no `rate`",
                "remove `rate`",
            ),
            (
                "dependent",
                "a held coordinate cannot also be solved from the constraints",
                "remove `dependent` or `held`",
            ),
            (
                "dependent_rate",
                "a held coordinate's rate is zero, not solved from the constraints",
                "remove `dependent_rate` or `held`",
            ),
        ];
        let mut bad = false;
        for (key, message, hint) in refused {
            let set = match fields.get(key) {
                Some(Value::Bool(b)) => *b,
                Some(_) => true,
                None => false,
            };
            if set {
                self.diag.hint(&held_path, message, hint);
                bad = true;
            }
        }
        if bad {
            return;
        }
        let value = match fields.get("initial") {
            Some(v) => {
                let ipath = key_path(path, "initial");
                self.scalar(v, &ipath, Context::constant("a held coordinate's value"))
            }
            None => Some(Expr::zero()),
        };
        entry.held = true;
        entry.motion = value;
        entry.rate = 0.0;
    }
}
