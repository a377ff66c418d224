//! Simulation: integrate a [`System`] over time and tabulate the motion (step 6).
//!
//! The state integrated is `[q, q']`; each output row then evaluates the system once more
//! at the interpolated state for q'', the energies and the reactions.

use super::friction::Held;
use super::integrate::{integrate, Options, Solution, Stop};
use super::system::{describe_state, ReactionColumn, System};
use super::SolveError;
use crate::problem::SimulateSettings;
pub use switching::Switch;

/// The most rows [`simulate`] writes unless [`Limits::max_rows`] is raised: a million rows of
/// a few dozen numbers is already tens of megabytes of CSV, and a mistyped `output_step`
/// should be an error at once, not hours of work.
pub const MAX_ROWS: usize = 1_000_000;

/// The most integration steps [`simulate`] takes unless [`Limits::max_steps`] is raised.
pub const MAX_STEPS: usize = 10_000_000;

/// Bounds on the work one simulation may do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Most output rows; default [`MAX_ROWS`].
    pub max_rows: usize,
    /// Most integration steps; default `MAX_STEPS`.
    pub max_steps: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_rows: MAX_ROWS,
            max_steps: MAX_STEPS,
        }
    }
}

/// A simulated motion: one row per output time.
#[derive(Clone, Debug, PartialEq)]
pub struct Trajectory {
    /// `t`, each coordinate (`q1`), each rate (`q1'`), each second derivative (`q1''`),
    /// `kinetic`, `potential`, `total`, then the reaction columns (`O.force.x` ...).
    pub columns: Vec<String>,
    /// The rows, each as long as `columns`: seconds, SI units, joules (potential and total
    /// relative to the initial configuration), newtons and newton-metres.
    pub rows: Vec<Vec<f64>>,
    /// Why the run ended before `duration`, if it did; `rows` then holds the motion up to
    /// the last output time reached.
    pub stopped: Option<SolveError>,
    /// The number of coordinates, so `q` is `row[1..=n]` and the rates follow.
    pub coordinates: usize,
    /// The potential energy at the start from the problem's datum (gravity's from `N`'s
    /// origin, springs' from their free length), which the rows' columns leave out: added
    /// back, it gives the energies that the answers and a textbook measure.
    pub potential_at_start: f64,
    /// Where a friction site switched between sticking and sliding, in order.
    pub switches: Vec<Switch>,
}

/// Integrates `system` from `q0` and `rates0` at `t = 0` over `settings.duration`, with the
/// default [`Limits`].
///
/// # Errors
/// See [`simulate_with_limits`].
pub fn simulate(
    system: &dyn System,
    q0: &[f64],
    rates0: &[f64],
    settings: &SimulateSettings,
) -> Result<Trajectory, SolveError> {
    simulate_with_limits(system, q0, rates0, settings, &Limits::default())
}

/// Integrates `system` from `q0` and `rates0` at `t = 0` and tabulates it every
/// `settings.output_step` seconds up to `settings.duration` inclusive, with
/// `atol = rtol = settings.tolerance`.
///
/// A failure during the run (a singular configuration, a step that collapses) is not an
/// error here: it ends the run and is kept in [`Trajectory::stopped`] with the rows so far.
///
/// # Errors
/// Before any work: [`SolveError::BadSimulation`] for unusable settings or an initial state
/// of the wrong length or not finite; [`SolveError::TooManyRows`] when the run would write
/// more than `limits.max_rows` rows.
pub fn simulate_with_limits(
    system: &dyn System,
    q0: &[f64],
    rates0: &[f64],
    settings: &SimulateSettings,
    limits: &Limits,
) -> Result<Trajectory, SolveError> {
    let names = system.coordinate_names();
    let n = names.len();
    check_start(n, q0, rates0, settings.tolerance)?;
    let tolerance = settings.tolerance;
    let times = output_times(settings.duration, settings.output_step, limits.max_rows)?;
    let reactions = system.reaction_columns();
    let mut trajectory = Trajectory {
        columns: column_names(&names, &reactions),
        rows: Vec::with_capacity(times.len()),
        stopped: None,
        coordinates: n,
        potential_at_start: 0.0,
        switches: Vec::new(),
    };
    let (mut q0, mut rates0) = (q0.to_vec(), rates0.to_vec());
    if let Err(e) = system.assemble(0.0, &mut q0, &mut rates0) {
        trajectory.stopped = Some(e);
        return Ok(trajectory);
    }
    let (q0, rates0) = (q0.as_slice(), rates0.as_slice());
    let potential0 = match system.evaluate(0.0, q0, rates0) {
        Ok(evaluation) => evaluation.potential,
        Err(e) => {
            trajectory.stopped = Some(e);
            return Ok(trajectory);
        }
    };
    trajectory.potential_at_start = potential0;

    // With constraints, the integrated dependent coordinates and rates only serve as the
    // starting guess: each evaluation solves them again from the independent ones.
    let constrained = system.is_constrained();
    let derivative =
        |t: f64, y: &[f64], dy: &mut [f64], held: Option<&[Held]>| -> Result<(), SolveError> {
            let mut assembled = Vec::new();
            let (q, rates) = if constrained {
                assembled.extend_from_slice(y);
                let (q, rates) = assembled.split_at_mut(n);
                system.assemble(t, q, rates)?;
                (&*q, &*rates)
            } else {
                y.split_at(n)
            };
            let accelerations = match held {
                Some(held) => system.accelerations_held(t, q, rates, held)?,
                None => system.accelerations(t, q, rates)?,
            };
            if accelerations.len() != n {
                return Err(mismatch("accelerations", n, accelerations.len()));
            }
            if accelerations.iter().any(|a| !a.is_finite()) {
                let state = describe_state(t, &names, q, rates);
                return Err(SolveError::NotFinite {
                    state,
                    what: "an acceleration".into(),
                });
            }
            dy[..n].copy_from_slice(rates);
            dy[n..].copy_from_slice(&accelerations);
            Ok(())
        };
    let y0: Vec<f64> = q0.iter().chain(rates0).copied().collect();
    let options = Options {
        max_steps: limits.max_steps,
        ..Options::with_tolerance(tolerance)
    };
    let solution = if system.friction_sites().is_empty() {
        integrate(
            |t, y: &[f64], dy: &mut [f64]| derivative(t, y, dy, None),
            0.0,
            &y0,
            &times,
            &options,
        )
    } else {
        let settle = |t: f64, y: &[f64]| -> Result<Vec<f64>, SolveError> {
            let mut y = y.to_vec();
            if constrained {
                let (q, rates) = y.split_at_mut(n);
                system.assemble(t, q, rates)?;
            }
            Ok(y)
        };
        let mut held_derivative =
            |t: f64, y: &[f64], dy: &mut [f64], held: &[Held]| derivative(t, y, dy, Some(held));
        let (solution, switches) =
            switching::integrate(system, &mut held_derivative, &settle, &y0, &times, &options);
        trajectory.switches = switches;
        solution
    };

    if !record(
        system,
        &solution,
        (potential0, reactions.len()),
        &mut trajectory,
    ) {
        return Ok(trajectory);
    }
    trajectory.stopped = solution.stop.map(|stop| stop_error(stop, &names));
    Ok(trajectory)
}

/// Refuses an initial state of the wrong length or not finite, and a tolerance outside
/// (0, 1).
fn check_start(n: usize, q0: &[f64], rates0: &[f64], tolerance: f64) -> Result<(), SolveError> {
    if q0.len() != n || rates0.len() != n {
        return Err(SolveError::BadSimulation {
            what: format!(
                "{n} coordinates but {} initial values and {} initial rates",
                q0.len(),
                rates0.len()
            ),
        });
    }
    if q0.iter().chain(rates0).any(|v| !v.is_finite()) {
        return Err(SolveError::BadSimulation {
            what: "the initial state is not finite".into(),
        });
    }
    if !(tolerance > 0.0 && tolerance < 1.0) {
        return Err(SolveError::BadSimulation {
            what: format!("`tolerance` must be between 0 and 1, not {tolerance}"),
        });
    }
    Ok(())
}

/// Writes a row of `trajectory` for each output time of `solution`: the state, the
/// accelerations, the energies (the potential from its value at the start) and the
/// reactions. False when an evaluation failed: the run stops there, its error kept.
fn record(
    system: &dyn System,
    solution: &Solution<SolveError>,
    (potential0, reaction_count): (f64, usize),
    trajectory: &mut Trajectory,
) -> bool {
    let n = trajectory.coordinates;
    for (&t, y) in solution.times.iter().zip(&solution.states) {
        let mut y = y.clone();
        let (q, rates) = y.split_at_mut(n);
        if let Err(e) = system.assemble(t, q, rates) {
            trajectory.stopped = Some(e);
            return false;
        }
        let (q, rates) = (&*q, &*rates);
        let evaluation = match system.evaluate(t, q, rates) {
            Ok(e) if e.accelerations.len() != n => {
                Err(mismatch("accelerations", n, e.accelerations.len()))
            }
            Ok(e) if e.reactions.len() != reaction_count => {
                Err(mismatch("reactions", reaction_count, e.reactions.len()))
            }
            other => other,
        };
        let evaluation = match evaluation {
            Ok(evaluation) => evaluation,
            Err(e) => {
                trajectory.stopped = Some(e);
                return false;
            }
        };
        let potential = evaluation.potential - potential0;
        let mut row = Vec::with_capacity(trajectory.columns.len());
        row.push(t);
        row.extend_from_slice(&y);
        row.extend_from_slice(&evaluation.accelerations);
        row.extend([
            evaluation.kinetic,
            potential,
            evaluation.kinetic + potential,
        ]);
        row.extend_from_slice(&evaluation.reactions);
        trajectory.rows.push(row);
    }
    true
}

/// The error that ended the integration early, with the state it stopped at.
fn stop_error(stop: Stop<SolveError>, names: &[String]) -> SolveError {
    let n = names.len();
    match stop {
        Stop::Derivative(e) => e,
        Stop::StepUnderflow { t, y, step } => SolveError::StepSizeUnderflow {
            state: describe_state(t, names, &y[..n], &y[n..]),
            step,
        },
        Stop::TooManySteps { t, y, steps } => SolveError::TooManySteps {
            state: describe_state(t, names, &y[..n], &y[n..]),
            steps,
        },
        Stop::NotFinite { t, y } => SolveError::NotFinite {
            state: describe_state(t, names, &y[..n], &y[n..]),
            what: "an acceleration".into(),
        },
        Stop::BadArguments(what) => SolveError::BadSimulation { what: what.into() },
    }
}

fn mismatch(what: &str, expected: usize, got: usize) -> SolveError {
    SolveError::BadSimulation {
        what: format!("the equations gave {got} {what} where {expected} were expected"),
    }
}

/// The column names in the order of the command-line contract.
pub fn column_names(coordinates: &[String], reactions: &[ReactionColumn]) -> Vec<String> {
    let mut columns = vec!["t".to_string()];
    columns.extend(coordinates.iter().cloned());
    columns.extend(coordinates.iter().map(|q| format!("{q}'")));
    columns.extend(coordinates.iter().map(|q| format!("{q}''")));
    columns.extend(["kinetic", "potential", "total"].map(String::from));
    columns.extend(reactions.iter().map(ReactionColumn::to_string));
    columns
}

/// `0, step, 2 step, ...` up to `duration`, which is always the last time (s).
///
/// Each time is `i * step`, never a running sum, so the grid does not drift; a duration
/// within round-off of a multiple of the step replaces that multiple.
///
/// # Errors
/// [`SolveError::BadSimulation`] for a negative or non-finite duration or a step that is
/// not positive; [`SolveError::TooManyRows`] past `max_rows`.
pub fn output_times(duration: f64, step: f64, max_rows: usize) -> Result<Vec<f64>, SolveError> {
    if !(duration >= 0.0 && duration.is_finite()) {
        return Err(SolveError::BadSimulation {
            what: format!("`duration` must be 0 or more, not {duration}"),
        });
    }
    if !(step > 0.0 && step.is_finite()) {
        return Err(SolveError::BadSimulation {
            what: format!("`output_step` must be positive, not {step}"),
        });
    }
    let intervals = duration / step;
    let rows = intervals.ceil() + 1.0;
    if rows > max_rows as f64 {
        return Err(SolveError::TooManyRows {
            rows,
            limit: max_rows,
        });
    }
    let whole = (intervals + 1e-9).floor() as usize;
    let mut times: Vec<f64> = (0..=whole).map(|i| i as f64 * step).collect();
    match times.last_mut() {
        Some(last) if (duration - *last).abs() <= 1e-9 * step => *last = duration,
        _ => times.push(duration),
    }
    Ok(times)
}

impl Trajectory {
    /// The index of the column called `name`.
    pub fn column(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|c| c == name)
    }

    /// The column called `name` against time, for plots.
    pub fn series(&self, name: &str) -> Option<Vec<(f64, f64)>> {
        let index = self.column(name)?;
        Some(self.rows.iter().map(|row| (row[0], row[index])).collect())
    }

    /// The table as CSV: a header row, then one line per row, numbers in full precision.
    pub fn to_csv(&self) -> String {
        let mut text = self.columns.join(",");
        text.push('\n');
        for row in &self.rows {
            let cells: Vec<String> = row.iter().map(|x| full_precision(*x)).collect();
            text.push_str(&cells.join(","));
            text.push('\n');
        }
        text
    }

    /// The table as JSON: `{ "columns": [...], "rows": [[...], ...] }`, numbers in full
    /// precision (a non-finite number, which a finished row never holds, becomes `null`).
    pub fn to_json(&self) -> String {
        let columns: Vec<String> = self
            .columns
            .iter()
            .map(|c| serde_json::Value::String(c.clone()).to_string())
            .collect();
        let rows: Vec<String> = self
            .rows
            .iter()
            .map(|row| {
                let cells: Vec<String> = row
                    .iter()
                    .map(|x| {
                        if x.is_finite() {
                            full_precision(*x)
                        } else {
                            "null".into()
                        }
                    })
                    .collect();
                format!("    [{}]", cells.join(", "))
            })
            .collect();
        format!(
            "{{\n  \"columns\": [{}],\n  \"rows\": [\n{}\n  ]\n}}\n",
            columns.join(", "),
            rows.join(",\n")
        )
        .replace("[\n\n  ]", "[]")
    }
}

/// The shortest text that reads back as the same `f64`, with an exponent for very large or
/// small magnitudes (`0.1`, `1.0`, `1e-7`); negative zero prints as `0.0`.
pub fn full_precision(x: f64) -> String {
    if x == 0.0 {
        return "0.0".into();
    }
    format!("{x:?}")
}

mod switching;

/// Small systems with hand-written equations, for the tests here and in `checks`.
#[cfg(test)]
pub(crate) mod test_systems;

#[cfg(test)]
mod tests;
