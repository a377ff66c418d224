//! `mbd-tutor explain`.

use crate::Error;

/// Arguments of `mbd-tutor explain`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub common: crate::cli::Common,
}

/// Runs `mbd-tutor explain`.
///
/// # Errors
/// Not written yet.
pub fn run(_args: Args) -> Result<(), Error> {
    Err(Error::Usage("`explain` is not available yet".into()))
}
