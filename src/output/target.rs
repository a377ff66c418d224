//! The file an output goes to: checked before anything is written, and its temporary file.

use crate::Error;
use std::fs::{File, Metadata};
use std::path::{Path, PathBuf};

/// A checked target: where the bytes go (a link's target, when the name is a link to a
/// regular file) and what the existing file there was.
pub(super) struct Target {
    /// The file renamed over: the name given, or the file a link names.
    real: PathBuf,
    /// The existing file's metadata, when there is one.
    existing: Option<Metadata>,
}

impl Target {
    /// Checks `path`: missing, or a regular file (through links) that can be written and
    /// that this run did not read.
    ///
    /// # Errors
    /// [`Error::Usage`] naming the file and why it is refused.
    pub fn check(path: &Path) -> Result<Target, Error> {
        let refuse = |why: String| {
            Err(Error::Usage(format!(
                "refusing to write {}: {why}; name another file with -o",
                path.display()
            )))
        };
        let existing = match std::fs::metadata(path) {
            Ok(meta) => Some(meta),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
            Err(source) => {
                return Err(Error::Io {
                    path: path.to_path_buf(),
                    source,
                })
            }
        };
        let Some(meta) = existing else {
            // A dangling link: the rename replaces the link itself.
            return Ok(Target {
                real: path.to_path_buf(),
                existing: None,
            });
        };
        if !meta.is_file() {
            return refuse(format!(
                "it is {}, not a regular file",
                crate::input::kind(&meta.file_type())
            ));
        }
        {
            use std::os::unix::fs::PermissionsExt;
            if meta.permissions().mode() & 0o222 == 0 {
                return refuse("it is read-only".into());
            }
        }
        if crate::input::was_read(&meta) {
            return refuse("it is a file this command reads".into());
        }
        let real = std::fs::canonicalize(path).map_err(|source| Error::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Ok(Target {
            real,
            existing: Some(meta),
        })
    }

    /// The path renamed over.
    pub fn real(&self) -> &Path {
        &self.real
    }

    /// A new temporary file beside the target, created exclusively and without following a
    /// link: a name already taken (by anything, a planted link included) is skipped.
    pub fn create_temporary(&self) -> std::io::Result<(PathBuf, File)> {
        use std::os::unix::fs::OpenOptionsExt;
        let directory = self
            .real
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let name = self
            .real
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        // A long name leaves room for the temporary's dot and suffix (255 bytes a name).
        let mut cut = name.len().min(180);
        while !name.is_char_boundary(cut) {
            cut -= 1;
        }
        let name = &name[..cut];
        let mut last = None;
        for attempt in 0..64u32 {
            let temporary = directory.join(format!(".{name}.{}.{attempt}.tmp", std::process::id()));
            let opened = std::fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .mode(0o600)
                .custom_flags(libc::O_NOFOLLOW | libc::O_CLOEXEC)
                .open(&temporary);
            match opened {
                Ok(file) => return Ok((temporary, file)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => last = Some(e),
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| std::io::Error::other("no free temporary name")))
    }

    /// Gives the temporary file the existing target's permissions (and, where allowed, its
    /// owner), or those a new file gets (0666 less the umask).
    pub fn keep_owner_and_mode(&self, file: &File) -> std::io::Result<()> {
        use std::os::unix::fs::{MetadataExt, PermissionsExt};
        let mode = match &self.existing {
            Some(meta) => {
                // Only the owner's own files may be given away; failing that, keep ours.
                let _ = std::os::unix::fs::fchown(file, Some(meta.uid()), Some(meta.gid()));
                meta.permissions().mode() & 0o7777
            }
            None => 0o666 & !umask(),
        };
        file.set_permissions(std::fs::Permissions::from_mode(mode))
    }
}

/// The process's umask (read by setting it and setting it back).
fn umask() -> libc::mode_t {
    // SAFETY: umask only sets the process's file-creation mask and returns the old one.
    let old = unsafe { libc::umask(0o022) };
    // SAFETY: as above, restoring the mask read.
    unsafe { libc::umask(old) };
    old
}

#[cfg(test)]
mod tests {
    use super::super::write_output;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("mbd-target-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_link_planted_at_the_temporary_name_is_not_followed() {
        let dir = scratch("planted");
        let victim = dir.join("victim");
        std::fs::write(&victim, b"precious").unwrap();
        let planted = dir.join(format!(".out.txt.{}.0.tmp", std::process::id()));
        std::os::unix::fs::symlink(&victim, &planted).unwrap();
        let out = dir.join("out.txt");
        write_output(Some(&out), b"result").unwrap();
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
        assert!(std::fs::symlink_metadata(&planted)
            .unwrap()
            .file_type()
            .is_symlink());
        assert!(std::fs::symlink_metadata(&out)
            .unwrap()
            .file_type()
            .is_file());
        assert_eq!(std::fs::read(&out).unwrap(), b"result");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn every_temporary_name_taken_is_an_error_that_writes_nothing() {
        let dir = scratch("taken");
        let victim = dir.join("victim");
        std::fs::write(&victim, b"precious").unwrap();
        for attempt in 0..64 {
            let planted = dir.join(format!(".out.txt.{}.{attempt}.tmp", std::process::id()));
            std::os::unix::fs::symlink(&victim, &planted).unwrap();
        }
        let out = dir.join("out.txt");
        assert!(write_output(Some(&out), b"result").is_err());
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
        assert!(!out.exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_private_file_stays_private_and_a_new_one_follows_the_umask() {
        use std::os::unix::fs::PermissionsExt;
        let dir = scratch("mode");
        let key = dir.join("key.csv");
        std::fs::write(&key, b"old").unwrap();
        std::fs::set_permissions(&key, std::fs::Permissions::from_mode(0o600)).unwrap();
        write_output(Some(&key), b"new").unwrap();
        let mode = std::fs::metadata(&key).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o600);
        let fresh = dir.join("fresh.txt");
        write_output(Some(&fresh), b"new").unwrap();
        let mode = std::fs::metadata(&fresh).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o666 & !super::umask());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
