//! The HTTP side of `serve`: hyper's HTTP/1 server on the event loop, with what one client
//! may hold bounded, so that no client can stop the server answering the others:
//!
//! - a request's head within [`HEAD_BYTES`], sent within [`HEAD_TIMEOUT`] (a client that
//!   sends it a byte at a time, or opens a connection and says nothing, is cut off);
//! - a connection lives at most [`CONNECTION_LIFE`];
//! - at most [`connection_cap`] connections at once (a few below the descriptor limit); one
//!   more is closed at once instead of ending the server with "too many open files";
//! - no request body is read: a request that announces one is answered 413 and the
//!   connection closed, whatever length it announces;
//! - GET and HEAD only (405 otherwise), and the `Host` checked ([`super::host`]).

use super::host::Served;
use super::{page, Shown};
use http_body_util::Full;
use hyper::body::{Bytes, Incoming};
use hyper::header::{self, HeaderValue};
use hyper::{Method, Request, Response, StatusCode};
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::watch::Receiver;

/// How long a tab's request for news is held open before it is answered "no news".
pub(crate) const LONG_POLL: Duration = Duration::from_secs(20);

/// How long a client has to send a request's head, and how long an idle connection waits
/// for the next one.
pub(crate) const HEAD_TIMEOUT: Duration = Duration::from_secs(5);

/// The longest a connection is kept: a few long polls; the tab's script reconnects.
pub(crate) const CONNECTION_LIFE: Duration = Duration::from_secs(60);

/// The largest request head read (hyper's smallest allowed buffer is 8 KiB).
const HEAD_BYTES: usize = 16 * 1024;

/// The most headers in one request.
const MAX_HEADERS: usize = 64;

/// Descriptors kept free for the build (the problem file, templates) and the standard ones.
const RESERVED_DESCRIPTORS: u64 = 64;

/// Never more connections than this, whatever the descriptor limit.
const MOST_CONNECTIONS: u64 = 1000;

/// How many connections are served at once: [`MOST_CONNECTIONS`], or fewer when the
/// process may open fewer descriptors (less [`RESERVED_DESCRIPTORS`]).
pub(crate) fn connection_cap() -> usize {
    let mut limit = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: getrlimit writes one rlimit into the struct it is given.
    let known = unsafe { libc::getrlimit(libc::RLIMIT_NOFILE, &mut limit) } == 0;
    let descriptors = if known { limit.rlim_cur } else { 1024 };
    let cap = descriptors
        .saturating_sub(RESERVED_DESCRIPTORS)
        .clamp(8, MOST_CONNECTIONS);
    usize::try_from(cap).unwrap_or(8)
}

/// Accepts connections for ever, each served on its own task within the limits above.
pub(crate) async fn accept(
    listener: tokio::net::TcpListener,
    served: Arc<Served>,
    shown: Receiver<Shown>,
) {
    let slots = Arc::new(tokio::sync::Semaphore::new(connection_cap()));
    loop {
        let stream = match listener.accept().await {
            Ok((stream, _)) => stream,
            // Out of descriptors or a connection reset before it was accepted: wait a
            // moment for connections to end, then go on.
            Err(_) => {
                tokio::time::sleep(Duration::from_millis(50)).await;
                continue;
            }
        };
        // Over the cap: the connection is closed at once (dropped).
        let Ok(slot) = Arc::clone(&slots).try_acquire_owned() else {
            continue;
        };
        let served = Arc::clone(&served);
        let shown = shown.clone();
        tokio::spawn(async move {
            let _slot = slot;
            connection(stream, served, shown).await;
        });
    }
}

async fn connection(stream: tokio::net::TcpStream, served: Arc<Served>, shown: Receiver<Shown>) {
    let service = hyper::service::service_fn(move |request| {
        let served = Arc::clone(&served);
        let shown = shown.clone();
        async move { Ok::<_, std::convert::Infallible>(respond(&request, &served, shown).await) }
    });
    let mut builder = hyper::server::conn::http1::Builder::new();
    builder
        .timer(hyper_util::rt::TokioTimer::new())
        .header_read_timeout(HEAD_TIMEOUT)
        .max_buf_size(HEAD_BYTES)
        .max_headers(MAX_HEADERS);
    let served = builder.serve_connection(hyper_util::rt::TokioIo::new(stream), service);
    // An error (a malformed request, an HTTP/2 preface, a timeout) or the end of its life
    // closes this connection only.
    let _ = tokio::time::timeout(CONNECTION_LIFE, served).await;
}

/// The answer to one request.
async fn respond(
    request: &Request<Incoming>,
    served: &Served,
    shown: Receiver<Shown>,
) -> Response<Full<Bytes>> {
    if let Err(refusal) = check(request, served) {
        return refusal;
    }
    let query = request.uri().query().unwrap_or("");
    match request.uri().path() {
        "/" | "/index.html" => {
            let page = {
                let s = shown.borrow();
                page::with_script(&s.page, s.version)
            };
            reply(StatusCode::OK, "text/html; charset=utf-8", page)
        }
        "/wait" => {
            let number = |key: &str| -> u64 {
                query
                    .split('&')
                    .find_map(|pair| pair.strip_prefix(key))
                    .and_then(|v| v.parse().ok())
                    .unwrap_or(0)
            };
            let (version, building) = news(shown, number("v="), number("b=") == 1).await;
            reply(
                StatusCode::OK,
                "application/json",
                format!("{{\"version\":{version},\"building\":{building}}}"),
            )
        }
        _ => plain(StatusCode::NOT_FOUND, "not found"),
    }
}

/// The refusals that come before any route: a host not served (421, or 400 when none is
/// named), a method other than GET and HEAD (405), a request with a body (413).
fn check(request: &Request<Incoming>, served: &Served) -> Result<(), Response<Full<Bytes>>> {
    let host = match request.uri().authority() {
        Some(authority) => Some(authority.as_str().to_string()),
        None => match request.headers().get(header::HOST).map(HeaderValue::to_str) {
            Some(Ok(host)) => Some(host.to_string()),
            Some(Err(_)) | None => None,
        },
    };
    let Some(host) = host else {
        return Err(plain(StatusCode::BAD_REQUEST, "the request names no host"));
    };
    if !served.accepts(&host) {
        return Err(plain(
            StatusCode::MISDIRECTED_REQUEST,
            &format!("this server answers only to {}", served.url()),
        ));
    }
    if request.method() != Method::GET && request.method() != Method::HEAD {
        let mut response = plain(StatusCode::METHOD_NOT_ALLOWED, "only GET and HEAD");
        response
            .headers_mut()
            .insert(header::ALLOW, HeaderValue::from_static("GET, HEAD"));
        return Err(response);
    }
    let headers = request.headers();
    let announced = headers
        .get(header::CONTENT_LENGTH)
        .is_some_and(|length| length.as_bytes() != b"0")
        || headers.contains_key(header::TRANSFER_ENCODING);
    if announced {
        let mut response = plain(StatusCode::PAYLOAD_TOO_LARGE, "requests here have no body");
        response
            .headers_mut()
            .insert(header::CONNECTION, HeaderValue::from_static("close"));
        return Err(response);
    }
    Ok(())
}

/// The version and whether a rebuild is under way, as soon as either differs from what the
/// tab knows (`seen`, `building`), or after [`LONG_POLL`].
async fn news(mut shown: Receiver<Shown>, seen: u64, building: bool) -> (u64, bool) {
    let changed = shown.wait_for(|s| s.version != seen || s.building != building);
    let _ = tokio::time::timeout(LONG_POLL, changed).await;
    let s = shown.borrow();
    (s.version, s.building)
}

fn plain(status: StatusCode, text: &str) -> Response<Full<Bytes>> {
    reply(status, "text/plain; charset=utf-8", format!("{text}\n"))
}

fn reply(status: StatusCode, content_type: &'static str, body: String) -> Response<Full<Bytes>> {
    let mut response = Response::new(Full::new(Bytes::from(body)));
    *response.status_mut() = status;
    let headers = response.headers_mut();
    headers.insert(header::CONTENT_TYPE, HeaderValue::from_static(content_type));
    headers.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    headers.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    response
}
