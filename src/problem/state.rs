//! A state of the system, [`State`]: time, coordinates and rates, and the initial one a
//! problem gives ([`Problem::initial_state`]).

use super::Problem;

/// A state of the system: time, coordinates and rates in coordinate order. The
/// coordinates and rates are those written in the problem (the speeds, where it declares
/// its own, follow from the rates).
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Time `t`.
    pub t: f64,
    /// The coordinates.
    pub q: Vec<f64>,
    /// Their rates.
    pub rates: Vec<f64>,
}

impl Problem {
    /// The initial state as written: `t = 0`, every coordinate's `initial` and `rate`.
    /// It may not yet meet the constraints: the solver assembles it.
    pub fn initial_state(&self) -> State {
        State {
            t: 0.0,
            q: self.coordinates.iter().map(|c| c.initial).collect(),
            rates: self.coordinates.iter().map(|c| c.rate).collect(),
        }
    }
}
