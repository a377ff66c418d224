//! `mbd-tutor serve`: the HTML worked solution on a local web server, rebuilt whenever the
//! problem file changes, with the open tabs reloading by themselves.
//!
//! One thread watches the file (its modification time, size and inode, every
//! [`POLL`]: an editor that saves by writing a new file and renaming it over the old one
//! changes the inode, which a watch on the old file would miss). Each rebuild makes a new
//! page and bumps the version. Each tab's small script asks `/wait?v=N`, which answers as
//! soon as the version is no longer N or a rebuild starts (or after [`LONG_POLL`]): a new
//! version reloads the tab; a rebuild that lasts over a second shows "rebuilding…".

use crate::cli::{ExplainArgs, MethodArg, ServeArgs};
use crate::Error;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, SystemTime};

/// How often the problem file is looked at.
const POLL: Duration = Duration::from_millis(150);

/// How long a tab's request for news is held open before it is answered "no news".
const LONG_POLL: Duration = Duration::from_secs(20);

/// How often the request loop looks for SIGINT and SIGTERM.
const SIGNAL_CHECK: Duration = Duration::from_millis(100);

/// What the tabs are shown: the page and its version.
struct Shown {
    /// Counts rebuilds; a tab that loaded an older one reloads.
    version: u64,
    /// The page, without the reloading script.
    page: String,
    /// A rebuild is under way.
    building: bool,
}

/// The page shared between the watcher and the request handlers.
struct Site {
    shown: Mutex<Shown>,
    changed: Condvar,
}

impl Site {
    fn update(&self, change: impl FnOnce(&mut Shown)) {
        let mut shown = self.shown.lock().unwrap_or_else(|e| e.into_inner());
        change(&mut shown);
        self.changed.notify_all();
    }

    fn read<T>(&self, look: impl FnOnce(&Shown) -> T) -> T {
        look(&self.shown.lock().unwrap_or_else(|e| e.into_inner()))
    }
}

/// Runs `mbd-tutor serve` until SIGINT or SIGTERM.
///
/// # Errors
/// [`Error::Io`] when the address cannot be listened on (a port in use, an unknown host).
pub fn run(args: ServeArgs) -> Result<(), Error> {
    let server =
        tiny_http::Server::http((args.host.as_str(), args.port)).map_err(|e| Error::Io {
            path: PathBuf::from(format!("{}:{}", args.host, args.port)),
            source: std::io::Error::other(e.to_string()),
        })?;
    let port = server
        .server_addr()
        .to_ip()
        .map_or(args.port, |address| address.port());
    let stop = Arc::new(AtomicBool::new(false));
    for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        signal_hook::flag::register(signal, Arc::clone(&stop)).map_err(|source| Error::Io {
            path: PathBuf::from("signal handler"),
            source,
        })?;
    }
    let site = Arc::new(Site {
        shown: Mutex::new(Shown {
            version: 1,
            page: page(&args.problem, args.method),
            building: false,
        }),
        changed: Condvar::new(),
    });
    println!("serving http://{}:{port}/", args.host);
    use std::io::Write;
    let _ = std::io::stdout().flush();
    {
        let site = Arc::clone(&site);
        let stop = Arc::clone(&stop);
        std::thread::spawn(move || watch(&args.problem, args.method, &site, &stop));
    }
    while !stop.load(Ordering::Relaxed) {
        match server.recv_timeout(SIGNAL_CHECK) {
            Ok(Some(request)) => {
                let site = Arc::clone(&site);
                std::thread::spawn(move || answer(request, &site));
            }
            Ok(None) => {}
            // An interrupted wait (a signal arrived): look at the flag again.
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(source) => {
                return Err(Error::Io {
                    path: PathBuf::from(format!("http://{}:{port}/", args.host)),
                    source,
                })
            }
        }
    }
    Ok(())
}

/// The file's identity and state: a change in any of them is an edit.
fn stamp(path: &Path) -> Option<(SystemTime, u64, u64)> {
    let meta = std::fs::metadata(path).ok()?;
    #[cfg(unix)]
    let inode = std::os::unix::fs::MetadataExt::ino(&meta);
    #[cfg(not(unix))]
    let inode = 0;
    Some((meta.modified().ok()?, meta.len(), inode))
}

/// Rebuilds the page whenever the file changes, until `stop`.
fn watch(path: &Path, method: MethodArg, site: &Site, stop: &AtomicBool) {
    let mut last = stamp(path);
    while !stop.load(Ordering::Relaxed) {
        std::thread::sleep(POLL);
        let now = stamp(path);
        if now == last {
            continue;
        }
        last = now;
        site.update(|s| s.building = true);
        let page = page(path, method);
        site.update(|s| {
            s.page = page;
            s.version += 1;
            s.building = false;
        });
    }
}

/// The worked solution of the file as it is now, or the page of its errors.
fn page(path: &Path, method: MethodArg) -> String {
    let args = ExplainArgs {
        common: crate::cli::Common {
            problem: path.to_path_buf(),
            method,
            set: Vec::new(),
            output: None,
            max_bodies: crate::cli::MAX_BODIES,
            max_coordinates: crate::cli::MAX_COORDINATES,
            max_work: crate::symbolic::budget::DEFAULT_LIMIT / 1_000_000,
        },
        format: crate::cli::FormatArg::Html,
        templates: None,
        student: false,
        both: false,
        linearize: None,
        verbose: false,
    };
    // A panic deep in a rebuild must not take the server down with it.
    let built = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        super::explain::rendered(&args, path, None, false)
    }));
    match built {
        Ok(Ok((html, _))) => html,
        Ok(Err(error)) => error_page(path, &error),
        Err(_) => error_page(
            path,
            &Error::Usage("the worked solution could not be built (an internal error)".into()),
        ),
    }
}

/// The errors `check` gives, as a page: each with its JSON path, column and hint.
fn error_page(path: &Path, error: &Error) -> String {
    use crate::render::escape::html;
    let mut items = String::new();
    match error {
        Error::Problem(errors) => {
            for e in &errors.0 {
                let mut place = html(&e.path);
                if let Some(column) = e.column {
                    place.push_str(&format!(", column {column}"));
                }
                items.push_str("<li>");
                if !place.is_empty() {
                    items.push_str(&format!("<code class=\"path\">{place}</code>: "));
                }
                items.push_str(&html(&e.message));
                if let Some(hint) = &e.hint {
                    items.push_str(&format!(
                        " <span class=\"hint\">(hint: {})</span>",
                        html(hint)
                    ));
                }
                items.push_str("</li>\n");
            }
        }
        other => items.push_str(&format!("<li>{}</li>\n", html(&other.one_line()))),
    }
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Errors in {name}</title>\n\
<style>body {{ font-family: Georgia, serif; max-width: 60rem; margin: 2rem auto; padding: 0 1rem; }} \
.errors li {{ margin: 0.4rem 0; }} code.path {{ color: #c0392b; font-weight: bold; }} .hint {{ color: #555; }}</style>\n\
</head>\n<body>\n<h1>{name} cannot be explained</h1>\n<p>{summary}</p>\n<ul class=\"errors\" id=\"problem-errors\">\n{items}</ul>\n\
<p>Fix the file and save it: this page updates by itself.</p>\n</body>\n</html>\n",
        name = html(&path.display().to_string()),
        summary = html(&match error {
            Error::Problem(errors) => format!(
                "The problem has {} error{}:",
                errors.0.len(),
                if errors.0.len() == 1 { "" } else { "s" }
            ),
            _ => "The worked solution could not be made:".into(),
        }),
    )
}

/// The tab's script: waits for news, reloads on a new version, says "rebuilding…" when a
/// rebuild lasts over a second.
const LIVE_SCRIPT: &str = r#"<div id="mbd-rebuilding" style="display:none;position:fixed;top:0;right:0;padding:0.4rem 0.8rem;background:#222;color:#fff;font:14px sans-serif;z-index:9">rebuilding…</div>
<script>
(function () {
  var version = VERSION, timer = null;
  var banner = document.getElementById("mbd-rebuilding");
  function ask() {
    fetch("/wait?v=" + version + "&b=" + (timer === null ? 0 : 1), { cache: "no-store" })
      .then(function (r) { return r.json(); })
      .then(function (news) {
        if (news.version !== version) { location.reload(); return; }
        if (news.building && timer === null) {
          timer = setTimeout(function () { banner.style.display = "block"; }, 1000);
        }
        ask();
      })
      .catch(function () { setTimeout(ask, 500); });
  }
  ask();
})();
</script>
"#;

/// The page with its live script, just before `</body>`.
fn with_script(page: &str, version: u64) -> String {
    let script = LIVE_SCRIPT.replace("VERSION", &version.to_string());
    match page.rfind("</body>") {
        Some(at) => format!("{}{script}{}", &page[..at], &page[at..]),
        None => format!("{page}{script}"),
    }
}

/// Answers one request: the page at `/`, news at `/wait?v=N&b=0|1`, nothing else.
fn answer(request: tiny_http::Request, site: &Site) {
    let url = request.url().to_string();
    let (route, query) = url.split_once('?').unwrap_or((url.as_str(), ""));
    let (status, content_type, body) = match route {
        "/" | "/index.html" => (
            200,
            "text/html; charset=utf-8",
            site.read(|s| with_script(&s.page, s.version)),
        ),
        "/wait" => {
            let number = |key: &str| -> u64 {
                query
                    .split('&')
                    .find_map(|pair| pair.strip_prefix(key))
                    .and_then(|v| v.parse().ok())
                    .unwrap_or(0)
            };
            let (version, building) = wait_for_news(site, number("v="), number("b=") == 1);
            (
                200,
                "application/json",
                format!("{{\"version\":{version},\"building\":{building}}}"),
            )
        }
        _ => (404, "text/plain; charset=utf-8", "not found".to_string()),
    };
    let mut response = tiny_http::Response::from_string(body).with_status_code(status);
    for (name, value) in [
        ("Content-Type", content_type),
        ("Cache-Control", "no-store"),
    ] {
        if let Ok(header) = tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response = response.with_header(header);
        }
    }
    // A tab closed meanwhile: nothing to do.
    let _ = request.respond(response);
}

/// The version and whether a rebuild is under way, as soon as either differs from what the
/// tab knows (`seen`, `building`), or after [`LONG_POLL`].
fn wait_for_news(site: &Site, seen: u64, building: bool) -> (u64, bool) {
    let shown = site.shown.lock().unwrap_or_else(|e| e.into_inner());
    let (shown, _) = site
        .changed
        .wait_timeout_while(shown, LONG_POLL, |s| {
            s.version == seen && s.building == building
        })
        .unwrap_or_else(|e| e.into_inner());
    (shown.version, shown.building)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_script_goes_before_the_end_of_the_body() {
        let page = with_script("<html><body><p>x</p></body></html>", 7);
        assert!(page.contains("var version = 7,"));
        assert!(page.ends_with("</script>\n</body></html>"));
    }

    #[test]
    fn an_error_page_names_the_json_path_column_and_hint() {
        let error = Error::Problem(crate::problem::ProblemErrors(vec![
            crate::problem::ProblemError {
                path: "bodies[0].mass".into(),
                column: Some(3),
                message: "unknown name `mm`".into(),
                hint: Some("did you mean `m`?".into()),
            },
        ]));
        let page = error_page(Path::new("p.json"), &error);
        assert!(page.contains("<code class=\"path\">bodies[0].mass, column 3</code>"));
        assert!(page.contains("did you mean `m`?"));
    }
}
