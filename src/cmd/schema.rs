//! `mbd-tutor schema`: the JSON Schema of the problem format.

use crate::cli::SchemaArgs;
use crate::Error;

/// Runs `mbd-tutor schema`: prints the schema (draft 2020-12).
///
/// # Errors
/// [`Error::Io`] when the output cannot be written.
pub fn run(args: SchemaArgs) -> Result<(), Error> {
    crate::output::write_output(args.output.as_deref(), crate::problem::SCHEMA.as_bytes())
}
