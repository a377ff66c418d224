//! Where output may go and what is read: a target that is not a regular file, a read-only
//! one or the problem itself is refused before anything is written (exit status 2); a
//! private file stays private; the files written beside an output (variants, pictures, the
//! student's handout) never replace the problem; a problem that is not a regular file, is
//! too long or declares too much is refused at once.

use super::scratch;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn run(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Runs the binary under a memory limit of about 1 GB, and says how long it took.
fn run_bounded(args: &[&std::ffi::OsStr]) -> (Output, Duration) {
    let start = Instant::now();
    let output = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 1000000 && exec \"$@\"")
        .arg("sh")
        .arg(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("the binary runs");
    (output, start.elapsed())
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn bundled(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("problems")
        .join(name)
}

fn listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("readable")
        .map(|e| {
            let path = e.expect("entry").path();
            let bytes = std::fs::read(&path).unwrap_or_default();
            (
                path.file_name().unwrap().to_string_lossy().into_owned(),
                bytes,
            )
        })
        .collect();
    files.sort();
    files
}

#[test]
fn targets_that_are_not_regular_files_are_refused() {
    let dir = scratch("special-targets");
    let problem = bundled("simple-pendulum.json");
    let fifo = dir.join("fifo");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success()));
    let link = dir.join("null-link.json");
    std::os::unix::fs::symlink("/dev/null", &link).expect("linked");
    let targets: [(&Path, &str); 4] = [
        (Path::new("/dev/null"), "a character device"),
        (&fifo, "a FIFO"),
        (&dir, "a directory"),
        (&link, "a character device"),
    ];
    for (target, kind) in targets {
        let start = Instant::now();
        let output = run(&[
            "solve".as_ref(),
            problem.as_os_str(),
            "-o".as_ref(),
            target.as_os_str(),
        ]);
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "{target:?}: no wait"
        );
        assert_eq!(
            output.status.code(),
            Some(2),
            "{target:?}: {}",
            stderr(&output)
        );
        let message = stderr(&output);
        assert!(
            message.contains(kind) && message.contains("not a regular file"),
            "{message}"
        );
    }
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_read_only_target_is_refused_and_a_private_one_stays_private() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("modes");
    let problem = bundled("simple-pendulum.json");
    let read_only = dir.join("read-only.json");
    std::fs::write(&read_only, b"keep").expect("written");
    std::fs::set_permissions(&read_only, std::fs::Permissions::from_mode(0o444)).unwrap();
    let output = run(&[
        "solve".as_ref(),
        problem.as_os_str(),
        "-o".as_ref(),
        read_only.as_os_str(),
    ]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(stderr(&output).contains("read-only"));
    assert_eq!(std::fs::read(&read_only).unwrap(), b"keep");

    let private = dir.join("answers.json");
    std::fs::write(&private, b"old").expect("written");
    std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o600)).unwrap();
    let output = run(&[
        "answer".as_ref(),
        problem.as_os_str(),
        "-o".as_ref(),
        private.as_os_str(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_ne!(std::fs::read(&private).unwrap(), b"old");
    let mode = std::fs::metadata(&private).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600, "the key's mode is kept");
    let names: Vec<String> = listing(&dir).into_iter().map(|(n, _)| n).collect();
    assert_eq!(
        names,
        ["answers.json", "read-only.json"],
        "no temporary file left"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn files_written_beside_an_output_never_replace_the_problem() {
    let dir = scratch("beside");
    // variants PROBLEM -o DIR, the problem named as the first variant in DIR.
    let hw = dir.join("hw");
    std::fs::create_dir_all(&hw).unwrap();
    let variant = hw.join("variant-01.json");
    std::fs::copy(bundled("four-bar.json"), &variant).expect("copied");
    // draw PROBLEM -o DIR, the problem named as the picture of the configuration.
    let d = dir.join("d");
    std::fs::create_dir_all(&d).unwrap();
    let picture = d.join("configuration.svg");
    std::fs::copy(bundled("simple-pendulum.json"), &picture).expect("copied");
    // explain --both -o sol.json, the problem named as the student's handout.
    let both = dir.join("both");
    std::fs::create_dir_all(&both).unwrap();
    let student = both.join("sol-student.json");
    std::fs::copy(bundled("simple-pendulum.json"), &student).expect("copied");
    let sol = both.join("sol.json");
    let runs: [(&Path, Vec<&std::ffi::OsStr>); 3] = [
        (
            &hw,
            vec![
                "variants".as_ref(),
                variant.as_os_str(),
                "--count".as_ref(),
                "2".as_ref(),
                "--format".as_ref(),
                "markdown".as_ref(),
                "-o".as_ref(),
                hw.as_os_str(),
            ],
        ),
        (
            &d,
            vec![
                "draw".as_ref(),
                picture.as_os_str(),
                "-o".as_ref(),
                d.as_os_str(),
            ],
        ),
        (
            &both,
            vec![
                "explain".as_ref(),
                student.as_os_str(),
                "--both".as_ref(),
                "-o".as_ref(),
                sol.as_os_str(),
            ],
        ),
    ];
    for (folder, args) in runs {
        let before = listing(folder);
        let output = run(&args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).contains("refusing to overwrite the problem file"),
            "{}",
            stderr(&output)
        );
        assert_eq!(listing(folder), before, "{args:?}: nothing written");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn problems_that_are_not_regular_files_or_too_large_are_refused_at_once() {
    let dir = scratch("bounded-reads");
    for special in ["/dev/zero", "/dev/null"] {
        let (output, took) = run_bounded(&["check".as_ref(), special.as_ref()]);
        assert_eq!(output.status.code(), Some(1), "{special}");
        assert!(
            stderr(&output).contains("not a regular file"),
            "{}",
            stderr(&output)
        );
        assert!(took < Duration::from_secs(2), "{special}: {took:?}");
    }
    // A million constants: more bytes than a problem may have.
    let mut text = String::from("{\"title\":\"many\",\"dimension\":2,\"constants\":{");
    for i in 0..1_000_000 {
        text.push_str(&format!("\"c{i}\":1,"));
    }
    text.push_str("\"last\":1}}");
    let million = dir.join("million.json");
    std::fs::write(&million, &text).expect("written");
    let (output, took) = run_bounded(&["explain".as_ref(), million.as_os_str()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("longer than the limit"),
        "{}",
        stderr(&output)
    );
    assert!(took < Duration::from_secs(2), "{took:?}");
    // 200,000 constants fit in the bytes but not in the limit on constants: one error.
    let mut text = String::from("{\"title\":\"many\",\"dimension\":2,\"constants\":{");
    for i in 0..200_000 {
        text.push_str(&format!("\"c{i}\":1,"));
    }
    text.push_str("\"last\":1}}");
    let many = dir.join("many.json");
    std::fs::write(&many, &text).expect("written");
    let (output, took) = run_bounded(&["check".as_ref(), many.as_os_str()]);
    assert_eq!(output.status.code(), Some(1));
    let message = stderr(&output);
    assert!(
        message.contains("200001 constants, more than the limit of 20000"),
        "{message:.500}"
    );
    assert!(message.lines().count() < 5, "one error: {message:.500}");
    assert!(took < Duration::from_secs(5), "{took:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_of_a_chain_of_three_thousand_rods_is_refused_within_ten_seconds() {
    let dir = scratch("long-chain");
    let chain = dir.join("chain.json");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tools/bench/chains.py");
    let written = Command::new("python3")
        .arg(&script)
        .args(["write", "revolute", "3000"])
        .arg(&chain)
        .status();
    assert!(
        written.is_ok_and(|s| s.success()),
        "tools/bench/chains.py writes the chain"
    );
    let (output, took) = run_bounded(&["check".as_ref(), chain.as_os_str()]);
    assert!(took < Duration::from_secs(10), "{took:?}");
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    // Its 30,001 constants are refused first, before any body is read.
    let message = stderr(&output);
    assert!(
        message.contains("30001 constants, more than the limit of 20000"),
        "{message:.500}"
    );
    assert!(message.lines().count() < 5, "one error: {message:.500}");
    // A thousand rods (10,001 constants): the bodies are over `--max-bodies`, as for `solve`.
    let written = Command::new("python3")
        .arg(&script)
        .args(["write", "revolute", "1000"])
        .arg(&chain)
        .status();
    assert!(
        written.is_ok_and(|s| s.success()),
        "tools/bench/chains.py writes the chain"
    );
    let (output, took) = run_bounded(&["check".as_ref(), chain.as_os_str()]);
    assert!(took < Duration::from_secs(10), "{took:?}");
    let message = stderr(&output);
    assert!(
        message.contains("1000 bodies, more than the limit of 30"),
        "{message:.500}"
    );
    assert!(message.contains("--max-bodies 1000"), "{message:.500}");
    let _ = std::fs::remove_dir_all(&dir);
}
