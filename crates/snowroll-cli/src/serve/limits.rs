//! The server's limits, and `GET /api/params`: the parameter table as the
//! page reads it to build its form.

use std::time::Duration;

/// Connections open at once. At the limit, a new connection asks the idle
/// ones (keep-alive, or a head still being sent) to close, and waits up to
/// [`ACCEPT_WAIT`] for one to go.
pub const MAX_CONNECTIONS: usize = 256;
/// New connections that may wait for a place at once; more are answered 503
/// and closed without being read.
pub const MAX_WAITING: usize = 64;
/// How long a new connection waits for a place, when all are taken.
pub const ACCEPT_WAIT: Duration = Duration::from_secs(1);
/// Runs (child processes) at once.
pub const MAX_RUNS: usize = 4;
/// Requests that may wait for a run at once (in arrival order); more are
/// answered 503 with `Retry-After` at once. A class loading the page at
/// once asks for a few runs each, most of them taking milliseconds.
pub const MAX_QUEUED: usize = 64;
/// How long a request waits for a run before it is answered 503.
pub const QUEUE_WAIT: Duration = Duration::from_secs(10);
/// `Retry-After` of a 503, s.
pub const RETRY_AFTER_S: u32 = 5;
/// Longest request target (path and query), bytes.
pub const MAX_URL: usize = 8 * 1024;
/// Longest request line: the target, the method and the version.
pub const MAX_LINE: usize = MAX_URL + 64;
/// Largest request head (the line and the headers), bytes.
pub const MAX_HEAD: usize = 16 * 1024;
/// Most header lines of one request.
pub const MAX_HEADERS: usize = 64;
/// Largest request body, bytes (the API takes none; it is never read).
pub const MAX_BODY: usize = 1024;
/// Time to send a request's head, from the first byte awaited: also how long
/// an idle keep-alive connection is kept.
pub const HEAD_TIMEOUT: Duration = Duration::from_secs(5);
/// Longest a write to a client may make no progress (a client that does not
/// read its answer).
pub const WRITE_TIMEOUT: Duration = Duration::from_secs(10);
/// Longest the sending of one answer may take, from its first byte.
pub const SEND_TIMEOUT: Duration = Duration::from_secs(60);
/// After SIGINT or SIGTERM: how long the answers being sent are given
/// before the program exits (runs are ended at once).
pub const SHUTDOWN_GRACE: Duration = Duration::from_millis(1500);
/// Most rows one `simulate` request may ask for (known before the run:
/// `t_end/dt + 1`, or the number of `times`).
pub const MAX_ROWS: u64 = 20_000;
/// Most turns one request may ask for.
pub const MAX_TURNS: u64 = 20_000;
/// Longest a run may take, s.
pub const MAX_SECONDS: f64 = 10.0;
/// Largest answer, bytes.
pub const MAX_ANSWER: usize = 32 * 1024 * 1024;

/// The JSON of `GET /api/params`: the settable parameters, the models (ids,
/// equations, which are turn models) and the limits.
pub fn params_json() -> String {
    let mut table = snowroll_io::page_table::page_table();
    table.insert(
        "limits".into(),
        serde_json::json!({
            "max_connections": MAX_CONNECTIONS,
            "max_runs": MAX_RUNS,
            "max_queued": MAX_QUEUED,
            "queue_wait_s": QUEUE_WAIT.as_secs_f64(),
            "max_url_bytes": MAX_URL,
            "max_head_bytes": MAX_HEAD,
            "max_headers": MAX_HEADERS,
            "max_body_bytes": MAX_BODY,
            "head_timeout_s": HEAD_TIMEOUT.as_secs_f64(),
            "write_timeout_s": WRITE_TIMEOUT.as_secs_f64(),
            "max_rows": MAX_ROWS,
            "max_turns": MAX_TURNS,
            "max_seconds": MAX_SECONDS,
            "max_answer_bytes": MAX_ANSWER,
        }),
    );
    serde_json::Value::Object(table).to_string()
}
