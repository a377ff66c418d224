//! The command line: clap types, converted into a plain `Config` before any work.

mod commands;
mod common;

pub use commands::*;
pub use common::*;

use clap::{Parser, Subcommand};

/// Derive, solve and explain the equations of motion of rigid multibody systems.
#[derive(Parser, Debug)]
#[command(name = "mbd-tutor", version, about)]
pub struct Cli {
    /// The command to run.
    #[command(subcommand)]
    pub command: Command,
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
    /// Equilibria at rest: reactions, holding forces, stability and friction ratios.
    Statics(StaticsArgs),
    /// The rates just after the problem's impact, its impulses and the kinetic energy
    /// before and after.
    Impact(ImpactArgs),
    /// Check a student's submission against the worked solution, item by item, with a
    /// diagnosis of each mistake; `--batch` grades a class into one gradebook (CSV).
    Grade(GradeArgs),
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
