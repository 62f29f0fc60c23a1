//! A request's query string turned into the command line of `simulate`,
//! `turns` or `models`, with the parameter table's keys as the query's keys
//! (`alpha_deg=35` is `--alpha-deg=35`), and the server's limits checked
//! before any run.

use snowroll::params::{Group, Kind, Scope};
use snowroll::{Given, Param, Scenario, Settings, PARAMS};

use super::limits::{MAX_ROWS, MAX_TURNS};
use crate::args::TURNS_DEFAULT;

/// The commands the API runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Endpoint {
    /// `snowroll simulate`.
    Simulate,
    /// `snowroll turns`.
    Turns,
    /// `snowroll models`.
    Models,
}

impl Endpoint {
    /// The subcommand's name.
    pub fn command(self) -> &'static str {
        match self {
            Endpoint::Simulate => "simulate",
            Endpoint::Turns => "turns",
            Endpoint::Models => "models",
        }
    }

    /// Whether the command takes parameter `p` (as its flags do).
    pub fn takes(self, p: &Param) -> bool {
        match self {
            Endpoint::Simulate => snowroll_io::page_table::simulate_takes(p),
            Endpoint::Turns => snowroll_io::page_table::turns_takes(p),
            Endpoint::Models => {
                p.scope == Scope::Shared && matches!(p.group, Group::Scenario | Group::Losses)
            }
        }
    }

    /// The keys it takes besides the table's.
    fn own_keys(self) -> &'static [&'static str] {
        match self {
            Endpoint::Simulate | Endpoint::Turns => &["model", "format"],
            Endpoint::Models => &[],
        }
    }
}

/// Why a query is refused before any run.
#[derive(Debug, PartialEq)]
pub enum Refused {
    /// Not a query of this command (status 400).
    Bad(String),
    /// Over a limit of the server (status 413).
    TooLarge(String),
}

/// A query read: the command line, and what the page wants to know.
#[derive(Debug)]
pub struct Request {
    /// The arguments after the program's name.
    pub args: Vec<String>,
    /// `format=csv` was asked for.
    pub csv: bool,
    /// g sin α of the scenario, m/s², when the values given make one.
    pub g_along: Option<f64>,
}

/// `%XX` and `+` decoded; `None` for a bad escape or bytes that are not UTF-8.
pub fn decode(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' => {
                let hex = text.get(i + 1..i + 3)?;
                out.push(u8::from_str_radix(hex, 16).ok()?);
                i += 2;
            }
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8(out).ok()
}

/// The pairs of `query` (the text after `?`), decoded, each key once.
///
/// # Errors
/// A bad escape, a NUL character (no command-line argument can hold one),
/// or a key given twice.
pub fn pairs(query: &str) -> Result<Vec<(String, String)>, Refused> {
    let mut out: Vec<(String, String)> = Vec::new();
    for part in query.split('&').filter(|p| !p.is_empty()) {
        let (k, v) = part.split_once('=').unwrap_or((part, ""));
        let (Some(k), Some(v)) = (decode(k), decode(v)) else {
            let shown: String = part.chars().take(100).collect();
            return Err(Refused::Bad(format!(
                "`{shown}` is not URL-encoded text (a bad %-escape, or not UTF-8)"
            )));
        };
        if k.contains('\0') || v.contains('\0') {
            let shown: String = k.chars().filter(|c| *c != '\0').take(100).collect();
            return Err(Refused::Bad(format!(
                "`{shown}` holds a NUL character (%00); no parameter takes one"
            )));
        }
        if out.iter().any(|(seen, _)| *seen == k) {
            return Err(Refused::Bad(format!("`{k}` is given twice; give it once")));
        }
        out.push((k, v));
    }
    Ok(out)
}

/// The command line of `endpoint` for `query`, with `--format json` unless
/// `format` is given, checked against the server's limits.
///
/// # Errors
/// A key the command does not take, a flag's value that is neither `true`
/// nor `false`, or a run over the limits. Every other bad value is left to
/// the command, whose message the API returns.
pub fn command_line(endpoint: Endpoint, query: &str) -> Result<Request, Refused> {
    let mut args = vec![endpoint.command().to_string()];
    let mut given = Given::new();
    let mut format = None;
    for (key, value) in pairs(query)? {
        if endpoint.own_keys().contains(&key.as_str()) {
            if key == "format" {
                format = Some(value.to_ascii_lowercase());
            }
            args.push(format!("--{key}={value}"));
            continue;
        }
        let Some(p) = Param::of_key(&key).filter(|p| p.settable() && endpoint.takes(p)) else {
            return Err(Refused::Bad(unknown_key(endpoint, &key)));
        };
        if let Some(arg) = flag_of(p, &value)? {
            args.push(arg);
        }
        if let Ok(v) = p.parse_text(&value) {
            if !value.trim().is_empty() {
                given.insert(p, v);
            }
        }
    }
    if endpoint == Endpoint::Models || format.is_none() {
        args.push("--format=json".to_string());
    }
    let settings = given.apply(Settings::default()).ok();
    if let Some(s) = &settings {
        check_size(endpoint, s)?;
    }
    Ok(Request {
        args,
        csv: format.as_deref() == Some("csv"),
        g_along: settings
            .and_then(|s| Scenario::new(s.scenario).ok())
            .map(|s| s.g_along()),
    })
}

/// The flag for `p = value`: `--key-flag=value`; a flag (`ledger`) is
/// given for `true` and left out for `false`; an empty value leaves the
/// parameter at its default.
fn flag_of(p: &Param, value: &str) -> Result<Option<String>, Refused> {
    if p.kind == Kind::Flag {
        return match value.trim() {
            "true" => Ok(Some(format!("--{}", p.flag()))),
            "false" | "" => Ok(None),
            other => Err(Refused::Bad(format!(
                "`{} = {other}` is not true or false",
                p.key
            ))),
        };
    }
    Ok((!value.trim().is_empty()).then(|| format!("--{}={value}", p.flag())))
}

/// The message for a key `endpoint` does not take, listing those it does.
fn unknown_key(endpoint: Endpoint, key: &str) -> String {
    let keys: Vec<&str> = endpoint
        .own_keys()
        .iter()
        .copied()
        .chain(
            PARAMS
                .iter()
                .filter(|p| p.settable() && endpoint.takes(p))
                .map(|p| p.key),
        )
        .collect();
    let shown: String = key.chars().take(100).collect();
    format!(
        "`{shown}` is not a parameter of {}; the parameters are {}",
        endpoint.command(),
        keys.join(", ")
    )
}

/// Refuses a run that would write more rows, or run more turns, than the
/// server allows ([`MAX_ROWS`], [`MAX_TURNS`]).
fn check_size(endpoint: Endpoint, s: &Settings) -> Result<(), Refused> {
    let turns = match endpoint {
        Endpoint::Turns => Some(s.options.turns.unwrap_or(TURNS_DEFAULT)),
        _ => s.options.turns,
    };
    if let Some(n) = turns.filter(|n| *n > MAX_TURNS) {
        return Err(Refused::TooLarge(format!(
            "turns = {n} is more than this server runs for one request ({MAX_TURNS}); \
             ask for fewer turns, or run `snowroll turns` on the command line"
        )));
    }
    if endpoint != Endpoint::Simulate {
        return Ok(());
    }
    // Up to t_end: an upper bound when x_end or turns may end the run sooner.
    match s.options.sampling.known_rows(s.options.t_end) {
        Some(rows) if rows > MAX_ROWS as f64 => Err(Refused::TooLarge(format!(
            "this run would write up to {rows:.0} rows, more than this server writes for one \
             request ({MAX_ROWS}); ask for a coarser dt, fewer times or a shorter t_end, or \
             run `snowroll simulate` on the command line"
        ))),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decode_reads_percent_escapes_and_plus() {
        assert_eq!(decode("0.5%2C1%2c2").as_deref(), Some("0.5,1,2"));
        assert_eq!(decode("a+b").as_deref(), Some("a b"));
        assert_eq!(decode("%C3%A9").as_deref(), Some("é"));
        // A bad escape, a cut one, bytes that are not UTF-8.
        assert_eq!(decode("%zz"), None);
        assert_eq!(decode("1%2"), None);
        assert_eq!(decode("%FF"), None);
    }

    #[test]
    fn command_line_maps_keys_to_the_tables_flags() {
        let r = command_line(
            Endpoint::Simulate,
            "model=energy&alpha_deg=12&ledger=true&x_end=",
        )
        .unwrap();
        assert_eq!(
            r.args,
            [
                "simulate",
                "--model=energy",
                "--alpha-deg=12",
                "--ledger",
                "--format=json"
            ]
        );
        assert!(!r.csv);
        // g sin(12 degrees) with the default g, 9.81 m/s^2; to rounding.
        let expected = 9.81 * 12f64.to_radians().sin();
        assert!((r.g_along.unwrap() - expected).abs() < 1e-12);
        let bad = command_line(Endpoint::Simulate, "model=energy&alpha_deg=1%zz");
        assert!(matches!(bad, Err(Refused::Bad(m)) if m.contains("not URL-encoded")));
        // A NUL, in a value or a key: refused here (a command line cannot
        // hold one), not left to fail at the run.
        for query in ["model=energy&alpha_deg=1%00", "model=energy&alpha%00deg=1"] {
            let bad = command_line(Endpoint::Simulate, query);
            assert!(
                matches!(&bad, Err(Refused::Bad(m)) if m.contains("NUL")),
                "{query}: {bad:?}"
            );
        }
    }
}
