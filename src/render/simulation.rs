//! Step 6 of the worked solution: the simulation, its confirmation checks and its plots.

use super::context::{Check, Plot, Solution};
use crate::numeric::checks;
use crate::numeric::format::fixed;
use crate::numeric::simulate::Trajectory;
use crate::numeric::SolveError;
use crate::problem::Problem;

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
    let names: Vec<String> = problem.coordinates.iter().map(|c| c.name.clone()).collect();
    let coordinate_series: Vec<(String, Vec<(f64, f64)>)> = names
        .iter()
        .filter_map(|n| trajectory.series(n).map(|s| (n.clone(), s)))
        .collect();
    let energy_series: Vec<(String, Vec<(f64, f64)>)> = ["kinetic", "potential", "total"]
        .iter()
        .filter_map(|n| trajectory.series(n).map(|s| (n.to_string(), s)))
        .collect();
    for (kind, title, y_label, series) in [
        (
            "coordinates",
            "Coordinates against time",
            "coordinate",
            coordinate_series,
        ),
        ("energy", "Energy against time", "energy (J)", energy_series),
    ] {
        let svg =
            crate::render::plot::line_plot(title, "t (s)", y_label, &series).unwrap_or_default();
        solution.simulation.plots.push(Plot {
            kind: kind.into(),
            title: title.into(),
            svg_file: String::new(),
            image_svg: svg,
            pgfplots_latex: crate::render::plot::pgfplots(title, "t (s)", y_label, &series),
        });
    }
}
