//! The explorer's physics in WebAssembly: `snowroll simulate` and
//! `snowroll turns` for one model, written by the same library code
//! (`snowroll`, `snowroll-io`) as the command line, so that the bytes are
//! the same; and the parameter table the page builds its form from.
//!
//! The page passes a JSON object of strings, the same keys as the server's
//! API (`{"model": "turns", "alpha_deg": "65", "format": "csv"}`), and gets
//! the output's bytes back ([`answer`]); [`abi`] is the module's interface
//! (pointers and lengths). `scripts/build-explorer.sh` builds it for
//! `wasm32-unknown-unknown` and inlines it into one HTML file.

use std::collections::BTreeMap;

use snowroll::models::{TURNS_DEFAULT, TURNS_T_END_S};
use snowroll::params::{Applies, Group, Kind, Scope};
use snowroll::trajectory::{LedgerRow, Sample, SampleSink, TurnState};
use snowroll::{
    default_atol, run_warnings, ModelKind, Param, Sampling, Scenario, Settings, SimOptions,
    SinkError, TurnMethod, TurnModel, TurnRow, TurnSink, TurnVariant, Value, WarningCode, PARAMS,
};
use snowroll_io::notes::{stop_note, times_note, turns_stop_note};
use snowroll_io::{Format, RunParams, TrajectoryWriter, TurnTableWriter};

pub mod abi;

/// What the page asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Command {
    /// The parameter table and the models ([`params_json`]).
    Params,
    /// `snowroll simulate --model ID ...`.
    Simulate,
    /// `snowroll turns --model ID ...`.
    Turns,
}

impl Command {
    /// The subcommand's name.
    pub fn name(self) -> &'static str {
        match self {
            Command::Params => "params",
            Command::Simulate => "simulate",
            Command::Turns => "turns",
        }
    }

    /// Whether the command takes parameter `p`, as its flags do (the
    /// server's API draws the same line).
    pub fn takes(self, p: &Param) -> bool {
        match self {
            Command::Simulate => {
                matches!(p.scope, Scope::Shared | Scope::Sampling | Scope::Turns)
            }
            Command::Turns => matches!(p.scope, Scope::Shared | Scope::Turns),
            Command::Params => false,
        }
    }
}

/// An answer: the output's bytes and g sin α of the run's scenario (m/s²,
/// by which the page divides a; 0 for the parameter table).
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// What the command writes to its output.
    pub body: Vec<u8>,
    /// g sin α, m/s².
    pub g_along: f64,
}

/// Runs `command` with the parameters of `request` (a JSON object of
/// strings: `model`, `format` (`csv` or `json`, JSON by default) and the
/// table's keys; an empty value is the default). `progress` is told the
/// fraction done, now and then, during a long run.
///
/// # Errors
/// A message naming what is wrong (a key the command does not take, a bad
/// value, a run the model refuses), as the command line would refuse it.
pub fn answer(
    command: Command,
    request: &str,
    progress: &mut dyn FnMut(f64),
) -> Result<Answer, String> {
    if command == Command::Params {
        return Ok(Answer {
            body: params_json().into_bytes(),
            g_along: 0.0,
        });
    }
    let pairs: BTreeMap<String, String> = serde_json::from_str(request)
        .map_err(|e| format!("the request is not a JSON object of strings: {e}"))?;
    let mut model = None;
    let mut format = Format::Json;
    let mut given = snowroll::Given::new();
    for (key, value) in &pairs {
        match key.as_str() {
            "model" => {
                model = Some(
                    value
                        .parse::<ModelKind>()
                        .map_err(|e| format!("--model {value}: {e}"))?,
                )
            }
            "format" => {
                format = match value.trim().to_ascii_lowercase().as_str() {
                    "csv" => Format::Csv,
                    "json" | "" => Format::Json,
                    other => return Err(format!("format `{other}`: expected csv or json")),
                }
            }
            _ => {
                let p = Param::of_key(key)
                    .filter(|p| p.settable() && command.takes(p))
                    .ok_or_else(|| format!("`{key}` is not a parameter of {}", command.name()))?;
                if let Some(v) = value_of(p, value)? {
                    given.insert(p, v);
                }
            }
        }
    }
    match command {
        Command::Simulate => {
            let model = model.ok_or("no model given: pass `model`")?;
            simulate(model, &given, format, progress)
        }
        _ => turns(model.unwrap_or(ModelKind::Turns), &given, format, progress),
    }
}

/// The value of `p` given as `text`: `None` for an empty text (the
/// default) and for a flag given as `false`.
fn value_of(p: &Param, text: &str) -> Result<Option<Value>, String> {
    let text = text.trim();
    if text.is_empty() {
        return Ok(None);
    }
    match p.kind {
        Kind::Flag => match text {
            "true" => Ok(Some(Value::Flag(true))),
            "false" => Ok(None),
            other => Err(format!("`{} = {other}` is not true or false", p.key)),
        },
        _ => p.parse_text(text).map(Some),
    }
}

/// The run options: the library's defaults with the command's end time,
/// sampling and turns, then every value given.
fn options(given: &snowroll::Given, base: SimOptions) -> Result<Settings, String> {
    let settings = Settings {
        options: base,
        ..Settings::default()
    };
    given.apply(settings).map_err(|e| e.to_string())
}

/// Refuses a run whose row count is known and above `max_rows`.
fn check_rows(opts: &SimOptions, rows: Option<f64>, what: &str) -> Result<(), String> {
    match rows {
        Some(n) if n > opts.max_rows as f64 => Err(format!(
            "{what} would write {n:.0} rows, more than max_rows = {}: raise max_rows, or ask \
             for fewer rows",
            opts.max_rows
        )),
        _ => Ok(()),
    }
}

/// `snowroll simulate --model MODEL` with the values `given`, as
/// `crates/snowroll-cli/src/commands/simulate.rs` runs one model.
fn simulate(
    model: ModelKind,
    given: &snowroll::Given,
    format: Format,
    progress: &mut dyn FnMut(f64),
) -> Result<Answer, String> {
    let settings = options(given, SimOptions::default())?;
    let scenario = Scenario::new(settings.scenario).map_err(|e| e.to_string())?;
    let mut opts = settings.options;
    if opts.turns.is_some() && !model.is_turn_model() {
        return Err(format!(
            "`turns` applies only to the turn models, not to {}",
            model.id()
        ));
    }
    if given.get(Param::of_key("atol").ok_or("atol")?).is_none() {
        opts.tolerances.atol = default_atol(model, &scenario);
    }
    opts.sampling.validate().map_err(|e| e.to_string())?;
    check_rows(&opts, opts.known_rows(), "this sampling")?;
    model
        .build()
        .check(&scenario, &opts)
        .map_err(|e| e.to_string())?;
    let mut params = RunParams::new(&scenario, &opts);
    params.warnings = run_warnings(model, &scenario, &opts)
        .iter()
        .map(ToString::to_string)
        .collect();
    let mut writer =
        TrajectoryWriter::new(Vec::new(), format, model, &params).map_err(|e| e.to_string())?;
    let mut sink = Progress {
        inner: &mut writer,
        progress,
        every: 4096,
        count: 0,
        total: opts.t_end,
    };
    let end = model
        .build()
        .simulate_into(&scenario, &opts, &mut sink)
        .map_err(|e| format!("simulating {} ({}): {e}", model.id(), model.equation()))?;
    let mut notes: Vec<String> = stop_note(model, end.stop, writer.last_turn(), &scenario, &opts)
        .into_iter()
        .collect();
    notes.extend(times_note(writer.rows(), end.stop, &opts));
    let body = writer.finish(&end, &notes).map_err(|e| e.to_string())?;
    Ok(Answer {
        body,
        g_along: scenario.g_along(),
    })
}

/// `snowroll turns --model MODEL` with the values `given` (the closed
/// method unless it does not cover the run), as
/// `crates/snowroll-cli/src/commands/turns.rs` runs it.
fn turns(
    model: ModelKind,
    given: &snowroll::Given,
    format: Format,
    progress: &mut dyn FnMut(f64),
) -> Result<Answer, String> {
    if !model.is_turn_model() {
        return Err(format!(
            "`snowroll turns` needs a turn model (turns, turns-exact), not {}",
            model.id()
        ));
    }
    let turns_key = Param::of_key("turns").ok_or("turns")?;
    let wanted = match given.get(turns_key) {
        Some(Value::Count(n)) => *n,
        _ => TURNS_DEFAULT,
    };
    let base = SimOptions {
        t_end: TURNS_T_END_S,
        sampling: Sampling::Ends,
        turns: Some(wanted),
        ..SimOptions::default()
    };
    let settings = options(given, base)?;
    let scenario = Scenario::new(settings.scenario).map_err(|e| e.to_string())?;
    let mut opts = settings.options;
    if given.get(Param::of_key("atol").ok_or("atol")?).is_none() {
        opts.tolerances.atol = default_atol(model, &scenario);
    }
    check_rows(&opts, Some(wanted as f64), &format!("turns = {wanted}"))?;
    model
        .build()
        .check(&scenario, &opts)
        .map_err(|e| e.to_string())?;
    let variant = TurnVariant::of(model).ok_or("a turn model")?;
    let turn_model = TurnModel::new(variant).with_method(TurnMethod::default());
    let method = turn_model.method_for(&scenario, &opts);
    let mut params = RunParams::new(&scenario, &opts);
    params.settings.per_turn = true;
    params.warnings = run_warnings(model, &scenario, &opts)
        .iter()
        .filter(|w| method == TurnMethod::Ode || w.code != WarningCode::LooseTolerance)
        .map(ToString::to_string)
        .collect();
    params.method = Some(method);
    let mut writer =
        TurnTableWriter::new(Vec::new(), format, model, &params).map_err(|e| e.to_string())?;
    let mut sink = Progress {
        inner: &mut writer,
        progress,
        every: 1024,
        count: 0,
        total: wanted as f64,
    };
    let end = turn_model
        .run_table_into(&scenario, &opts, &mut sink)
        .map_err(|e| format!("running {} ({}): {e}", model.id(), model.equation()))?;
    let notes: Vec<String> = turns_stop_note(&end, wanted, opts.t_end)
        .into_iter()
        .collect();
    let body = writer.finish(&end, &notes).map_err(|e| e.to_string())?;
    Ok(Answer {
        body,
        g_along: scenario.g_along(),
    })
}

/// A sink that hands every row on and tells `progress` the fraction done
/// every `every` rows (of time for a trajectory, of turns for a table).
struct Progress<'a, S> {
    inner: &'a mut S,
    progress: &'a mut dyn FnMut(f64),
    every: u64,
    count: u64,
    total: f64,
}

impl<S> Progress<'_, S> {
    fn tick(&mut self, done: f64) {
        self.count += 1;
        if self.count.is_multiple_of(self.every) && self.total > 0.0 {
            (self.progress)((done / self.total).clamp(0.0, 1.0));
        }
    }
}

impl<S: SampleSink> SampleSink for Progress<'_, S> {
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError> {
        self.inner.sample(sample, turn)?;
        self.tick(sample.t_s);
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.inner.ledger(row)
    }
}

impl<S: TurnSink> TurnSink for Progress<'_, S> {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.inner.turn(row)?;
        self.tick(row.turn as f64 + 1.0);
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.inner.ledger(row)
    }
}

/// The parameter table and the models as the page reads them to build its
/// form: the same `params` and `models` as the server's `GET /api/params`
/// (`crates/snowroll-cli/src/serve/limits.rs`; the browser test compares
/// the two), without the server's limits.
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
    })
    .to_string()
}

/// A parameter's value as JSON (`null` for none).
fn value_json(v: &Value) -> serde_json::Value {
    match v {
        Value::None => serde_json::Value::Null,
        Value::Real(x) => serde_json::json!(x),
        Value::Count(n) => serde_json::json!(n),
        Value::Flag(b) => serde_json::json!(b),
        Value::Word(w) => serde_json::json!(w),
        Value::Reals(xs) => serde_json::json!(xs),
    }
}

/// One parameter as the page reads it.
fn param_json(p: &Param) -> serde_json::Value {
    let commands: Vec<&str> = [Command::Simulate, Command::Turns]
        .into_iter()
        .filter(|c| c.takes(p))
        .map(Command::name)
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
fn bounds(p: &Param) -> (Option<f64>, bool, Option<f64>) {
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
        Value::Real(x) => x.abs().max(1.0),
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
    fn a_key_the_command_does_not_take_is_refused() {
        let e = answer(
            Command::Turns,
            r#"{"model":"turns","dt":"0.1"}"#,
            &mut |_| {},
        )
        .unwrap_err();
        assert!(e.contains("`dt` is not a parameter of turns"), "{e}");
        let e = answer(Command::Simulate, r#"{"model":"nope"}"#, &mut |_| {}).unwrap_err();
        assert!(e.contains("--model nope"), "{e}");
        let e = answer(
            Command::Simulate,
            r#"{"model":"energy","alpha_deg":"95"}"#,
            &mut |_| {},
        )
        .unwrap_err();
        assert!(e.contains("alpha_deg") && e.contains("95"), "{e}");
    }

    #[test]
    fn progress_reaches_the_end_of_a_long_table() {
        let mut last = 0.0;
        let a = answer(
            Command::Turns,
            r#"{"model":"turns","turns":"5000","format":"csv"}"#,
            &mut |f| last = f,
        )
        .unwrap();
        // 5000 turns, told every 1024: the last report at turn 4096.
        assert!((last - 4096.0 / 5000.0).abs() < 1e-12, "{last}");
        assert!(a.body.starts_with(b"# snowroll"));
    }
}
