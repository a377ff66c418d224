//! Reading what the tool is given, bounded before it is read: regular files only (a FIFO,
//! a device, a directory or a link to one is refused without waiting on it), at most a
//! given size, with a message that names the limit.

use std::collections::HashSet;
use std::fs::Metadata;
use std::io::Read;
use std::path::Path;
use std::sync::Mutex;

/// The files this run read, by identity (device and inode, which a hard link or a symbolic
/// link shares), so that no output of the run is ever one of them.
static READ: Mutex<Option<HashSet<(u64, u64)>>> = Mutex::new(None);

fn identity(meta: &Metadata) -> (u64, u64) {
    use std::os::unix::fs::MetadataExt;
    (meta.dev(), meta.ino())
}

/// Records a file this run read.
fn record(meta: &Metadata) {
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

/// The largest problem file read: a problem at the limits (30 bodies, 60 coordinates) with
/// every description written out takes well under 1 MB.
pub const MAX_PROBLEM_BYTES: u64 = 4 * 1024 * 1024;

/// The largest template read by `explain --templates`.
pub const MAX_TEMPLATE_BYTES: u64 = 1024 * 1024;

/// The bytes of the regular file at `path`, refused when it is anything else or longer
/// than `limit` bytes. The file is opened without blocking, so that a FIFO with no writer
/// is refused at once rather than waited on.
///
/// # Errors
/// The open's error; [`std::io::ErrorKind::InvalidInput`] for a file that is not regular
/// or is over the limit, with a sentence that says which.
pub fn read_bounded(path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
    use std::os::unix::fs::OpenOptionsExt;
    let file = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY)
        .open(path)?;
    let meta = file.metadata()?;
    // Recorded before anything else, so that no output of this run is ever this file.
    record(&meta);
    if !meta.is_file() {
        return Err(refused(format!(
            "{} is not a regular file: only a file's contents can be read",
            kind(&meta.file_type())
        )));
    }
    let too_long = || {
        refused(format!(
            "the file is longer than the limit of {} bytes ({} MiB)",
            limit,
            limit / (1024 * 1024)
        ))
    };
    if meta.len() > limit {
        return Err(too_long());
    }
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if u64::try_from(bytes.len()).unwrap_or(u64::MAX) > limit {
        return Err(too_long());
    }
    Ok(bytes)
}

/// The text of the regular file at `path`, as [`read_bounded`], then checked as UTF-8.
///
/// # Errors
/// As [`read_bounded`]; [`std::io::ErrorKind::InvalidData`] for text that is not UTF-8.
pub fn read_text_bounded(path: &Path, limit: u64) -> std::io::Result<String> {
    String::from_utf8(read_bounded(path, limit)?).map_err(|e| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "the file is not UTF-8 text: the byte at offset {} is not valid UTF-8",
                e.utf8_error().valid_up_to()
            ),
        )
    })
}

fn refused(message: String) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidInput, message)
}

/// What a file that is not regular is, in a sentence's words.
pub(crate) fn kind(file_type: &std::fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if file_type.is_dir() {
        "a directory"
    } else if file_type.is_fifo() {
        "a FIFO (named pipe)"
    } else if file_type.is_char_device() {
        "a character device"
    } else if file_type.is_block_device() {
        "a block device"
    } else if file_type.is_socket() {
        "a socket"
    } else if file_type.is_symlink() {
        "a symbolic link"
    } else {
        "the file"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_device_and_a_directory_are_refused_without_reading() {
        for path in ["/dev/zero", "/tmp"] {
            let error = read_bounded(Path::new(path), 10).unwrap_err();
            assert_eq!(error.kind(), std::io::ErrorKind::InvalidInput, "{path}");
            assert!(error.to_string().contains("not a regular file"), "{error}");
        }
    }

    #[test]
    fn a_file_over_the_limit_is_refused_and_one_at_it_read() {
        let path = std::env::temp_dir().join(format!("mbd-bounded-{}", std::process::id()));
        std::fs::write(&path, b"0123456789").unwrap();
        assert_eq!(read_bounded(&path, 10).unwrap(), b"0123456789");
        let error = read_bounded(&path, 9).unwrap_err();
        assert!(error.to_string().contains("limit of 9 bytes"), "{error}");
        let _ = std::fs::remove_file(&path);
    }
}
