//! One file per subcommand; each turns its arguments into work on the pipeline. The
//! entry is [`run`]; [`derivation_at`] serves the drawings' tests.

mod answer;
mod check;
mod draw;
mod explain;
mod grade;
mod impact;
mod linearize;
mod schema;
mod serve;
mod simulate;
mod solve;
mod statics;
mod variants;

pub use draw::derivation_at;

use crate::cli::Command;
use crate::problem::{ProblemError, ProblemErrors};
use crate::Error;
use std::path::Path;

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
        Command::Linearize(args) => linearize::run(args),
        Command::Schema(args) => schema::run(args),
        Command::Draw(args) => draw::run(args),
        Command::Answer(args) => answer::run(args),
        Command::Variants(args) => variants::run(args),
        Command::Serve(args) => serve::run(args),
        Command::Statics(args) => statics::run(args),
        Command::Impact(args) => impact::run(args),
        Command::Grade(args) => grade::run(args),
    }
}

/// The method chosen on the command line.
pub fn method(arg: crate::cli::MethodArg) -> crate::equations::Method {
    match arg {
        crate::cli::MethodArg::MotionLaw => crate::equations::Method::MotionLaw,
        crate::cli::MethodArg::NewtonEuler => crate::equations::Method::NewtonEuler,
        crate::cli::MethodArg::Kane => crate::equations::Method::Kane,
        crate::cli::MethodArg::Lagrange => crate::equations::Method::Lagrange,
    }
}

/// Says on standard error which coordinates and rates the constraints solve for and which
/// rows were dropped, and which `--state` values are only guesses or are ignored, so that
/// JSON on standard output stays clean.
pub fn report_constraints(model: &crate::mechanics::Model, state: &[String]) {
    let constraints = &model.constraints;
    for note in &constraints.notes {
        eprintln!("{note}");
    }
    for (row, why) in &constraints.dropped {
        eprintln!("Constraint `{row}` left out: {why}.");
    }
    let problem = model.problem;
    let Ok(assignments) = crate::cli::parse_assignments(state) else {
        return;
    };
    for (name, _) in assignments {
        let (base, is_rate) = match name.strip_suffix('\'') {
            Some(base) => (base, true),
            None => (name.as_str(), false),
        };
        let Some(i) = problem.coordinates.iter().position(|c| c.name == base) else {
            continue;
        };
        if problem.coordinates[i].motion.is_some() {
            eprintln!("--state {name}: ignored, `{base}` is prescribed by its motion");
        } else if is_rate && constraints.dependent_rates.contains(&i) {
            eprintln!("--state {name}: ignored, the rate of `{base}` is solved from the velocity constraints");
        } else if !is_rate && constraints.dependent.contains(&i) {
            eprintln!("--state {name}: a starting guess, `{base}` is solved from the position constraints");
        }
    }
}

/// Loads the problem named on the command line and applies `--set`, refusing an output
/// file that is the problem file and a problem beyond the size limits.
///
/// # Errors
/// A usage error when `-o` names the problem file; an unreadable or invalid problem, a
/// `--set` that names no constant, or more bodies or coordinates than the limits allow.
pub fn load_with_overrides(common: &crate::cli::Common) -> Result<crate::problem::Problem, Error> {
    refuse_overwriting(&common.problem, common.output.as_deref())?;
    let mut problem = crate::pipeline::load(&common.problem)?;
    let overrides = crate::cli::parse_assignments(&common.set)?;
    crate::problem::apply_overrides(&mut problem, &overrides)?;
    check_size(&problem, common.max_bodies, common.max_coordinates)?;
    // Every derivation of this command is counted against the limit (see `budget`).
    crate::symbolic::budget::set_limit(common.max_work.saturating_mul(1_000_000));
    Ok(problem)
}

/// A usage error when `output` is the file `problem` (under any name, links included):
/// writing the result there would destroy the problem.
///
/// # Errors
/// [`Error::Usage`] naming the file.
pub fn refuse_overwriting(problem: &Path, output: Option<&Path>) -> Result<(), Error> {
    let Some(output) = output else {
        return Ok(());
    };
    if crate::input::same_file(problem, output) {
        return Err(Error::Usage(format!(
            "refusing to overwrite the problem file {} with the output: name another file with -o",
            output.display()
        )));
    }
    Ok(())
}

/// An error naming the limit and the flag that raises it, for a problem beyond
/// `--max-bodies` or `--max-coordinates`.
///
/// # Errors
/// [`Error::Problem`] naming each limit passed and the flag that raises it.
pub fn check_size(
    problem: &crate::problem::Problem,
    max_bodies: usize,
    max_coordinates: usize,
) -> Result<(), Error> {
    let limits = [
        (
            "bodies",
            "bodies",
            problem.bodies.len(),
            max_bodies,
            "--max-bodies",
        ),
        (
            "joints",
            "coordinates",
            problem.coordinates.len(),
            max_coordinates,
            "--max-coordinates",
        ),
    ];
    let errors: Vec<ProblemError> = limits
        .into_iter()
        .filter(|&(_, _, count, limit, _)| count > limit)
        .map(|(path, what, count, limit, flag)| ProblemError {
            path: path.to_string(),
            column: None,
            message: format!(
                "the problem has {count} {what}, more than the limit of {limit}: deriving its equations could take hours"
            ),
            hint: Some(format!("raise the limit with {flag} {count}")),
        })
        .collect();
    if errors.is_empty() {
        Ok(())
    } else {
        Err(Error::Problem(ProblemErrors(errors)))
    }
}
