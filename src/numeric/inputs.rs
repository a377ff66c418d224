//! The inputs of every compiled program of a problem, in the one order they all share:
//! constants, coordinates, rates, time, then the declared speeds.

use crate::problem::Problem;
use crate::symbolic::Symbol;

/// The input symbols of the compiled program: constants, coordinates, rates, time, and
/// the declared speeds when there are any (computed from the rates, see [`super::speeds::SpeedProgram`]).
pub fn input_symbols(problem: &Problem) -> Vec<Symbol> {
    let mut inputs = state_symbols(problem);
    if problem.has_speeds() {
        inputs.extend(problem.speed_symbols(1));
    }
    inputs
}

/// Constants, coordinates, rates and time: the state a command gives.
pub fn state_symbols(problem: &Problem) -> Vec<Symbol> {
    let mut inputs: Vec<Symbol> = problem
        .constants
        .iter()
        .map(|c| Symbol::Const(c.name.as_str().into()))
        .collect();
    for order in 0..2 {
        inputs.extend((0..problem.coordinates.len()).map(|i| problem.coordinate_symbol(i, order)));
    }
    inputs.push(Symbol::Time);
    inputs
}
