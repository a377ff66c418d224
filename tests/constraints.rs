//! Constrained systems (closures, prescribed motion, rolling contacts, position and velocity
//! constraints) against references that do not come from this program: hand derivations
//! written out in the tests, closed forms and conservation of energy. Every check runs with
//! each of the four methods.

mod invalid;
mod loops;
mod nonminimal;
mod rolling;

/// `NAME=VALUE,...` for `--state`, with every digit a double carries.
fn state(pairs: &[(&str, f64)]) -> String {
    pairs
        .iter()
        .map(|(name, value)| format!("{name}={value:.17e}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// A plane vector turned by `angle`: components in a frame turned by `angle` to N's.
fn turn(angle: f64, v: [f64; 2]) -> [f64; 2] {
    let (s, c) = angle.sin_cos();
    [c * v[0] - s * v[1], s * v[0] + c * v[1]]
}

/// The largest of `|value|` over a column of a simulation.
fn largest(values: impl Iterator<Item = f64>) -> f64 {
    values.fold(0.0, |m, v| m.max(v.abs()))
}
