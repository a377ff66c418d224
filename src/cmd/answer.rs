//! `mbd-tutor answer`: every question of `find.questions` answered, without a handout.

use crate::cli::Common;
use crate::output::write_output;
use crate::render::answer_sheet;
use crate::Error;
use clap::ValueEnum;

/// The output format of `answer`.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AnswerFormat {
    /// One block per question: its text, then each value with its unit.
    #[default]
    Text,
    /// `{ "answers": [ … ] }`, every number in full precision, for a grader.
    Json,
}

/// Arguments of `mbd-tutor answer`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: AnswerFormat,
}

/// Runs `mbd-tutor answer`.
///
/// # Errors
/// An invalid problem, a problem without questions, equations that cannot be derived, or
/// the first question that cannot be answered (its JSON path and a hint).
pub fn run(args: Args) -> Result<(), Error> {
    let problem = super::load_with_overrides(&args.common)?;
    if problem.questions.is_empty() {
        let mut error = crate::problem::ProblemError::file(
            "the problem asks nothing: `find.questions` is empty or missing",
        );
        error.path = "find.questions".into();
        error.hint = Some(
            "add questions, e.g. \"find\": { \"questions\": [ { \"value\": \"q1''\" } ] }".into(),
        );
        return Err(Error::Problem(crate::problem::ProblemErrors(vec![error])));
    }
    let answers = crate::pipeline::answers(&problem, super::method(args.common.method))?;
    let text = match args.format {
        AnswerFormat::Text => answer_sheet::text(&problem, &answers),
        AnswerFormat::Json => answer_sheet::json(&problem, &answers),
    };
    write_output(args.common.output.as_deref(), text.as_bytes())
}
