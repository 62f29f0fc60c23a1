//! `snowroll serve` (feature `serve`): the API answers with the bytes of the
//! command line's `simulate`, `turns` and `models`; bad values get 400 and
//! the command's own message; requests over a limit are refused before any
//! run; many clients at once are all answered, and a slow request does not
//! hold up the others; SIGINT stops the server with success.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::support::bin;

/// A server started for one test, stopped (SIGINT) when dropped.
struct Server {
    child: Child,
    /// `127.0.0.1:PORT`.
    addr: String,
}

impl Server {
    fn start() -> Server {
        let mut child = Command::new(bin())
            .args(["serve", "--port", "0"])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let url = line
            .split_whitespace()
            .find(|w| w.starts_with("http://"))
            .unwrap_or_else(|| panic!("no URL printed: {line:?}"));
        let addr = url.trim_start_matches("http://").trim_end_matches('/');
        Server {
            child,
            addr: addr.to_string(),
        }
    }

    /// Sends SIGINT and waits for the exit.
    fn interrupt(&mut self) -> std::process::ExitStatus {
        let pid = self.child.id().to_string();
        assert!(Command::new("kill")
            .args(["-INT", &pid])
            .status()
            .unwrap()
            .success());
        self.child.wait().unwrap()
    }

    fn get(&self, path: &str) -> Reply {
        request(
            &self.addr,
            &format!("GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"),
        )
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            let _ = self.interrupt();
        }
    }
}

/// An HTTP answer.
#[derive(Debug, Clone, PartialEq)]
struct Reply {
    status: u16,
    headers: String,
    body: Vec<u8>,
}

impl Reply {
    fn error(&self) -> String {
        let v: serde_json::Value = serde_json::from_slice(&self.body)
            .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&self.body)));
        v["error"].as_str().unwrap().to_string()
    }
}

/// Sends `raw` to `addr`; reads the whole answer (the server closes).
fn request(addr: &str, raw: &str) -> Reply {
    let mut s = TcpStream::connect(addr).unwrap();
    s.write_all(raw.as_bytes()).unwrap();
    let mut all = Vec::new();
    s.read_to_end(&mut all).unwrap();
    let split = all.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
    let headers = String::from_utf8_lossy(&all[..split]).into_owned();
    let status = headers.split_whitespace().nth(1).unwrap().parse().unwrap();
    Reply {
        status,
        headers,
        body: all[split + 4..].to_vec(),
    }
}

/// `snowroll ARGS`, run directly.
fn cli(args: &[&str]) -> Output {
    Command::new(bin()).args(args).output().unwrap()
}

/// The command line's message on stderr: from `error: ` (left out) to the
/// first blank line (clap's hint on `--help` after it is left out).
fn cli_error(out: &Output) -> String {
    let text = String::from_utf8_lossy(&out.stderr);
    let start = text.find("error: ").unwrap() + "error: ".len();
    let text = &text[start..];
    text[..text.find("\n\n").unwrap_or(text.len())]
        .trim()
        .to_string()
}

/// Scenarios as (query, the command line's flags): the default run, the
/// ball with the chord swath, losses, a grid, chosen times, a turn model.
const SIMULATE: &[(&str, &[&str])] = &[
    ("model=torque-cm", &["--model", "torque-cm"]),
    (
        "model=energy&alpha_deg=12.5&shape=sphere&swath_width=chord&snow_depth=0.02",
        &[
            "--model",
            "energy",
            "--alpha-deg",
            "12.5",
            "--shape",
            "sphere",
            "--swath-width",
            "chord",
            "--snow-depth",
            "0.02",
        ],
    ),
    (
        "model=loney&drag_coefficient=0.8&rolling_resistance=0.01&ledger=true&t_end=20",
        &[
            "--model",
            "loney",
            "--drag-coefficient",
            "0.8",
            "--rolling-resistance",
            "0.01",
            "--ledger",
            "--t-end",
            "20",
        ],
    ),
    (
        "model=quasi-circular&dt=0.25&t_end=30&mu=0.3",
        &[
            "--model",
            "quasi-circular",
            "--dt",
            "0.25",
            "--t-end",
            "30",
            "--mu",
            "0.3",
        ],
    ),
    (
        "model=snowless&times=0.5%2C1%2C2.5",
        &["--model", "snowless", "--times", "0.5,1,2.5"],
    ),
    (
        "model=turns&dt=0.05&t_end=5&alpha_deg=40",
        &[
            "--model",
            "turns",
            "--dt",
            "0.05",
            "--t-end",
            "5",
            "--alpha-deg",
            "40",
        ],
    ),
    (
        "model=torque-contact&alpha_deg=75&on_hop=stop",
        &[
            "--model",
            "torque-contact",
            "--alpha-deg",
            "75",
            "--on-hop",
            "stop",
        ],
    ),
];

#[test]
fn simulate_answers_the_bytes_of_the_command_line() {
    let server = Server::start();
    let mut bodies = Vec::new();
    for (query, flags) in SIMULATE {
        for format in ["json", "csv"] {
            let path = if format == "json" {
                format!("/api/simulate?{query}")
            } else {
                format!("/api/simulate?{query}&format=csv")
            };
            let reply = server.get(&path);
            let mut args = vec!["simulate", "--format", format];
            args.extend_from_slice(flags);
            let out = cli(&args);
            assert!(
                out.status.success(),
                "{args:?}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            assert_eq!(
                reply.status,
                200,
                "{path}: {}",
                String::from_utf8_lossy(&reply.body)
            );
            assert!(
                reply.body == out.stdout,
                "{path}: the bytes differ from `snowroll {args:?}`"
            );
            bodies.push(reply.body);
        }
    }
    // A control: the scenarios' answers all differ, so equal bytes above
    // were not the same answer for every query.
    let n = bodies.len();
    bodies.sort();
    bodies.dedup();
    assert_eq!(bodies.len(), n);
}

#[test]
fn turns_and_models_answer_the_bytes_of_the_command_line() {
    let server = Server::start();
    let cases: &[(&str, &[&str])] = &[
        ("model=turns", &["--model", "turns"]),
        (
            "model=turns-exact&turns=30&alpha_deg=20&collision=pivot",
            &[
                "--model",
                "turns-exact",
                "--turns",
                "30",
                "--alpha-deg",
                "20",
                "--collision",
                "pivot",
            ],
        ),
        (
            "model=eq73&turns=7&format=csv",
            &["--model", "eq73", "--turns", "7", "--format", "csv"],
        ),
    ];
    for (query, flags) in cases {
        let reply = server.get(&format!("/api/turns?{query}"));
        let mut args = vec!["turns"];
        args.extend_from_slice(flags);
        if !query.contains("format=") {
            args.extend_from_slice(&["--format", "json"]);
        }
        let out = cli(&args);
        assert!(out.status.success());
        assert_eq!(reply.status, 200);
        assert!(
            reply.body == out.stdout,
            "{query}: the bytes differ from `snowroll {args:?}` ({} and {} bytes)",
            reply.body.len(),
            out.stdout.len()
        );
    }
    let reply = server.get("/api/models?snow_depth=0.03");
    let out = cli(&["models", "--format", "json", "--snow-depth", "0.03"]);
    assert_eq!(reply.status, 200);
    assert!(reply.body == out.stdout);
    // The header the page divides by: g sin(alpha) of the scenario, here
    // g = 9.81 m/s^2 and alpha = 30 degrees: 9.81 / 2 to rounding.
    let reply = server.get("/api/simulate?model=energy");
    let g_along: f64 = reply
        .headers
        .lines()
        .find_map(|l| l.strip_prefix("X-Snowroll-G-Along: "))
        .unwrap()
        .parse()
        .unwrap();
    // Tolerance: sin(30 degrees) in floating point, a few ulps from 1/2.
    assert!((g_along - 4.905).abs() < 1e-12, "{g_along}");
}

#[test]
fn bad_values_get_400_and_the_command_lines_message() {
    let server = Server::start();
    let cases: &[(&str, &[&str])] = &[
        (
            "model=energy&alpha_deg=95",
            &["simulate", "--model", "energy", "--alpha-deg", "95"],
        ),
        (
            "model=energy&alpha_deg=steep",
            &["simulate", "--model", "energy", "--alpha-deg", "steep"],
        ),
        (
            "model=energy&shape=cube",
            &["simulate", "--model", "energy", "--shape", "cube"],
        ),
        ("model=nonesuch", &["simulate", "--model", "nonesuch"]),
        (
            "model=turns&shape=sphere",
            &["simulate", "--model", "turns", "--shape", "sphere"],
        ),
        (
            "model=energy&r0=-1",
            &["simulate", "--model", "energy", "--r0=-1"],
        ),
        ("alpha_deg=10", &["simulate", "--alpha-deg", "10"]),
    ];
    for (query, args) in cases {
        let reply = server.get(&format!("/api/simulate?{query}"));
        let out = cli(args);
        assert!(!out.status.success(), "{args:?} should fail");
        assert_eq!(reply.status, 400, "{query}");
        assert_eq!(reply.error(), cli_error(&out), "{query}");
    }
    let reply = server.get("/api/turns?model=energy");
    assert_eq!(reply.status, 400);
    assert_eq!(
        reply.error(),
        cli_error(&cli(&["turns", "--model", "energy"]))
    );
    // Refused by the server itself: an unknown key, a key twice, a flag
    // that is neither true nor false, an unknown path.
    for (path, words) in [
        (
            "/api/simulate?model=energy&alpha=3",
            "`alpha` is not a parameter of simulate",
        ),
        (
            "/api/turns?model=turns&dt=1",
            "`dt` is not a parameter of turns",
        ),
        ("/api/simulate?r0=1&r0=2", "`r0` is given twice"),
        (
            "/api/simulate?ledger=maybe",
            "`ledger = maybe` is not true or false",
        ),
    ] {
        let reply = server.get(path);
        assert_eq!(reply.status, 400, "{path}");
        assert!(reply.error().contains(words), "{path}: {}", reply.error());
    }
    assert_eq!(server.get("/nothing-here").status, 404);
}

#[test]
fn requests_over_a_limit_are_refused_before_any_run() {
    let server = Server::start();
    // Each would take minutes or gigabytes; refused at once. 2 s is far
    // above the time to answer without running (milliseconds) and far below
    // any of these runs.
    for (path, words) in [
        ("/api/simulate?model=energy&dt=1e-6", "rows"),
        ("/api/simulate?model=energy&times=1,2,3&t_end=4&dt=1", ""),
        ("/api/turns?model=turns&turns=100000000", "turns"),
        ("/api/simulate?model=turns&turns=100000000", "turns"),
    ] {
        let start = Instant::now();
        let reply = server.get(path);
        assert!(
            start.elapsed() < Duration::from_secs(2),
            "{path}: {:?}",
            start.elapsed()
        );
        assert!(
            matches!(reply.status, 400 | 413),
            "{path}: {}",
            reply.status
        );
        assert!(reply.error().contains(words), "{path}: {}", reply.error());
    }
    let long = format!("/api/simulate?model=energy&times={}", "1,".repeat(5000));
    assert_eq!(server.get(&long).status, 414);
    let body = "x".repeat(4096);
    let reply = request(
        &server.addr,
        &format!("POST /api/simulate HTTP/1.1\r\nHost: x\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}", body.len()),
    );
    assert_eq!(reply.status, 413);
    assert_eq!(
        request(
            &server.addr,
            "DELETE /api/simulate HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"
        )
        .status,
        405
    );
}

#[test]
fn params_lists_the_table_with_its_defaults() {
    let server = Server::start();
    let reply = server.get("/api/params");
    assert_eq!(reply.status, 200);
    let v: serde_json::Value = serde_json::from_slice(&reply.body).unwrap();
    let params = v["params"].as_array().unwrap();
    let settable: Vec<&snowroll::Param> =
        snowroll::PARAMS.iter().filter(|p| p.settable()).collect();
    assert_eq!(params.len(), settable.len());
    for (p, j) in settable.iter().zip(params) {
        assert_eq!(j["key"], p.key);
        assert_eq!(j["unit"], p.unit);
        assert_eq!(j["range"], p.range);
        assert_eq!(j["default_text"], p.default_text());
    }
    // The default alpha, as the simulate answer records it.
    let run: serde_json::Value =
        serde_json::from_slice(&server.get("/api/simulate?model=energy").body).unwrap();
    let alpha = params.iter().find(|j| j["key"] == "alpha_deg").unwrap();
    assert_eq!(alpha["default"], run["params"]["alpha_deg"]);
    // The page and its assets are served, and name no other host.
    let page = server.get("/");
    assert_eq!(page.status, 200);
    for asset in ["/", "/app.js", "/race.js", "/plots.js", "/style.css"] {
        let body = String::from_utf8(server.get(asset).body).unwrap();
        assert!(
            !body.contains("http://") && !body.contains("https://"),
            "{asset} names a host"
        );
    }
}

#[test]
fn many_clients_at_once_are_all_answered_alike() {
    let server = Server::start();
    let queries = [
        "/api/simulate?model=energy",
        "/api/simulate?model=loney&alpha_deg=20",
        "/api/turns?model=turns&turns=20",
        "/api/simulate?model=torque-cm&shape=sphere",
        "/api/params",
    ];
    let addr = server.addr.clone();
    // 300 requests from 30 threads, each query 60 times.
    let handles: Vec<_> = (0..30)
        .map(|t| {
            let addr = addr.clone();
            std::thread::spawn(move || {
                (0..10)
                    .map(|i| {
                        let q = queries[(t + i) % queries.len()];
                        let r = request(
                            &addr,
                            &format!("GET {q} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"),
                        );
                        (q, r)
                    })
                    .collect::<Vec<_>>()
            })
        })
        .collect();
    let mut answers: std::collections::HashMap<&str, Vec<u8>> = Default::default();
    let mut count = 0;
    for h in handles {
        for (q, r) in h.join().unwrap() {
            assert_eq!(r.status, 200, "{q}");
            let first = answers.entry(q).or_insert_with(|| r.body.clone());
            assert!(*first == r.body, "{q}: two different answers");
            count += 1;
        }
    }
    assert_eq!(count, 300);
}

#[test]
fn a_slow_request_does_not_hold_up_the_others() {
    let server = Server::start();
    let addr = server.addr.clone();
    // A turn-by-turn run over 10^6 s: minutes of work, ended at the
    // server's limit (10 s) with 413.
    let slow = std::thread::spawn(move || {
        request(&addr, "GET /api/simulate?model=turns&t_end=1e6&dt=1e5 HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
    });
    std::thread::sleep(Duration::from_millis(300));
    let start = Instant::now();
    for _ in 0..10 {
        assert_eq!(server.get("/api/simulate?model=energy").status, 200);
    }
    // Ten small runs take milliseconds each; 5 s is half the slow run's limit.
    let small = start.elapsed();
    assert!(small < Duration::from_secs(5), "{small:?}");
    assert!(
        !slow.is_finished(),
        "the slow request ended before the small ones"
    );
    let reply = slow.join().unwrap();
    assert_eq!(reply.status, 413);
    assert!(reply.error().contains("took longer"), "{}", reply.error());
}

#[test]
fn sigint_stops_the_server_with_success_and_frees_the_port() {
    let mut server = Server::start();
    assert_eq!(server.get("/api/params").status, 200);
    let status = server.interrupt();
    assert!(status.success(), "{status:?}");
    assert!(
        std::net::TcpListener::bind(&server.addr).is_ok(),
        "the port is still held"
    );
}

#[test]
fn a_host_that_is_not_loopback_is_warned_about() {
    let mut child = Command::new(bin())
        .args(["serve", "--port", "0", "--host", "0.0.0.0"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stderr.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    // Serving once the URL is out: SIGINT then stops it with success.
    let mut url = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut url)
        .unwrap();
    assert!(url.contains("http://0.0.0.0:"), "{url}");
    let _ = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    assert!(child.wait().unwrap().success());
    assert!(line.starts_with("warning: --host 0.0.0.0"), "{line}");
    let out = cli(&["serve", "--host", "localhost-ish"]);
    assert!(!out.status.success());
    assert!(cli_error(&out).contains("is not an IP address"));
}

#[test]
fn open_without_xdg_open_says_so() {
    // No xdg-open on this PATH: the page's address is printed to open by hand.
    let empty = tempfile::tempdir().unwrap();
    let mut child = Command::new(bin())
        .args(["serve", "--port", "0", "--open"])
        .env("PATH", empty.path())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut url = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut url)
        .unwrap();
    let mut note = String::new();
    BufReader::new(child.stderr.take().unwrap())
        .read_line(&mut note)
        .unwrap();
    let _ = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    assert!(child.wait().unwrap().success());
    let addr = url
        .split_whitespace()
        .find(|w| w.starts_with("http://"))
        .unwrap();
    assert!(
        note.contains("no xdg-open") && note.contains(addr),
        "{note}"
    );
}
