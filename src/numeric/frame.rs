//! A sampled state of a motion (one frame of step 6's animation), and how many frames a
//! duration at a frame rate makes.

use crate::Error;

/// The most frames a motion may have (400 s at 25 frames per second): each frame adds a
/// value to every animation of the picture, and more would make a file no viewer plays.
pub const MAX_FRAMES: usize = 10_000;

/// Frames per second unless `--fps` says otherwise.
pub const DEFAULT_FPS: f64 = 25.0;

/// One sampled state.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// The time.
    pub t: f64,
    /// The coordinates.
    pub q: Vec<f64>,
    /// Their rates.
    pub rates: Vec<f64>,
}

/// The number of frames of `duration` seconds at `fps`, or a usage error when the numbers
/// are not usable or give more than [`MAX_FRAMES`]; checked before any work.
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
