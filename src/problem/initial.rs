//! A coordinate's `initial` and `rate`: a number, or a scalar expression of constants
//! (`"rate": "v/rR"`) that `--set` and `linearize --sweep` evaluate again.

use super::expressions::{ConstantValues, Context};
use super::json::{key_path, number};
use super::reader::Reader;
use super::validate;
use super::validated::Problem;
use crate::symbolic::Expr;
use serde_json::{Map, Value};

impl Reader {
    /// The value of `fields[key]` (0 when absent) and, when it is written as an expression,
    /// the expression. Errors name the JSON path and, inside an expression, the column.
    pub fn coordinate_value(
        &mut self,
        fields: &Map<String, Value>,
        path: &str,
        key: &str,
    ) -> (f64, Option<Expr>) {
        let path = key_path(path, key);
        match fields.get(key) {
            None => (0.0, None),
            Some(value @ Value::String(_)) => {
                let what = if key == "rate" {
                    "an initial rate"
                } else {
                    "an initial value"
                };
                let Some(e) = self.scalar(value, &path, Context::constant(what)) else {
                    return (0.0, None);
                };
                let x = validate::finite(&e, &self.values, &path, &mut self.diag).unwrap_or(0.0);
                (x, Some(e))
            }
            Some(value) => (number(value, &path, &mut self.diag).unwrap_or(0.0), None),
        }
    }
}

/// Evaluates the coordinates' expression-valued `initial` and `rate` with `values` (after
/// `--set`); a value that cannot be computed becomes NaN, which [`super::apply_overrides`] reports.
pub fn evaluate(problem: &mut Problem, values: &ConstantValues) {
    for c in &mut problem.coordinates {
        if let Some(e) = &c.initial_expr {
            c.initial = values.eval(e).unwrap_or(f64::NAN);
        }
        if let Some(e) = &c.rate_expr {
            c.rate = values.eval(e).unwrap_or(f64::NAN);
        }
    }
}

/// The coordinates' expression-valued `initial` and `rate` with their JSON paths.
pub fn expressions(problem: &Problem) -> Vec<(String, &Expr)> {
    let mut out = Vec::new();
    for c in &problem.coordinates {
        let path = key_path("coordinates", &c.name);
        for (key, e) in [("initial", &c.initial_expr), ("rate", &c.rate_expr)] {
            if let Some(e) = e {
                out.push((key_path(&path, key), e));
            }
        }
    }
    out
}
