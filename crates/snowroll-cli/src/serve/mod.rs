//! `snowroll serve`: the classroom explorer. One page (`assets/`, built into
//! the binary) and a JSON API on a local HTTP server.
//!
//! The HTTP crate is `tiny_http`: synchronous, four small dependencies, no
//! async runtime. Requests are answered by a fixed pool of [`WORKERS`]
//! threads, each running at most one child at a time ([`child`]), so that
//! one slow request holds one worker and the others keep answering; every
//! request is checked against the [`limits`] before any run.
//!
//! | request | answer |
//! |---|---|
//! | `GET /` | the page (`/app.js`, `/style.css` beside it) |
//! | `GET /api/params` | the parameter table: keys, units, kinds, defaults, ranges, help ([`limits::params_json`]) |
//! | `GET /api/models` | `snowroll models --format json` |
//! | `GET /api/simulate?model=...&alpha_deg=...` | `snowroll simulate --format json` (or `format=csv`) |
//! | `GET /api/turns?...` | `snowroll turns --format json` (or `format=csv`) |
//!
//! A bad value is answered with 400 and `{"error": "<the command's message>"}`,
//! a request over a limit with 413.

mod child;
mod limits;
mod query;
mod respond;

use std::io::Write;
use std::net::{IpAddr, SocketAddr};
use std::path::Path;
use std::sync::{Arc, OnceLock};
use std::thread;

use anyhow::{anyhow, Context, Result};

use crate::args::ServeArgs;
use crate::console::{self, report};
pub use limits::WORKERS;

/// What a signal does while the server runs: unblocks its workers.
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
    if !ip.is_loopback() {
        report!(
            "warning: --host {ip} serves this page and its API to other machines on the network, \
             with no password; 127.0.0.1 (the default) serves this machine only"
        );
    }
    let server = tiny_http::Server::http(SocketAddr::new(ip, args.port))
        .map_err(|e| anyhow!("cannot listen on {ip} port {}: {e}", args.port))?;
    let server = Arc::new(server);
    let addr = server
        .server_addr()
        .to_ip()
        .ok_or_else(|| anyhow!("the server has no IP address"))?;
    let url = match addr {
        SocketAddr::V6(a) => format!("http://[{}]:{}/", a.ip(), a.port()),
        SocketAddr::V4(a) => format!("http://{a}/"),
    };
    let exe = std::env::current_exe().context("cannot find the snowroll program to run")?;
    {
        let server = Arc::clone(&server);
        let _ = ON_SIGNAL.set(Box::new(move || {
            for _ in 0..=WORKERS {
                server.unblock();
            }
        }));
    }
    let mut out = console::Stdout;
    let _ = writeln!(out, "snowroll serve: {url} (Ctrl-C stops it)");
    let _ = out.flush();
    if args.open {
        open_browser(&url);
    }
    let workers: Vec<_> = (0..WORKERS)
        .map(|i| {
            let (server, exe) = (Arc::clone(&server), exe.clone());
            thread::Builder::new()
                .name(format!("serve-{i}"))
                .spawn(move || work(&server, &exe))
        })
        .collect::<std::io::Result<_>>()?;
    for w in workers {
        let _ = w.join();
    }
    report!("snowroll serve: stopped");
    Ok(())
}

/// Answers requests until the server is unblocked.
fn work(server: &tiny_http::Server, exe: &Path) {
    while let Ok(request) = server.recv() {
        respond::answer(request, exe);
    }
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
        Ok(mut child) => drop(thread::spawn(move || child.wait())),
        Err(e) => report!("note: --open: xdg-open failed ({e}); open {url} in a browser"),
    }
}
