//! `mbd-tutor statics`: the equilibria of the free coordinates with every rate zero, the
//! reactions there, the holding forces of held coordinates, the stability and each friction
//! site's |F|/(μ|N|).

use crate::cli::{parse_assignments, SolveFormat, StaticsArgs};
use crate::numeric::SiteState;
use crate::pipeline::{Equilibrium, Statics};
use crate::problem::Problem;
use crate::symbolic::fixed;
use crate::Error;
use serde_json::{json, Map, Value};

/// Runs `mbd-tutor statics`.
///
/// # Errors
/// An invalid problem or `--near`, equations that cannot be derived, or no equilibrium
/// near a guess.
pub fn run(args: StaticsArgs) -> Result<(), Error> {
    // At rest the speeds are zero with the rates: the equations in the rates serve.
    let problem = super::load_with_overrides(&args.common)?.without_speeds();
    let method = super::method(args.common.method);
    let guesses = guesses(&problem, &args.near)?;
    let statics = Statics::new(&problem, method)?;
    let equilibria = guesses
        .iter()
        .map(|(q, from)| statics.equilibrium(q, from))
        .collect::<Result<Vec<_>, _>>()?;
    let text = match args.format {
        SolveFormat::Json => {
            let mut text =
                serde_json::to_string_pretty(&to_json(&problem, method.name(), &equilibria))
                    .unwrap_or_default();
            text.push('\n');
            text
        }
        SolveFormat::Text => to_text(&problem, method.title(), &guesses, &equilibria),
    };
    crate::output::write_output(args.common.output.as_deref(), text.as_bytes())
}

/// The starting configurations: the initial one, or one per `--near`, each with the words
/// that say where it came from.
///
/// # Errors
/// A usage error for a name that is not a free or dependent coordinate.
pub fn guesses(problem: &Problem, near: &[String]) -> Result<Vec<(Vec<f64>, String)>, Error> {
    let initial: Vec<f64> = problem.initial_coordinates();
    if near.is_empty() {
        return Ok(vec![(initial, "the initial configuration".into())]);
    }
    near.iter()
        .map(|item| {
            let mut q = initial.clone();
            for (name, value) in parse_assignments(std::slice::from_ref(item))? {
                let Some(i) = problem.coordinates.iter().position(|c| c.name == name) else {
                    return Err(Error::Usage(format!(
                        "--near: `{name}` is not a coordinate (the coordinates are {})",
                        names(problem)
                    )));
                };
                if problem.coordinates[i].motion.is_some() {
                    return Err(Error::Usage(format!(
                        "--near: `{name}` is held or prescribed, so there is nothing to guess"
                    )));
                }
                q[i] = value;
            }
            Ok((q, format!("--near {item}")))
        })
        .collect()
}

fn names(problem: &Problem) -> String {
    let names: Vec<&str> = problem
        .coordinates
        .iter()
        .map(|c| c.name.as_str())
        .collect();
    names.join(", ")
}

/// −0 written as 0: a valid number, but read as a sign error by a student.
fn clean(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

/// |F| / (μ|N|): `None` where μ|N| is zero and friction is needed.
pub fn ratio(site: &SiteState) -> Option<f64> {
    site.friction_ratio()
}

/// The JSON object of the command-line contract.
pub fn to_json(problem: &Problem, method: &str, equilibria: &[Equilibrium]) -> Value {
    let list: Vec<Value> = equilibria
        .iter()
        .map(|e| equilibrium_json(problem, e))
        .collect();
    json!({ "method": method, "equilibria": list })
}

fn equilibrium_json(problem: &Problem, e: &Equilibrium) -> Value {
    let state: Map<String, Value> = problem
        .coordinates
        .iter()
        .zip(&e.q)
        .map(|(c, x)| (c.name.clone(), json!(clean(*x))))
        .collect();
    let reactions: Map<String, Value> = e
        .motion
        .reactions
        .iter()
        .map(|(site, f, m)| {
            let entry = json!({ "force": f.map(clean), "moment": m.map(clean) });
            (site.clone(), entry)
        })
        .collect();
    let held: Map<String, Value> = e
        .motion
        .drives
        .iter()
        .map(|(name, x)| (name.clone(), json!(clean(*x))))
        .collect();
    let mut value = json!({ "state": state, "reactions": reactions, "held": held });
    if let Some(stability) = &e.stability {
        value["stability"] = json!(stability.kind.name());
        let eigenvalues: Vec<[f64; 2]> = stability
            .eigenvalues
            .iter()
            .map(|&(re, im)| [re, im])
            .collect();
        value["eigenvalues"] = json!(eigenvalues);
    }
    let friction: Map<String, Value> = e
        .motion
        .friction
        .iter()
        .map(|site| {
            let entry = json!({
                "normal": clean(site.normal),
                "tangential": clean(site.friction()),
                "ratio": ratio(site).map(clean),
            });
            (site.name.clone(), entry)
        })
        .collect();
    if !friction.is_empty() {
        value["friction"] = Value::Object(friction);
    }
    value
}

/// The readable report: one block per equilibrium.
pub fn to_text(
    problem: &Problem,
    method: &str,
    guesses: &[(Vec<f64>, String)],
    equilibria: &[Equilibrium],
) -> String {
    let mut out = format!("{}\nstatics by {method}\n", problem.title);
    for (k, (e, (_, from))) in equilibria.iter().zip(guesses).enumerate() {
        out.push_str(&format!("\nequilibrium {} (from {from})\n", k + 1));
        out.push_str(&equilibrium_text(problem, e));
    }
    out
}

fn equilibrium_text(problem: &Problem, e: &Equilibrium) -> String {
    let mut out = String::from("coordinate        value\n");
    for (c, x) in problem.coordinates.iter().zip(&e.q) {
        let how = match (c.held, c.motion.is_some()) {
            (true, _) => "  (held)",
            (false, true) => "  (prescribed)",
            _ => "",
        };
        out.push_str(&format!("{:<10} {:>12}{how}\n", c.name, fixed(clean(*x))));
    }
    let v = |x: &[f64; 3]| {
        format!(
            "[{}, {}, {}]",
            fixed(clean(x[0])),
            fixed(clean(x[1])),
            fixed(clean(x[2]))
        )
    };
    if !e.motion.reactions.is_empty() {
        out.push_str(
            "\nreaction (parent on child, parent's unit vectors; moment about the joint point)\n",
        );
        for (site, f, m) in &e.motion.reactions {
            out.push_str(&format!("{site}: force {}  moment {}\n", v(f), v(m)));
        }
    }
    if !e.motion.drives.is_empty() {
        out.push_str("\nholding force (generalized force along or about the held coordinate)\n");
        for (name, x) in &e.motion.drives {
            out.push_str(&format!("{name}: {}\n", fixed(clean(*x))));
        }
    }
    if !e.motion.friction.is_empty() {
        out.push_str(
            "\nfriction (normal force N, friction force |F| that rest needs, |F|/(mu |N|))\n",
        );
        for site in &e.motion.friction {
            let (ratio, verdict) = match ratio(site) {
                Some(r) if r <= 1.0 => (fixed(r), "friction can hold it"),
                Some(r) => (fixed(r), "friction cannot hold it: it slips"),
                None => ("infinite".into(), "friction cannot hold it: it slips"),
            };
            out.push_str(&format!(
                "{}: N = {}  |F| = {}  |F|/(mu |N|) = {ratio} (mu = {}): {verdict}\n",
                site.name,
                fixed(clean(site.normal)),
                fixed(site.friction()),
                fixed(site.coefficient)
            ));
        }
    }
    match &e.stability {
        Some(s) => {
            let list: Vec<String> = s
                .eigenvalues
                .iter()
                .map(|&(re, im)| match im {
                    0.0 => fixed(re),
                    _ if re == 0.0 => format!("{}i", fixed(im)),
                    _ => format!("{} {} {}i", fixed(re), if im < 0.0 { "-" } else { "+" }, fixed(im.abs())),
                })
                .collect();
            out.push_str(&format!(
                "\nstability: {} (eigenvalues {})\n",
                s.kind.name(),
                list.join(", ")
            ));
        }
        None => out.push_str("\nno coordinate is free (each is held, prescribed or fixed by the constraints): only the reactions to find\n"),
    }
    out
}
