//! One request, one answer: the checks, the route, the run.

use std::convert::Infallible;
use std::io;
use std::net::{IpAddr, Ipv4Addr, Ipv6Addr};
use std::path::PathBuf;
use std::pin::Pin;
use std::sync::Arc;
use std::task::{Context, Poll};

use hyper::body::{Body, Bytes, Frame, Incoming, SizeHint};
use hyper::header::{self, HeaderValue};
use hyper::{Method, Request, Response, StatusCode, Version};
use tokio::sync::{watch, OwnedSemaphorePermit, Semaphore};
use tokio::time::{timeout, Instant};

use super::child::{self, Ended, Limits};
use super::files;
use super::limits::{
    MAX_ANSWER, MAX_BODY, MAX_QUEUED, MAX_RUNS, MAX_SECONDS, MAX_URL, QUEUE_WAIT, RETRY_AFTER_S,
    SEND_TIMEOUT,
};
use super::query::{self, Endpoint, Refused};
use super::wait::{race, stopped, Either};
use crate::console::report;

/// What every request shares.
#[derive(Debug)]
pub struct Server {
    /// The program to run for the API (this one).
    pub exe: PathBuf,
    /// The `Host` names it answers to.
    pub hosts: Hosts,
    /// Places for runs ([`MAX_RUNS`]).
    pub runs: Arc<Semaphore>,
    /// Places to wait for a run ([`MAX_QUEUED`]).
    pub queue: Arc<Semaphore>,
    /// Turns true when the server stops.
    pub stop: watch::Receiver<bool>,
    /// Changes when idle connections should close (the connections are full).
    pub shed: watch::Receiver<u64>,
    /// The answer of `GET /api/params`, made once.
    pub params: Bytes,
}

impl Server {
    /// The shared state of a server answering to `hosts`.
    pub fn new(
        exe: PathBuf,
        hosts: Hosts,
        stop: watch::Receiver<bool>,
        shed: watch::Receiver<u64>,
    ) -> Server {
        Server {
            exe,
            hosts,
            runs: Arc::new(Semaphore::new(MAX_RUNS)),
            queue: Arc::new(Semaphore::new(MAX_QUEUED)),
            stop,
            shed,
            params: Bytes::from(super::limits::params_json()),
        }
    }
}

/// The names a request's `Host` may give (with this server's port, or no
/// port). A page on another site that a browser is made to send here by
/// DNS rebinding names that site, and is refused: its name is not a
/// loopback name, and a rebound name is never an IP address.
#[derive(Debug)]
pub struct Hosts {
    port: u16,
    /// Any IP address is taken (listening on all of them).
    any_ip: bool,
    /// Names and addresses taken, lower case (IPv6 in brackets).
    names: Vec<String>,
}

impl Hosts {
    /// The names of a server listening on `ip` port `port`: the loopback
    /// names, `ip` itself, any IP address when `ip` is 0.0.0.0 or ::, and
    /// `extra`.
    pub fn new(ip: IpAddr, port: u16, extra: &[String]) -> Hosts {
        let mut names: Vec<String> = ["localhost", "127.0.0.1", "[::1]"]
            .iter()
            .map(|n| n.to_string())
            .collect();
        if !ip.is_unspecified() && !names.contains(&literal(ip)) {
            names.push(literal(ip));
        }
        for name in extra.iter().map(|n| n.to_ascii_lowercase()) {
            if !names.contains(&name) {
                names.push(name);
            }
        }
        Hosts {
            port,
            any_ip: ip.is_unspecified(),
            names,
        }
    }

    /// Whether `host` (a `Host` header's value) is one of these.
    pub fn allows(&self, host: &str) -> bool {
        let host = host.to_ascii_lowercase();
        let Some((name, port)) = split_host(&host) else {
            return false;
        };
        if port.is_some_and(|p| p != self.port) {
            return false;
        }
        self.names.iter().any(|n| n == name) || (self.any_ip && is_ip(name))
    }

    /// The names, for a message.
    fn list(&self) -> String {
        let mut list = self.names.join(", ");
        if self.any_ip {
            list.push_str(", any IP address");
        }
        list
    }
}

/// `ip` as a `Host` names it.
fn literal(ip: IpAddr) -> String {
    match ip {
        IpAddr::V4(ip) => ip.to_string(),
        IpAddr::V6(ip) => format!("[{ip}]"),
    }
}

/// Whether `name` is an IP address as a `Host` gives it.
fn is_ip(name: &str) -> bool {
    name.parse::<Ipv4Addr>().is_ok()
        || name
            .strip_prefix('[')
            .and_then(|n| n.strip_suffix(']'))
            .is_some_and(|n| n.parse::<Ipv6Addr>().is_ok())
}

/// `host` as name and port: `name`, `name:port`, `[v6]`, `[v6]:port`.
fn split_host(host: &str) -> Option<(&str, Option<u16>)> {
    let (name, rest) = if host.starts_with('[') {
        let end = host.find(']')?;
        host.split_at(end + 1)
    } else {
        match host.rfind(':') {
            Some(i) => host.split_at(i),
            None => (host, ""),
        }
    };
    if name.is_empty() {
        return None;
    }
    if rest.is_empty() {
        return Some((name, None));
    }
    let digits = rest.strip_prefix(':')?;
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((name, Some(digits.parse().ok()?)))
}

/// An answer before it is sent.
#[derive(Debug)]
pub struct Answer {
    /// HTTP status.
    pub status: u16,
    /// `Content-Type`.
    pub content_type: &'static str,
    /// The body.
    pub body: Bytes,
    /// g sin α of the run's scenario, m/s², for the page's a/(g sin α).
    pub g_along: Option<f64>,
    /// The run's place, held until the answer is sent: what the answers of
    /// runs hold in memory at once is bounded by the places.
    pub place: Option<OwnedSemaphorePermit>,
}

impl Answer {
    fn json(status: u16, body: Bytes) -> Answer {
        Answer {
            status,
            content_type: "application/json",
            body,
            g_along: None,
            place: None,
        }
    }

    /// `{"error": message}` with `status`.
    pub fn error(status: u16, message: &str) -> Answer {
        Answer::json(
            status,
            Bytes::from(serde_json::json!({ "error": message }).to_string()),
        )
    }

    /// The answer as hyper sends it.
    fn into_response(self) -> Response<AnswerBody> {
        let status = self.status;
        let mut response = Response::new(AnswerBody::new(self.body, self.place));
        *response.status_mut() =
            StatusCode::from_u16(status).unwrap_or(StatusCode::INTERNAL_SERVER_ERROR);
        let headers = response.headers_mut();
        headers.insert(
            header::CONTENT_TYPE,
            HeaderValue::from_static(self.content_type),
        );
        headers.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
        headers.insert(
            header::X_CONTENT_TYPE_OPTIONS,
            HeaderValue::from_static("nosniff"),
        );
        if let Some(g) = self
            .g_along
            .and_then(|g| HeaderValue::from_str(&format!("{g:?}")).ok())
        {
            headers.insert("x-snowroll-g-along", g);
        }
        if status == 503 {
            headers.insert(header::RETRY_AFTER, HeaderValue::from(RETRY_AFTER_S));
        }
        if status == 405 {
            headers.insert(header::ALLOW, HeaderValue::from_static("GET, HEAD"));
        }
        response
    }
}

/// The body of an answer: all in memory, sent in pieces of 64 KiB, within
/// [`SEND_TIMEOUT`] from the first piece (past it the connection is
/// closed); the run's place is given back when it is sent or dropped.
#[derive(Debug)]
pub struct AnswerBody {
    data: Bytes,
    deadline: Option<Instant>,
    place: Option<OwnedSemaphorePermit>,
}

impl AnswerBody {
    /// The size of one piece.
    const PIECE: usize = 64 * 1024;

    fn new(data: Bytes, place: Option<OwnedSemaphorePermit>) -> AnswerBody {
        AnswerBody {
            data,
            deadline: None,
            place,
        }
    }
}

impl Body for AnswerBody {
    type Data = Bytes;
    type Error = io::Error;

    fn poll_frame(
        self: Pin<&mut Self>,
        _cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, io::Error>>> {
        let this = self.get_mut();
        if this.data.is_empty() {
            this.place = None;
            return Poll::Ready(None);
        }
        let now = Instant::now();
        let deadline = *this.deadline.get_or_insert(now + SEND_TIMEOUT);
        if now > deadline {
            this.place = None;
            return Poll::Ready(Some(Err(io::Error::new(
                io::ErrorKind::TimedOut,
                "the answer took longer than the send timeout",
            ))));
        }
        let piece = this.data.split_to(this.data.len().min(Self::PIECE));
        Poll::Ready(Some(Ok(Frame::data(piece))))
    }

    fn is_end_stream(&self) -> bool {
        self.data.is_empty()
    }

    fn size_hint(&self) -> SizeHint {
        SizeHint::with_exact(self.data.len() as u64)
    }
}

/// Answers `request` (hyper's service).
///
/// # Errors
/// None: every failure is an answer.
pub async fn answer(
    request: Request<Incoming>,
    server: Arc<Server>,
) -> Result<Response<AnswerBody>, Infallible> {
    Ok(reply(&request, &server).await.into_response())
}

/// The message of a 414.
pub fn too_long_message(len: usize) -> String {
    format!("the request's path and query are {len} bytes long, more than this server reads ({MAX_URL})")
}

/// The answer to `request`: its size, its `Host`, its method, then the route.
async fn reply(request: &Request<Incoming>, server: &Server) -> Answer {
    let uri = request.uri();
    let target = uri.path_and_query().map_or(0, |p| p.as_str().len())
        + uri.authority().map_or(0, |a| a.as_str().len());
    if target > MAX_URL {
        return Answer::error(414, &too_long_message(target));
    }
    if let Err(refused) = check_host(request, &server.hosts) {
        return refused;
    }
    let body = request.body().size_hint();
    if body.upper().is_none_or(|n| n > MAX_BODY as u64) {
        return Answer::error(
            413,
            &format!(
                "the request has a body of more than {MAX_BODY} bytes, or of a length not \
                 given; the API takes none"
            ),
        );
    }
    if !matches!(*request.method(), Method::GET | Method::HEAD) {
        return Answer::error(405, "the API answers GET (and HEAD) requests only");
    }
    route(uri.path(), uri.query().unwrap_or(""), server).await
}

/// Refuses a request whose `Host` (or absolute target) is not one of
/// `hosts`: 403; 400 when an HTTP/1.1 request has none, or two.
fn check_host(request: &Request<Incoming>, hosts: &Hosts) -> Result<(), Answer> {
    let mut given: Vec<&str> = Vec::new();
    for value in request.headers().get_all(header::HOST) {
        let Ok(value) = value.to_str() else {
            return Err(Answer::error(400, "the Host header is not plain text"));
        };
        given.push(value);
    }
    if given.len() > 1 {
        return Err(Answer::error(
            400,
            "the request has more than one Host header",
        ));
    }
    if let Some(authority) = request.uri().authority() {
        given.push(authority.as_str());
    }
    if given.is_empty() && request.version() == Version::HTTP_11 {
        return Err(Answer::error(
            400,
            "an HTTP/1.1 request needs a Host header",
        ));
    }
    match given.into_iter().find(|h| !hosts.allows(h)) {
        None => Ok(()),
        Some(host) => {
            let shown: String = host.chars().take(100).collect();
            Err(Answer::error(
                403,
                &format!(
                    "this server answers requests for {} (port {}) only, not for Host `{shown}` \
                     (a guard against DNS rebinding); `snowroll serve --allow-host NAME` \
                     answers NAME too",
                    hosts.list(),
                    hosts.port
                ),
            ))
        }
    }
}

/// The answer for `path` and `query`.
async fn route(path: &str, query: &str, server: &Server) -> Answer {
    match path {
        "/api/params" => Answer::json(200, server.params.clone()),
        "/api/models" => run(Endpoint::Models, query, server).await,
        "/api/simulate" => run(Endpoint::Simulate, query, server).await,
        "/api/turns" => run(Endpoint::Turns, query, server).await,
        _ => match files::find(path) {
            Some(file) => Answer {
                status: 200,
                content_type: file.content_type,
                body: Bytes::from_static(file.body),
                g_along: None,
                place: None,
            },
            None => Answer::error(
                404,
                &format!(
                    "no such page: {}",
                    path.chars().take(200).collect::<String>()
                ),
            ),
        },
    }
}

/// The 503 of a server whose runs are all taken and whose queue is full,
/// or that kept a request waiting [`QUEUE_WAIT`].
fn busy() -> Answer {
    Answer::error(
        503,
        &format!(
            "the server is running {MAX_RUNS} requests and more are waiting; \
             ask again in {RETRY_AFTER_S} s"
        ),
    )
}

/// The 503 of a server that is stopping.
fn stopping() -> Answer {
    Answer::error(503, "the server is stopping; its runs were ended")
}

/// Runs the command of `endpoint` for `query`: at most [`MAX_RUNS`] at
/// once, the others waiting in turn (at most [`MAX_QUEUED`], each at most
/// [`QUEUE_WAIT`]).
async fn run(endpoint: Endpoint, query: &str, server: &Server) -> Answer {
    let request = match query::command_line(endpoint, query) {
        Ok(r) => r,
        Err(Refused::Bad(m)) => return Answer::error(400, &m),
        Err(Refused::TooLarge(m)) => return Answer::error(413, &m),
    };
    let Ok(queued) = Arc::clone(&server.queue).try_acquire_owned() else {
        return busy();
    };
    let place = race(
        timeout(QUEUE_WAIT, Arc::clone(&server.runs).acquire_owned()),
        stopped(server.stop.clone()),
    )
    .await;
    drop(queued);
    let place = match place {
        Either::Left(Ok(Ok(place))) => place,
        Either::Left(_) => return busy(),
        Either::Right(()) => return stopping(),
    };
    let limits = Limits {
        seconds: MAX_SECONDS,
        answer_bytes: MAX_ANSWER,
    };
    let ran = match child::run(&server.exe, &request.args, limits, server.stop.clone()).await {
        Ok(ran) => ran,
        Err(e) => {
            report!(
                "error: snowroll serve could not run {}: {e}",
                endpoint.command()
            );
            return Answer::error(
                500,
                &format!("the server could not run {}: {e}", endpoint.command()),
            );
        }
    };
    match ran.ended {
        Ended::Stopped => stopping(),
        _ if *server.stop.borrow() => stopping(),
        Ended::Exited(status) if status.success() => Answer {
            status: 200,
            content_type: if request.csv {
                "text/csv; charset=utf-8"
            } else {
                "application/json"
            },
            body: Bytes::from(ran.stdout),
            g_along: request.g_along,
            place: Some(place),
        },
        Ended::Exited(_) => Answer::error(400, &child::error_message(&ran.stderr)),
        Ended::TimedOut => Answer::error(
            413,
            &format!(
                "the run took longer than this server allows for one request ({MAX_SECONDS} s) \
                 and was stopped; ask for fewer turns, a shorter t_end or x_end, or run \
                 `snowroll {}` on the command line",
                endpoint.command()
            ),
        ),
        Ended::TooLong => Answer::error(
            413,
            &format!(
                "the answer grew past {} MB, more than this server sends for one request, and \
                 the run was stopped; ask for a coarser dt, a shorter t_end, or run `snowroll {}` \
                 on the command line",
                MAX_ANSWER / (1024 * 1024),
                endpoint.command()
            ),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hosts_take_loopback_names_with_this_port_only() {
        let local = Hosts::new(IpAddr::from([127, 0, 0, 1]), 8000, &[]);
        for ok in [
            "localhost",
            "localhost:8000",
            "LocalHost:8000",
            "127.0.0.1:8000",
            "127.0.0.1",
            "[::1]:8000",
            "[::1]",
        ] {
            assert!(local.allows(ok), "{ok}");
        }
        for refused in [
            "evil.example",
            "evil.example:8000",
            "localhost:8001",
            "localhost:",
            "localhost:+8000",
            "127.0.0.2:8000",
            "192.168.1.5:8000",
            "localhost.evil.example:8000",
            "[::1",
            "",
            ":8000",
        ] {
            assert!(!local.allows(refused), "{refused}");
        }
        // Listening on every address: any IP address, and the names given.
        let all = Hosts::new(IpAddr::from([0, 0, 0, 0]), 8000, &["Teacher.local".into()]);
        for ok in ["192.168.1.5:8000", "[fe80::1]:8000", "teacher.local:8000"] {
            assert!(all.allows(ok), "{ok}");
        }
        assert!(!all.allows("evil.example:8000"));
        // One address: that address.
        let one = Hosts::new(IpAddr::from([192, 168, 1, 5]), 8000, &[]);
        assert!(one.allows("192.168.1.5:8000"));
        assert!(!one.allows("192.168.1.6:8000"));
    }
}
