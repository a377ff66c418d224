//! Walks the JSON of a problem top-down, collecting every error, into a [`Problem`].
//!
//! Names are declared first (constants, bodies, joints with their coordinates, points)
//! so that expressions anywhere can refer to anything; then every section is read.
//! A value with an error is replaced by a placeholder so reading can go on; the problem
//! is only returned when there was no error at all.

use super::expressions::ConstantValues;
use super::json::{
    self, check_keys, key_path, kind, number, object, optional_string, required, string,
    Diagnostics,
};
use super::model::*;
use super::names::{Kind, Names};
use super::reader::{Known, Reader};
use super::validate;
use super::validated::Problem;
use serde_json::Value;

/// The most constants a problem may declare: a course's problems use a few dozen, a chain
/// of a thousand links with full inertia ten thousand; each is a line of the handout, and
/// reading 20,000 takes about a second.
pub const MAX_CONSTANTS: usize = 20_000;

const TOP_KEYS: [&str; 17] = [
    "format",
    "title",
    "statement",
    "dimension",
    "constants",
    "coordinates",
    "gravity",
    "bodies",
    "joints",
    "points",
    "loads",
    "find",
    "simulate",
    "closures",
    "constraints",
    "speeds",
    "impact",
];

/// Reads a whole problem; the errors are in the order found.
pub fn read(root: &Value) -> Result<Problem, Vec<super::error::ProblemError>> {
    let mut r = Reader {
        diag: Diagnostics::default(),
        names: Names::default(),
        dimension: None,
        values: ConstantValues::default(),
        orientation: None,
    };
    let Some(top) = object(root, "", &mut r.diag) else {
        return Err(r.diag.errors);
    };
    check_keys(top, "", &TOP_KEYS, &mut r.diag);
    r.format(top.get("format"));
    let title = required(top, "title", "", &mut r.diag)
        .and_then(|v| r.title(v))
        .unwrap_or_default();
    let statement = optional_string(top, "statement", "", &mut r.diag);
    r.dimension = required(top, "dimension", "", &mut r.diag).and_then(|v| r.read_dimension(v));

    // Too many constants: that one error, before anything is read.
    if r.too_many_constants(top.get("constants")) {
        return Err(r.diag.errors);
    }
    let constants = top
        .get("constants")
        .map(|v| r.constants(v))
        .unwrap_or_default();
    let body_entries = r.declare_bodies(top.get("bodies"));
    let joint_values = r.joint_list(top.get("joints"));
    let (heads, owners) = r.declare_joints(joint_values);
    let closure_values = r.list(top, "closures");
    let constraint_values = r.list(top, "constraints");
    r.declare_constrained(closure_values, constraint_values);
    let point_entries = r.declare_points(top.get("points"));
    let coordinates = r.coordinates(top.get("coordinates"), &owners);

    let joints = r.joints(joint_values, &heads);
    let closures = r.closures(closure_values);
    let constraints = r.constraints(constraint_values);
    let gravity = top
        .get("gravity")
        .and_then(|v| r.position(v, "gravity", BodyId::GROUND, "gravity"));
    if let Some(g) = &gravity {
        validate::vector(g, &r.values, "gravity", &mut r.diag);
    }
    let bodies: Vec<Body> = body_entries
        .iter()
        .map(|(name, value)| r.body(name, value))
        .collect();
    let points: Vec<PointDef> = point_entries
        .iter()
        .map(|(name, value)| r.point(name, value))
        .collect();
    let known = Known {
        joints: &joints,
        points: &points,
        coordinates: &coordinates,
    };
    let loads = top
        .get("loads")
        .map(|v| r.loads(v, &known))
        .unwrap_or_default();
    let (find_reactions, questions) = top
        .get("find")
        .map(|v| r.find(v, constraint_values))
        .unwrap_or_default();
    let simulate = top
        .get("simulate")
        .map(|v| r.simulate(v))
        .unwrap_or_default();
    let speeds = top
        .get("speeds")
        .map(|v| {
            r.speeds(
                v,
                &coordinates,
                !closures.is_empty() || !constraints.is_empty(),
            )
        })
        .unwrap_or_default();
    let impact = top.get("impact").and_then(|v| r.impact(v, &known));
    r.check_sliders(&joints, &coordinates);

    if !r.diag.is_empty() {
        return Err(r.diag.errors);
    }
    Ok(Problem {
        title,
        statement,
        dimension: r.dimension.unwrap_or(Dimension::Three),
        constants,
        coordinates,
        gravity,
        bodies,
        joints,
        points,
        loads,
        closures,
        constraints,
        find_reactions,
        questions,
        simulate,
        speeds,
        decimals: decimals_written(root),
        impact,
    })
}

/// The fractions the problem's expressions write as decimals (`0.4`, `2.0e-3`), each once,
/// so that the worked solution prints them so; the statement and the descriptions are
/// prose, not expressions.
fn decimals_written(value: &Value) -> Vec<(crate::symbolic::Number, String)> {
    const PROSE: [&str; 5] = ["title", "statement", "description", "unit", "note"];
    let mut out = Vec::new();
    let mut walk = vec![value];
    while let Some(v) = walk.pop() {
        match v {
            Value::String(text) => {
                for found in crate::symbolic::decimal_literals(text) {
                    if !out.contains(&found) {
                        out.push(found);
                    }
                }
            }
            Value::Array(items) => walk.extend(items.iter().rev()),
            Value::Object(map) => walk.extend(
                map.iter()
                    .filter(|(k, _)| !PROSE.contains(&k.as_str()))
                    .map(|(_, v)| v)
                    .rev(),
            ),
            _ => {}
        }
    }
    out
}

impl Reader {
    /// Records the one error of more constants than [`MAX_CONSTANTS`]; whether there are.
    fn too_many_constants(&mut self, value: Option<&Value>) -> bool {
        let count = value
            .and_then(Value::as_object)
            .map_or(0, serde_json::Map::len);
        if count <= MAX_CONSTANTS {
            return false;
        }
        self.diag.hint(
            "constants",
            format!(
                "the problem declares {count} constants, more than the limit of {MAX_CONSTANTS}"
            ),
            "a problem needs a few dozen constants: give repeated values one name and use it",
        );
        true
    }

    /// The entries of `joints`, which is required.
    fn joint_list<'v>(&mut self, value: Option<&'v Value>) -> &'v [Value] {
        match value {
            Some(v) => json::array(v, "joints", &mut self.diag).unwrap_or(&[]),
            None => {
                self.diag.hint(
                    "joints",
                    "`joints` is required",
                    "every body needs a joint to its parent, e.g. a revolute joint to N",
                );
                &[]
            }
        }
    }

    fn format(&mut self, value: Option<&Value>) {
        let Some(value) = value else { return };
        match value.as_u64() {
            Some(1) => {}
            Some(n) => self.diag.hint(
                "format",
                format!("format {n} is not supported"),
                "this version reads format 1",
            ),
            None => self.diag.hint(
                "format",
                format!("expected the integer 1, found {}", kind(value)),
                "write \"format\": 1 or leave it out",
            ),
        }
    }

    fn title(&mut self, value: &Value) -> Option<String> {
        let title = string(value, "title", &mut self.diag)?;
        if title.trim().is_empty() {
            self.diag.error("title", "the title is empty");
            return None;
        }
        Some(title.to_string())
    }

    fn read_dimension(&mut self, value: &Value) -> Option<Dimension> {
        match value.as_u64() {
            Some(2) => Some(Dimension::Two),
            Some(3) => Some(Dimension::Three),
            _ => {
                let found = if value.is_number() {
                    format!("`{value}`")
                } else {
                    kind(value).to_string()
                };
                self.diag.hint(
                    "dimension",
                    format!("the dimension must be 2 or 3, not {found}"),
                    "2 for planar motion, 3 for spatial",
                );
                None
            }
        }
    }

    fn constants(&mut self, value: &Value) -> Vec<Constant> {
        let Some(map) = object(value, "constants", &mut self.diag) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (name, value) in map {
            let path = key_path("constants", name);
            self.names
                .declare(name, Kind::Constant, &path, &mut self.diag);
            let (number_value, unit, description, vary) = match value {
                Value::Object(fields) => {
                    check_keys(
                        fields,
                        &path,
                        &["value", "unit", "description", "vary", "step"],
                        &mut self.diag,
                    );
                    let v = required(fields, "value", &path, &mut self.diag)
                        .and_then(|v| number(v, &key_path(&path, "value"), &mut self.diag));
                    let unit = optional_string(fields, "unit", &path, &mut self.diag);
                    (
                        v,
                        unit,
                        optional_string(fields, "description", &path, &mut self.diag),
                        super::vary::read(fields, &path, v, &mut self.diag),
                    )
                }
                Value::Number(_) => (number(value, &path, &mut self.diag), None, None, None),
                other => {
                    let hint = match other {
                        Value::String(_) => "constants are numbers; an expression belongs where the constant is used",
                        _ => "write a number, or { \"value\": 9.81, \"unit\": \"m/s^2\" }",
                    };
                    self.diag.hint(
                        &path,
                        format!("expected a number or an object, found {}", kind(other)),
                        hint,
                    );
                    (None, None, None, None)
                }
            };
            if let Some(v) = number_value {
                self.values.set(name, v);
            }
            out.push(Constant {
                name: name.clone(),
                value: number_value.unwrap_or(f64::NAN),
                unit,
                description,
                vary,
            });
        }
        out
    }
}
