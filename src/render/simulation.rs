//! Step 6 of the worked solution: the simulation, its confirmation checks and its plots.

use super::context::{Check, Plot, Solution};
use crate::numeric::checks;
use crate::numeric::format::fixed;
use crate::numeric::simulate::Trajectory;
use crate::numeric::SolveError;
use crate::problem::{CoordinateKind, Problem};

/// Fills step 6 of `solution` from the simulation from the (assembled) initial state and its
/// confirmation checks; a run that could not start or stopped early is said in the step's
/// note.
pub fn simulation(
    solution: &mut Solution,
    problem: &Problem,
    simulated: &Result<(Trajectory, Vec<checks::Check>), SolveError>,
) {
    let (trajectory, checks) = match simulated {
        Ok(run) => run,
        Err(e) => {
            solution.simulation.note = format!("The simulation could not run: {e}");
            return;
        }
    };
    if let Some(reason) = &trajectory.stopped {
        solution.simulation.note = format!("The simulation stopped early: {reason}");
    }
    solution.simulation.checks = checks
        .iter()
        .map(|c| Check {
            name: c.name.clone(),
            value: fixed(c.value),
            tolerance: fixed(c.tolerance),
            passed: c.passed,
        })
        .collect();
    // One quantity per axis: angles and distances on plots of their own.
    let series_of = |kind: CoordinateKind| -> Vec<(String, Vec<(f64, f64)>)> {
        problem
            .coordinates
            .iter()
            .filter(|c| c.kind == kind)
            .filter_map(|c| trajectory.series(&c.name).map(|s| (c.name.clone(), s)))
            .collect()
    };
    let energy_series: Vec<(String, Vec<(f64, f64)>)> = ["kinetic", "potential", "total"]
        .iter()
        .filter_map(|n| trajectory.series(n).map(|s| (n.to_string(), s)))
        .collect();
    let mut plots = vec![
        (
            "coordinates",
            "Angles against time",
            "angle (rad)",
            series_of(CoordinateKind::Angle),
        ),
        (
            "positions",
            "Positions against time",
            "position (m)",
            series_of(CoordinateKind::Distance),
        ),
    ];
    if plots[0].3.is_empty() {
        // A system without angles: its positions are the coordinates' plot.
        let positions = plots.remove(1);
        plots[0] = ("coordinates", positions.1, positions.2, positions.3);
    }
    plots.push(("energy", "Energy against time", "energy (J)", energy_series));
    if let Some(drift) = energy_drift(trajectory) {
        plots.push(drift);
    }
    for (kind, title, y_label, series) in plots {
        if series.is_empty() {
            continue;
        }
        // The picture prints θ₁ and E₀; pgfplots in a LaTeX document takes only ASCII here.
        let pictured: Series = series
            .iter()
            .map(|(name, points)| (legend(name), points.clone()))
            .collect();
        let svg = crate::render::plot::line_plot(title, "t (s)", &legend_label(y_label), &pictured)
            .unwrap_or_default();
        solution.simulation.plots.push(Plot {
            kind: kind.into(),
            title: title.into(),
            svg_file: String::new(),
            image_svg: svg,
            pgfplots_latex: crate::render::plot::pgfplots(title, "t (s)", y_label, &series),
        });
    }
}

type Series = Vec<(String, Vec<(f64, f64)>)>;

/// The total energy's change, (E − E₀)/|E₀| (or E − E₀ in joules when E₀ is 0), on an axis
/// of its own, since beside the energies it is invisible: the integration's drift when no
/// load does work, which is what the energy check measures.
fn energy_drift(
    trajectory: &Trajectory,
) -> Option<(&'static str, &'static str, &'static str, Series)> {
    let total = trajectory.series("total")?;
    let e0 = total.first()?.1;
    let relative = e0.abs() > 1e-12;
    let drift: Vec<(f64, f64)> = total
        .iter()
        .map(|&(t, e)| {
            (
                t,
                if relative {
                    (e - e0) / e0.abs()
                } else {
                    e - e0
                },
            )
        })
        .collect();
    let (label, name) = if relative {
        ("(E - E0)/|E0|", "relative change")
    } else {
        ("E - E0 (J)", "change")
    };
    Some((
        "energy-drift",
        "Change of the total energy",
        label,
        vec![(name.to_string(), drift)],
    ))
}

/// An axis label as the picture prints it: `E0` as E₀, a minus as a minus sign.
fn legend_label(label: &str) -> String {
    label.replace("E0", "E₀").replace(" - ", " − ")
}

/// A coordinate's name as a plot legend prints it: a Greek letter's name as the letter and
/// trailing digits as subscripts (`theta` → θ, `q12` → q₁₂).
fn legend(name: &str) -> String {
    const GREEK: [(&str, &str); 24] = [
        ("alpha", "α"),
        ("beta", "β"),
        ("gamma", "γ"),
        ("delta", "δ"),
        ("epsilon", "ε"),
        ("zeta", "ζ"),
        ("eta", "η"),
        ("theta", "θ"),
        ("iota", "ι"),
        ("kappa", "κ"),
        ("lambda", "λ"),
        ("mu", "μ"),
        ("nu", "ν"),
        ("xi", "ξ"),
        ("omicron", "ο"),
        ("pi", "π"),
        ("rho", "ρ"),
        ("sigma", "σ"),
        ("tau", "τ"),
        ("upsilon", "υ"),
        ("phi", "φ"),
        ("chi", "χ"),
        ("psi", "ψ"),
        ("omega", "ω"),
    ];
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    let digits = &name[stem.len()..];
    let stem = match stem.strip_suffix('_') {
        Some(s) if !digits.is_empty() => s,
        _ => stem,
    };
    let letter = GREEK
        .iter()
        .find(|(word, _)| *word == stem)
        .map_or(stem.to_string(), |(_, l)| l.to_string());
    let sub: String = digits
        .chars()
        .map(|d| char::from_u32(0x2080 + d.to_digit(10).unwrap_or(0)).unwrap_or(d))
        .collect();
    format!("{letter}{sub}")
}

#[cfg(test)]
mod tests {
    use super::legend;

    #[test]
    fn legends_use_the_letters_and_subscripts() {
        assert_eq!(legend("theta"), "θ");
        assert_eq!(legend("q12"), "q₁₂");
        assert_eq!(legend("phi_2"), "φ₂");
        assert_eq!(legend("x"), "x");
    }
}
