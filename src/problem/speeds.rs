//! Reading `speeds`: generalized speeds declared in place of the coordinates' rates, each
//! `u_r = W_r(q) q'`, linear in the first rates, with `W` invertible at the initial state.

use super::expressions::Context;
use super::json::{check_keys, key_path, object, optional_string, required};
use super::model::*;
use super::names::Kind;
use super::reader::Reader;
use crate::symbolic::{eval, linear_split, Expr, Symbol, Values};
use serde_json::Value;

impl Reader {
    /// The `speeds` object: as many speeds as coordinates, each linear in the rates, the
    /// matrix `W` invertible at the initial state. `constrained`: the problem has closures
    /// or constraints, which speeds do not support.
    pub fn speeds(
        &mut self,
        value: &Value,
        coordinates: &[Coordinate],
        constrained: bool,
    ) -> Vec<Speed> {
        let Some(map) = value.as_object() else {
            self.diag.hint(
                "speeds",
                format!("expected an object, found {}", super::json::kind(value)),
                "write { \"u1\": { \"equals\": \"q1'\" }, ... }, one speed per coordinate",
            );
            return Vec::new();
        };
        let rates: Vec<Symbol> = coordinates
            .iter()
            .map(|c| Symbol::Coord(c.name.as_str().into(), 1))
            .collect();
        let mut out = Vec::new();
        for (name, value) in map {
            let path = key_path("speeds", name);
            let declared = self.names.declare(name, Kind::Speed, &path, &mut self.diag);
            let Some(fields) = object(value, &path, &mut self.diag) else {
                continue;
            };
            check_keys(
                fields,
                &path,
                &["equals", "unit", "description"],
                &mut self.diag,
            );
            let unit = optional_string(fields, "unit", &path, &mut self.diag);
            let description = optional_string(fields, "description", &path, &mut self.diag);
            let equals_path = key_path(&path, "equals");
            let Some(equals) = required(fields, "equals", &path, &mut self.diag)
                .and_then(|v| self.speed_expression(v, &equals_path, &rates))
            else {
                continue;
            };
            if declared {
                out.push(Speed {
                    name: name.clone(),
                    equals,
                    unit,
                    description,
                    path,
                });
            }
        }
        if map.is_empty() {
            self.diag.hint(
                "speeds",
                "`speeds` is empty",
                "declare one speed per coordinate, or leave `speeds` out to use the rates",
            );
            return Vec::new();
        }
        let free: Vec<&Coordinate> = coordinates
            .iter()
            .filter(|c| !c.dependent && !c.dependent_rate && c.motion.is_none())
            .collect();
        if constrained || free.len() != coordinates.len() {
            self.diag.hint(
                "speeds",
                "declared speeds are not supported with closures, constraints, dependent or prescribed coordinates",
                "leave `speeds` out: the speeds are then the coordinates' rates",
            );
            return Vec::new();
        }
        if map.len() != coordinates.len() {
            let names: Vec<&str> = coordinates.iter().map(|c| c.name.as_str()).collect();
            self.diag.hint(
                "speeds",
                format!(
                    "{} speed{} declared for {} coordinates",
                    map.len(),
                    if map.len() == 1 { "" } else { "s" },
                    coordinates.len()
                ),
                format!(
                    "declare exactly one speed per coordinate ({}), so that the speeds determine every rate",
                    names.join(", ")
                ),
            );
            return Vec::new();
        }
        if out.len() == coordinates.len() {
            self.check_invertible(&out, coordinates, &rates);
        }
        out
    }

    /// `equals`: linear and homogeneous in the rates, coefficients of constants and coordinates.
    fn speed_expression(&mut self, value: &Value, path: &str, rates: &[Symbol]) -> Option<Expr> {
        let text = value.as_str().unwrap_or_default().to_string();
        let e = self.scalar(value, path, Context::load("a speed"))?;
        if e.contains(&Symbol::Time) {
            self.diag.push(
                path,
                token_column(&text, "t"),
                "a speed may not depend on time `t`",
                Some("write the speed with constants, coordinates and their rates, e.g. \"q1' + q2'\""),
            );
            return None;
        }
        // The column of the first rate that is not linear, for the messages below.
        let nonlinear = rates
            .iter()
            .find(|r| match linear_split(&e, std::slice::from_ref(*r)) {
                Err(_) => true,
                Ok((c, _)) => c[0].contains(r),
            })
            .and_then(|r| token_column(&text, &r.to_string()));
        match linear_split(&e, rates) {
            Err(_) => {
                self.diag.push(
                    path,
                    nonlinear.or(Some(1)),
                    "the speed is not linear in the rates",
                    Some("a speed is a sum of rates times coefficients of constants and coordinates, e.g. \"cos(q2)*q1' + q3'\""),
                );
                None
            }
            Ok((coefficients, rest)) => {
                let has_rate = |c: &Expr| rates.iter().any(|r| c.contains(r));
                if coefficients.iter().any(has_rate) {
                    self.diag.push(
                        path,
                        nonlinear.or(Some(1)),
                        "the speed is not linear in the rates: a rate multiplies a rate",
                        Some("a speed is a sum of rates times coefficients of constants and coordinates"),
                    );
                    return None;
                }
                if !crate::symbolic::simplify(&rest).is_zero() {
                    self.diag.push(
                        path,
                        Some(1),
                        "the speed has a part without rates: it must vanish when every rate does",
                        Some("write u = W(q) q' only, e.g. \"q1' + q2'\" rather than \"q1' + 1\""),
                    );
                    return None;
                }
                if coefficients.iter().all(Expr::is_zero) {
                    self.diag.push(
                        path,
                        Some(1),
                        "the speed holds no rate",
                        Some("a speed is a combination of the coordinates' rates, e.g. \"q1'\""),
                    );
                    return None;
                }
                Some(e)
            }
        }
    }

    /// Records an error when `W` is singular at the initial coordinates.
    fn check_invertible(&mut self, speeds: &[Speed], coordinates: &[Coordinate], rates: &[Symbol]) {
        let mut values: Values = self.values.values();
        for c in coordinates {
            values.set(Symbol::Coord(c.name.as_str().into(), 0), c.initial);
        }
        let n = coordinates.len();
        let mut w = nalgebra::DMatrix::<f64>::zeros(n, n);
        for (r, speed) in speeds.iter().enumerate() {
            let Ok((coefficients, _)) = linear_split(&speed.equals, rates) else {
                return;
            };
            for (s, c) in coefficients.iter().enumerate() {
                w[(r, s)] = eval(c, &values);
            }
        }
        if w.iter().any(|x| !x.is_finite()) {
            return;
        }
        let singular = w.clone().svd(false, false).singular_values;
        let largest = singular.max();
        if largest <= 0.0 || singular.min() <= 1e-10 * largest {
            let names: Vec<&str> = coordinates.iter().map(|c| c.name.as_str()).collect();
            self.diag.hint(
                "speeds",
                format!(
                    "the speeds do not determine the rates {} at the initial state: the matrix W of u = W(q) q' is singular there",
                    names.join(", ")
                ),
                "choose speeds that are independent combinations of the rates (no speed a combination of the others), and an initial state away from gimbal lock",
            );
        }
    }
}

/// The 1-based column of the first occurrence of `token` (a name, or a name and its primes)
/// standing alone in `text`: not part of a longer name.
fn token_column(text: &str, token: &str) -> Option<usize> {
    let is_name = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut from = 0;
    while let Some(i) = text[from..].find(token) {
        let start = from + i;
        let end = start + token.len();
        let before = text[..start].chars().next_back();
        let after = text[end..].chars().next();
        // A prime after it makes it another symbol: `q1` in `q1'`, `q1'` in `q1''`.
        if !before.is_some_and(is_name) && !after.is_some_and(|c| is_name(c) || c == '\'') {
            return Some(text[..start].chars().count() + 1);
        }
        from = end;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::token_column;

    #[test]
    fn token_column_finds_whole_names_only() {
        assert_eq!(token_column("theta*t*q1'", "t"), Some(7));
        assert_eq!(token_column("q1'' + q1'", "q1'"), Some(8));
        assert_eq!(token_column("q12' + q1'", "q1'"), Some(8));
        assert_eq!(token_column("q2", "q1'"), None);
    }
}
