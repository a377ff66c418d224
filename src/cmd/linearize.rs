//! `mbd-tutor linearize`: small motions about a state, their eigenvalues and modes;
//! with `--sweep`, over a range of one constant.

use super::solve::initial_state;
use crate::cli::{LinearizeArgs, SolveFormat as Format};
use crate::numeric::format::fixed;
use crate::numeric::linearize::modes::{self, Shape};
use crate::numeric::linearize::Linearization;
use crate::pipeline::{derive, Linearizer};
use crate::problem::Problem;
use crate::Error;
use nalgebra::DMatrix;
use serde_json::{json, Map, Value};
use std::path::Path;

/// The most values a sweep may take.
pub const MAX_SWEEP: usize = 100_000;

/// `--sweep NAME=FROM:TO:COUNT`, parsed.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// The constant.
    pub name: String,
    /// Its values, first `FROM`, last `TO`.
    pub values: Vec<f64>,
}

/// Parses `NAME=FROM:TO:COUNT`.
///
/// # Errors
/// A usage error naming what is malformed.
pub fn parse_sweep(text: &str) -> Result<Sweep, Error> {
    let usage = |what: String| {
        Error::Usage(format!(
            "--sweep `{text}`: {what} (write NAME=FROM:TO:COUNT, e.g. w=0:20:41)"
        ))
    };
    let Some((name, range)) = text.split_once('=') else {
        return Err(usage("no `=`".into()));
    };
    let parts: Vec<&str> = range.split(':').map(str::trim).collect();
    let [from, to, count] = parts[..] else {
        return Err(usage("expected FROM:TO:COUNT".into()));
    };
    let number = |s: &str| {
        s.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| usage(format!("`{s}` is not a finite number")))
    };
    let (from, to) = (number(from)?, number(to)?);
    let count: usize = count
        .parse()
        .ok()
        .filter(|c| (1..=MAX_SWEEP).contains(c))
        .ok_or_else(|| {
            usage(format!(
                "COUNT `{count}` must be a whole number from 1 to {MAX_SWEEP}"
            ))
        })?;
    let values = (0..count)
        .map(|i| match i {
            0 => from,
            _ if i + 1 == count => to,
            _ => from + (to - from) * i as f64 / (count - 1) as f64,
        })
        .collect();
    Ok(Sweep {
        name: name.trim().to_string(),
        values,
    })
}

/// Runs `mbd-tutor linearize`.
///
/// # Errors
/// An invalid problem or command line, a singular system, or eigenvalues that do not
/// converge.
pub fn run(args: LinearizeArgs) -> Result<(), Error> {
    args.at.given.check_time()?;
    let sweep = args.sweep.as_deref().map(parse_sweep).transpose()?;
    let svg_output = args.at.common.output.as_deref().filter(|p| is_svg(p));
    let plot_path = args.plot.as_deref().or(svg_output);
    if plot_path.is_some() && sweep.is_none() {
        return Err(Error::Usage(
            "a plot needs --sweep NAME=FROM:TO:COUNT: it shows the eigenvalues against the constant".into(),
        ));
    }
    if let Some(plot) = &args.plot {
        super::refuse_overwriting(&args.at.common.problem, Some(plot))?;
    }
    // Small motions are about the coordinates and their rates, whatever the speeds.
    let problem = super::load_with_overrides(&args.at.common)?.without_speeds();
    let method = super::method(args.at.common.method);
    let linearizer = Linearizer::new(&derive(&problem, method)?);
    let report_output = if svg_output.is_some() && args.plot.is_none() {
        None
    } else {
        args.at.common.output.as_deref()
    };
    let Some(sweep) = sweep else {
        let (q, rates) = initial_state(&problem, &args.at.given.state)?;
        let l = linearizer.at(&problem, args.at.given.time, &q, &rates)?;
        let text = match args.at.format {
            Format::Json => pretty(&to_json(&problem, &l)),
            Format::Text => to_text(&problem, method.title(), &l),
        };
        return crate::output::write_output(report_output, text.as_bytes());
    };
    let mut results = Vec::with_capacity(sweep.values.len());
    for &value in &sweep.values {
        let mut swept = problem.clone();
        crate::problem::apply_overrides(&mut swept, &[(sweep.name.clone(), value)])?;
        let (q, rates) = initial_state(&swept, &args.at.given.state)?;
        results.push(linearizer.at(&swept, args.at.given.time, &q, &rates)?);
    }
    if let Some(path) = plot_path {
        let svg = crate::solution::eigen_plot::sweep_plot(
            &problem.title,
            &sweep.name,
            &sweep.values,
            &results,
        )
        .map_err(|e| Error::Usage(e.to_string()))?;
        crate::output::write_output(Some(path), svg.as_bytes())?;
    }
    let stable: Vec<bool> = results
        .iter()
        .map(|l| modes::is_stable(&l.eigen, 0.0))
        .collect();
    let mut edges = Vec::new();
    for i in 1..results.len() {
        if stable[i] != stable[i - 1] {
            let at = |value: f64| -> Result<Linearization, Error> {
                let mut swept = problem.clone();
                crate::problem::apply_overrides(&mut swept, &[(sweep.name.clone(), value)])?;
                let (q, rates) = initial_state(&swept, &args.at.given.state)?;
                linearizer.at(&swept, args.at.given.time, &q, &rates)
            };
            let (a, b) = (sweep.values[i - 1], sweep.values[i]);
            edges.push((boundary(&at, a, b)?, stable[i]));
        }
    }
    let text = match args.at.format {
        Format::Json => {
            let items: Vec<Value> = sweep
                .values
                .iter()
                .zip(&results)
                .map(|(value, l)| {
                    let mut object = Map::new();
                    object.insert("sweep".into(), json!({ sweep.name.clone(): value }));
                    if let Value::Object(rest) = to_json(&problem, l) {
                        object.extend(rest);
                    }
                    Value::Object(object)
                })
                .collect();
            pretty(&Value::Array(items))
        }
        Format::Text => {
            let mut text = sweep_text(&problem, method.title(), &sweep, &results);
            for (value, becomes_stable) in &edges {
                text.push_str(&format!(
                    "{} {} = {} (bisection: where the largest real part of an eigenvalue crosses zero)\n",
                    if *becomes_stable {
                        "stable from"
                    } else {
                        "unstable from"
                    },
                    sweep.name,
                    crate::numeric::simulate::full_precision(*value),
                ));
            }
            text
        }
    };
    crate::output::write_output(report_output, text.as_bytes())
}

fn pretty(value: &Value) -> String {
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
    object.insert("stable".into(), json!(modes::is_stable(&l.eigen, 0.0)));
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
    let stable = modes::is_stable(&l.eigen, 0.0);
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
                shape_text(&names, &m.shape)
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

fn sweep_text(problem: &Problem, method: &str, sweep: &Sweep, results: &[Linearization]) -> String {
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
            if modes::is_stable(&l.eigen, 0.0) {
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
/// [`modes::ROUND_OFF`] times the largest |λ|), as sentences.
pub fn stable_ranges(name: &str, values: &[f64], results: &[Linearization]) -> String {
    let stable: Vec<bool> = results
        .iter()
        .map(|l| modes::is_stable(&l.eigen, 0.0))
        .collect();
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

/// Where stability changes between `a` and `b` (whose stability differs), by bisection on
/// the largest real part of the eigenvalues that are not structural zeros (those of
/// ignorable coordinates, counted where the bracket's ends agree).
fn boundary(
    at: &dyn Fn(f64) -> Result<Linearization, Error>,
    a: f64,
    b: f64,
) -> Result<f64, Error> {
    let raw = |value: f64| -> Result<Vec<nalgebra::Complex<f64>>, Error> {
        let l = at(value)?;
        let a = without_ignorable(&l.a);
        let mut values = crate::numeric::linearize::hqr::eigenvalues(&a).unwrap_or_default();
        values.sort_by(|x, y| x.norm().total_cmp(&y.norm()));
        Ok(values)
    };
    let zeros = |values: &[nalgebra::Complex<f64>]| -> usize {
        let scale = values.iter().map(|v| v.norm()).fold(0.0, f64::max);
        values
            .iter()
            .filter(|v| v.norm() <= modes::ROUND_OFF * scale)
            .count()
    };
    let (low, high) = (raw(a)?, raw(b)?);
    let structural = zeros(&low).min(zeros(&high));
    let largest = |values: &[nalgebra::Complex<f64>]| -> f64 {
        values
            .iter()
            .skip(structural)
            .map(|v| v.re)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (mut a, mut b) = (a, b);
    let sign_a = largest(&low) > 0.0;
    for _ in 0..60 {
        let middle = 0.5 * (a + b);
        if (b - a).abs() <= 1e-13 * middle.abs().max(1.0) {
            break;
        }
        if (largest(&raw(middle)?) > 0.0) == sign_a {
            a = middle;
        } else {
            b = middle;
        }
    }
    Ok(0.5 * (a + b))
}

/// `a` without the rows and columns of the states nothing depends on (zero columns, such
/// as a bicycle's position and heading), repeated until none is left. Expanding the
/// determinant along such a column, each removal takes away one eigenvalue 0 and keeps the
/// others exactly; left in, these zeros form Jordan blocks whose round-off of 1e-16 moves
/// them by 1e-8, enough to blur a slow mode's crossing of zero.
fn without_ignorable(a: &nalgebra::DMatrix<f64>) -> nalgebra::DMatrix<f64> {
    let mut a = a.clone();
    let scale = a.amax();
    while let Some(i) =
        (0..a.ncols()).find(|&i| a.column(i).iter().all(|x| x.abs() <= 1e-14 * scale))
    {
        if a.ncols() == 1 {
            break;
        }
        a = a.remove_row(i).remove_column(i);
    }
    a
}

/// Whether a path names an SVG file.
pub fn is_svg(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ignorable_states_go_and_the_slow_mode_stays_exact() {
        // x' = ψ (a heading that moves the position), ψ' = 0, and a slow mode s' = 1e-9 s:
        // x's column is zero, then ψ's; what is left is the slow mode alone, exactly.
        let a = nalgebra::DMatrix::from_row_slice(
            3,
            3,
            &[0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1e-9],
        );
        let reduced = without_ignorable(&a);
        assert_eq!(reduced, nalgebra::DMatrix::from_element(1, 1, 1e-9));
        // Nothing to take away from a matrix without a zero column.
        let full = nalgebra::DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -1.0, 0.0]);
        assert_eq!(without_ignorable(&full), full);
    }

    #[test]
    fn sweeps_include_both_ends() {
        let s = parse_sweep("w=0:1:5").unwrap();
        assert_eq!(s.name, "w");
        assert_eq!(s.values, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(parse_sweep("w=2:3:1").unwrap().values, vec![2.0]);
        for bad in ["w", "w=0:1", "w=0:1:0", "w=a:1:2", "w=0:1:2.5", "w=0:inf:3"] {
            assert!(parse_sweep(bad).is_err(), "{bad}");
        }
    }
}
