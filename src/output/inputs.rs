//! No output is ever an input: the refusals of a command about to write over the file it
//! read (the files read are recorded by [`crate::input`]).

use crate::input::same_file;
use crate::Error;
use std::path::Path;

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
