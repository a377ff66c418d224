//! `mbd-tutor grade`: a student's work checked against the worked solution, item by item,
//! and the mistake named; `--batch` grades a class into one gradebook.

use crate::cli::{GradeArgs, GradeFormat};
use crate::grade::{grade, Reference};
use crate::output::write_output;
use crate::Error;

/// Runs `mbd-tutor grade`.
///
/// # Errors
/// A usage error for missing files, an invalid problem or submission (with its JSON path
/// and a hint), or equations that cannot be derived.
pub fn run(args: GradeArgs) -> Result<(), Error> {
    let method = super::method(args.method);
    if let Some(dir) = &args.batch {
        let key = args.key.as_deref().ok_or_else(|| {
            Error::Usage("--batch needs --key KEY.csv (written by `variants`)".into())
        })?;
        let csv = crate::grade::grade_batch(dir, key, method)?;
        return write_output(args.output.as_deref(), csv.as_bytes());
    }
    let (Some(problem_path), Some(submission_path)) = (&args.problem, &args.submission) else {
        return Err(Error::Usage(
            "grade needs PROBLEM.json and SUBMISSION.json, or --batch DIR --key KEY.csv".into(),
        ));
    };
    super::refuse_overwriting(problem_path, args.output.as_deref())?;
    super::refuse_overwriting(submission_path, args.output.as_deref())?;
    let problem = crate::pipeline::load(problem_path)?;
    let text = std::fs::read_to_string(submission_path).map_err(|source| Error::Io {
        path: submission_path.clone(),
        source,
    })?;
    let submission = crate::grade::read(&text).map_err(Error::Submission)?;
    let asked = crate::grade::asked_questions([&submission]);
    let reference = Reference::answering(&problem, method, &asked)?;
    let report = grade(&reference, &submission);
    let text = match args.format {
        GradeFormat::Text => report.text(),
        GradeFormat::Json => {
            let mut text = serde_json::to_string_pretty(&report.json()).unwrap_or_default();
            text.push('\n');
            text
        }
    };
    write_output(args.output.as_deref(), text.as_bytes())
}
