//! `mbd-tutor serve`: the HTML worked solution on a local web server, rebuilt whenever the
//! problem file changes, with the open tabs reloading by themselves.
//!
//! One thread builds the pages: the first, then a new one whenever the file's modification
//! time, size or inode changes (looked at every [`watch::POLL`]: an editor that saves by
//! writing a new file and renaming it over the old one changes the inode). Each rebuild
//! bumps the version. Each tab's small script asks `/wait?v=N`, which answers as soon as
//! the version is no longer N or a rebuild starts (or after [`http::LONG_POLL`]): a new
//! version reloads the tab; a rebuild that lasts over a second shows "rebuilding…".
//!
//! The server itself ([`http`]) is hyper's HTTP/1 on one thread, with limits on what one
//! client may hold: the size of a request's head, the time to send it, the life of a
//! connection and the number of connections. SIGINT and SIGTERM end it at once, even in
//! the middle of a build (the build is abandoned: nothing is written anywhere).

mod host;
mod http;
mod page;
mod watch;

use crate::cli::ServeArgs;
use crate::Error;
use std::path::PathBuf;
use std::sync::Arc;

/// What the tabs are shown: the page and its version.
#[derive(Clone)]
pub(crate) struct Shown {
    /// Counts builds; a tab that loaded an older one reloads. 0 until the first is done.
    pub version: u64,
    /// The page, without the reloading script.
    pub page: Arc<str>,
    /// A rebuild is under way.
    pub building: bool,
}

/// Runs `mbd-tutor serve` until SIGINT or SIGTERM.
///
/// # Errors
/// [`Error::Io`] when the address cannot be listened on (a port in use, an unknown host)
/// or the signals cannot be caught.
pub fn run(args: ServeArgs) -> Result<(), Error> {
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .map_err(|source| io_error("the server's event loop", source))?;
    runtime.block_on(serve(args))
}

fn io_error(what: &str, source: std::io::Error) -> Error {
    Error::Io {
        path: PathBuf::from(what),
        source,
    }
}

async fn serve(args: ServeArgs) -> Result<(), Error> {
    use tokio::signal::unix::{signal, SignalKind};
    // Caught before anything slow starts, so that a signal during the first build ends it.
    let mut interrupt =
        signal(SignalKind::interrupt()).map_err(|e| io_error("signal handler", e))?;
    let mut terminate =
        signal(SignalKind::terminate()).map_err(|e| io_error("signal handler", e))?;
    let (address, listener) = host::Served::bind(&args.host, args.port)?;
    if !address.is_loopback() {
        eprintln!(
            "warning: listening on {}, which other machines can reach: anyone who can reach it \
             can read the worked solution. Serve on 127.0.0.1 (the default) to keep it on this machine.",
            address.url()
        );
    }
    let (news, shown) = tokio::sync::watch::channel(Shown {
        version: 0,
        page: Arc::from(page::FIRST_BUILD),
        building: true,
    });
    let problem = args.problem.clone();
    let method = args.method;
    std::thread::spawn(move || watch::build_and_watch(&problem, method, &news));
    let mut first = shown.clone();
    let server = tokio::spawn(http::accept(listener, Arc::new(address.clone()), shown));
    tokio::select! {
        _ = interrupt.recv() => return Ok(()),
        _ = terminate.recv() => return Ok(()),
        _ = first.wait_for(|s| s.version > 0) => {}
    }
    {
        use std::io::Write;
        let mut stdout = std::io::stdout().lock();
        let _ = writeln!(stdout, "serving {}", address.url());
        let _ = stdout.flush();
    }
    tokio::select! {
        _ = interrupt.recv() => {}
        _ = terminate.recv() => {}
        _ = server => {}
    }
    Ok(())
}
