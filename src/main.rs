//! The `mbd-tutor` command: parses the command line and runs the command (see the
//! library, `mbd_tutor`).

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = match mbd_tutor::cli::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    match mbd_tutor::cmd::run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) if error.is_closed_output() => ExitCode::SUCCESS,
        Err(error) => {
            // The whole cause chain, so that the student sees where and why.
            eprintln!("error: {error}");
            let mut source = std::error::Error::source(&error);
            while let Some(cause) = source {
                eprintln!("  caused by: {cause}");
                source = cause.source();
            }
            ExitCode::from(error.exit_code())
        }
    }
}
