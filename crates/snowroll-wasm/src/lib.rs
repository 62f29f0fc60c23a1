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
use snowroll::params::Kind;
use snowroll::trajectory::{LedgerRow, Sample, SampleSink, TurnState};
use snowroll::{
    default_atol, run_warnings, ModelKind, Param, Sampling, Scenario, Settings, SimOptions,
    SinkError, TurnMethod, TurnModel, TurnRow, TurnSink, TurnVariant, Value, WarningCode,
};
use snowroll_io::notes::{hop_doubt_note, stop_note, times_note, turns_notes};
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
            Command::Simulate => snowroll_io::page_table::simulate_takes(p),
            Command::Turns => snowroll_io::page_table::turns_takes(p),
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
    notes.extend(hop_doubt_note(end.hop_doubt));
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
    let notes = turns_notes(&end, wanted, opts.t_end);
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
    serde_json::Value::Object(snowroll_io::page_table::page_table()).to_string()
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
