//! `mbd-tutor simulate`.

use crate::Error;

/// Arguments of `mbd-tutor simulate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub common: crate::cli::Common,
}

/// Runs `mbd-tutor simulate`.
///
/// # Errors
/// Not written yet.
pub fn run(_args: Args) -> Result<(), Error> {
    Err(Error::Usage("`simulate` is not available yet".into()))
}
