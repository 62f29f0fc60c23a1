//! `snowroll simulate`: one model, one scenario, one trajectory.

use anyhow::{anyhow, bail, Context, Result};
use snowroll::{
    default_atol, format_number, run_warnings, ModelKind, Sampling, Scenario, SimError, SimOptions,
    Stop, StopReason, TurnState,
};
use snowroll_io::{RunParams, TrajectoryWriter};

use snowroll::trajectory::Collected;
use snowroll_report::run_plot::{run_panels, RunCurves};

use super::figure::{self, Keep};
use super::inputs::{self, id_list, is_non_finite, turn_models};
use crate::args::SimulateArgs;
use crate::config;
use crate::console::report;
use crate::sink::Sink;

/// Merges flags over the config file, runs the model, writes the trajectory.
pub fn run(flags: SimulateArgs) -> Result<()> {
    let args = match &flags.output.config {
        Some(path) => {
            let file = config::load(path, config::Origin::Simulate)?;
            flags.over(file)
        }
        None => flags,
    };
    inputs::refuse_own_files(&args.output)?;
    let plot = figure::planned(&args.output)?;
    let (model, scenario, opts) = prepare(&args)?;
    let runner = model.build();
    let format = inputs::format(&args.output)?;
    // The same checks, in the same order, as a sweep's `warnings` column.
    let warnings: Vec<String> = run_warnings(model, &scenario, &opts)
        .iter()
        .map(ToString::to_string)
        .collect();
    for w in &warnings {
        report!("warning: {w}");
    }

    // Open the destination before the run, so that a bad path fails at once.
    let mut sink = Sink::open(&args.output)?;
    let name = sink.name();
    let mut params = RunParams::new(&scenario, &opts);
    params.warnings = warnings;
    let mut writer = TrajectoryWriter::new(&mut sink, format, model, &params)
        .with_context(|| format!("writing {name}"))?;
    // Rows go out as they are computed; the stop and the notes are written last.
    let mut keep = Keep {
        inner: &mut writer,
        kept: plot.map(|_| Collected::default()),
    };
    let run = runner.simulate_into(&scenario, &opts, &mut keep);
    let kept = keep.kept.take();
    let end = match run {
        Ok(end) => end,
        Err(SimError::Sink(e)) if !is_non_finite(&e) => {
            return Err(anyhow::Error::from(SimError::Sink(e)).context(format!("writing {name}")))
        }
        Err(e) => {
            return Err(anyhow::Error::from(e).context(format!(
                "simulating {} ({})",
                model.id(),
                model.equation()
            )))
        }
    };
    params.notes = stop_note(model, end.stop, writer.last_turn(), &scenario, &opts)
        .into_iter()
        .collect();
    params
        .notes
        .extend(times_note(writer.rows(), end.stop, &opts));
    let written = writer.finish(&end, &params.notes).map(drop);
    written
        .map_err(anyhow::Error::from)
        .and_then(|()| Ok(sink.commit()?))
        .with_context(|| format!("writing {name}"))?;
    for note in &params.notes {
        report!("note: {note}");
    }
    if let (Some((path, format)), Some(kept)) = (plot, kept) {
        let run = RunCurves {
            model,
            samples: &kept.samples,
            ledger: &kept.ledger,
        };
        let panels = run_panels(&[run], scenario.g_along());
        let prov = figure::provenance(&[model], &args.scenario.params.given);
        figure::write(path, format, &panels, &prov)?;
    }
    Ok(())
}

/// The model, the scenario and the options of the run, each checked:
/// everything the model refuses is refused here, before any output (nothing
/// reaches stdout).
fn prepare(args: &SimulateArgs) -> Result<(ModelKind, Scenario, SimOptions)> {
    let model = inputs::model(&args.scenario, &ModelKind::ALL)?;
    if args.turns.is_some() && !model.is_turn_model() {
        bail!(
            "--turns (config key `turns`) applies only to the turn models {}, not to {}",
            id_list(&turn_models()),
            model.id()
        );
    }
    let scenario = inputs::scenario(&args.scenario)?;
    let mut opts = options(args)?;
    if !args.scenario.atol_given() {
        opts.tolerances.atol = default_atol(model, &scenario);
    }
    // The grid spacing first: the row count needs dt > 0.
    opts.sampling.validate()?;
    let what = match (&opts.sampling, args.dt) {
        (Sampling::Every(_), Some(dt)) => format!(
            "--dt {} up to t_end = {} s",
            format_number(dt),
            format_number(opts.t_end)
        ),
        _ => "--times".to_string(),
    };
    inputs::check_row_count(&opts, opts.known_rows(), &what)?;
    model.build().check(&scenario, &opts)?;
    Ok((model, scenario, opts))
}

/// The run options: each from the arguments, else the library default.
fn options(a: &SimulateArgs) -> Result<SimOptions> {
    let sampling = match (&a.times, a.dt) {
        (Some(times), None) => Sampling::Times(times.clone()),
        (None, Some(dt)) => Sampling::Every(dt),
        (None, None) => SimOptions::default().sampling,
        // clap and `config::load` each reject both; reachable only by a bug.
        (Some(_), Some(_)) => return Err(anyhow!("`times` and `dt` conflict, give one of them")),
    };
    Ok(inputs::options(
        &a.scenario,
        SimOptions::default().t_end,
        sampling,
        a.turns,
    )?)
}

/// How many requested times were not written because the run stopped
/// before them (times after `t_end` are refused before the run).
fn times_note(rows: u64, stop: Stop, opts: &SimOptions) -> Option<String> {
    let Sampling::Times(times) = &opts.sampling else {
        return None;
    };
    let missing = times.len().saturating_sub(rows as usize);
    (missing > 0).then(|| {
        format!(
            "{missing} of the {} requested times are after the stop at t = {} s and were not written",
            times.len(),
            format_number(stop.t_s)
        )
    })
}

/// One line for stderr when the run ended before its end time, or reached
/// it short of the turns asked for.
fn stop_note(
    model: ModelKind,
    stop: Stop,
    last_turn: Option<TurnState>,
    scenario: &Scenario,
    opts: &SimOptions,
) -> Option<String> {
    if stop.reason == StopReason::EndTime {
        let (wanted, last) = (opts.turns?, last_turn?);
        return Some(format!(
            "reached t_end = {} s in turn {} (0-based) of the {wanted} asked for; \
             raise --t-end for more",
            format_number(opts.t_end),
            last.turn
        ));
    }
    let mut note = format!(
        "run stopped at {}: {}",
        stop.place(),
        stop.reason.describe()
    );
    if stop.reason == StopReason::DoesNotStart {
        // The run's own body, swath and losses set the threshold.
        let threshold = model.stall_threshold_in(scenario, &opts.losses);
        match threshold.map(|t| t.slope.to_degrees()) {
            Some(deg) if deg < 89.9999 => note.push_str(&format!(
                "; from rest this model needs alpha > {deg:.4} degrees"
            )),
            Some(_) => {
                note.push_str("; with this snow, radius and losses it cannot start on any slope")
            }
            None => {}
        }
    }
    match stop.reason {
        StopReason::StepLimit => {
            note.push_str("; a looser --rtol or a shorter --t-end needs fewer steps");
        }
        StopReason::RowLimit => note.push_str(&format!(
            " ({}); raise --max-rows, or sample with {}",
            opts.max_rows,
            // A grid run can only coarsen its grid; a step-by-step run can take one.
            if matches!(opts.sampling, Sampling::Every(_)) {
                "a coarser --dt"
            } else {
                "--dt"
            }
        )),
        _ => {}
    }
    Some(note)
}
