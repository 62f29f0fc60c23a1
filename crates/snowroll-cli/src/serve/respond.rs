//! One request, one answer: the route, the limits, the run.

use std::path::Path;

use tiny_http::{Header, Method, Request, Response};

use super::child::{self, Ended, Limits};
use super::limits::{self, MAX_ANSWER, MAX_BODY, MAX_SECONDS, MAX_URL};
use super::query::{self, Endpoint, Refused};
use crate::console::report;

/// The page and its assets, built into the binary: the server needs no
/// file and no network.
const PAGE: &str = include_str!("assets/index.html");
const SCRIPT: &str = include_str!("assets/app.js");
const RACE: &str = include_str!("assets/race.js");
const PLOTS: &str = include_str!("assets/plots.js");
const STYLE: &str = include_str!("assets/style.css");

/// An answer before it is sent.
#[derive(Debug)]
pub struct Answer {
    /// HTTP status.
    pub status: u16,
    /// `Content-Type`.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
    /// g sin α of the run's scenario, m/s², for the page's a/(g sin α).
    pub g_along: Option<f64>,
}

impl Answer {
    fn json(status: u16, body: String) -> Answer {
        Answer {
            status,
            content_type: "application/json",
            body: body.into_bytes(),
            g_along: None,
        }
    }

    /// `{"error": message}` with `status`.
    pub fn error(status: u16, message: &str) -> Answer {
        Answer::json(status, serde_json::json!({ "error": message }).to_string())
    }

    fn text(content_type: &'static str, text: &str) -> Answer {
        Answer {
            status: 200,
            content_type,
            body: text.as_bytes().to_vec(),
            g_along: None,
        }
    }
}

/// Answers `request` (a failed send, a client gone, is dropped).
pub fn answer(request: Request, exe: &Path) {
    let body_too_large = request.body_length().is_some_and(|n| n > MAX_BODY);
    let reply = if request.url().len() > MAX_URL {
        Answer::error(
            414,
            &format!(
                "the request is {} bytes long, more than this server reads ({MAX_URL})",
                request.url().len()
            ),
        )
    } else if body_too_large {
        Answer::error(
            413,
            &format!("the request has a body of more than {MAX_BODY} bytes; the API takes none"),
        )
    } else if !matches!(request.method(), Method::Get | Method::Head) {
        Answer::error(405, "the API answers GET requests only")
    } else {
        route(request.url(), exe)
    };
    // Never chunked: every answer is whole in memory, its length known.
    let mut response = Response::from_data(reply.body)
        .with_status_code(reply.status)
        .with_chunked_threshold(usize::MAX);
    let mut headers = vec![
        ("Content-Type", reply.content_type.to_string()),
        ("Cache-Control", "no-store".to_string()),
    ];
    if let Some(g) = reply.g_along {
        headers.push(("X-Snowroll-G-Along", format!("{g:?}")));
    }
    for (name, value) in headers {
        // Plain ASCII, all of them: never refused.
        if let Ok(h) = Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response.add_header(h);
        }
    }
    let _ = request.respond(response);
}

/// The answer for `url` (path and query).
pub fn route(url: &str, exe: &Path) -> Answer {
    let (path, query) = url.split_once('?').unwrap_or((url, ""));
    match path {
        "/" | "/index.html" => Answer::text("text/html; charset=utf-8", PAGE),
        "/app.js" => Answer::text("text/javascript; charset=utf-8", SCRIPT),
        "/race.js" => Answer::text("text/javascript; charset=utf-8", RACE),
        "/plots.js" => Answer::text("text/javascript; charset=utf-8", PLOTS),
        "/style.css" => Answer::text("text/css; charset=utf-8", STYLE),
        "/api/params" => Answer::json(200, limits::params_json()),
        "/api/models" => run(Endpoint::Models, query, exe),
        "/api/simulate" => run(Endpoint::Simulate, query, exe),
        "/api/turns" => run(Endpoint::Turns, query, exe),
        _ => Answer::error(
            404,
            &format!(
                "no such page: {}",
                path.chars().take(200).collect::<String>()
            ),
        ),
    }
}

/// Runs the command of `endpoint` for `query`.
pub fn run(endpoint: Endpoint, query: &str, exe: &Path) -> Answer {
    let request = match query::command_line(endpoint, query) {
        Ok(r) => r,
        Err(Refused::Bad(m)) => return Answer::error(400, &m),
        Err(Refused::TooLarge(m)) => return Answer::error(413, &m),
    };
    let limits = Limits {
        seconds: MAX_SECONDS,
        answer_bytes: MAX_ANSWER,
    };
    let ran = match child::run(exe, &request.args, limits) {
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
        Ended::Exited(status) if status.success() => Answer {
            status: 200,
            content_type: if request.csv {
                "text/csv; charset=utf-8"
            } else {
                "application/json"
            },
            body: ran.stdout,
            g_along: request.g_along,
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
