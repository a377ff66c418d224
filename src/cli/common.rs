//! What every command that reads a problem shares: the problem, the method, `--set`,
//! `-o` and the limits on the size of a derivation.

use clap::ValueEnum;
use std::path::PathBuf;

/// The most bodies that `explain`, `solve` and `simulate` derive unless `--max-bodies`
/// raises it: the symbolic work grows steeply with the size of the system.
pub const MAX_BODIES: usize = 30;

/// The most coordinates those commands derive unless `--max-coordinates` raises it.
pub const MAX_COORDINATES: usize = 60;

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
    /// Lagrange's equations, with multipliers for the constraints.
    Lagrange,
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
