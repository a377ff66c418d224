//! `mbd-tutor solve`.

use crate::Error;

/// Arguments of `mbd-tutor solve`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub common: crate::cli::Common,
}

/// Runs `mbd-tutor solve`.
///
/// # Errors
/// Not written yet.
pub fn run(_args: Args) -> Result<(), Error> {
    Err(Error::Usage("`solve` is not available yet".into()))
}
