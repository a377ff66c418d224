//! `mbd-tutor linearize`: small motions about a state, their eigenvalues and modes;
//! with `--sweep`, over a range of one constant.

mod report;

use super::solve::initial_state;
use crate::cli::{LinearizeArgs, SolveFormat as Format};
use crate::pipeline::{derive, Linearizer, Purpose, Sweep, Swept};
use crate::problem::Problem;
use crate::Error;
use report::{pretty, sweep_text, to_json, to_text};
use serde_json::{json, Map, Value};
use std::path::Path;

/// The most values a sweep may take.
pub const MAX_SWEEP: usize = 100_000;

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
    let linearizer = Linearizer::new(&derive(&problem, method, Purpose::Numbers)?);
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
    let state_of = |p: &Problem| initial_state(p, &args.at.given.state);
    let Swept { results, edges } =
        crate::pipeline::sweep(&problem, &linearizer, &sweep, args.at.given.time, &state_of)?;
    if let Some(path) = plot_path {
        let svg = crate::solution::sweep_plot(&problem.title, &sweep.name, &sweep.values, &results)
            .map_err(|e| Error::Usage(e.to_string()))?;
        crate::output::write_output(Some(path), svg.as_bytes())?;
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
                    crate::numeric::full_precision(*value),
                ));
            }
            text
        }
    };
    crate::output::write_output(report_output, text.as_bytes())
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
