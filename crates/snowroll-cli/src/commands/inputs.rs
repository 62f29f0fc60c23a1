//! From the flags that `simulate` and `turns` share ([`ScenarioArgs`]) to
//! the library's inputs: the model, the [`Scenario`] and the [`SimOptions`].

use anyhow::{anyhow, Result};
use snowroll::integrate::Tolerances;
use snowroll::{Losses, ModelKind, ParamError, Sampling, Scenario, ScenarioFile, SimOptions};

use crate::args::ScenarioArgs;

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

/// The model asked for, or an error saying how to give one of `choices`.
pub fn model(a: &ScenarioArgs, choices: &[ModelKind]) -> Result<ModelKind> {
    a.model.ok_or_else(|| {
        anyhow!(
            "no model given: pass --model ID (or set `model` in the config file), ID one of {}",
            id_list(choices)
        )
    })
}

/// The scenario: each parameter from the arguments, else the library default.
pub fn scenario(a: &ScenarioArgs) -> Result<Scenario, ParamError> {
    let d = ScenarioFile::default();
    Scenario::new(ScenarioFile {
        alpha_deg: a.alpha_deg.unwrap_or(d.alpha_deg),
        snow_depth: a.snow_depth.unwrap_or(d.snow_depth),
        r0: a.r0.unwrap_or(d.r0),
        g: a.g.unwrap_or(d.g),
        density: a.density.unwrap_or(d.density),
        length: a.length.unwrap_or(d.length),
        v0: a.v0.unwrap_or(d.v0),
        shape: a.shape.unwrap_or(d.shape),
        swath_width: a.swath_width.or(d.swath_width),
    })
}

/// The run options: end time, end distance and tolerances from the
/// arguments, else `t_end_default` and the library defaults; `sampling` and
/// `turns` as given. Not yet validated.
pub fn options(
    a: &ScenarioArgs,
    t_end_default: f64,
    sampling: Sampling,
    turns: Option<u64>,
) -> SimOptions {
    let d = SimOptions::default();
    SimOptions {
        t_end: a.t_end.unwrap_or(t_end_default),
        x_end: a.x_end.or(d.x_end),
        turns,
        tolerances: Tolerances {
            rtol: a.rtol.unwrap_or(d.tolerances.rtol),
            atol: a.atol.unwrap_or(d.tolerances.atol),
            max_steps: a.max_steps.unwrap_or(d.tolerances.max_steps),
            ..d.tolerances
        },
        sampling,
        max_rows: a.max_rows.unwrap_or(d.max_rows),
        mu: a.mu,
        collision: a.collision.unwrap_or(d.collision),
        on_hop: a.on_hop.unwrap_or(d.on_hop),
        losses: Losses {
            drag_coefficient: a.drag_coefficient.unwrap_or(d.losses.drag_coefficient),
            air_density: a.air_density.unwrap_or(d.losses.air_density),
            rolling_resistance: a.rolling_resistance.unwrap_or(d.losses.rolling_resistance),
            compaction_energy: a.compaction_energy.unwrap_or(d.losses.compaction_energy),
            ledger: a.ledger,
            terminal_tol: a.terminal_tol.unwrap_or(d.losses.terminal_tol),
        },
    }
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
