//! `serve` under hostile clients, all on the loopback address, each test bounded in time
//! and in the connections it opens, and ending the server itself: a body of 10¹² bytes
//! announced, 700 idle connections under a 1,024-descriptor limit, a client that sends its
//! request a byte at a time, an HTTP/2 preface. Through all of them the server answers
//! another client within 1 s, and SIGTERM ends it with status 0 within 1 s, also during
//! its first build.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

const SECOND: Duration = Duration::from_secs(1);

/// A `serve` process and the port it listens on.
struct Server {
    child: Child,
    port: u16,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn bundled(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(name)
}

/// Starts `serve PROBLEM --port 0` under `ulimit -n descriptors` and waits (at most 60 s)
/// for its first line, `serving http://127.0.0.1:PORT/`.
fn start(problem: &Path, descriptors: u32) -> Server {
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -n {descriptors} && exec \"$0\" serve \"$1\" --port 0"
        ))
        .arg(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg(problem)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("serve starts");
    let stdout = child.stdout.take().expect("its standard output");
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = send.send(line);
    });
    let line = receive
        .recv_timeout(Duration::from_secs(60))
        .expect("the first line within 60 s");
    let port = line
        .trim()
        .strip_prefix("serving http://127.0.0.1:")
        .and_then(|rest| rest.strip_suffix('/'))
        .and_then(|port| port.parse().ok())
        .unwrap_or_else(|| panic!("first line `serving http://127.0.0.1:PORT/`: {line:?}"));
    Server { child, port }
}

fn connect(port: u16) -> TcpStream {
    let stream = TcpStream::connect(("127.0.0.1", port)).expect("connects");
    stream
        .set_read_timeout(Some(Duration::from_secs(10)))
        .expect("timeout");
    stream
}

/// Sends `request` on a new connection and reads the answer to its end (the connection
/// closed by `Connection: close`).
fn ask(port: u16, request: &str) -> String {
    let mut stream = connect(port);
    stream.write_all(request.as_bytes()).expect("sent");
    let mut answer = Vec::new();
    let _ = stream.read_to_end(&mut answer);
    String::from_utf8_lossy(&answer).into_owned()
}

fn get(port: u16, path: &str) -> String {
    ask(
        port,
        &format!("GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n"),
    )
}

/// The page is answered, 200 with the worked solution, within 1 s.
fn answers_within_a_second(port: u16, while_what: &str) {
    let start = Instant::now();
    let answer = get(port, "/");
    let took = start.elapsed();
    assert!(
        answer.starts_with("HTTP/1.1 200"),
        "{while_what}: {answer:.200}"
    );
    assert!(answer.contains("</html>"), "{while_what}: the whole page");
    assert!(took < SECOND, "{while_what}: answered in {took:?}");
}

/// SIGTERM ends the server with status 0 within 1 s.
fn ends_on_sigterm(mut server: Server, when: &str) {
    let start = Instant::now();
    let pid = server.child.id().to_string();
    let killed = Command::new("kill").args(["-TERM", &pid]).status();
    assert!(killed.is_ok_and(|s| s.success()), "kill -TERM {pid}");
    loop {
        if let Some(status) = server.child.try_wait().expect("waits") {
            assert_eq!(status.code(), Some(0), "{when}: exit status");
            break;
        }
        assert!(
            start.elapsed() < SECOND,
            "{when}: still running 1 s after SIGTERM"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

#[test]
fn serve_answers_only_get_and_head_for_its_own_host() {
    let server = start(&bundled("problems/simple-pendulum.json"), 1024);
    let port = server.port;
    let head = ask(
        port,
        &format!("HEAD / HTTP/1.1\r\nHost: localhost:{port}\r\nConnection: close\r\n\r\n"),
    );
    assert!(head.starts_with("HTTP/1.1 200"), "{head}");
    assert!(!head.contains("<html"), "HEAD has no body: {head}");
    for method in ["POST", "PUT", "DELETE", "OPTIONS"] {
        let answer = ask(
            port,
            &format!("{method} / HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"),
        );
        assert!(answer.starts_with("HTTP/1.1 405"), "{method}: {answer}");
        assert!(
            answer.to_ascii_lowercase().contains("allow: get, head"),
            "{answer}"
        );
    }
    // A page on another site whose name has been made to point at 127.0.0.1.
    let rebound = ask(
        port,
        &format!("GET / HTTP/1.1\r\nHost: attacker.example:{port}\r\nConnection: close\r\n\r\n"),
    );
    assert!(rebound.starts_with("HTTP/1.1 421"), "{rebound}");
    assert!(!rebound.contains("<html"), "{rebound}");
    let nameless = ask(port, "GET / HTTP/1.0\r\n\r\n");
    assert!(
        nameless.starts_with("HTTP/1.0 400") || nameless.starts_with("HTTP/1.1 400"),
        "{nameless}"
    );
    assert!(get(port, "/../../etc/passwd").starts_with("HTTP/1.1 404"));
    ends_on_sigterm(server, "after refusals");
}

#[test]
fn serve_keeps_answering_under_hostile_clients() {
    let server = start(&bundled("problems/simple-pendulum.json"), 1024);
    let port = server.port;
    answers_within_a_second(port, "at first");

    // 10¹² bytes announced and never sent: refused at once, nothing allocated.
    let huge = ask(
        port,
        &format!(
            "GET / HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Length: 1000000000000\r\n\r\n"
        ),
    );
    assert!(huge.starts_with("HTTP/1.1 413"), "{huge}");
    answers_within_a_second(port, "after a 10^12-byte Content-Length");

    // An HTTP/2 preface: that connection is closed, the server goes on.
    let mut h2 = connect(port);
    h2.write_all(b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n")
        .expect("sent");
    let mut rest = Vec::new();
    let _ = h2.read_to_end(&mut rest);
    answers_within_a_second(port, "after an HTTP/2 preface");

    // A client that sends its request's head a byte at a time, and 700 that say nothing.
    let start = Instant::now();
    let mut slow = connect(port);
    slow.write_all(b"GET / HTTP/1.1\r\nHost: 127.0.0.1")
        .expect("sent");
    let idle: Vec<TcpStream> = (0..700).map(|_| connect(port)).collect();
    let idle_since = Instant::now();
    let mut cut_off = None;
    while start.elapsed() < Duration::from_secs(12) {
        answers_within_a_second(port, "with 700 idle connections and a slow client");
        if slow.write_all(b"X").is_err() {
            cut_off = Some(start.elapsed());
            break;
        }
        std::thread::sleep(Duration::from_millis(500));
    }
    let cut_off = cut_off.expect("the slow client is cut off within 12 s");
    assert!(
        cut_off >= Duration::from_secs(3),
        "not before its time: {cut_off:?}"
    );
    // The idle connections were closed by the server too, once their time was up.
    std::thread::sleep(Duration::from_secs(7).saturating_sub(idle_since.elapsed()));
    let mut open = 0;
    for mut stream in idle {
        let mut byte = [0u8; 1];
        stream
            .set_read_timeout(Some(Duration::from_millis(20)))
            .expect("timeout");
        // Closed: the end of the stream, a reset, or a last answer before the end.
        let waiting = matches!(
            stream.read(&mut byte),
            Err(e) if matches!(e.kind(), std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut)
        );
        open += usize::from(waiting);
    }
    assert_eq!(open, 0, "idle connections still open after 7 s");
    answers_within_a_second(port, "at the end");
    ends_on_sigterm(server, "after hostile clients");
}

#[test]
fn serve_ends_at_once_on_sigterm_during_its_first_build() {
    // Six spherical links: the first build takes seconds.
    let mut child = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg("serve")
        .arg(bundled("tests/browser/six-spherical-links.json"))
        .args(["--port", "0"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("serve starts");
    std::thread::sleep(Duration::from_millis(500));
    assert!(child.try_wait().expect("waits").is_none(), "still building");
    ends_on_sigterm(Server { child, port: 0 }, "during the first build");
}

#[test]
fn serve_shows_a_fifo_or_a_device_in_place_of_the_problem_as_an_error() {
    let dir = super::scratch("serve-fifo");
    let problem = dir.join("problem.json");
    let made = Command::new("mkfifo").arg(&problem).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let server = start(&problem, 1024);
    let page = get(server.port, "/");
    assert!(page.starts_with("HTTP/1.1 200"), "{page:.300}");
    assert!(page.contains("not a regular file"), "{page:.3000}");
    // A link to a device that never ends: refused, not read.
    std::fs::remove_file(&problem).expect("removed");
    std::os::unix::fs::symlink("/dev/zero", &problem).expect("linked");
    let start_wait = Instant::now();
    let mut seen = false;
    while start_wait.elapsed() < Duration::from_secs(5) && !seen {
        std::thread::sleep(Duration::from_millis(300));
        seen = get(server.port, "/").contains("a character device is not a regular file");
    }
    assert!(seen, "the device is named on the page within 5 s");
    answers_within_a_second(server.port, "after a FIFO and a device");
    ends_on_sigterm(server, "after a FIFO and a device");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn serve_on_the_ipv6_loopback_writes_its_address_in_brackets() {
    if std::net::TcpListener::bind("[::1]:0").is_err() {
        eprintln!("skipped: no IPv6 loopback on this machine");
        return;
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg("serve")
        .arg(bundled("problems/simple-pendulum.json"))
        .args(["--port", "0", "--host", "::1"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("serve starts");
    let stdout = child.stdout.take().expect("its standard output");
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = send.send(line);
    });
    let line = receive
        .recv_timeout(Duration::from_secs(60))
        .expect("the first line within 60 s");
    assert!(line.starts_with("serving http://[::1]:"), "{line}");
    ends_on_sigterm(Server { child, port: 0 }, "on [::1]");
}

#[test]
fn serve_beyond_loopback_warns_on_standard_error() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg("serve")
        .arg(bundled("problems/simple-pendulum.json"))
        .args(["--port", "0", "--host", "0.0.0.0"])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("serve starts");
    let stderr = child.stderr.take().expect("its standard error");
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stderr).read_line(&mut line);
        let _ = send.send(line);
    });
    let line = receive
        .recv_timeout(Duration::from_secs(60))
        .expect("a line on standard error within 60 s");
    assert!(
        line.starts_with("warning: listening on http://0.0.0.0:")
            && line.contains("other machines can reach"),
        "{line}"
    );
    ends_on_sigterm(Server { child, port: 0 }, "on 0.0.0.0");
}
