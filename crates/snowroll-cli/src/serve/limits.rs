//! The server's limits, and `GET /api/params`: the parameter table as the
//! page reads it to build its form.

use std::time::Duration;

use snowroll::params::{Applies, Group, Kind, Scope};
use snowroll::{ModelKind, Param, Settings, PARAMS};

use super::query::{value_json, Endpoint};
use crate::args::{TURNS_DEFAULT, TURNS_T_END_S};

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
    let params: Vec<serde_json::Value> = PARAMS
        .iter()
        .filter(|p| p.settable())
        .map(param_json)
        .collect();
    let models: Vec<serde_json::Value> = ModelKind::ALL
        .iter()
        .map(|m| {
            serde_json::json!({
                "id": m.id(),
                "alias": m.alias(),
                "equation": m.equation(),
                "description": m.description(),
                "turn_model": m.is_turn_model(),
            })
        })
        .collect();
    serde_json::json!({
        "params": params,
        "models": models,
        "turns_command_defaults": { "turns": TURNS_DEFAULT, "t_end": TURNS_T_END_S },
        "limits": {
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
        },
    })
    .to_string()
}

/// One parameter as the page reads it.
fn param_json(p: &Param) -> serde_json::Value {
    let commands: Vec<&str> = [Endpoint::Simulate, Endpoint::Turns]
        .into_iter()
        .filter(|e| e.takes(p))
        .map(Endpoint::command)
        .collect();
    let choices = match p.kind {
        Kind::Choice(c) => c.ids(),
        Kind::OptionalRealOr(word) => vec![word],
        _ => Vec::new(),
    };
    serde_json::json!({
        "key": p.key,
        "flag": p.flag(),
        "unit": p.unit,
        "kind": kind_id(p.kind),
        "group": match p.group { Group::Scenario => "scenario", Group::Run => "run", Group::Losses => "losses" },
        "scope": match p.scope { Scope::Shared => "shared", Scope::Sampling => "sampling", Scope::Turns => "turns", Scope::Record => "record" },
        "applies": match p.applies { Applies::All => "all", Applies::Sphere => "sphere", Applies::TurnModels => "turn-models", Applies::CircularModels => "circular-models" },
        "range": p.range,
        "help": p.help,
        "default": value_json(&p.get(&Settings::default())),
        "default_text": p.default_text(),
        "choices": choices,
        "commands": commands,
        "slider": slider(p),
    })
}

/// The kind as a word.
fn kind_id(kind: Kind) -> &'static str {
    match kind {
        Kind::Real => "real",
        Kind::OptionalReal => "optional-real",
        Kind::OptionalRealOr(_) => "optional-real-or-word",
        Kind::Count => "count",
        Kind::OptionalCount => "optional-count",
        Kind::Flag => "flag",
        Kind::Choice(_) => "choice",
        Kind::Reals => "reals",
        Kind::Text => "text",
    }
}

/// The bounds the range text sets on either side of the key: `(lower,
/// lower is strict, upper)`; `infinity` or no bound is `None`.
pub fn bounds(p: &Param) -> (Option<f64>, bool, Option<f64>) {
    let words: Vec<&str> = p.range.split_whitespace().collect();
    let num = |i: usize| words.get(i).and_then(|w| w.parse::<f64>().ok());
    let Some(at) = words.iter().position(|w| *w == p.key) else {
        return (None, false, None);
    };
    let (mut lo, mut strict, mut hi) = (None, false, None);
    if at >= 2 && matches!(words[at - 1], "<" | "<=") {
        lo = num(at - 2);
        strict = words[at - 1] == "<";
    }
    match words.get(at + 1).copied() {
        Some("<" | "<=") => hi = num(at + 2).filter(|x| x.is_finite()),
        Some(op @ (">" | ">=")) => {
            lo = num(at + 2);
            strict = op == ">";
        }
        _ => {}
    }
    (lo, strict, hi)
}

/// A slider's span for a real parameter: its range where that is finite and
/// within a thousand times the default's size, else up to ten times the
/// default; logarithmic for the tolerances. `null` for other kinds.
fn slider(p: &Param) -> serde_json::Value {
    if !matches!(
        p.kind,
        Kind::Real | Kind::OptionalReal | Kind::OptionalRealOr(_)
    ) {
        return serde_json::Value::Null;
    }
    let (lo, strict, hi) = bounds(p);
    let lo = lo.unwrap_or(0.0);
    let size = match p.get(&Settings::default()) {
        snowroll::Value::Real(x) => x.abs().max(1.0),
        _ => 1.0,
    };
    let max = match hi {
        Some(h) if p.exponent || h - lo <= 1000.0 * size => h,
        _ => lo + 10.0 * size,
    };
    let min = if strict && !p.exponent {
        lo + (max - lo) * 1e-3
    } else {
        lo
    };
    serde_json::json!({ "min": min, "max": max, "log": p.exponent })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_read_the_range_text() {
        let b = |key| bounds(Param::of_key(key).unwrap());
        assert_eq!(b("alpha_deg"), (Some(0.0), true, Some(90.0)));
        assert_eq!(b("snow_depth"), (Some(0.0), false, None));
        assert_eq!(b("rtol"), (Some(1e-15), false, Some(1.0)));
        assert_eq!(b("t_end"), (Some(0.0), true, None));
    }
}
