//! `mbd-tutor check`: validate a problem and report every error in it at once.

use crate::cli::CheckArgs;
use crate::problem::{self, Dimension, Problem};
use crate::Error;

/// Runs `mbd-tutor check`: prints a one-line summary when the problem is valid.
///
/// # Errors
/// [`Error::Problem`] with every error found; [`Error::Io`] when the file cannot be read;
/// [`Error::Usage`] for a malformed `--set`; [`Error::Problem`] naming the limit for a problem
/// beyond `--max-bodies` or `--max-coordinates`.
pub fn run(args: CheckArgs) -> Result<(), Error> {
    let overrides = crate::cli::parse_assignments(&args.set)?;
    let mut problem = problem::load_file(&args.problem)?;
    problem::apply_overrides(&mut problem, &overrides)?;
    // The same limits as `solve`, before the model is built: a chain of thousands of links
    // is refused at once rather than built for minutes.
    super::check_size(&problem, args.max_bodies, args.max_coordinates)?;
    crate::symbolic::budget::set_limit(args.max_work.saturating_mul(1_000_000));
    structure(&problem)?;
    println!("{}", summary(&problem));
    Ok(())
}

/// The checks of the model's structure that `solve` makes before any number is solved
/// for (dependent coordinates and rates against the constraints, constraints the joints
/// already keep, a massless body that nothing fixes): the same code, through the model's
/// construction, reported as a problem error with its path and hint.
fn structure(problem: &Problem) -> Result<(), Error> {
    match crate::mechanics::Model::build(problem) {
        Ok(_) => Ok(()),
        Err(e) => Err(Error::Problem(problem::ProblemErrors(vec![
            problem::ProblemError {
                path: e.path,
                column: None,
                message: e.message,
                hint: e.hint,
            },
        ]))),
    }
}

fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// `ok: <title>: 2 bodies, 2 joints, 2 coordinates (2D)`.
pub fn summary(problem: &Problem) -> String {
    let dimension = match problem.dimension {
        Dimension::Two => "2D",
        Dimension::Three => "3D",
    };
    format!(
        "ok: {}: {}, {}, {} ({dimension})",
        problem.title,
        count(problem.bodies.len(), "body", "bodies"),
        count(problem.joints.len(), "joint", "joints"),
        count(problem.coordinates.len(), "coordinate", "coordinates"),
    )
}
