//! `mbd-tutor impact`: the rates just after the problem's impact, the impulses of the
//! collision and of the requested reactions, and the kinetic energy before and after.

use crate::cli::{ImpactArgs, SolveFormat};
use crate::numeric::System;
use crate::pipeline::ImpactSolution;
use crate::symbolic::fixed;
use crate::Error;
use serde_json::{json, Map, Value};

/// Runs `mbd-tutor impact`.
///
/// # Errors
/// An invalid problem, one without `impact`, a collision whose point is not approaching
/// its surface, or equations that cannot be solved.
pub fn run(args: ImpactArgs) -> Result<(), Error> {
    let problem = super::load_with_overrides(&args.common)?;
    let method = super::method(args.common.method);
    let derivation = crate::pipeline::derive(&problem, method, crate::pipeline::Purpose::Numbers)?;
    super::report_constraints(&derivation.model, &[]);
    let solver = crate::pipeline::Solver::fastest(&problem, &derivation);
    let solution = crate::pipeline::impact_at_start(&problem, &derivation.model, &solver)?;
    let names = solver.coordinate_names();
    let text = match args.format {
        SolveFormat::Json => {
            let mut text =
                serde_json::to_string_pretty(&to_json(&names, &solution)).unwrap_or_default();
            text.push('\n');
            text
        }
        SolveFormat::Text => to_text(&problem.title, &names, &solution),
    };
    crate::output::write_output(args.common.output.as_deref(), text.as_bytes())
}

// -0.0 is a valid JSON number, but reads as a sign error to a student.
fn clean(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

fn rates(names: &[String], values: &[f64]) -> Map<String, Value> {
    names
        .iter()
        .zip(values)
        .map(|(n, v)| (format!("{n}'"), json!(clean(*v))))
        .collect()
}

/// The JSON object of the command-line contract: `method`, `before`, `after`, `impulses`
/// (the collision's in its surface body's unit vectors, each requested reaction's as
/// `force` and `moment`), `energy`; a `collision` entry says whether it stuck or slid,
/// and `drives` gives the impulses of the prescribed coordinates' drives.
pub fn to_json(names: &[String], s: &ImpactSolution) -> Value {
    let mut impulses = Map::new();
    if let Some((name, p)) = &s.collision {
        impulses.insert(name.clone(), json!(p.components.map(clean)));
    }
    for (site, force, moment) in &s.reactions {
        impulses.insert(
            site.clone(),
            json!({ "force": force.map(clean), "moment": moment.map(clean) }),
        );
    }
    let mut value = json!({
        "method": s.method.name(),
        "before": rates(names, &s.before),
        "after": rates(names, &s.after),
        "impulses": impulses,
        "energy": { "before": s.energy[0], "after": s.energy[1] },
    });
    if let Some((name, p)) = &s.collision {
        value["collision"] = json!({
            "name": name,
            "mode": p.mode.name(),
            "normal": clean(p.normal),
            "tangential": clean(p.tangential),
        });
    }
    if !s.drives.is_empty() {
        let drives: Map<String, Value> = s
            .drives
            .iter()
            .map(|(n, v)| (n.clone(), json!(clean(*v))))
            .collect();
        value["drives"] = Value::Object(drives);
    }
    value
}

fn to_text(title: &str, names: &[String], s: &ImpactSolution) -> String {
    let mut out = format!("{title}\nthe impact, by {}\n\n", s.method.title());
    out.push_str("coordinate        value  rate before   rate after\n");
    for (i, name) in names.iter().enumerate() {
        out.push_str(&format!(
            "{name:<10} {:>12} {:>12} {:>12}\n",
            fixed(s.q[i]),
            fixed(s.before[i]),
            fixed(s.after[i])
        ));
    }
    let v = |x: &[f64; 3]| format!("[{}, {}, {}]", fixed(x[0]), fixed(x[1]), fixed(x[2]));
    if let Some((name, p)) = &s.collision {
        out.push_str(&format!(
            "\ncollision {name} ({}): impulse {} (surface's unit vectors), normal {}, tangential {}\n",
            p.mode.name(),
            v(&p.components),
            fixed(p.normal),
            fixed(p.tangential)
        ));
    }
    if !s.reactions.is_empty() {
        out.push_str("\nimpulsive reaction (parent on child, parent's unit vectors; moment about the joint point)\n");
        for (site, f, m) in &s.reactions {
            out.push_str(&format!("{site}: force {}  moment {}\n", v(f), v(m)));
        }
    }
    for (name, value) in &s.drives {
        out.push_str(&format!("drive of {name}: impulse {}\n", fixed(*value)));
    }
    out.push_str(&format!(
        "\nkinetic energy: before {}, after {}\n",
        fixed(s.energy[0]),
        fixed(s.energy[1])
    ));
    out
}
