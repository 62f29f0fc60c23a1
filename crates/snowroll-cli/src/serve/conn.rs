//! Connections: accepting them within [`MAX_CONNECTIONS`], reading each
//! one's first request line, handing it to hyper, and closing it on the
//! server's stop.
//!
//! What bounds a connection, and where:
//!
//! | bound | where |
//! |---|---|
//! | connections at once ([`MAX_CONNECTIONS`]); at the limit the idle ones are asked to close, a new one waits [`ACCEPT_WAIT`] for a place, at most [`MAX_WAITING`] wait, more get 503 unread | [`accept_loop`] |
//! | the first request line: [`MAX_LINE`] bytes (414), an HTTP version other than 1.0 and 1.1 (505, HTTP/2's preface too) | [`first_line`] |
//! | the head (line and headers): [`MAX_HEAD`] bytes, [`MAX_HEADERS`] lines (431), sent within [`HEAD_TIMEOUT`]; also the idle keep-alive time | hyper's `http1::Builder` |
//! | a write that makes no progress for [`WRITE_TIMEOUT`] | [`Timed`] |
//! | the server's stop: idle connections closed at once, runs ended | [`serve_connection`] |
//!
//! Request bodies are never read: hyper drains one that is already in
//! memory (to keep the connection) and otherwise closes the connection.

use std::future::Future;
use std::io;
use std::pin::{pin, Pin};
use std::sync::Arc;
use std::task::{Context, Poll};
use std::time::Duration;

use hyper::server::conn::http1;
use hyper::service::service_fn;
use hyper_util::rt::{TokioIo, TokioTimer};
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{watch, OwnedSemaphorePermit, Semaphore};
use tokio::time::{sleep, timeout, timeout_at, Instant, Sleep};

use super::limits::{
    ACCEPT_WAIT, HEAD_TIMEOUT, MAX_CONNECTIONS, MAX_HEAD, MAX_HEADERS, MAX_LINE, MAX_URL,
    MAX_WAITING, RETRY_AFTER_S, SHUTDOWN_GRACE, WRITE_TIMEOUT,
};
use super::respond::{self, Server};
use super::wait::{race, stopped, Either};

/// Ends when the server stops or asks idle connections to close.
async fn stopped_or_shed(stop: watch::Receiver<bool>, mut shed: watch::Receiver<u64>) {
    let shed = async move {
        if shed.changed().await.is_err() {
            std::future::pending::<()>().await;
        }
    };
    race(stopped(stop), shed).await;
}

/// Accepts connections until `stop` turns true, then gives those still
/// open [`SHUTDOWN_GRACE`] to end.
pub async fn accept_loop(listener: TcpListener, server: Arc<Server>, shed: watch::Sender<u64>) {
    let places = Arc::new(Semaphore::new(MAX_CONNECTIONS));
    let waiting = Arc::new(Semaphore::new(MAX_WAITING));
    loop {
        let accepted = match race(listener.accept(), stopped(server.stop.clone())).await {
            Either::Left(accepted) => accepted,
            Either::Right(()) => break,
        };
        let stream = match accepted {
            Ok((stream, _)) => stream,
            Err(_) => {
                // Out of file descriptors, or a connection reset before it
                // was taken: try again shortly rather than spin.
                sleep(Duration::from_millis(50)).await;
                continue;
            }
        };
        let _ = stream.set_nodelay(true);
        if let Ok(place) = Arc::clone(&places).try_acquire_owned() {
            tokio::spawn(serve_connection(stream, Arc::clone(&server), place));
            continue;
        }
        // Full: the idle connections are asked to close, and this one waits
        // for a place (a fair queue: the first to wait is the first placed).
        shed.send_modify(|n| *n = n.wrapping_add(1));
        let Ok(wait) = Arc::clone(&waiting).try_acquire_owned() else {
            refuse_unread(&stream);
            continue;
        };
        let (places, server) = (Arc::clone(&places), Arc::clone(&server));
        tokio::spawn(async move {
            let place = timeout(ACCEPT_WAIT, places.acquire_owned()).await;
            match place {
                Ok(Ok(place)) => {
                    drop(wait);
                    serve_connection(stream, server, place).await;
                }
                _ => {
                    refuse(stream, 503, &busy_message()).await;
                    drop(wait);
                }
            }
        });
    }
    drop(listener);
    // Every place back: every connection closed.
    let all = u32::try_from(MAX_CONNECTIONS).unwrap_or(u32::MAX);
    let _ = timeout(SHUTDOWN_GRACE, places.acquire_many(all)).await;
}

/// The message of a 503 for a full server.
fn busy_message() -> String {
    format!(
        "the server has {MAX_CONNECTIONS} connections open and more waiting; \
         ask again in {RETRY_AFTER_S} s"
    )
}

/// Serves one connection until it closes, the client is idle past
/// [`HEAD_TIMEOUT`], or the server stops or sheds idle connections.
async fn serve_connection(mut stream: TcpStream, server: Arc<Server>, place: OwnedSemaphorePermit) {
    let _place = place;
    let stop = server.stop.clone();
    let mut shed = server.shed.clone();
    // Only a request to shed made from now on counts.
    shed.borrow_and_update();
    let first = match race(
        first_line(&mut stream),
        stopped_or_shed(stop.clone(), shed.clone()),
    )
    .await
    {
        Either::Left(first) => first,
        Either::Right(()) => return,
    };
    let prefix = match first {
        First::Pass(prefix) => prefix,
        First::Refuse(status, message) => {
            refuse(stream, status, &message).await;
            return;
        }
        First::Gone => return,
    };
    let io = TokioIo::new(Timed::new(stream, prefix));
    let service = {
        let server = Arc::clone(&server);
        service_fn(move |request| respond::answer(request, Arc::clone(&server)))
    };
    let conn = http1::Builder::new()
        .timer(TokioTimer::new())
        .header_read_timeout(HEAD_TIMEOUT)
        .max_buf_size(MAX_HEAD)
        .max_header_size(MAX_HEAD)
        .max_headers(MAX_HEADERS)
        // `X-Snowroll-G-Along`, as the server has always written it.
        .title_case_headers(true)
        // A client that closes its side after its request (as `nc -N`
        // does) still gets its answer. (Without this hyper drops the
        // request when it reads that end, a static page's too; the cost is
        // that a run whose client has gone is not ended until it ends or
        // reaches its 10 s, since hyper reads nothing more while it
        // answers.)
        .half_close(true)
        .serve_connection(io, service);
    let mut conn = pin!(conn);
    if let Either::Right(()) = race(conn.as_mut(), stopped_or_shed(stop, shed)).await {
        // Closes it now if it is idle or still reading a head; else after
        // the answer being made (a run is ended when the server stops).
        conn.as_mut().graceful_shutdown();
        let _ = conn.await;
    }
}

/// What the first request line of a connection asks for.
#[derive(Debug)]
enum First {
    /// An HTTP/1 request: the bytes read so far, for hyper to read first.
    Pass(Vec<u8>),
    /// Refused with this status and message.
    Refuse(u16, String),
    /// Closed, or silent past [`HEAD_TIMEOUT`].
    Gone,
}

/// Reads a connection's first request line: at most [`MAX_LINE`] bytes and
/// [`HEAD_TIMEOUT`]. hyper reads every later one, and answers 400 where
/// this answers 505, and 431 where this answers 414 (past [`MAX_HEAD`]).
async fn first_line(stream: &mut TcpStream) -> First {
    let deadline = Instant::now() + HEAD_TIMEOUT;
    let mut buf = Vec::with_capacity(1024);
    let mut chunk = [0u8; 2048];
    loop {
        if let Some(end) = buf.iter().position(|b| *b == b'\n') {
            return judge(buf, end);
        }
        if buf.len() > MAX_LINE {
            return First::Refuse(
                414,
                format!(
                    "the request line is longer than this server reads ({MAX_LINE} bytes; \
                     the path and query at most {MAX_URL})"
                ),
            );
        }
        match timeout_at(deadline, stream.read(&mut chunk)).await {
            Ok(Ok(n)) if n > 0 => buf.extend_from_slice(&chunk[..n]),
            _ => return First::Gone,
        }
    }
}

/// The verdict on a first request line, `read[..end]` (`read` is every byte
/// read so far, `read[end]` the line's `\n`).
fn judge(read: Vec<u8>, end: usize) -> First {
    let line = &read[..end];
    let line = line.strip_suffix(b"\r").unwrap_or(line);
    let mut words = line.split(|b| *b == b' ').filter(|w| !w.is_empty());
    let (target, version) = (words.nth(1), words.next_back());
    if let Some(version) = version.filter(|v| v.starts_with(b"HTTP/")) {
        if version != b"HTTP/1.1" && version != b"HTTP/1.0" {
            let shown: String = String::from_utf8_lossy(version).chars().take(20).collect();
            return First::Refuse(
                505,
                format!(
                    "this server speaks HTTP/1.1 (and 1.0) only, not {shown}; \
                     ask again with HTTP/1.1"
                ),
            );
        }
    }
    if let Some(target) = target.filter(|t| t.len() > MAX_URL) {
        return First::Refuse(414, respond::too_long_message(target.len()));
    }
    First::Pass(read)
}

/// Answers `status` with `{"error": message}` without reading the request
/// on, then closes: the write bounded by [`WRITE_TIMEOUT`], and what the
/// client still sends read and dropped for at most 1 s and 1 MiB, so that
/// the close does not reset the connection before the answer is read.
async fn refuse(mut stream: TcpStream, status: u16, message: &str) {
    let answer = raw_answer(status, message);
    if timeout(WRITE_TIMEOUT, stream.write_all(&answer))
        .await
        .is_err()
    {
        return;
    }
    let _ = stream.shutdown().await;
    let deadline = Instant::now() + Duration::from_secs(1);
    let mut chunk = [0u8; 8192];
    let mut dropped = 0;
    while dropped < 1 << 20 {
        match timeout_at(deadline, stream.read(&mut chunk)).await {
            Ok(Ok(n)) if n > 0 => dropped += n,
            _ => break,
        }
    }
}

/// A 503 written at once if the socket takes it, then closed: for a
/// connection past every limit, with no task of its own.
fn refuse_unread(stream: &TcpStream) {
    let _ = stream.try_write(&raw_answer(503, &busy_message()));
}

/// A whole HTTP/1.1 answer with a JSON error body, closing the connection.
fn raw_answer(status: u16, message: &str) -> Vec<u8> {
    let body = serde_json::json!({ "error": message }).to_string();
    let reason = hyper::StatusCode::from_u16(status)
        .ok()
        .and_then(|s| s.canonical_reason())
        .unwrap_or("Error");
    let retry = if status == 503 {
        format!("Retry-After: {RETRY_AFTER_S}\r\n")
    } else {
        String::new()
    };
    format!(
        "HTTP/1.1 {status} {reason}\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\
         Cache-Control: no-store\r\n{retry}Connection: close\r\n\r\n{body}",
        body.len()
    )
    .into_bytes()
}

/// A connection as hyper reads it: first the bytes [`first_line`] read,
/// then the socket; a write that makes no progress for [`WRITE_TIMEOUT`]
/// fails (the client is not reading).
struct Timed {
    stream: TcpStream,
    prefix: Vec<u8>,
    at: usize,
    stall: Option<Pin<Box<Sleep>>>,
}

impl Timed {
    fn new(stream: TcpStream, prefix: Vec<u8>) -> Timed {
        Timed {
            stream,
            prefix,
            at: 0,
            stall: None,
        }
    }

    /// A write's outcome, with the stall timer: reset on progress, started
    /// on the first `Pending`, an error when it runs out.
    fn timed<T>(
        &mut self,
        cx: &mut Context<'_>,
        polled: Poll<io::Result<T>>,
    ) -> Poll<io::Result<T>> {
        if polled.is_ready() {
            self.stall = None;
            return polled;
        }
        let stall = self
            .stall
            .get_or_insert_with(|| Box::pin(sleep(WRITE_TIMEOUT)));
        match stall.as_mut().poll(cx) {
            Poll::Ready(()) => Poll::Ready(Err(io::Error::new(
                io::ErrorKind::TimedOut,
                "the client read nothing of its answer for the write timeout",
            ))),
            Poll::Pending => Poll::Pending,
        }
    }
}

impl AsyncRead for Timed {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        if this.at < this.prefix.len() {
            let n = buf.remaining().min(this.prefix.len() - this.at);
            buf.put_slice(&this.prefix[this.at..this.at + n]);
            this.at += n;
            if this.at == this.prefix.len() {
                this.prefix = Vec::new();
                this.at = 0;
            }
            return Poll::Ready(Ok(()));
        }
        Pin::new(&mut this.stream).poll_read(cx, buf)
    }
}

impl AsyncWrite for Timed {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        data: &[u8],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.stream).poll_write(cx, data);
        this.timed(cx, polled)
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.stream).poll_write_vectored(cx, bufs);
        this.timed(cx, polled)
    }

    fn is_write_vectored(&self) -> bool {
        self.stream.is_write_vectored()
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.stream).poll_flush(cx);
        this.timed(cx, polled)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.stream).poll_shutdown(cx);
        this.timed(cx, polled)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn status(line: &str) -> Option<u16> {
        let read = format!("{line}\nHost: x\r\n").into_bytes();
        match judge(read, line.len()) {
            First::Refuse(status, _) => Some(status),
            First::Pass(_) => None,
            First::Gone => Some(0),
        }
    }

    #[test]
    fn judge_refuses_other_versions_and_long_targets() {
        assert_eq!(status("GET / HTTP/1.1\r"), None);
        assert_eq!(status("GET /api/params HTTP/1.0"), None);
        assert_eq!(status("GET / HTTP/2.0\r"), Some(505));
        assert_eq!(status("PRI * HTTP/2.0\r"), Some(505));
        assert_eq!(status("GET / HTTP/3"), Some(505));
        // Not HTTP at all: left to hyper, which answers 400.
        assert_eq!(status("hello"), None);
        let long = format!("GET /{} HTTP/1.1", "a".repeat(MAX_URL));
        assert_eq!(status(&long), Some(414));
        let fits = format!("GET /{} HTTP/1.1", "a".repeat(MAX_URL - 1));
        assert_eq!(status(&fits), None);
    }
}
