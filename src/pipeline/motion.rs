//! The motion's frames for step 6's animation: the problem's initial state integrated as
//! `simulate` integrates it, sampled at the frame rate by the integrator's dense output.

use super::Solver;
use crate::equations::Derivation;
use crate::error::Error;
use crate::numeric::{simulate_with_limits, Frame, Limits};
use crate::problem::Problem;

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
    let initial = problem.initial_state();
    let (q0, rates0) = (initial.q, initial.rates);
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

/// The most frames a motion may have (400 s at 25 frames per second): each frame adds a
/// value to every animation of the picture, and more would make a file no viewer plays.
pub const MAX_FRAMES: usize = 10_000;

/// The number of frames of `duration` seconds at `fps`, or a usage error when the numbers
/// are not usable or give more than `MAX_FRAMES` (10,000); checked before any work.
///
/// # Errors
/// [`Error::Usage`] naming the flag.
pub fn frame_count(duration: f64, fps: f64) -> Result<usize, Error> {
    if !(duration.is_finite() && duration > 0.0) {
        return Err(Error::Usage(
            "--duration must be a positive number of seconds".into(),
        ));
    }
    if !(fps.is_finite() && fps > 0.0) {
        return Err(Error::Usage(
            "--fps must be a positive number of frames per second".into(),
        ));
    }
    let frames = (duration * fps).ceil() + 1.0;
    if frames > MAX_FRAMES as f64 {
        return Err(Error::Usage(format!(
            "{duration} s at {fps} frames per second is {frames} frames, more than {MAX_FRAMES}: shorten --duration or lower --fps"
        )));
    }
    Ok(frames as usize)
}

#[cfg(test)]
mod tests {
    use super::frame_count;

    #[test]
    fn absurd_frame_counts_are_refused_before_any_work() {
        assert_eq!(frame_count(5.0, 25.0).ok(), Some(126));
        assert!(frame_count(1e6, 25.0).is_err());
        assert!(frame_count(5.0, 0.0).is_err());
        assert!(frame_count(f64::NAN, 25.0).is_err());
    }
}
