//! The motion's frames for step 6's animation: the problem's initial state integrated as
//! `simulate` integrates it, sampled at the frame rate by the integrator's dense output.

use super::Solver;
use crate::equations::Derivation;
use crate::numeric::{frame_count, simulate_with_limits, Frame, Limits};
use crate::problem::Problem;
use crate::Error;

/// The motion from the problem's initial state over `duration` seconds, sampled every
/// `1/fps` s by the integrator's dense output, as `simulate` integrates it. A run that stops
/// early gives the frames up to then.
///
/// # Errors
/// Unusable `duration` or `fps` (see [`frame_count`]); a simulation that cannot start.
pub fn frames(
    problem: &Problem,
    derivation: &Derivation,
    duration: f64,
    fps: f64,
) -> Result<Vec<Frame>, Error> {
    let count = frame_count(duration, fps)?;
    let solver = &Solver::new(problem, derivation);
    let q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let settings = crate::problem::SimulateSettings {
        duration,
        output_step: 1.0 / fps,
        ..problem.simulate.clone()
    };
    let limits = Limits {
        max_rows: count + 1,
        ..Limits::default()
    };
    let run =
        simulate_with_limits(solver, &q0, &rates0, &settings, &limits).map_err(Error::Solve)?;
    let n = run.coordinates;
    let frames: Vec<Frame> = run
        .rows
        .iter()
        .map(|row| Frame {
            t: row[0],
            q: row[1..=n].to_vec(),
            rates: row[n + 1..=2 * n].to_vec(),
        })
        .collect();
    match (frames.len(), run.stopped) {
        (0 | 1, Some(reason)) => Err(Error::Solve(reason)),
        _ => Ok(frames),
    }
}
