//! From the flags that `simulate` and `turns` share ([`ScenarioArgs`]) to
//! the library's inputs: the model, the [`Scenario`] and the [`SimOptions`].

use anyhow::{anyhow, Result};
use snowroll::{ModelKind, ParamError, Sampling, Scenario, Settings, SimOptions};

use crate::args::{value_name, ModelList, OutputArgs, ScenarioArgs};
use crate::clash::{refuse_clashes, RunFile};
use snowroll_io::Format;

/// The turn-by-turn models of §3.4, which alone take `--turns`.
pub fn turn_models() -> Vec<ModelKind> {
    ModelKind::ALL
        .into_iter()
        .filter(|k| k.is_turn_model())
        .collect()
}

/// `ids` as `a, b, c`.
pub fn id_list(kinds: &[ModelKind]) -> String {
    kinds.iter().map(|k| k.id()).collect::<Vec<_>>().join(", ")
}

/// The models asked for, in the order given, or an error saying how to
/// give one of `choices`.
pub fn models<'a>(a: &'a ScenarioArgs, choices: &[ModelKind]) -> Result<&'a [ModelKind]> {
    a.model.as_ref().map(ModelList::models).ok_or_else(|| {
        anyhow!(
            "no model given: pass --model ID (or set `model` in the config file), ID one of {}",
            id_list(choices)
        )
    })
}

/// The settings: each parameter given in `a`, else from `base` (the
/// library's defaults with the command's own end time, sampling and turns).
fn settings(a: &ScenarioArgs, base: Settings) -> Result<Settings, ParamError> {
    a.params.given.apply(base)
}

/// The scenario: each parameter from the arguments, else the library default.
pub fn scenario(a: &ScenarioArgs) -> Result<Scenario, ParamError> {
    Scenario::new(settings(a, Settings::default())?.scenario)
}

/// The run options: each parameter from the arguments, else the library
/// default, the end time `t_end_default`; `sampling` and `turns` as given.
/// Not yet validated.
pub fn options(
    a: &ScenarioArgs,
    t_end_default: f64,
    sampling: Sampling,
    turns: Option<u64>,
) -> Result<SimOptions, ParamError> {
    let mut base = Settings::default();
    base.options.t_end = t_end_default;
    base.options.sampling = sampling;
    base.options.turns = turns;
    Ok(settings(a, base)?.options)
}

/// The output format: `--format` (or the config file's), else the one the
/// name of `-o` ends in (`.json`, `.csv`, any case), else CSV. A format
/// that contradicts the name is refused (issue 20: `-o run.json` wrote CSV).
pub fn format(out: &OutputArgs) -> Result<Format> {
    let named = out.output.as_deref().and_then(|p| {
        let ext = p.extension()?.to_str()?.to_ascii_lowercase();
        let format = match ext.as_str() {
            "json" => Format::Json,
            "csv" => Format::Csv,
            _ => return None,
        };
        Some((format, ext))
    });
    match (out.format, named) {
        (Some(given), Some((by_name, ext))) if given != by_name => {
            Err(anyhow!(
            "the output {} ends in .{ext} but the format is {}: give --format {ext}, or a name \
             that ends in .{}",
            out.output.as_deref().map_or(String::new(), |p| p.display().to_string()),
            value_name(given),
            value_name(given)
        ))
        }
        (Some(given), _) => Ok(given),
        (None, Some((by_name, _))) => Ok(by_name),
        (None, None) => Ok(Format::default()),
    }
}

/// Refuses an output (`-o`, or the config's `output`, and `--plot`) that
/// is the run's `--config` file or the other output, however spelt.
pub fn refuse_own_files(out: &OutputArgs) -> Result<()> {
    let mut files = Vec::new();
    if let Some(config) = &out.config {
        files.push(RunFile::input(config, "--config file"));
    }
    if let Some(output) = &out.output {
        files.push(RunFile::output(output, "-o output"));
    }
    if let Some(plot) = &out.plot {
        files.push(RunFile::output(plot, "--plot figure"));
    }
    refuse_clashes(&files)
}

/// Refuses, before the run, a run whose row count is known and above
/// `--max-rows`, naming the count and the flag.
pub fn check_row_count(opts: &SimOptions, rows: Option<f64>, what: &str) -> Result<()> {
    match rows {
        Some(n) if n > opts.max_rows as f64 => Err(anyhow!(
            "{what} would write {} rows, more than --max-rows {} (config key `max_rows`): \
             raise --max-rows, or ask for fewer rows",
            count(n),
            opts.max_rows
        )),
        _ => Ok(()),
    }
}

/// A row count: exact up to 10^15, else to three digits (`1.00e302`).
fn count(n: f64) -> String {
    if n < 1e15 {
        format!("{n:.0}")
    } else {
        format!("{n:.2e}")
    }
}

/// Whether a sink failed because a number to write was not finite: a fault
/// of the run (a quantity overflowed), reported as the run's error rather
/// than the output's.
pub fn is_non_finite(e: &snowroll::SinkError) -> bool {
    matches!(
        e.inner().downcast_ref::<snowroll_io::OutputError>(),
        Some(snowroll_io::OutputError::NonFinite(_))
    )
}
