//! `mbd-tutor schema`.

use crate::Error;

/// Arguments of `mbd-tutor schema`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Write there instead of standard output.
    #[arg(short, long)]
    pub output: Option<std::path::PathBuf>,
}

/// Runs `mbd-tutor schema`.
///
/// # Errors
/// Not written yet.
pub fn run(_args: Args) -> Result<(), Error> {
    Err(Error::Usage("`schema` is not available yet".into()))
}
