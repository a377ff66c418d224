//! A sampled state of a motion (one frame of step 6's animation) and the usual frame rate.

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
