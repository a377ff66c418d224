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
