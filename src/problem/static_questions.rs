//! The questions of statics in `find.questions` (cli.md, version 4): `slips` (a site with
//! friction), `tips` (a contact) and `impending` (the value of a constant at which slip,
//! or the loss of a contact, impends at rest). Whether the site has friction is checked
//! when the question is answered, where the friction sites are known.

use super::json::{check_keys, key_path, number, object, string};
use super::question_model::QuestionKind;
use super::reader::Reader;
use serde_json::Value;

impl Reader {
    /// Reads the `slips`, `tips` or `impending` entry of the question at `path`.
    pub(super) fn static_question(
        &mut self,
        key: &str,
        value: &Value,
        path: &str,
        constraints: &[Value],
    ) -> Option<QuestionKind> {
        let kpath = key_path(path, key);
        match key {
            "slips" => {
                let site = self.site_ref(value, &kpath, constraints)?;
                Some(QuestionKind::Slips { site })
            }
            "tips" => {
                let site = self.contact_ref(value, &kpath, constraints)?;
                Some(QuestionKind::Tips { site })
            }
            _ => self.impending(value, &kpath, constraints),
        }
    }

    /// A site that must be a `contact` constraint, as a site index.
    fn contact_ref(&mut self, value: &Value, path: &str, constraints: &[Value]) -> Option<usize> {
        let site = self.site_ref(value, path, constraints)?;
        let first = self.names.joints.len() + self.names.closures.len();
        let is_contact = site
            .checked_sub(first)
            .and_then(|k| constraints.get(k))
            .and_then(|c| c.get("type"))
            .and_then(Value::as_str)
            == Some("contact");
        if !is_contact {
            self.diag.hint(
                path,
                format!(
                    "`{}` is not a contact, so it cannot tip off",
                    value.as_str().unwrap_or("").trim()
                ),
                "name a constraint of type \"contact\"",
            );
            return None;
        }
        Some(site)
    }

    /// `{ "find": "P", "at": "floor", "tips"?: true, "guess"?: v }`.
    fn impending(
        &mut self,
        value: &Value,
        path: &str,
        constraints: &[Value],
    ) -> Option<QuestionKind> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(
            fields,
            path,
            &["find", "at", "tips", "guess"],
            &mut self.diag,
        );
        let fpath = key_path(path, "find");
        let Some(find) = fields.get("find") else {
            self.diag.hint(
                &fpath,
                "an impending question names the constant to find",
                "e.g. \"impending\": { \"find\": \"P\", \"at\": \"floor\" }",
            );
            return None;
        };
        let name = string(find, &fpath, &mut self.diag)?.trim();
        let Some(constant) = self.names.constants.iter().position(|c| c == name) else {
            let known: Vec<&str> = self.names.constants.iter().map(String::as_str).collect();
            let hint = match crate::symbolic::closest(name, known.iter().copied()) {
                Some(close) => format!("did you mean `{close}`?"),
                None => format!("name one of the constants: {}", known.join(", ")),
            };
            self.diag
                .hint(&fpath, format!("`{name}` is not a constant"), hint);
            return None;
        };
        let apath = key_path(path, "at");
        let Some(at) = fields.get("at") else {
            self.diag.hint(
                &apath,
                "an impending question names the site where slip or tipping impends",
                "e.g. \"at\": \"floor\" (a site with friction, or with \"tips\": true a contact)",
            );
            return None;
        };
        let tips = match fields.get("tips") {
            None => false,
            Some(v) => match v.as_bool() {
                Some(b) => b,
                None => {
                    self.diag.hint(
                        &key_path(path, "tips"),
                        format!("expected true or false, found {v}"),
                        "write \"tips\": true",
                    );
                    return None;
                }
            },
        };
        let site = match tips {
            true => self.contact_ref(at, &apath, constraints)?,
            false => self.site_ref(at, &apath, constraints)?,
        };
        let guess = match fields.get("guess") {
            Some(v) => Some(number(v, &key_path(path, "guess"), &mut self.diag)?),
            None => None,
        };
        Some(QuestionKind::Impending {
            constant,
            site,
            tips,
            guess,
        })
    }
}
