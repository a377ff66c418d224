//! One file per subcommand; each turns its arguments into work on the pipeline.

pub mod check;
pub mod explain;
pub mod schema;
pub mod simulate;
pub mod solve;

use crate::cli::Command;
use crate::Error;

/// Runs one command.
///
/// # Errors
/// Whatever the command's stage reports; see [`Error`].
pub fn run(command: Command) -> Result<(), Error> {
    match command {
        Command::Explain(args) => explain::run(args),
        Command::Solve(args) => solve::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Check(args) => check::run(args),
        Command::Schema(args) => schema::run(args),
    }
}

/// The method chosen on the command line.
pub fn method(arg: crate::cli::MethodArg) -> crate::equations::Method {
    match arg {
        crate::cli::MethodArg::MotionLaw => crate::equations::Method::MotionLaw,
        crate::cli::MethodArg::NewtonEuler => crate::equations::Method::NewtonEuler,
        crate::cli::MethodArg::Kane => crate::equations::Method::Kane,
    }
}

/// Loads the problem named on the command line and applies `--set`.
///
/// # Errors
/// An unreadable or invalid problem, or a `--set` that names no constant.
pub fn load_with_overrides(common: &crate::cli::Common) -> Result<crate::problem::Problem, Error> {
    let mut problem = crate::problem::load_file(&common.problem)?;
    let overrides = crate::cli::parse_assignments(&common.set)?;
    crate::problem::apply_overrides(&mut problem, &overrides)?;
    Ok(problem)
}
