//! `mbd-tutor answer`: every question of `find.questions` answered, without a handout.

use crate::cli::{AnswerArgs, AnswerFormat};
use crate::output::write_output;
use crate::solution::{answer_sheet_json, answer_sheet_text};
use crate::Error;

/// Runs `mbd-tutor answer`.
///
/// # Errors
/// An invalid problem, a problem without questions, equations that cannot be derived, or
/// the first question that cannot be answered (its JSON path and a hint).
pub fn run(args: AnswerArgs) -> Result<(), Error> {
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
        AnswerFormat::Text => answer_sheet_text(&problem, &answers),
        AnswerFormat::Json => answer_sheet_json(&problem, &answers),
    };
    write_output(args.common.output.as_deref(), text.as_bytes())
}
