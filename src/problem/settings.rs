//! Reading what a problem asks for: the reactions to find and the simulation's settings.

use super::json::{self, check_keys, key_path, number, object, Diagnostics};
use super::model::SimulateSettings;
use super::reader::Reader;
use serde_json::Value;

impl Reader {
    /// Reads `find`: the reactions requested, then the questions asked.
    pub(super) fn find(
        &mut self,
        value: &Value,
        constraints: &[Value],
    ) -> (Vec<usize>, Vec<super::question_model::Question>) {
        let Some(fields) = object(value, "find", &mut self.diag) else {
            return (Vec::new(), Vec::new());
        };
        check_keys(fields, "find", &["reactions", "questions"], &mut self.diag);
        let reactions = self.find_reactions(fields.get("reactions"), constraints);
        let questions = fields
            .get("questions")
            .map(|v| self.questions(v, &reactions, constraints))
            .unwrap_or_default();
        (reactions, questions)
    }

    fn find_reactions(&mut self, value: Option<&Value>, constraints: &[Value]) -> Vec<usize> {
        let Some(items) = value.and_then(|v| json::array(v, "find.reactions", &mut self.diag))
        else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let path = json::index_path("find.reactions", i);
            if let Some(joint) = self.site_ref(item, &path, constraints) {
                if out.contains(&joint) {
                    self.diag.error(
                        &path,
                        match self.names.joints.get(joint) {
                            Some(name) => format!("the joint `{name}` is listed twice"),
                            None => format!("`{}` is listed twice", item.as_str().unwrap_or("")),
                        },
                    );
                } else {
                    out.push(joint);
                }
            }
        }
        out
    }

    pub(super) fn simulate(&mut self, value: &Value) -> SimulateSettings {
        let mut settings = SimulateSettings::default();
        let Some(fields) = object(value, "simulate", &mut self.diag) else {
            return settings;
        };
        check_keys(
            fields,
            "simulate",
            &["duration", "output_step", "tolerance"],
            &mut self.diag,
        );
        let positive = |key: &str, default: f64, diag: &mut Diagnostics| {
            let path = key_path("simulate", key);
            let Some(v) = fields.get(key).and_then(|v| number(v, &path, diag)) else {
                return default;
            };
            if v <= 0.0 {
                diag.error(
                    &path,
                    format!(
                        "`{key}` must be positive, not {}",
                        crate::symbolic::fixed(v)
                    ),
                );
                return default;
            }
            v
        };
        settings.duration = positive("duration", settings.duration, &mut self.diag);
        settings.output_step = positive("output_step", settings.output_step, &mut self.diag);
        settings.tolerance = positive("tolerance", settings.tolerance, &mut self.diag);
        if settings.output_step > settings.duration {
            self.diag.hint(
                "simulate.output_step",
                format!(
                    "the output step {} is longer than the duration {}",
                    crate::symbolic::fixed(settings.output_step),
                    crate::symbolic::fixed(settings.duration)
                ),
                "make the step smaller than the duration",
            );
        }
        settings
    }
}
