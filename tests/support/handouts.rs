//! Handouts of the bundled problems, written by the built binary and read many at a time.

use std::path::Path;
use std::process::Output;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// `mbd-tutor explain PATH --method METHOD --format FORMAT`; `None` where the method is
/// refused (other tests see to which are).
pub fn handout_of(path: &Path, method: &str, format: &str) -> Option<String> {
    handout_with(path, method, format, &[])
}

/// `mbd-tutor explain PATH --method METHOD --format FORMAT FLAGS…`; `None` where it is
/// refused (other tests see to which are).
pub fn handout_with(path: &Path, method: &str, format: &str, flags: &[&str]) -> Option<String> {
    let out = explained_with(path, method, format, flags);
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The handout of the bundled problem `name` by `method` in `format`; panics where it is
/// refused.
pub fn bundled(name: &str, method: &str, format: &str) -> String {
    handout_of(&super::problem(name), method, format).expect("the handout")
}

/// Asserts that `text` (the handout of `name`) holds `what`.
pub fn has(text: &str, what: &str, name: &str) {
    assert!(text.contains(what), "{name}: `{what}` not found");
}

/// Asserts that `text` (the handout of `name`) does not hold `what`, showing where it does.
pub fn lacks(text: &str, what: &str, name: &str) {
    if let Some(at) = text.find(what) {
        let end = (at + 200).min(text.len());
        let around = text.get(at..end).unwrap_or(what);
        panic!("{name}: `{what}` in: {around}");
    }
}

/// The run of `mbd-tutor explain PATH --method METHOD --format FORMAT`, with `--student`
/// for the student's handout: one for the whole suite, whichever test asks first.
pub fn explained(path: &Path, method: &str, format: &str, student: bool) -> Output {
    let flags: &[&str] = if student { &["--student"] } else { &[] };
    explained_with(path, method, format, flags)
}

/// The run of `mbd-tutor explain PATH --method METHOD --format FORMAT FLAGS…` (such as
/// `--student`, `--statics`): one for the whole suite, whichever test asks first.
pub fn explained_with(path: &Path, method: &str, format: &str, flags: &[&str]) -> Output {
    let mut args = vec![
        "explain".as_ref(),
        path.as_os_str(),
        "--method".as_ref(),
        method.as_ref(),
        "--format".as_ref(),
        format.as_ref(),
    ];
    args.extend(flags.iter().map(std::ffi::OsStr::new));
    super::run(&args)
}

/// What `check` finds wrong in each of `jobs`, run two at a time (the machine's cores),
/// gathered in the order they were found.
pub fn two_at_a_time<J, F>(jobs: &[J], check: F) -> Vec<String>
where
    J: Sync,
    F: Fn(&J) -> Vec<String> + Sync,
{
    let found = Mutex::new(Vec::new());
    let next = AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                let Some(job) = jobs.get(k) else {
                    break;
                };
                let wrong = check(job);
                found.lock().expect("lock").extend(wrong);
            });
        }
    });
    found.into_inner().expect("lock")
}
