//! `mbd-tutor solve`: the q'' and the requested reactions at one state.

use crate::cli::{parse_assignments, SolveArgs, SolveFormat};
use crate::numeric::StateSolution;
use crate::numeric::System;
use crate::symbolic::fixed;
use crate::Error;
use serde_json::{json, Map, Value};

/// A problem's state at the start, with `--state` overrides applied.
///
/// # Errors
/// A usage error for a name that is not a coordinate or a rate.
pub fn initial_state(
    problem: &crate::problem::Problem,
    assignments: &[String],
) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let initial = problem.initial_state();
    let (mut q, mut rates) = (initial.q, initial.rates);
    for (name, value) in parse_assignments(assignments)? {
        let (base, is_rate) = match name.strip_suffix('\'') {
            Some(base) => (base, true),
            None => (name.as_str(), false),
        };
        let Some(index) = problem.coordinates.iter().position(|c| c.name == base) else {
            let names: Vec<&str> = problem
                .coordinates
                .iter()
                .map(|c| c.name.as_str())
                .collect();
            let hint = crate::symbolic::closest(base, names.iter().copied())
                .map(|c| format!(" (did you mean `{c}`?)"))
                .unwrap_or_else(|| format!(" (the coordinates are {})", names.join(", ")));
            return Err(Error::Usage(format!(
                "--state: `{name}` is not a coordinate or a rate{hint}"
            )));
        };
        if is_rate {
            rates[index] = value;
        } else {
            q[index] = value;
        }
    }
    Ok((q, rates))
}

/// Runs `mbd-tutor solve`.
///
/// # Errors
/// An invalid problem, an unknown name in `--set` or `--state`, or a singular system.
pub fn run(args: SolveArgs) -> Result<(), Error> {
    args.at.given.check_time()?;
    let problem = super::load_with_overrides(&args.at.common)?;
    let (mut q, mut rates) = initial_state(&problem, &args.at.given.state)?;
    let method = super::method(args.at.common.method);
    let derivation = crate::pipeline::derive(&problem, method, crate::pipeline::Purpose::Numbers)?;
    super::report_constraints(&derivation.model, &args.at.given.state);
    let solver = crate::pipeline::Solver::fastest(&problem, &derivation);
    solver.assemble(args.at.given.time, &mut q, &mut rates)?;
    let solution = solver.solve(args.at.given.time, &q, &rates)?;
    let coordinates = solver.coordinate_names();
    let text = match args.at.format {
        SolveFormat::Json => {
            let value = to_json(
                method.name(),
                args.at.given.time,
                &coordinates,
                &q,
                &rates,
                &solution,
            );
            let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
            text.push('\n');
            text
        }
        SolveFormat::Text => to_text(
            &problem,
            method.title(),
            args.at.given.time,
            &coordinates,
            &q,
            &rates,
            &solution,
        ),
    };
    crate::output::write_output(args.at.common.output.as_deref(), text.as_bytes())
}

/// The JSON object of the command-line contract.
pub fn to_json(
    method: &str,
    time: f64,
    names: &[String],
    q: &[f64],
    rates: &[f64],
    solution: &StateSolution,
) -> Value {
    // -0.0 is a valid JSON number, but reads as a sign error to a student.
    let clean = |x: f64| if x == 0.0 { 0.0 } else { x };
    let clean3 = |v: &[f64; 3]| v.map(clean);
    let mut state = Map::new();
    for (name, value) in names.iter().zip(q) {
        state.insert(name.clone(), json!(value));
    }
    for (name, value) in names.iter().zip(rates) {
        state.insert(format!("{name}'"), json!(value));
    }
    let mut accelerations = Map::new();
    for (name, value) in names.iter().zip(&solution.accelerations) {
        accelerations.insert(name.clone(), json!(clean(*value)));
    }
    let mut reactions = Map::new();
    for (joint, force, moment) in &solution.reactions {
        reactions.insert(
            joint.clone(),
            json!({ "force": clean3(force), "moment": clean3(moment) }),
        );
    }
    let mut value = json!({
        "method": method,
        "time": time,
        "state": state,
        "accelerations": accelerations,
        "reactions": reactions,
    });
    if !solution.drives.is_empty() {
        let drives: Map<String, Value> = solution
            .drives
            .iter()
            .map(|(name, v)| (name.clone(), json!(clean(*v))))
            .collect();
        value["drives"] = Value::Object(drives);
    }
    if !solution.speeds.is_empty() {
        // Declared speeds: u and u' beside the contract's q''.
        let (speeds, derivatives): (Map<String, Value>, Map<String, Value>) = solution
            .speeds
            .iter()
            .map(|(name, u, du)| {
                (
                    (name.clone(), json!(clean(*u))),
                    (name.clone(), json!(clean(*du))),
                )
            })
            .unzip();
        value["speeds"] = Value::Object(speeds);
        value["speed_derivatives"] = Value::Object(derivatives);
    }
    if !solution.friction.is_empty() {
        // Per site: the normal force's component along the normal, the friction force's
        // magnitude, and their ratio, which never exceeds μ.
        let friction: Map<String, Value> = solution
            .friction
            .iter()
            .map(|site| {
                let entry = json!({
                    "mode": site.mode.name(),
                    "normal": clean(site.normal),
                    "tangential": clean(site.friction()),
                    "ratio": clean(site.ratio()),
                });
                (site.name.clone(), entry)
            })
            .collect();
        value["friction"] = Value::Object(friction);
    }
    value
}

fn to_text(
    problem: &crate::problem::Problem,
    method: &str,
    time: f64,
    names: &[String],
    q: &[f64],
    rates: &[f64],
    s: &StateSolution,
) -> String {
    let mut out = format!("{}\nby {method}, at t = {}\n\n", problem.title, fixed(time));
    out.push_str("coordinate        value         rate  second derivative\n");
    for (i, name) in names.iter().enumerate() {
        out.push_str(&format!(
            "{name:<10} {:>12} {:>12} {:>18}\n",
            fixed(q[i]),
            fixed(rates[i]),
            fixed(s.accelerations[i])
        ));
    }
    if !s.reactions.is_empty() {
        out.push_str("\nreaction (parent on child; moment about the joint point)\n");
        for (joint, f, m) in &s.reactions {
            let v = |x: &[f64; 3]| format!("[{}, {}, {}]", fixed(x[0]), fixed(x[1]), fixed(x[2]));
            let frame = crate::numeric::reaction_frame_named(problem, joint);
            out.push_str(&format!(
                "{joint}: force {}  moment {}  ({frame}'s unit vectors)\n",
                v(f),
                v(m)
            ));
        }
    }
    if !s.drives.is_empty() {
        out.push_str("\ndrive (generalized force along or about the prescribed coordinate)\n");
        for (name, value) in &s.drives {
            out.push_str(&format!("{name}: {}\n", fixed(*value)));
        }
    }
    if !s.friction.is_empty() {
        out.push_str("\nfriction (mode, normal force N, friction force |F|, |F|/|N|)\n");
        for site in &s.friction {
            out.push_str(&format!(
                "{}: {}  N = {}  |F| = {}  |F|/|N| = {} (mu = {})\n",
                site.name,
                site.mode.name(),
                fixed(site.normal),
                fixed(site.friction()),
                fixed(site.ratio()),
                fixed(site.coefficient)
            ));
        }
    }
    out
}
