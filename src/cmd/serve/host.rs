//! The address `serve` listens on, and which `Host` headers name it.
//!
//! A page served on 127.0.0.1 can still be reached from a web site in the browser through
//! DNS rebinding (a name of the attacker's that resolves to 127.0.0.1 a moment later), so
//! every request must name the address served in its `Host` header: the host given to
//! `--host`, the address it resolved to, `localhost` for a loopback address, and any
//! address literal when listening on every interface (0.0.0.0 or ::). A name that is not
//! one of these is refused (421), a request without a host too (400).

use crate::Error;
use std::net::{IpAddr, SocketAddr, ToSocketAddrs};
use std::path::PathBuf;

/// The address listened on and the host name it was given as.
#[derive(Clone, Debug)]
pub(crate) struct Served {
    /// `--host` as given, lower case, without the brackets of an IPv6 literal.
    name: String,
    /// The address bound.
    address: SocketAddr,
}

impl Served {
    /// Listens on `host` (a name or an address, IPv6 with or without brackets) at `port`:
    /// the address and its socket, ready for the event loop.
    ///
    /// # Errors
    /// [`Error::Io`] when the host is unknown or the port cannot be listened on.
    pub fn bind(host: &str, port: u16) -> Result<(Self, tokio::net::TcpListener), Error> {
        let name = host
            .trim()
            .trim_start_matches('[')
            .trim_end_matches(']')
            .to_ascii_lowercase();
        let io = |source| Error::Io {
            path: PathBuf::from(format!("{host}:{port}")),
            source,
        };
        let candidates: Vec<SocketAddr> = (name.as_str(), port)
            .to_socket_addrs()
            .map_err(io)?
            .collect();
        let mut last = std::io::Error::other("the host has no address");
        for candidate in candidates {
            match std::net::TcpListener::bind(candidate) {
                Ok(socket) => {
                    let address = socket.local_addr().map_err(io)?;
                    socket.set_nonblocking(true).map_err(io)?;
                    let listener = tokio::net::TcpListener::from_std(socket).map_err(io)?;
                    return Ok((Served { name, address }, listener));
                }
                Err(e) => last = e,
            }
        }
        Err(io(last))
    }

    /// Whether only this machine can reach the address.
    pub fn is_loopback(&self) -> bool {
        self.address.ip().is_loopback()
    }

    /// `http://HOST:PORT/`, HOST as given (an IPv6 address in brackets), PORT the one bound.
    pub fn url(&self) -> String {
        let port = self.address.port();
        if self.name.contains(':') {
            format!("http://[{}]:{port}/", self.name)
        } else {
            format!("http://{}:{port}/", self.name)
        }
    }

    /// Whether a request's `Host` (or the authority of its target) names this server.
    pub fn accepts(&self, host: &str) -> bool {
        let Some((name, port)) = split_host(host) else {
            return false;
        };
        if port != self.address.port() {
            return false;
        }
        let name = name.trim_end_matches('.').to_ascii_lowercase();
        if name == self.name {
            return true;
        }
        let bound = self.address.ip();
        match name.parse::<IpAddr>() {
            Ok(ip) => {
                ip == bound || bound.is_unspecified() || (bound.is_loopback() && ip.is_loopback())
            }
            Err(_) => name == "localhost" && (bound.is_loopback() || bound.is_unspecified()),
        }
    }
}

/// The name and port of a `Host` value (`name`, `name:port`, `[v6]`, `[v6]:port`); the
/// port is 80 when none is written.
fn split_host(host: &str) -> Option<(&str, u16)> {
    let port = |text: &str| -> Option<u16> {
        if text.is_empty() {
            Some(80)
        } else {
            text.parse().ok()
        }
    };
    if let Some(rest) = host.strip_prefix('[') {
        let (name, after) = rest.split_once(']')?;
        let after = match after {
            "" => "",
            _ => after.strip_prefix(':')?,
        };
        return Some((name, port(after)?));
    }
    match host.rsplit_once(':') {
        Some((name, after)) if !name.contains(':') => Some((name, port(after)?)),
        Some(_) => None,
        None => Some((host, 80)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn served(name: &str, address: &str) -> Served {
        Served {
            name: name.into(),
            address: address.parse().unwrap(),
        }
    }

    #[test]
    fn loopback_accepts_its_own_names_and_nothing_else() {
        let s = served("127.0.0.1", "127.0.0.1:7070");
        for good in [
            "127.0.0.1:7070",
            "localhost:7070",
            "LOCALHOST:7070",
            "[::1]:7070",
        ] {
            assert!(s.accepts(good), "{good}");
        }
        for bad in [
            "evil.example:7070",
            "127.0.0.1:7071",
            "127.0.0.1",
            "localhost.evil.example:7070",
            "",
            "[::1:7070",
            "127.0.0.1:70x",
        ] {
            assert!(!s.accepts(bad), "{bad}");
        }
    }

    #[test]
    fn an_ipv6_host_is_written_in_brackets() {
        let s = served("::1", "[::1]:8000");
        assert_eq!(s.url(), "http://[::1]:8000/");
        assert!(s.accepts("[::1]:8000"));
        assert!(!s.accepts("::1:8000"));
    }

    #[test]
    fn every_interface_accepts_address_literals_but_not_names() {
        let s = served("0.0.0.0", "0.0.0.0:80");
        assert!(s.accepts("192.0.2.7"));
        assert!(s.accepts("localhost"));
        assert!(!s.accepts("rebound.example"));
    }
}
