//! Output that is never lost, never misdirected and never the input. The entry is
//! [`write_output`]; [`refuse_input`] and [`short_stem`] serve the commands that name
//! their outputs.
//!
//! A file is written to a temporary file beside it, created exclusively (a file or link
//! planted under the temporary name is never followed nor overwritten), then renamed over
//! the target; the target keeps its permissions. A target that is not a regular file (a
//! FIFO, a device, a directory, a link to one) or is read-only is refused, and so is any
//! file this run has read ([`refuse_input`]). The temporary file is removed on every failure,
//! and on SIGINT or SIGTERM while it is written (`cleanup`).

mod cleanup;
mod inputs;
mod names;
mod target;

use crate::Error;
use std::io::Write;
use std::path::Path;

pub use inputs::{refuse_input, refuse_input_in};
pub use names::short_stem;

/// Writes `bytes` to `path` atomically, or to standard output when `path` is `None` or `-`.
///
/// A failed run never leaves a half-written file and never truncates an existing one.
///
/// # Errors
/// [`Error::Usage`] for a target that is not a regular file, is read-only, or is a file
/// this run read; [`Error::Io`] when the temporary file cannot be written or renamed.
pub fn write_output(path: Option<&Path>, bytes: &[u8]) -> Result<(), Error> {
    let Some(path) = path.filter(|p| p.as_os_str() != "-") else {
        let mut stdout = std::io::stdout().lock();
        return stdout
            .write_all(bytes)
            .and_then(|()| stdout.flush())
            .map_err(|source| Error::Io {
                path: "<stdout>".into(),
                source,
            });
    };
    let target = target::Target::check(path)?;
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let (temporary, mut file) = target.create_temporary().map_err(io)?;
    let guard = cleanup::Guard::new(&temporary);
    let result = file
        .write_all(bytes)
        .and_then(|()| target.keep_owner_and_mode(&file))
        .and_then(|()| file.sync_all())
        .and_then(|()| {
            drop(file);
            std::fs::rename(&temporary, target.real())
        });
    if result.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    drop(guard);
    result.map_err(io)
}
