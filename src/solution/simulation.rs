//! Step 6 of the worked solution: the simulation, its confirmation checks and its plots.

use crate::numeric::{CheckKind, Phrase, SolveError, Trajectory};
use crate::problem::{CoordinateKind, Problem};
use crate::render::context::{Check, Plot, Solution};
use crate::render::text::{FileName, LatexCode, MarkupLine, SvgDocument};
use crate::render::{literal, literal_with_numbers, PlotData, PlotLabel as Label, Series};
use crate::symbolic::{fixed, latex, latex_name};

/// Fills step 6 of `solution` from the simulation from the (assembled) initial state and its
/// confirmation checks; a run that could not start or stopped early is said in the step's
/// note.
pub fn simulation(
    solution: &mut Solution,
    problem: &Problem,
    simulated: &Result<(Trajectory, Vec<crate::numeric::Check>), SolveError>,
) {
    let (trajectory, checks) = match simulated {
        Ok(run) => run,
        Err(e) => {
            solution.simulation.note = format!("The simulation could not run: {e}");
            return;
        }
    };
    let mut notes = Vec::new();
    if let Some(reason) = &trajectory.stopped {
        notes.push(format!("The simulation stopped early: {reason}"));
    }
    // Where friction changed its mode; the first switch of a site a question asks about is
    // answered in the Answers, in words, and not said here again.
    let asked: Vec<&str> = (problem.questions.iter())
        .filter_map(|q| q.at.switch)
        .map(|k| problem.site_name(k))
        .collect();
    let unasked: Vec<String> = (trajectory.switches.iter().enumerate())
        .filter(|(i, s)| {
            let first = !trajectory.switches[..*i].iter().any(|e| e.site == s.site);
            !(first && asked.contains(&s.site.as_str()))
        })
        .map(|(_, s)| s.describe(problem))
        .collect();
    if !unasked.is_empty() {
        let lines = unasked;
        notes.push(format!(
            "Friction changes its mode during the motion: {}.",
            lines.join("; ")
        ));
    }
    solution.simulation.note = notes.join(" ");
    // The work of the applied forces and couples, where the energy changes by it alone.
    let work = crate::numeric::load_work(problem, trajectory);
    solution.simulation.checks = checks_said(problem, checks, trajectory, work.as_deref());
    if let Some(work) = energy_changed_by_work(checks, trajectory) {
        solution.simulation.checks.push(work);
    }
    // One quantity per axis: angles and distances on plots of their own.
    // A coordinate that stays at its value is said, not drawn as a flat line.
    let still = say_still(solution, problem, trajectory);
    let series_of = |kind: CoordinateKind| -> Vec<Series> {
        problem
            .coordinates
            .iter()
            .enumerate()
            .filter(|(i, c)| c.kind == kind && !still.iter().any(|s| s.0 == *i))
            .filter_map(|(_, c)| {
                trajectory.series(&c.name).map(|points| Series {
                    name: Label::math(&latex_name(&c.name), ""),
                    points,
                })
            })
            .collect()
    };
    let energy_series = energy_series(problem, trajectory);
    let energy_title = super::plot_titles::energy(problem, &energy_series);
    // Angles of very different ranges (a top's spin, precession and nutation) each on an
    // axis of their own, named by what they are: on one axis the smaller would look flat.
    let ranges = by_range(series_of(CoordinateKind::Angle));
    let split = ranges.len() > 1;
    let last = ranges.len().saturating_sub(1);
    let mut plots: Vec<(String, String, Label, Vec<Series>)> = (ranges.into_iter().enumerate())
        .map(|(k, group)| {
            let (kind, title) = match (k, split) {
                (0, false) => ("coordinates".to_string(), "Angles against time".to_string()),
                (0, true) => (
                    "coordinates".to_string(),
                    angles_title(problem, &group, true),
                ),
                (k, _) if k == last => {
                    ("nutation".to_string(), angles_title(problem, &group, false))
                }
                (k, _) => (
                    format!("angles-{}", k + 1),
                    angles_title(problem, &group, false),
                ),
            };
            (kind, title, Label::words("angle (rad)"), group)
        })
        .collect();
    plots.push((
        "positions".into(),
        "Positions against time".into(),
        Label::words("position (m)"),
        series_of(CoordinateKind::Distance),
    ));
    if plots[0].3.is_empty() {
        // A system without angles: its positions are the coordinates' plot.
        let positions = plots.remove(1);
        plots[0] = ("coordinates".into(), positions.1, positions.2, positions.3);
    }
    let kinetic = match problem.constants.iter().any(|c| c.name == "T") {
        true => "K",
        false => "T",
    };
    plots.extend(super::energy_plots::energy_plots(
        energy_series,
        kinetic,
        energy_title,
    ));
    // The drift is the integrator's error only where no load or drive does work, and it
    // teaches only where it is not negligible: a constant energy shows on the energy's plot.
    let drifting = checks
        .iter()
        .any(|c| c.kind == CheckKind::EnergyConservation && !c.passed);
    if let Some((kind, title, label, series)) = energy_drift(trajectory).filter(|_| drifting) {
        plots.push((kind.into(), title.into(), label, series));
    }
    let time = Label::math("t", "(s)");
    plots.retain(|plot| !plot.3.is_empty());
    // One or two plots share a row, wide enough to read at print size; three or four,
    // narrower, rather than one alone on a row of its own.
    let plots_in_row = plots.len().clamp(2, 4);
    solution.simulation.plots_in_row = plots_in_row;
    for (kind, title, y_label, series) in plots {
        // Drawn by the renderer, in the format asked.
        solution.simulation.plots.push(Plot {
            kind,
            title,
            svg_file: FileName::from(String::new()),
            image_svg: SvgDocument::default(),
            image_latex: LatexCode::default(),
            data: Some(PlotData {
                x_label: time.clone(),
                y_label,
                series,
                plots_in_row,
            }),
        });
    }
}

/// The confirmation checks of the run by `method`, each said as physics, in the course's
/// words.
fn checks_said(
    problem: &Problem,
    checks: &[crate::numeric::Check],
    trajectory: &Trajectory,
    work: Option<&[f64]>,
) -> Vec<Check> {
    checks
        .iter()
        // A passed check that the other methods agree, or that a small oscillation has the
        // linearized period, is nothing a student can follow on paper: said only if it fails.
        .filter(|c| {
            !(c.passed
                && matches!(
                    c.kind,
                    CheckKind::MethodAgreement | CheckKind::SmallOscillationPeriod
                ))
        })
        .map(|c| {
            // Said as physics, in the course's words; the check's own sentence only where
            // the motion does not hold it.
            let own = detail(problem, c);
            let said = match (c.kind, work) {
                (CheckKind::EnergyBalanceWithLoads, Some(work)) => {
                    super::confirmation::work_balance(problem, trajectory, work, c.passed)
                }
                _ => None,
            };
            let said =
                said.unwrap_or_else(|| super::confirmation::sentence(c, trajectory, own.as_str()));
            Check {
                name: c.name().to_string(),
                value: fixed(c.value),
                tolerance: fixed(c.tolerance),
                passed: c.passed,
                detail: MarkupLine::from(said),
            }
        })
        .collect()
}

/// Where no check speaks of the energy but the energy plot shows E change (a cart pulled by
/// a force, a gear driven by a torque): why, so a student does not read it as an error.
fn energy_changed_by_work(
    checks: &[crate::numeric::Check],
    trajectory: &Trajectory,
) -> Option<Check> {
    let energy_checked = checks.iter().any(|c| {
        matches!(
            c.kind,
            CheckKind::EnergyConservation
                | CheckKind::EnergyNeverRises
                | CheckKind::EnergyBalanceWithDrives
                | CheckKind::EnergyBalanceWithLoads
        )
    });
    let total = trajectory.series("total")?;
    let scale = total.iter().fold(1e-12f64, |m, p| m.max(p.1.abs()));
    if energy_checked || super::confirmation::range(&total) <= 1e-6 * scale {
        return None;
    }
    Some(Check {
        name: "energy".into(),
        value: String::new(),
        tolerance: String::new(),
        passed: true,
        detail: MarkupLine::from(
            "The loads applied to the system do work on it, so its total energy $E$ is not \
             constant: it changes by their work, as the energy plot shows."
                .to_string(),
        ),
    })
}

/// The kinetic, potential and total energy against time, for the energy's plot.
fn energy_series(problem: &Problem, trajectory: &Trajectory) -> Vec<Series> {
    // V and E from the problem's datum, as the answers give them, not from the start.
    let datum = trajectory.potential_at_start;
    // T is the kinetic energy, unless the problem names a constant T (a drive torque).
    let named_t = problem.constants.iter().any(|c| c.name == "T");
    let (kinetic, total) = match named_t {
        true => ("K", "E = K + V"),
        false => ("T", "E = T + V"),
    };
    [
        ("kinetic", kinetic, 0.0),
        ("potential", "V", datum),
        ("total", total, datum),
    ]
    .iter()
    .filter_map(|&(part, symbol, shift)| {
        trajectory.series(part).map(|points| Series {
            name: Label::math(symbol, ""),
            points: points.into_iter().map(|(t, e)| (t, e + shift)).collect(),
        })
    })
    .collect()
}

/// The total energy's change, (E − E₀)/|E₀|, on an axis of its own, since beside the
/// energies it is invisible: the integration's drift when no load does work, which is what
/// the energy check measures. E − E₀ in joules when E₀ is under a tenth of the energies the
/// motion exchanges (the datum of V is the start): a ratio to it would exaggerate the drift
/// the check, on the energy scale of the motion, finds small.
fn energy_drift(
    trajectory: &Trajectory,
) -> Option<(&'static str, &'static str, Label, Vec<Series>)> {
    let total = trajectory.series("total")?;
    let e0 = total.first()?.1;
    let scale = ["kinetic", "potential"]
        .iter()
        .filter_map(|part| trajectory.series(part))
        .flatten()
        .fold(0.0f64, |largest, (_, e)| largest.max(e.abs()));
    let relative = e0.abs() > 0.1 * scale && e0.abs() > 1e-12;
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
    let label = if relative {
        Label::math("(E - E_{0})/|E_{0}|", "")
    } else {
        Label::math("E - E_{0}", "(J)")
    };
    Some((
        "energy-drift",
        "Change of the total energy",
        label.clone(),
        vec![Series {
            name: label,
            points: drift,
        }],
    ))
}

/// What `check` compared, in markup: its coordinates in the solution's notation (`q̈₁` for
/// the plain `q1''`).
fn detail(problem: &Problem, check: &crate::numeric::Check) -> MarkupLine {
    let pieces: Vec<String> = (check.phrases.iter())
        .map(|phrase| match phrase {
            Phrase::Text(text) => literal_with_numbers(text),
            Phrase::Coordinate { name, order } => {
                match (problem.coordinates.iter()).position(|c| &c.name == name) {
                    Some(i) => format!("${}$", latex(&problem.coordinate_expr(i, *order as u8))),
                    None => literal(&Phrase::plain(std::slice::from_ref(phrase))),
                }
            }
        })
        .collect();
    MarkupLine::from(pieces.concat())
}

/// How many times the range of the angles on one axis may exceed the range of another on
/// it: past that, the smaller would show as a line lying flat beside the larger.
const RANGES_APART: f64 = 8.0;

/// `series` split into groups of like range, the largest first: sorted by range, a new
/// group starts at an angle whose range is under the group's largest over
/// [`RANGES_APART`] (a top's spin, precession and nutation make three). An angle that does
/// not move at all stays with the largest.
fn by_range(series: Vec<Series>) -> Vec<Vec<Series>> {
    let span = |s: &Series| {
        let (lo, hi) = (s.points.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.1), hi.max(p.1))
        });
        hi - lo
    };
    let largest = series.iter().map(span).fold(0.0, f64::max);
    let still = |x: f64| x <= largest * 1e-9;
    let mut order: Vec<(f64, usize)> = (series.iter().map(span).enumerate())
        .map(|(k, x)| (x, k))
        .collect();
    // Largest first; equal ranges in the problem's order.
    order.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut group_of = vec![0usize; series.len()];
    let (mut group, mut top) = (0usize, largest);
    for &(x, k) in &order {
        if !still(x) && x < top / RANGES_APART {
            group += 1;
            top = x;
        }
        group_of[k] = if still(x) { 0 } else { group };
    }
    let mut groups: Vec<Vec<Series>> = vec![Vec::new(); group + 1];
    for (s, g) in series.into_iter().zip(group_of) {
        groups[g].push(s);
    }
    groups.retain(|g| !g.is_empty());
    if groups.is_empty() {
        groups.push(Vec::new());
    }
    groups
}

/// The title of a plot of angles of one range (see `plot_titles`).
fn angles_title(problem: &Problem, series: &[Series], first: bool) -> String {
    super::plot_titles::angles_of_a_range(problem, series, first)
}

/// The coordinates that stay at their value, said after step 6's opening sentence.
fn say_still(
    solution: &mut Solution,
    problem: &Problem,
    trajectory: &Trajectory,
) -> Vec<(usize, f64)> {
    let still = still_coordinates(problem, trajectory);
    if let Some(sentence) = still_sentence(problem, &still) {
        solution.simulation.settings.0.push(' ');
        solution.simulation.settings.0.push_str(&sentence);
    }
    still
}

/// The coordinates that stay at their value along the whole motion (a collar's angle on a
/// rod that does not turn), each with that value: their index and value.
fn still_coordinates(problem: &Problem, trajectory: &Trajectory) -> Vec<(usize, f64)> {
    (problem.coordinates.iter().enumerate())
        .filter_map(|(i, c)| {
            let points = trajectory.series(&c.name)?;
            let first = points.first()?.1;
            let moved = (points.iter()).fold(0.0f64, |m, p| m.max((p.1 - first).abs()));
            let still = points.len() > 1 && moved <= 1e-9 * first.abs().max(1.0);
            still.then_some((i, if first.abs() < 1e-9 { 0.0 } else { first }))
        })
        .collect()
}

/// `θ stays at 0 rad and y at 0 m throughout, so neither is plotted.`, in markup, for the
/// coordinates that stay at their value.
fn still_sentence(problem: &Problem, still: &[(usize, f64)]) -> Option<String> {
    let said: Vec<String> = (still.iter())
        .map(|&(i, value)| {
            let c = &problem.coordinates[i];
            let unit = match c.kind {
                CoordinateKind::Angle => "rad",
                _ => "m",
            };
            let value = literal_with_numbers(&fixed(value));
            (
                format!("${}$", latex_name(&c.name)),
                format!("{value} {unit}"),
            )
        })
        .enumerate()
        .map(|(k, (name, value))| match k {
            0 => format!("{name} stays at {value}"),
            _ => format!("{name} at {value}"),
        })
        .collect();
    let (last, rest) = said.split_last()?;
    let list = match rest.is_empty() {
        true => last.clone(),
        false => format!("{} and {last}", rest.join(", ")),
    };
    let tail = match rest.is_empty() {
        true => "so it is not plotted",
        false if rest.len() == 1 => "so neither is plotted",
        false => "so none of them is plotted",
    };
    Some(format!("{list} throughout, {tail}."))
}
