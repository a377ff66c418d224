//! What `mbd-tutor linearize` prints: the linearization as JSON or as text, and a
//! sweep's table.

use crate::numeric::{is_stable, Linearization, Shape};
use crate::pipeline::Sweep;
use crate::problem::Problem;
use crate::symbolic::fixed;
use nalgebra::DMatrix;
use serde_json::{json, Map, Value};

pub(super) fn pretty(value: &Value) -> String {
    let mut text = serde_json::to_string_pretty(value).unwrap_or_default();
    text.push('\n');
    text
}

/// -0.0 is a valid JSON number, but reads as a sign error to a student.
fn clean(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

fn matrix_json(m: &DMatrix<f64>) -> Value {
    Value::Array(
        m.row_iter()
            .map(|row| json!(row.iter().map(|x| clean(*x)).collect::<Vec<f64>>()))
            .collect(),
    )
}

/// The JSON object of the command-line contract for one state.
pub fn to_json(problem: &Problem, l: &Linearization) -> Value {
    let names: Vec<&str> = problem
        .coordinates
        .iter()
        .map(|c| c.name.as_str())
        .collect();
    let mut state = Map::new();
    for (name, value) in names.iter().zip(&l.q) {
        state.insert(name.to_string(), json!(value));
    }
    for (name, value) in names.iter().zip(&l.rates) {
        state.insert(format!("{name}'"), json!(value));
    }
    let mut accelerations = Map::new();
    for (name, value) in names.iter().zip(&l.accelerations) {
        accelerations.insert(name.to_string(), json!(clean(*value)));
    }
    let eigenvalues: Vec<Value> = l
        .eigen
        .iter()
        .map(|e| json!({ "re": clean(e.value.re), "im": clean(e.value.im) }))
        .collect();
    let coordinate_names = &l.variables[..names.len().min(l.variables.len())];
    let modes: Vec<Value> = l
        .modes
        .iter()
        .map(|m| {
            let shape: Map<String, Value> = match &m.shape {
                Shape::Real(values) => coordinate_names
                    .iter()
                    .zip(values)
                    .map(|(n, v)| (n.clone(), json!(v)))
                    .collect(),
                Shape::Complex(values) => coordinate_names
                    .iter()
                    .zip(values)
                    .map(|(n, (magnitude, phase))| (n.clone(), json!([magnitude, phase])))
                    .collect(),
            };
            json!({
                "natural_frequency_hz": m.natural_frequency_hz,
                "damped_frequency_hz": m.damped_frequency_hz,
                "damping_ratio": m.damping_ratio,
                "shape": shape,
            })
        })
        .collect();
    let mut object = Map::new();
    object.insert("time".into(), json!(l.t));
    object.insert("state".into(), Value::Object(state));
    object.insert("accelerations".into(), Value::Object(accelerations));
    object.insert("variables".into(), json!(l.variables));
    object.insert("A".into(), matrix_json(&l.a));
    object.insert("eigenvalues".into(), Value::Array(eigenvalues));
    object.insert("modes".into(), Value::Array(modes));
    object.insert("stable".into(), json!(is_stable(&l.eigen, 0.0)));
    if let Some(m) = &l.matrices {
        object.insert("M".into(), matrix_json(&m.m));
        object.insert("C".into(), matrix_json(&m.c));
        object.insert("K".into(), matrix_json(&m.k));
    }
    Value::Object(object)
}

fn matrix_text(out: &mut String, title: &str, columns: &[String], m: &DMatrix<f64>) {
    out.push_str(&format!("\n{title}\n"));
    out.push_str(&format!("{:>10}", ""));
    for c in columns {
        out.push_str(&format!(" {c:>12}"));
    }
    out.push('\n');
    for (i, row) in m.row_iter().enumerate() {
        out.push_str(&format!(
            "{:>10}",
            columns.get(i).map_or("", String::as_str)
        ));
        for x in row.iter() {
            out.push_str(&format!(" {:>12}", fixed(*x)));
        }
        out.push('\n');
    }
}

fn complex_text(re: f64, im: f64) -> String {
    match (re == 0.0, im == 0.0) {
        (_, true) => fixed(re),
        (true, false) => format!("{}i", fixed(im)),
        (false, false) if im < 0.0 => format!("{} - {}i", fixed(re), fixed(-im)),
        _ => format!("{} + {}i", fixed(re), fixed(im)),
    }
}

/// The readable report for one state.
pub fn to_text(problem: &Problem, method: &str, l: &Linearization) -> String {
    let names: Vec<String> = problem.coordinates.iter().map(|c| c.name.clone()).collect();
    let mut out = format!(
        "{}\nlinearized by {method} about t = {}\n\n",
        problem.title,
        fixed(l.t)
    );
    out.push_str("coordinate        value         rate  second derivative\n");
    for (i, name) in names.iter().enumerate() {
        out.push_str(&format!(
            "{name:<10} {:>12} {:>12} {:>18}\n",
            fixed(l.q[i]),
            fixed(l.rates[i]),
            fixed(l.accelerations[i])
        ));
    }
    if l.accelerations.iter().any(|a| a.abs() > 1e-9) {
        out.push_str("(the second derivatives are not zero: this state is not steady, and the linearization holds only for an instant)\n");
    }
    if let Some(m) = &l.matrices {
        out.push_str("\nM δq'' + C δq' + K δq = 0\n");
        matrix_text(&mut out, "mass matrix M", &names, &m.m);
        matrix_text(
            &mut out,
            "damping matrix C (with gyroscopic terms)",
            &names,
            &m.c,
        );
        matrix_text(&mut out, "stiffness matrix K", &names, &m.k);
    }
    matrix_text(&mut out, "state matrix A = ∂ż/∂z", &l.variables, &l.a);
    out.push_str("\neigenvalues (1/s)\n");
    for e in &l.eigen {
        out.push_str(&format!("  {}\n", complex_text(e.value.re, e.value.im)));
    }
    let stable = is_stable(&l.eigen, 0.0);
    out.push_str(if stable {
        "no eigenvalue has a positive real part: stable to first order (marginally, where some are on the imaginary axis)\n"
    } else {
        "an eigenvalue has a positive real part: unstable\n"
    });
    if !l.modes.is_empty() {
        out.push_str(
            "\nmode  natural frequency (Hz)  damped frequency (Hz)  damping ratio  shape\n",
        );
        for (i, m) in l.modes.iter().enumerate() {
            out.push_str(&format!(
                "{:<5} {:>23} {:>22} {:>14}  {}\n",
                i + 1,
                fixed(m.natural_frequency_hz),
                fixed(m.damped_frequency_hz),
                fixed(m.damping_ratio),
                // The shape's entries are the state's coordinates, which with constraints
                // are the independent ones (`x`, `θ`), not the first of every coordinate.
                shape_text(&l.variables, &m.shape)
            ));
        }
    }
    out
}

/// A mode shape as `q1 1, q2 -0.5` or, when complex, `q1 1∠0, q2 0.5∠1.2`.
pub fn shape_text(names: &[String], shape: &Shape) -> String {
    match shape {
        Shape::Real(values) => names
            .iter()
            .zip(values)
            .map(|(n, v)| format!("{n} {}", fixed(*v)))
            .collect::<Vec<_>>()
            .join(", "),
        Shape::Complex(values) => names
            .iter()
            .zip(values)
            .map(|(n, (m, p))| format!("{n} {}∠{}", fixed(*m), fixed(*p)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

pub(super) fn sweep_text(
    problem: &Problem,
    method: &str,
    sweep: &Sweep,
    results: &[Linearization],
) -> String {
    let mut out = format!(
        "{}\nlinearized by {method}, {} from {} to {} in {} values\n\n",
        problem.title,
        sweep.name,
        fixed(sweep.values[0]),
        fixed(sweep.values[sweep.values.len() - 1]),
        sweep.values.len()
    );
    out.push_str(&format!(
        "{:>12} {:>14} {:>9}  natural frequencies (Hz)\n",
        sweep.name, "largest Re λ", "stable"
    ));
    for (value, l) in sweep.values.iter().zip(results) {
        let largest = l
            .eigen
            .iter()
            .map(|e| e.value.re)
            .fold(f64::NEG_INFINITY, f64::max);
        let frequencies: Vec<String> = l
            .modes
            .iter()
            .map(|m| fixed(m.natural_frequency_hz))
            .collect();
        out.push_str(&format!(
            "{:>12} {:>14} {:>9}  {}\n",
            fixed(*value),
            fixed(largest),
            if is_stable(&l.eigen, 0.0) {
                "yes"
            } else {
                "no"
            },
            frequencies.join(", ")
        ));
    }
    out.push('\n');
    out.push_str(&stable_ranges(&sweep.name, &sweep.values, results));
    out
}

/// The ranges of the swept values where every eigenvalue has Re λ ≤ 0 (up to round-off,
/// [`ROUND_OFF`](crate::numeric::ROUND_OFF) times the largest |λ|), as sentences.
pub fn stable_ranges(name: &str, values: &[f64], results: &[Linearization]) -> String {
    let stable: Vec<bool> = results.iter().map(|l| is_stable(&l.eigen, 0.0)).collect();
    let mut ranges = Vec::new();
    let mut start = None;
    for (i, &s) in stable.iter().enumerate() {
        match (s, start) {
            (true, None) => start = Some(i),
            (false, Some(first)) => {
                ranges.push((first, i - 1));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(first) = start {
        ranges.push((first, stable.len() - 1));
    }
    if ranges.is_empty() {
        return format!("unstable at every value of {name} tried\n");
    }
    let mut out = String::new();
    for (a, b) in ranges {
        out.push_str(&format!(
            "stable (every Re λ ≤ 0) for {name} from {} to {} (the values tried)\n",
            fixed(values[a]),
            fixed(values[b])
        ));
    }
    out
}
