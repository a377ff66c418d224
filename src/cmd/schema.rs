//! `mbd-tutor schema`: the JSON Schema of the problem format.

use crate::Error;

/// Arguments of `mbd-tutor schema`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Write there instead of standard output.
    #[arg(short, long)]
    pub output: Option<std::path::PathBuf>,
}

/// Runs `mbd-tutor schema`: prints the schema (draft 2020-12).
///
/// # Errors
/// [`Error::Io`] when the output cannot be written.
pub fn run(args: Args) -> Result<(), Error> {
    crate::output::write_output(
        args.output.as_deref(),
        crate::problem::schema::SCHEMA.as_bytes(),
    )
}
