//! `snowroll serve`: the classroom explorer. One page ([`files`], built
//! into the binary) and a JSON API on a local HTTP server.
//!
//! The HTTP/1.1 server is hyper's, on a single-threaded tokio runtime: the
//! work of a request is a child process ([`child`]), so the server itself
//! only reads requests and writes answers, and one thread does that for
//! every connection; a slow run or a slow client holds no thread. Every
//! bound on what a client can make the server hold or do is in [`limits`]:
//! what a connection may send and how slowly ([`conn`]), and what a
//! request may run ([`respond`], [`query`]).
//!
//! | request | answer |
//! |---|---|
//! | `GET /` | the page (and the other [`files`]) |
//! | `GET /api/params` | the parameter table: keys, units, kinds, defaults, ranges, help ([`limits::params_json`]) |
//! | `GET /api/models` | `snowroll models --format json` |
//! | `GET /api/simulate?model=...&alpha_deg=...` | `snowroll simulate --format json` (or `format=csv`) |
//! | `GET /api/turns?...` | `snowroll turns --format json` (or `format=csv`) |
//!
//! A bad value is answered with 400 and `{"error": "<the command's message>"}`,
//! a request over a limit with 413 (414, 431), a busy server with 503 and
//! `Retry-After`, a `Host` that is not this server's with 403.

mod child;
mod conn;
mod files;
mod limits;
mod query;
mod respond;
mod wait;

use std::io::Write;
use std::net::{IpAddr, SocketAddr};
use std::sync::{Arc, OnceLock};

use anyhow::{anyhow, bail, Context, Result};
use tokio::sync::watch;

use crate::args::ServeArgs;
use crate::console::{self, report};

/// What a signal does while the server runs: tells it to stop.
static ON_SIGNAL: OnceLock<Box<dyn Fn() + Send + Sync>> = OnceLock::new();

/// Stops the server if one is running (SIGINT, SIGTERM, SIGHUP); returns
/// whether one was.
pub fn stop_on_signal() -> bool {
    match ON_SIGNAL.get() {
        Some(stop) => {
            stop();
            true
        }
        None => false,
    }
}

/// Serves until a signal stops it.
pub fn run(args: &ServeArgs) -> Result<()> {
    let ip: IpAddr = args.host.parse().map_err(|_| {
        anyhow!(
            "--host {} is not an IP address (such as 127.0.0.1, ::1 or 0.0.0.0)",
            args.host
        )
    })?;
    for name in &args.allow_host {
        if name.is_empty() || name.contains(|c: char| c == '/' || c == ':' || c.is_whitespace()) {
            bail!(
                "--allow-host `{}` is not a host name or IPv4 address (such as teacher.local \
                 or 192.168.1.5, without a port)",
                name.chars().take(100).collect::<String>()
            );
        }
    }
    if !ip.is_loopback() {
        report!(
            "warning: --host {ip} serves this page and its API to other machines on the network, \
             with no password; 127.0.0.1 (the default) serves this machine only"
        );
    }
    let exe = std::env::current_exe().context("cannot find the snowroll program to run")?;
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_io()
        .enable_time()
        .build()
        .context("cannot start the server's event loop")?;
    let (stop_tx, stop) = watch::channel(false);
    let (shed_tx, shed) = watch::channel(0u64);
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(SocketAddr::new(ip, args.port))
            .await
            .map_err(|e| anyhow!("cannot listen on {ip} port {}: {e}", args.port))?;
        let addr = listener.local_addr()?;
        let url = match addr {
            SocketAddr::V6(a) => format!("http://[{}]:{}/", a.ip(), a.port()),
            SocketAddr::V4(a) => format!("http://{a}/"),
        };
        let hosts = respond::Hosts::new(ip, addr.port(), &args.allow_host);
        let server = Arc::new(respond::Server::new(exe, hosts, stop, shed));
        let _ = ON_SIGNAL.set(Box::new(move || {
            let _ = stop_tx.send(true);
        }));
        let mut out = console::Stdout;
        let _ = writeln!(out, "snowroll serve: {url} (Ctrl-C stops it)");
        let _ = out.flush();
        if args.open {
            open_browser(&url);
        }
        conn::accept_loop(listener, server, shed_tx).await;
        Ok::<(), anyhow::Error>(())
    })?;
    // Whatever is still open (an answer being sent past the grace time) is
    // dropped with the runtime; a run still going is killed with it.
    drop(runtime);
    report!("snowroll serve: stopped");
    Ok(())
}

/// Opens `url` with `xdg-open` when there is one, else says so.
fn open_browser(url: &str) {
    let found = std::env::var_os("PATH")
        .is_some_and(|path| std::env::split_paths(&path).any(|dir| dir.join("xdg-open").is_file()));
    if !found {
        report!("note: --open: no xdg-open on this machine; open {url} in a browser");
        return;
    }
    let spawned = std::process::Command::new("xdg-open")
        .arg(url)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
    match spawned {
        // Reaped when it ends (xdg-open returns once the browser is asked).
        Ok(mut child) => drop(std::thread::spawn(move || child.wait())),
        Err(e) => report!("note: --open: xdg-open failed ({e}); open {url} in a browser"),
    }
}
