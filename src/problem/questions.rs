//! `find.questions`: what the student is asked, each answered in the handout's "Answers".
//!
//! A question asks for one of
//! - `value`: any scalar expression of constants, coordinates, rates, second rates `q1''`
//!   and `t` (a coordinate, a spring force, a kinetic energy);
//! - `reaction`: the reaction at a joint (closure, rolling contact) listed in
//!   `find.reactions`;
//! - `drive`: the generalized force that drives a prescribed coordinate (one with a
//!   `motion`): a motor's torque or an actuator's force;
//! - `steady`: the values of some coordinates and rates (`unknowns`) that make the
//!   expressions in `zero` vanish (default: every second derivative `q1''`), the rest of the
//!   state held: a steady motion or an equilibrium; `zero` may add conditions such as a
//!   spin held, `"phi' + psi'*cos(theta) - 150"`;
//! - `period` and `show` (see [`super::question_kinds`]),
//!
//! `at` a state (`state`, with `time`, default 0), or at a time reached by simulating from
//! the initial state (`time` alone), or where a friction site first switches between
//! sticking and slipping (`switch`). Without `at`, the initial state at t = 0.

use super::expressions::{self, Context};
use super::json::{self, check_keys, index_path, key_path, number, object, string};
use super::question_model::{Question, QuestionAt, QuestionKind, StateEntry};
use super::reader::Reader;
use crate::symbolic::Expr;
use serde_json::{Map, Value};

const KEYS: [&str; 20] = [
    "text",
    "value",
    "reaction",
    "drive",
    "steady",
    "period",
    "show",
    "at",
    "about",
    "item",
    "unit",
    "symbol",
    "slips",
    "tips",
    "impending",
    "in",
    "stability",
    "where",
    "assuming",
    "describe",
];

/// The keys that say what a question asks for; a question has exactly one.
const ASKED: [&str; 11] = [
    "value",
    "reaction",
    "drive",
    "steady",
    "period",
    "show",
    "slips",
    "tips",
    "impending",
    "stability",
    "describe",
];

impl Reader {
    /// Whether a question's `symbol` is math every format can set: it is written inside
    /// `$…$` in every handout and names a column of key.csv. An error at `path` otherwise.
    fn typesettable(&mut self, symbol: &str, path: &str) -> bool {
        if crate::typeset::checked_math(symbol).is_some() && !symbol.contains(['<', '>']) {
            return true;
        }
        let shown: String = symbol.chars().take(40).collect();
        self.diag.hint(
            path,
            format!("the symbol `{shown}` is not math that can be typeset"),
            "write it as LaTeX math without dollars, from letters, digits, _ ^ { } and commands \
             such as \\omega or \\dot{x}: e.g. \"F_{max}\"",
        );
        false
    }

    /// Reads `find.questions`; `reactions` are the sites `find.reactions` requested.
    pub(super) fn questions(
        &mut self,
        value: &Value,
        reactions: &[usize],
        constraints: &[Value],
    ) -> Vec<Question> {
        let Some(items) = json::array(value, "find.questions", &mut self.diag) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let path = index_path("find.questions", i);
            if let Some(q) = self.question(item, &path, (reactions, constraints), items) {
                out.push(q);
            }
        }
        out
    }

    fn question(
        &mut self,
        value: &Value,
        path: &str,
        (reactions, constraints): (&[usize], &[Value]),
        all: &[Value],
    ) -> Option<Question> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(fields, path, &KEYS, &mut self.diag);
        let text = fields
            .get("text")
            .and_then(|v| string(v, &key_path(path, "text"), &mut self.diag))
            .map(str::to_string);
        let unit = fields
            .get("unit")
            .and_then(|v| string(v, &key_path(path, "unit"), &mut self.diag))
            .map(str::to_string);
        let symbol = fields
            .get("symbol")
            .and_then(|v| string(v, &key_path(path, "symbol"), &mut self.diag))
            .filter(|symbol| self.typesettable(symbol, &key_path(path, "symbol")))
            .map(str::to_string);
        let asked: Vec<&str> = ASKED
            .into_iter()
            .filter(|k| fields.contains_key(*k))
            .collect();
        if asked.len() != 1 {
            let message = if asked.is_empty() {
                "the question asks for nothing".to_string()
            } else {
                format!("the question asks for {} at once", json::list(&asked))
            };
            self.diag.hint(
                path,
                message,
                "give exactly one of `value` (an expression such as \"q1''\"), `reaction` (a joint in find.reactions), `drive` (a prescribed or held coordinate), `steady`, `period`, `show`, `describe`, `slips`, `tips` or `impending`",
            );
            return None;
        }
        let at = match fields.get("at") {
            Some(v) => self.question_at(v, &key_path(path, "at"), constraints)?,
            None => QuestionAt::default(),
        };
        let about = match fields.get("about") {
            Some(_) if fields.contains_key("at") => {
                self.diag.hint(
                    &key_path(path, "about"),
                    "`about` and `at` both say where the question is asked",
                    "give `about` (an earlier steady question's state) or `at`, not both",
                );
                return None;
            }
            Some(v) => Some(self.about(v, &key_path(path, "about"), all)?),
            None => None,
        };
        let item = match fields.get("item") {
            Some(v) => Some(self.item(v, &key_path(path, "item"))?),
            None => None,
        };
        let kind = self.asked(asked[0], fields, path, (reactions, constraints))?;
        let own = ["where", "assuming"]
            .into_iter()
            .find(|k| fields.contains_key(*k));
        if let (Some(key), false) = (own, matches!(kind, QuestionKind::Show { .. })) {
            self.diag.hint(
                &key_path(path, key),
                format!("only a `show` has `{key}`: the names or conditions of its identity"),
                format!("remove `{key}`, or ask a `show`"),
            );
            return None;
        }
        let frame = match fields.get("in") {
            Some(v) => Some(self.answer_frame(v, &key_path(path, "in"), &kind)?),
            None => None,
        };
        if matches!(kind, QuestionKind::Steady { .. })
            && at.state.is_none()
            && at.time.is_some_and(|t| t != 0.0)
        {
            self.diag.hint(
                &key_path(path, "at"),
                "a steady motion is sought at a state, not after a simulation",
                "give `at.state` (the starting guess and the values held); `time` then only sets t",
            );
            return None;
        }
        Some(Question {
            text,
            kind,
            at,
            unit,
            symbol,
            frame,
            path: path.to_string(),
            about,
            item,
        })
    }

    /// What question `key` asks for, read from its entry in `fields`.
    fn asked(
        &mut self,
        key: &str,
        fields: &serde_json::Map<String, Value>,
        path: &str,
        (reactions, constraints): (&[usize], &[Value]),
    ) -> Option<QuestionKind> {
        let kind = match key {
            "value" => {
                let vpath = key_path(path, "value");
                let v = &fields["value"];
                if let Some(found) = v.as_str().and_then(|s| self.vector_value(s, &vpath)) {
                    let text = v.as_str().unwrap_or_default().trim().to_string();
                    return found.map(|quantity| QuestionKind::VectorValue { quantity, text });
                }
                let expression = expressions::scalar(
                    v,
                    &vpath,
                    &self.names,
                    Context::question("a question's value"),
                    &mut self.diag,
                )?;
                let text = match v {
                    Value::String(s) => s.trim().to_string(),
                    other => other.to_string(),
                };
                QuestionKind::Value { expression, text }
            }
            "reaction" => {
                let rpath = key_path(path, "reaction");
                let site = self.site_ref(&fields["reaction"], &rpath, constraints)?;
                if !reactions.contains(&site) {
                    let name = fields["reaction"].as_str().unwrap_or("").trim();
                    self.diag.hint(
                        &rpath,
                        format!("the reaction at `{name}` is not solved for"),
                        format!("add \"{name}\" to find.reactions"),
                    );
                    return None;
                }
                QuestionKind::Reaction { site }
            }
            "drive" => {
                let dpath = key_path(path, "drive");
                let name = string(&fields["drive"], &dpath, &mut self.diag)?;
                let entry = self.state_name(name, &dpath)?;
                if entry.order != 0 {
                    self.diag.hint(
                        &dpath,
                        format!("`{}` is a rate, not a coordinate", name.trim()),
                        "name the prescribed coordinate itself, e.g. \"theta\"",
                    );
                    return None;
                }
                QuestionKind::Drive {
                    coordinate: entry.coordinate,
                }
            }
            "steady" => self.steady(&fields["steady"], &key_path(path, "steady"))?,
            "period" => self.period(&fields["period"], &key_path(path, "period"))?,
            "show" => {
                let mut kind = self.show(&fields["show"], &key_path(path, "show"))?;
                if let Some(v) = fields.get("assuming") {
                    kind = self.show_assuming(kind, v, &key_path(path, "assuming"))?;
                }
                match fields.get("where") {
                    Some(v) => self.show_names(kind, v, &key_path(path, "where"))?,
                    None => kind,
                }
            }
            "stability" => self.stability(&fields["stability"], &key_path(path, "stability"))?,
            "describe" => self.describe(&fields["describe"], &key_path(path, "describe"))?,
            key => self.static_question(key, &fields[key], path, constraints)?,
        };
        Some(kind)
    }

    /// `in`: the frame whose unit vectors a reaction's components are given in.
    fn answer_frame(
        &mut self,
        value: &Value,
        path: &str,
        kind: &QuestionKind,
    ) -> Option<crate::problem::BodyId> {
        if !matches!(
            kind,
            QuestionKind::Reaction { .. } | QuestionKind::VectorValue { .. }
        ) {
            self.diag.hint(
                path,
                "only a vector answer has components to give in a frame",
                "give `in` with a `reaction` or a vector `value` such as \"v(P)\", or remove it",
            );
            return None;
        }
        self.body_ref(value, path)
    }

    fn question_at(
        &mut self,
        value: &Value,
        path: &str,
        constraints: &[Value],
    ) -> Option<QuestionAt> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(
            fields,
            path,
            &["time", "state", "switch", "after_impact"],
            &mut self.diag,
        );
        let mut at = QuestionAt::default();
        if let Some(v) = fields.get("after_impact") {
            at.after_impact = self.after_impact(v, &key_path(path, "after_impact"))?;
        }
        if let Some(v) = fields.get("switch") {
            let spath = key_path(path, "switch");
            if fields.contains_key("time") || fields.contains_key("state") {
                self.diag.hint(
                    &spath,
                    "a switch sets its own instant and state",
                    "give `switch` alone: the question is asked where the site first switches, simulating from the initial state",
                );
                return None;
            }
            at.switch = Some(self.site_ref(v, &spath, constraints)?);
            return Some(at);
        }
        if let Some(v) = fields.get("time") {
            let tpath = key_path(path, "time");
            let t = number(v, &tpath, &mut self.diag)?;
            if t < 0.0 {
                self.diag.hint(
                    &tpath,
                    format!("the time {} is negative", crate::symbolic::fixed(t)),
                    "simulations start at t = 0; give a time of 0 or more",
                );
                return None;
            }
            at.time = Some(t);
        }
        if let Some(v) = fields.get("state") {
            let spath = key_path(path, "state");
            let entries = object(v, &spath, &mut self.diag)?;
            at.state = Some(self.state_entries(entries, &spath)?);
        }
        Some(at)
    }

    /// `after_impact`: a boolean; `true` asks at the state just after the problem's impact.
    fn after_impact(&mut self, value: &Value, path: &str) -> Option<bool> {
        match value.as_bool() {
            Some(b) => Some(b),
            None => {
                self.diag.hint(
                    path,
                    "`after_impact` is true or false",
                    "give \"after_impact\": true to ask at the state just after the impact",
                );
                None
            }
        }
    }

    fn state_entries(
        &mut self,
        entries: &Map<String, Value>,
        path: &str,
    ) -> Option<Vec<(StateEntry, f64)>> {
        let mut out = Vec::new();
        let mut ok = true;
        for (name, v) in entries {
            let epath = key_path(path, name);
            let entry = self.state_name(name, &epath);
            let value = number(v, &epath, &mut self.diag);
            match (entry, value) {
                (Some(e), Some(x)) => out.push((e, x)),
                _ => ok = false,
            }
        }
        ok.then_some(out)
    }

    /// `q1` or `q1'`, as a coordinate or its rate.
    pub(super) fn state_name(&mut self, name: &str, path: &str) -> Option<StateEntry> {
        let trimmed = name.trim();
        let (base, order) = match trimmed.strip_suffix('\'') {
            Some(base) => (base, 1),
            None => (trimmed, 0),
        };
        match self.names.coordinate(base) {
            Some(coordinate) if !base.ends_with('\'') => Some(StateEntry { coordinate, order }),
            _ => {
                let known: Vec<&str> = self.names.coordinates.iter().map(String::as_str).collect();
                self.diag.hint(
                    path,
                    format!("`{trimmed}` is not a coordinate or a rate"),
                    format!(
                        "name a coordinate (`q1`) or its rate (`q1'`); {}",
                        super::names::suggest(base, &known, "coordinates")
                    ),
                );
                None
            }
        }
    }

    fn steady(&mut self, value: &Value, path: &str) -> Option<QuestionKind> {
        let fields = object(value, path, &mut self.diag)?;
        check_keys(fields, path, &["unknowns", "zero"], &mut self.diag);
        let upath = key_path(path, "unknowns");
        let Some(list) = fields.get("unknowns") else {
            self.diag.hint(
                &upath,
                "`unknowns` is required",
                "name the coordinates or rates to solve for, e.g. [\"psi'\"] for a precession rate or [\"q1\"] for an equilibrium angle",
            );
            return None;
        };
        let items = json::array(list, &upath, &mut self.diag)?;
        let mut unknowns = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let ipath = index_path(&upath, i);
            let name = string(item, &ipath, &mut self.diag)?;
            let entry = self.state_name(name, &ipath)?;
            if unknowns.contains(&entry) {
                self.diag
                    .error(&ipath, format!("`{}` is listed twice", name.trim()));
                return None;
            }
            unknowns.push(entry);
        }
        if unknowns.is_empty() {
            self.diag.hint(
                &upath,
                "no unknowns",
                "name at least one coordinate or rate to solve for",
            );
            return None;
        }
        let zpath = key_path(path, "zero");
        let zero = match fields.get("zero") {
            None => (0..self.names.coordinates.len())
                .map(|i| {
                    let name = &self.names.coordinates[i];
                    (Expr::coord(name, 2), format!("{name}''"))
                })
                .collect(),
            Some(list) => {
                let items = json::array(list, &zpath, &mut self.diag)?;
                let mut zero = Vec::new();
                for (i, item) in items.iter().enumerate() {
                    let ipath = index_path(&zpath, i);
                    let e = expressions::scalar(
                        item,
                        &ipath,
                        &self.names,
                        Context::question("an expression to make zero"),
                        &mut self.diag,
                    )?;
                    let text = item.as_str().map(str::trim).unwrap_or("").to_string();
                    zero.push((e, text));
                }
                zero
            }
        };
        if zero.len() < unknowns.len() {
            self.diag.hint(
                path,
                format!(
                    "{} unknowns but only {} expressions to make zero",
                    unknowns.len(),
                    zero.len()
                ),
                "name no more unknowns than expressions in `zero`",
            );
            return None;
        }
        Some(QuestionKind::Steady { unknowns, zero })
    }
}
