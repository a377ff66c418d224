//! The files a run reads, so that none of them is ever written: every file read through
//! [`crate::input::read_bounded`] is recorded by its identity (device and inode, which a
//! hard link or a symbolic link shares), and every output is compared with them.

use crate::Error;
use std::collections::HashSet;
use std::fs::Metadata;
use std::path::Path;
use std::sync::Mutex;

static READ: Mutex<Option<HashSet<(u64, u64)>>> = Mutex::new(None);

fn identity(meta: &Metadata) -> (u64, u64) {
    use std::os::unix::fs::MetadataExt;
    (meta.dev(), meta.ino())
}

/// Records a file this run read.
pub fn record(meta: &Metadata) {
    let mut read = READ.lock().unwrap_or_else(|e| e.into_inner());
    read.get_or_insert_with(HashSet::new).insert(identity(meta));
}

/// Whether the file of `meta` was read by this run.
pub fn was_read(meta: &Metadata) -> bool {
    let read = READ.lock().unwrap_or_else(|e| e.into_inner());
    read.as_ref().is_some_and(|r| r.contains(&identity(meta)))
}

/// Whether `a` and `b` name one file (by any path, hard link or symbolic link).
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(ma), Ok(mb)) => identity(&ma) == identity(&mb),
        _ => false,
    }
}

fn refusal(input: &Path, output: &Path) -> Error {
    Error::Usage(format!(
        "refusing to overwrite the problem file {} with the output {}: name another file or directory with -o",
        input.display(),
        output.display()
    ))
}

/// A usage error when one of `outputs`, the files a command is about to write, is `input`.
///
/// # Errors
/// [`Error::Usage`] naming both.
pub fn refuse_input(input: &Path, outputs: &[&Path]) -> Result<(), Error> {
    match outputs.iter().find(|output| same_file(input, output)) {
        Some(output) => Err(refusal(input, output)),
        None => Ok(()),
    }
}

/// A usage error when a file in `directory` whose name `claims` (a name the command will
/// write there) is `input`, under that name or through a link.
///
/// # Errors
/// [`Error::Usage`] naming both.
pub fn refuse_input_in(
    input: &Path,
    directory: &Path,
    claims: impl Fn(&str) -> bool,
) -> Result<(), Error> {
    let Ok(entries) = std::fs::read_dir(directory) else {
        // A directory that does not exist yet holds no input.
        return Ok(());
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        if claims(&name.to_string_lossy()) && same_file(input, &entry.path()) {
            return Err(refusal(input, &entry.path()));
        }
    }
    Ok(())
}
