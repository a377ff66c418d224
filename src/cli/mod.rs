//! The command line: clap types, converted into a plain [`Config`] before any work.

mod commands;

pub use commands::*;

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// The most bodies that `explain`, `solve` and `simulate` derive unless `--max-bodies`
/// raises it: the symbolic work grows steeply with the size of the system.
pub const MAX_BODIES: usize = 30;

/// The most coordinates those commands derive unless `--max-coordinates` raises it.
pub const MAX_COORDINATES: usize = 60;

/// Derive, solve and explain the equations of motion of rigid multibody systems.
#[derive(Parser, Debug)]
#[command(name = "mbd-tutor", version, about)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// The equation-forming method.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MethodArg {
    /// Contact + distance + inertia forces = 0, about any point (the default).
    #[default]
    MotionLaw,
    /// Every body free, all reactions unknown.
    NewtonEuler,
    /// Generalized active plus inertia forces.
    Kane,
}

/// Options shared by the commands that read a problem.
#[derive(clap::Args, Debug, Clone)]
pub struct Common {
    /// The problem file (JSON); for `explain`, also a directory of them.
    pub problem: PathBuf,
    /// Which method forms the equations.
    #[arg(long, value_enum, default_value_t)]
    pub method: MethodArg,
    /// Override constants: NAME=VALUE,...
    #[arg(long, value_name = "NAME=VALUE,...")]
    pub set: Vec<String>,
    /// Write there instead of standard output; a failed run leaves an existing file untouched.
    /// The problem file itself is refused (exit status 2).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Refuse problems with more bodies than this, whose derivation could take hours.
    #[arg(long, value_name = "N", default_value_t = MAX_BODIES)]
    pub max_bodies: usize,
    /// Refuse problems with more coordinates than this, whose derivation could take hours.
    #[arg(long, value_name = "N", default_value_t = MAX_COORDINATES)]
    pub max_coordinates: usize,
    /// Refuse, in seconds, a derivation whose symbolic work passes this many million
    /// expression terms (about 30 s and 1.5 GB at the default).
    #[arg(long, value_name = "MILLIONS", default_value_t = crate::symbolic::budget::DEFAULT_LIMIT / 1_000_000)]
    pub max_work: u64,
}

/// The commands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// The worked solution: the six steps, the tables, the equations and the simulation.
    Explain(ExplainArgs),
    /// The second derivatives of the coordinates and the requested reactions at one state.
    Solve(SolveArgs),
    /// Integrate the equations of motion over time.
    Simulate(SimulateArgs),
    /// Validate a problem and report every error in it at once.
    Check(CheckArgs),
    /// Small motions about a state: the state matrix, its eigenvalues and the modes.
    Linearize(LinearizeArgs),
    /// Print the JSON Schema of the problem format.
    Schema(SchemaArgs),
    /// SVG pictures of the configuration and of every free-body diagram of the plan.
    Draw(DrawArgs),
    /// Every question of `find.questions` answered in full precision, as text or JSON.
    Answer(AnswerArgs),
    /// Randomized variants of a problem, each with its worked solution and student
    /// handout, and `key.csv` with every variant's constants and answers.
    Variants(VariantsArgs),
    /// Serve the HTML worked solution on a local web server, rebuilt when the file changes.
    Serve(ServeArgs),
}

/// Parses `NAME=VALUE,...` lists (repeatable flags are joined).
///
/// # Errors
/// A usage error naming the malformed item.
pub fn parse_assignments(items: &[String]) -> Result<Vec<(String, f64)>, crate::Error> {
    let mut out = Vec::new();
    for item in items
        .iter()
        .flat_map(|s| s.split(','))
        .map(str::trim)
        .filter(|s| !s.is_empty())
    {
        let Some((name, value)) = item.split_once('=') else {
            return Err(crate::Error::Usage(format!("`{item}` is not NAME=VALUE")));
        };
        let value: f64 = value.trim().parse().map_err(|_| {
            crate::Error::Usage(format!("`{}` in `{item}` is not a number", value.trim()))
        })?;
        if !value.is_finite() {
            return Err(crate::Error::Usage(format!(
                "`{item}`: the value must be finite"
            )));
        }
        out.push((name.trim().to_string(), value));
    }
    Ok(out)
}
