//! The conditions a `show` assumes (`assuming`): the motion its identity is asked of, said
//! in the question itself rather than read from the numbers of a state.

use super::expressions::{self, Context};
use super::json::{array, check_keys, index_path, key_path, string};
use super::question_model::QuestionKind;
use super::reader::Reader;
use crate::symbolic::{Expr, Symbol};
use serde_json::Value;

impl Reader {
    /// `"assuming": ["theta' = 0", "theta'' = 0", "psi'' = 0"]` of a `show`: each a
    /// coordinate, rate or second rate, `=`, and the value put in for it (an expression of
    /// constants). The handout puts them into the equations of step 5 in symbols.
    pub(super) fn show_assuming(
        &mut self,
        kind: QuestionKind,
        value: &Value,
        path: &str,
    ) -> Option<QuestionKind> {
        let list = array(value, path, &mut self.diag)?;
        let mut conditions = Vec::new();
        for (i, item) in list.iter().enumerate() {
            let ipath = index_path(path, i);
            conditions.push(self.condition(item, &ipath)?);
        }
        match kind {
            QuestionKind::Show {
                lhs,
                rhs,
                text,
                names,
                ..
            } => Some(QuestionKind::Show {
                lhs,
                rhs,
                text,
                names,
                assuming: conditions,
            }),
            other => Some(other),
        }
    }

    /// One condition, `"theta'' = 0"`: the symbol and its value.
    fn condition(&mut self, item: &Value, path: &str) -> Option<(Expr, Expr)> {
        let text = string(item, path, &mut self.diag)?.trim().to_string();
        let hint =
            "write a coordinate, rate or second rate, `=`, and its value, e.g. \"theta'' = 0\"";
        let Some((left, right)) = text.split_once('=').filter(|(_, r)| !r.contains('=')) else {
            self.diag
                .hint(path, format!("`{text}` is not one condition"), hint);
            return None;
        };
        let side = |reader: &mut Reader, s: &str, what: &'static str| {
            expressions::scalar(
                &Value::from(s.trim()),
                path,
                &reader.names,
                Context::question(what),
                &mut reader.diag,
            )
        };
        let symbol = side(self, left, "the quantity a condition sets")?;
        let value = side(self, right, "the value a condition sets")?;
        let is_state = matches!(symbol.as_symbol(), Some(Symbol::Coord(..)));
        let moving = value.any_symbol(&|s| matches!(s, Symbol::Coord(..) | Symbol::Time));
        if !is_state || moving {
            self.diag.hint(
                path,
                format!("`{text}` does not set one coordinate, rate or second rate to a value"),
                hint,
            );
            return None;
        }
        Some((symbol, value))
    }
}

impl Reader {
    /// `"describe": "theta"` or `{ "coordinate": "theta", "rates": ["psi"] }`: a
    /// coordinate's motion over the simulated run, with the ranges of other coordinates'
    /// rates.
    pub(super) fn describe(&mut self, value: &Value, path: &str) -> Option<QuestionKind> {
        let (name, cpath, listed) = match value {
            Value::Object(fields) => {
                check_keys(fields, path, &["coordinate", "rates"], &mut self.diag);
                let cpath = key_path(path, "coordinate");
                let Some(v) = fields.get("coordinate") else {
                    self.diag.hint(
                        path,
                        "the coordinate to describe is missing",
                        "give `coordinate`, e.g. \"theta\"",
                    );
                    return None;
                };
                (v, cpath, fields.get("rates"))
            }
            other => (other, path.to_string(), None),
        };
        let coordinate = self.described(name, &cpath)?;
        let mut rates = Vec::new();
        if let Some(list) = listed {
            let rpath = key_path(path, "rates");
            for (i, item) in array(list, &rpath, &mut self.diag)?.iter().enumerate() {
                rates.push(self.described(item, &index_path(&rpath, i))?);
            }
        }
        Some(QuestionKind::Describe { coordinate, rates })
    }

    /// A coordinate named by `value` (`"psi"`; a rate `"psi'"` names its coordinate).
    fn described(&mut self, value: &Value, path: &str) -> Option<usize> {
        let name = string(value, path, &mut self.diag)?;
        Some(self.state_name(name, path)?.coordinate)
    }
}
