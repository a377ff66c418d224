//! `mbd-tutor simulate`: integrate the equations of motion and tabulate the motion.

use crate::cli::{SimulateArgs, SimulateFormat};
use crate::numeric::Check;
use crate::numeric::{output_times, simulate_with_limits, Limits, SolveError};
use crate::pipeline::{derive, Purpose};
use crate::problem::{ProblemError, ProblemErrors};
use crate::symbolic::fixed;
use crate::Error;

/// Runs `mbd-tutor simulate`.
///
/// # Errors
/// An invalid problem, unusable settings, or a run that stops early (a singular
/// configuration): then everything computed up to that time is still written.
pub fn run(args: SimulateArgs) -> Result<(), Error> {
    let mut problem = super::load_with_overrides(&args.common)?;
    if let Some(duration) = args.duration {
        if !(duration.is_finite() && duration > 0.0) {
            return Err(Error::Usage(
                "--duration must be a positive number of seconds".into(),
            ));
        }
        problem.simulate.duration = duration;
    }
    // The output's size is known before any work: refuse it before deriving.
    if let Err(e) = output_times(
        problem.simulate.duration,
        problem.simulate.output_step,
        args.max_rows,
    ) {
        return Err(too_many_rows(e));
    }
    let derivation = derive(
        &problem,
        super::method(args.common.method),
        Purpose::Numbers,
    )?;
    super::report_constraints(&derivation.model, &[]);
    let solver = crate::pipeline::Solver::fastest(&problem, &derivation);
    let initial = problem.initial_state();
    let (mut q0, mut rates0) = (initial.q, initial.rates);
    if problem.impact.is_some() {
        // The motion after the impact: from its configuration, with the rates just after.
        let impact = crate::pipeline::impact_at_start(&problem, &derivation.model, &solver)?;
        eprintln!("The run starts just after the impact at t = 0.");
        (q0, rates0) = (impact.q, impact.after);
    }
    let limits = Limits {
        max_rows: args.max_rows,
        ..Limits::default()
    };
    let trajectory = simulate_with_limits(&solver, &q0, &rates0, &problem.simulate, &limits)
        .map_err(too_many_rows)?;
    // A run that stopped before its first row (a state that cannot be assembled) has
    // nothing to write: fail without touching the output.
    if trajectory.rows.is_empty() {
        if let Some(reason) = trajectory.stopped {
            return Err(Error::Solve(reason));
        }
    }
    for switch in &trajectory.switches {
        eprintln!("{}", switch.describe(&problem));
    }
    let text = match args.format {
        SimulateFormat::Csv => trajectory.to_csv(),
        SimulateFormat::Json => trajectory.to_json(),
    };
    crate::output::write_output(args.common.output.as_deref(), text.as_bytes())?;
    match trajectory.stopped {
        Some(reason) => Err(Error::Solve(reason)),
        None => {
            if !args.no_checks {
                let checks = crate::pipeline::confirm(&problem, &solver, &trajectory, &q0);
                eprint!("{}", report(solver.method().name(), &checks));
            }
            Ok(())
        }
    }
}

/// The checks as lines for standard error (the table itself goes to the output).
fn report(method: &str, checks: &[Check]) -> String {
    let mut text = format!("Confirmation of the {method} equations:\n");
    if checks.is_empty() {
        text.push_str("  no check applies to this problem\n");
    }
    for check in checks {
        text.push_str(&format!(
            "  {}: {} {} {} ({}): {}\n",
            check.name(),
            fixed(check.value),
            if check.passed { "<" } else { ">=" },
            fixed(check.tolerance),
            if check.passed { "pass" } else { "FAIL" },
            check.detail()
        ));
    }
    text
}

/// [`SolveError::TooManyRows`] as an error that names `--max-rows`; other errors as they are.
fn too_many_rows(error: SolveError) -> Error {
    match error {
        SolveError::TooManyRows { rows, limit } => Error::Problem(ProblemErrors(vec![ProblemError {
            path: "simulate.output_step".into(),
            column: None,
            message: format!("the simulation would write {rows} rows, more than the limit of {limit}"),
            hint: Some(format!(
                "shorten `duration`, lengthen `output_step`, or raise the limit with --max-rows {rows}"
            )),
        }])),
        other => Error::Solve(other),
    }
}
