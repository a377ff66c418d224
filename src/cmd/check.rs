//! `mbd-tutor check`.

use crate::Error;

/// Arguments of `mbd-tutor check`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub common: crate::cli::Common,
}

/// Runs `mbd-tutor check`.
///
/// # Errors
/// Not written yet.
pub fn run(_args: Args) -> Result<(), Error> {
    Err(Error::Usage("`check` is not available yet".into()))
}
