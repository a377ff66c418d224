//! The temporary file removed when SIGINT or SIGTERM arrives while it is written: the
//! handler unlinks it (async-signal-safe), then lets the signal end the process as it
//! would have.

use std::ffi::CString;
use std::path::Path;
use std::sync::atomic::{AtomicPtr, Ordering};
use std::sync::Once;

/// The temporary file being written, as a C string, or null.
static TEMPORARY: AtomicPtr<libc::c_char> = AtomicPtr::new(std::ptr::null_mut());

static INSTALL: Once = Once::new();

/// Registers a temporary file for removal on SIGINT or SIGTERM until dropped.
pub(super) struct Guard;

impl Guard {
    pub fn new(temporary: &Path) -> Guard {
        INSTALL.call_once(install);
        use std::os::unix::ffi::OsStrExt;
        if let Ok(path) = CString::new(temporary.as_os_str().as_bytes()) {
            let old = TEMPORARY.swap(path.into_raw(), Ordering::SeqCst);
            free(old);
        }
        Guard
    }
}

impl Drop for Guard {
    fn drop(&mut self) {
        free(TEMPORARY.swap(std::ptr::null_mut(), Ordering::SeqCst));
    }
}

fn free(path: *mut libc::c_char) {
    if !path.is_null() {
        // SAFETY: every non-null pointer stored came from CString::into_raw, and the swap
        // that returned it removed it from TEMPORARY, so it is freed once.
        drop(unsafe { CString::from_raw(path) });
    }
}

extern "C" fn on_signal(signal: libc::c_int) {
    let path = TEMPORARY.load(Ordering::SeqCst);
    // SAFETY: unlink, signal and raise are async-signal-safe; the path stays allocated
    // while registered (it is only freed after being swapped out).
    unsafe {
        if !path.is_null() {
            libc::unlink(path);
        }
        libc::signal(signal, libc::SIG_DFL);
        libc::raise(signal);
    }
}

fn install() {
    for signal in [libc::SIGINT, libc::SIGTERM] {
        // SAFETY: the handler only calls async-signal-safe functions. A signal already
        // ignored (a background job's SIGINT) is left ignored.
        unsafe {
            let previous = libc::signal(signal, on_signal as *const () as libc::sighandler_t);
            if previous == libc::SIG_IGN {
                libc::signal(signal, libc::SIG_IGN);
            }
        }
    }
}
