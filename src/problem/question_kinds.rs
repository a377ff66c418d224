//! The kinds of question added to `find.questions` beside `value`, `reaction`, `drive`
//! and `steady`: `period` (of small oscillations, from the linearization) and `show` (an
//! identity derived from the equations of motion), with `about` (the state of an earlier
//! `steady` question) and `item` (the statement's item a question answers).

use super::expressions::{self, Context};
use super::json::{check_keys, key_path, number, object, string};
use super::question_model::QuestionKind;
use super::reader::Reader;
use serde_json::Value;

impl Reader {
    /// `"period": {}` or `{ "coordinate": "theta" }`.
    pub(super) fn period(&mut self, value: &Value, path: &str) -> Option<QuestionKind> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(fields, path, &["coordinate"], &mut self.diag);
        let Some(v) = fields.get("coordinate") else {
            return Some(QuestionKind::Period { coordinate: None });
        };
        let cpath = key_path(path, "coordinate");
        let name = string(v, &cpath, &mut self.diag)?;
        let entry = self.state_name(name, &cpath)?;
        if entry.order != 0 {
            self.diag.hint(
                &cpath,
                format!("`{}` is a rate, not a coordinate", name.trim()),
                "name the coordinate whose oscillation is asked, e.g. \"theta\"",
            );
            return None;
        }
        Some(QuestionKind::Period {
            coordinate: Some(entry.coordinate),
        })
    }

    /// `"show": "LHS = RHS"`: two expressions of constants, coordinates, rates and second
    /// rates, split at the one `=`.
    pub(super) fn show(&mut self, value: &Value, path: &str) -> Option<QuestionKind> {
        let text = string(value, path, &mut self.diag)?.trim().to_string();
        let sides: Vec<&str> = text.split('=').collect();
        let [lhs, rhs] = sides[..] else {
            self.diag.hint(
                path,
                format!("`{text}` is not one identity"),
                "write two expressions with one `=` between them, e.g. \"m*g*h = psi'*I3*w3\"",
            );
            return None;
        };
        let side = |reader: &mut Reader, s: &str| {
            expressions::scalar(
                &Value::from(s.trim()),
                path,
                &reader.names,
                Context::question("a side of the identity to show"),
                &mut reader.diag,
            )
        };
        let lhs = side(self, lhs)?;
        let rhs = side(self, rhs)?;
        Some(QuestionKind::Show {
            lhs,
            rhs,
            text,
            names: Vec::new(),
            assuming: Vec::new(),
        })
    }

    /// `"where": { "Omega": "psi'", "I1": "It + m*h^2" }` of a `show`: the names its
    /// statement gives quantities of the identity, each an expression of the problem's
    /// names. The handout derives the identity in these names.
    pub(super) fn show_names(
        &mut self,
        kind: QuestionKind,
        value: &Value,
        path: &str,
    ) -> Option<QuestionKind> {
        let fields = object(value, path, &mut self.diag)?;
        let mut names = Vec::new();
        for (name, v) in fields {
            let npath = key_path(path, name);
            let fresh = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                && name.chars().all(|c| c.is_ascii_alphanumeric())
                && self.names.kind_of(name).is_none();
            if !fresh {
                self.diag.hint(
                    &npath,
                    format!("`{name}` is not a new name"),
                    "name each quantity with letters and digits not used by the problem, e.g. \"Omega\"",
                );
                return None;
            }
            let e = expressions::scalar(
                v,
                &npath,
                &self.names,
                Context::question("a quantity the identity names"),
                &mut self.diag,
            )?;
            names.push((name.clone(), e));
        }
        match kind {
            QuestionKind::Show {
                lhs,
                rhs,
                text,
                assuming,
                ..
            } => Some(QuestionKind::Show {
                lhs,
                rhs,
                text,
                names,
                assuming,
            }),
            other => Some(other),
        }
    }

    /// `"item": N`, a positive whole number.
    pub(super) fn item(&mut self, value: &Value, path: &str) -> Option<u32> {
        let x = number(value, path, &mut self.diag)?;
        if x < 1.0 || x.fract() != 0.0 || x > 1000.0 {
            self.diag.hint(
                path,
                format!("`{}` is not an item of the statement", value),
                "give the number of the statement's item this question answers: 1, 2, …",
            );
            return None;
        }
        Some(x as u32)
    }

    /// `"about": INDEX`: a question of `items` (all of find.questions) that asks for a
    /// steady motion, itself asked `at` a state.
    pub(super) fn about(&mut self, value: &Value, path: &str, items: &[Value]) -> Option<usize> {
        let x = number(value, path, &mut self.diag)?;
        let listed = x >= 0.0 && x.fract() == 0.0 && (x as usize) < items.len();
        let index = x as usize;
        if !listed || items[index].get("steady").is_none() || items[index].get("about").is_some() {
            self.diag.hint(
                path,
                format!("`{value}` is not a `steady` question of find.questions"),
                "give the index (from 0) of a question of find.questions that asks for a steady motion at a state (`at`, not `about`)",
            );
            return None;
        }
        Some(index)
    }

    /// `"stability": { "vary": "v", "from": 1, "to": 10, "count": 19 }`: where, as the
    /// constant `vary` goes from `from` to `to`, the question's state changes stability.
    pub(super) fn stability(&mut self, value: &Value, path: &str) -> Option<QuestionKind> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(
            fields,
            path,
            &["vary", "from", "to", "count"],
            &mut self.diag,
        );
        let vpath = key_path(path, "vary");
        let Some(name) = fields.get("vary") else {
            self.diag.hint(
                path,
                "the constant to vary is missing",
                "give `vary`, the name of a constant, e.g. \"v\"",
            );
            return None;
        };
        let name = string(name, &vpath, &mut self.diag)?.trim().to_string();
        let Some(constant) = self.names.constants.iter().position(|c| *c == name) else {
            self.diag.hint(
                &vpath,
                format!("`{name}` is not a constant of the problem"),
                "name a constant of `constants`",
            );
            return None;
        };
        let mut bound = |key: &str| -> Option<f64> {
            let Some(v) = fields.get(key) else {
                self.diag.hint(
                    path,
                    format!("`{key}` is missing"),
                    "give the range as `from` and `to`, numbers in the constant's unit",
                );
                return None;
            };
            number(v, &key_path(path, key), &mut self.diag)
        };
        let (from, to) = (bound("from")?, bound("to")?);
        let count = match fields.get("count") {
            Some(v) => number(v, &key_path(path, "count"), &mut self.diag)?,
            None => 19.0,
        };
        if from.partial_cmp(&to) != Some(std::cmp::Ordering::Less)
            || !(2.0..=1000.0).contains(&count)
            || count.fract() != 0.0
        {
            self.diag.hint(
                path,
                "the range is empty or the count is not a whole number from 2 to 1000",
                "give `from` below `to`, and `count` (default 19) values to try between them",
            );
            return None;
        }
        Some(QuestionKind::Stability {
            constant,
            from,
            to,
            count: count as usize,
        })
    }
}
