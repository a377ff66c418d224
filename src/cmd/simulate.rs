//! `mbd-tutor simulate`: integrate the equations of motion and tabulate the motion.

use crate::cli::Common;
use crate::equations::derive;
use crate::numeric::evaluate::Compiled;
use crate::numeric::simulate::{simulate_with_limits, Limits};
use crate::Error;
use clap::ValueEnum;

/// How `simulate` writes its table.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Format {
    /// A header row, then one row per output step.
    #[default]
    Csv,
    /// `{ "columns": [...], "rows": [[...], ...] }`.
    Json,
}

/// Arguments of `mbd-tutor simulate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub common: Common,
    /// Seconds to simulate; default the problem's `simulate.duration` (5 s).
    #[arg(long)]
    pub duration: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,
    /// The most output rows before the run is refused (a guard against gigabytes of output).
    #[arg(long, default_value_t = crate::numeric::simulate::MAX_ROWS)]
    pub max_rows: usize,
}

/// Runs `mbd-tutor simulate`.
///
/// # Errors
/// An invalid problem, unusable settings, or a run that stops early (a singular
/// configuration): then everything computed up to that time is still written.
pub fn run(args: Args) -> Result<(), Error> {
    let mut problem = super::load_with_overrides(&args.common)?;
    if let Some(duration) = args.duration {
        if !(duration.is_finite() && duration > 0.0) {
            return Err(Error::Usage(
                "--duration must be a positive number of seconds".into(),
            ));
        }
        problem.simulate.duration = duration;
    }
    let derivation = derive(&problem, super::method(args.common.method))?;
    let compiled = Compiled::new(&derivation);
    let q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let limits = Limits {
        max_rows: args.max_rows,
        ..Limits::default()
    };
    let trajectory = simulate_with_limits(&compiled, &q0, &rates0, &problem.simulate, &limits)?;
    let text = match args.format {
        Format::Csv => trajectory.to_csv(),
        Format::Json => trajectory.to_json(),
    };
    crate::output::write_output(args.common.output.as_deref(), text.as_bytes())?;
    match trajectory.stopped {
        Some(reason) => Err(Error::Solve(reason)),
        None => Ok(()),
    }
}
