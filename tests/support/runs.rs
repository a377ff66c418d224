//! The outputs of the commands the tests run, each run once for the whole suite (the
//! tests are threads of one process): most of the suite's time is the program writing the
//! same handouts for different tests.

use std::collections::HashMap;
use std::ffi::OsStr;
use std::path::Path;
use std::process::Output;
use std::sync::{Arc, Mutex, OnceLock};

/// The commands that read their files and write only to standard output.
const READING: [&str; 8] = [
    "explain",
    "solve",
    "simulate",
    "answer",
    "linearize",
    "statics",
    "impact",
    "check",
];

/// What a run is known by: its arguments, and the bytes of each one that names a file.
type Key = Vec<Vec<u8>>;

/// The outputs, each in its own cell so that one run waits only for the same run.
static OUTPUTS: OnceLock<Mutex<HashMap<Key, Arc<OnceLock<Output>>>>> = OnceLock::new();

/// The key of `args`, or `None` where the output may not be kept: a command that writes
/// a file (`-o`, `--output`), one outside [`READING`], or one that names a directory.
pub fn key<S: AsRef<OsStr>>(args: &[S]) -> Option<Key> {
    if std::env::var_os("MBD_TUTOR_TESTS_AFRESH").is_some() {
        return None;
    }
    let first = args.first()?.as_ref().to_str()?;
    if !READING.contains(&first) {
        return None;
    }
    let mut key = Vec::new();
    for arg in args {
        let arg = arg.as_ref();
        let text = arg.to_string_lossy();
        if text == "-o" || text.starts_with("--output") {
            return None;
        }
        key.push(arg.as_encoded_bytes().to_vec());
        let path = Path::new(arg);
        if path.is_dir() {
            return None;
        }
        if path.is_file() {
            key.push(std::fs::read(path).ok()?);
        }
    }
    Some(key)
}

/// The output of the run known by `key`, made by `run` the first time it is asked for.
pub fn once(key: Key, run: impl FnOnce() -> Output) -> Output {
    let cell = {
        let mut outputs = OUTPUTS.get_or_init(Mutex::default).lock().expect("lock");
        Arc::clone(outputs.entry(key).or_default())
    };
    cell.get_or_init(run).clone()
}
