//! Reading a body's `shape`, which only the pictures use: its type, its points in the
//! body's own unit vectors, its lengths of constants. Part of the [`Reader`](super::read)
//! walk.

use super::expressions::Context;
use super::json::{array, check_keys, index_path, key_path, object, required, string};
use super::model::*;
use super::validate;
use crate::symbolic::Expr;
use serde_json::{Map, Value};

const TYPES: &str = "rod, disc, block, particle or polygon";

impl super::reader::Reader {
    /// The `shape` of body `id` at `path`, or `None` after recording what is wrong.
    pub(super) fn shape(&mut self, value: &Value, path: &str, id: BodyId) -> Option<BodyShape> {
        let fields = object(value, path, &mut self.diag)?;
        let kind = required(fields, "type", path, &mut self.diag)
            .and_then(|v| string(v, &key_path(path, "type"), &mut self.diag))?;
        let keys: &[&str] = match kind {
            "rod" => &["type", "from", "to"],
            "disc" => &["type", "radius", "center", "axis"],
            "block" => &["type", "size", "center"],
            "particle" => &["type"],
            "polygon" => &["type", "points"],
            other => {
                self.diag.hint(
                    &key_path(path, "type"),
                    format!("`{other}` is not a shape"),
                    format!("use {TYPES}"),
                );
                return None;
            }
        };
        check_keys(fields, path, keys, &mut self.diag);
        match kind {
            "rod" => {
                let from = self.shape_point(fields, "from", path, id, true)?;
                let to = self.shape_point(fields, "to", path, id, true)?;
                Some(BodyShape::Rod {
                    from: from?,
                    to: to?,
                })
            }
            "disc" => {
                let value = required(fields, "radius", path, &mut self.diag)?;
                let radius = self.length(value, &key_path(path, "radius"))?;
                let center = self.shape_point(fields, "center", path, id, false)?;
                let axis_path = key_path(path, "axis");
                let axis = match fields.get("axis") {
                    Some(v) => {
                        let axis =
                            self.vector(v, &axis_path, Context::constant("a disc's axis"))?;
                        self.fixed_in(&axis, id, &axis_path, "a disc's axis");
                        validate::axis(&axis, &self.values, &axis_path, &mut self.diag);
                        Some(axis)
                    }
                    None => None,
                };
                Some(BodyShape::Disc {
                    radius,
                    center,
                    axis,
                })
            }
            "block" => {
                let size_path = key_path(path, "size");
                let value = required(fields, "size", path, &mut self.diag)?;
                let items = array(value, &size_path, &mut self.diag)?;
                let wanted = if self.dimension == Some(Dimension::Three) {
                    3
                } else {
                    2
                };
                if items.len() != wanted {
                    self.diag.hint(
                        &size_path,
                        format!("a block's size has {wanted} lengths, found {}", items.len()),
                        if wanted == 3 {
                            "write [W, H, D]"
                        } else {
                            "write [W, H]"
                        },
                    );
                    return None;
                }
                let size: Option<Vec<Expr>> = items
                    .iter()
                    .enumerate()
                    .map(|(k, v)| self.length(v, &index_path(&size_path, k)))
                    .collect();
                let center = self.shape_point(fields, "center", path, id, false)?;
                Some(BodyShape::Block {
                    size: size?,
                    center: center.unwrap_or_default(),
                })
            }
            "particle" => Some(BodyShape::Particle),
            _ => {
                let points_path = key_path(path, "points");
                let value = required(fields, "points", path, &mut self.diag)?;
                let items = array(value, &points_path, &mut self.diag)?;
                if items.len() < 3 {
                    self.diag.hint(
                        &points_path,
                        format!("a polygon has at least 3 points, found {}", items.len()),
                        "give the plate's corners in order",
                    );
                    return None;
                }
                let points: Option<Vec<VectorExpr>> = items
                    .iter()
                    .enumerate()
                    .map(|(k, v)| {
                        let p = index_path(&points_path, k);
                        let point = self.position(v, &p, id, "a shape's point")?;
                        validate::vector(&point, &self.values, &p, &mut self.diag);
                        Some(point)
                    })
                    .collect();
                Some(BodyShape::Polygon { points: points? })
            }
        }
    }

    /// The point under `key`: `Some(None)` when it is missing and optional, `None` after an
    /// error.
    fn shape_point(
        &mut self,
        fields: &Map<String, Value>,
        key: &str,
        path: &str,
        id: BodyId,
        needed: bool,
    ) -> Option<Option<VectorExpr>> {
        let value = if needed {
            Some(required(fields, key, path, &mut self.diag)?)
        } else {
            fields.get(key)
        };
        let Some(value) = value else {
            return Some(None);
        };
        let p = key_path(path, key);
        let point = self.position(value, &p, id, "a shape's point")?;
        validate::vector(&point, &self.values, &p, &mut self.diag);
        Some(Some(point))
    }

    /// A positive length of constants.
    fn length(&mut self, value: &Value, path: &str) -> Option<Expr> {
        let e = self.scalar(value, path, Context::constant("a length"))?;
        let v = validate::finite(&e, &self.values, path, &mut self.diag)?;
        if v <= 0.0 {
            self.diag.hint(
                path,
                format!("a length must be positive; `{e}` is {v}"),
                "give the size the picture should show",
            );
            return None;
        }
        Some(e)
    }
}
