//! `snowroll simulate`: one model, one scenario, one trajectory.

use anyhow::{anyhow, bail, Context, Result};
use snowroll::{
    default_atol, format_number, run_warnings, ModelKind, Sampling, Scenario, SimError, SimOptions,
};
use snowroll_io::notes::{hop_doubt_note, stop_note, times_note};
use snowroll_io::{RunParams, TrajectoryWriter};

use snowroll::trajectory::Collected;
use snowroll_report::run_plot::{run_panels, RunCurves};

use super::figure::{self, Keep};
use super::inputs::{self, id_list, is_non_finite, turn_models};
use super::stack::Stack;
use crate::args::SimulateArgs;
use crate::config;
use crate::console::report;
use crate::sink::Sink;

/// Merges flags over the config file, runs each model, writes the
/// trajectories (one output, model by model, [`Stack`]).
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
    let models = simulate_models(&args)?;
    let several = models.len() > 1;
    let scenario = inputs::scenario(&args.scenario)?;
    // Every model checked before any output (nothing reaches stdout).
    let runs = models
        .iter()
        .map(|&m| prepare(&args, m, &scenario))
        .collect::<Result<Vec<_>>>()?;
    let format = inputs::format(&args.output)?;
    for (model, _, warnings) in &runs {
        for w in warnings {
            report!("warning: {}{w}", lead(*model, several));
        }
    }

    // Open the destination before the run, so that a bad path fails at once.
    let mut sink = Sink::open(&args.output)?;
    let name = sink.name();
    let mut stack =
        Stack::new(&mut sink, format, &models).with_context(|| format!("writing {name}"))?;
    let mut notes = Vec::new();
    let mut kept = Vec::new();
    for (model, opts, warnings) in runs {
        stack
            .model(model, several)
            .with_context(|| format!("writing {name}"))?;
        let one = One {
            model,
            scenario: &scenario,
            opts: &opts,
            name: &name,
        };
        let (model_notes, samples) = one.write(&mut stack, format, warnings, plot.is_some())?;
        notes.extend(model_notes.into_iter().map(|n| (model, n)));
        kept.extend(samples.map(|k| (model, k)));
    }
    stack
        .end(several)
        .with_context(|| format!("writing {name}"))?;
    sink.commit().with_context(|| format!("writing {name}"))?;
    for (model, note) in &notes {
        report!("note: {}{note}", lead(*model, several));
    }
    if let Some((path, format)) = plot {
        let curves: Vec<RunCurves> = kept
            .iter()
            .map(|(model, k)| RunCurves {
                model: *model,
                samples: &k.samples,
                ledger: &k.ledger,
            })
            .collect();
        let panels = run_panels(&curves, scenario.g_along());
        let prov = figure::provenance(&models, &args.scenario.params.given);
        figure::write(path, format, &panels, &prov)?;
    }
    Ok(())
}

/// `model: ` before a line on stderr when several models run, else nothing.
fn lead(model: ModelKind, several: bool) -> String {
    if several {
        format!("{}: ", model.id())
    } else {
        String::new()
    }
}

/// The models asked for: any one model, or several circular models (their
/// rows share one set of columns), each once.
fn simulate_models(args: &SimulateArgs) -> Result<Vec<ModelKind>> {
    let models = inputs::models(&args.scenario, &ModelKind::ALL)?.to_vec();
    if models.len() > 1 {
        if let Some(m) = models.iter().find(|m| !m.is_circular()) {
            bail!(
                "--model {}: a list of models compares circular models only, and {} is a turn \
                 model; run it alone (`simulate --model {}`, or `snowroll turns`)",
                models.iter().map(|m| m.id()).collect::<Vec<_>>().join(","),
                m.id(),
                m.id()
            );
        }
    }
    Ok(models)
}

/// One model's run, written into the shared output.
struct One<'a> {
    model: ModelKind,
    scenario: &'a Scenario,
    opts: &'a SimOptions,
    /// The output's name, for errors.
    name: &'a str,
}

impl One<'_> {
    /// Runs the model, writing its rows to `out` as they come (its header
    /// with `warnings`, its stop and notes last); returns the notes and,
    /// when `keep`, the samples for the figure.
    fn write<W: std::io::Write>(
        &self,
        out: W,
        format: snowroll_io::Format,
        warnings: Vec<String>,
        keep: bool,
    ) -> Result<(Vec<String>, Option<Collected>)> {
        let (model, scenario, opts, name) = (self.model, self.scenario, self.opts, self.name);
        let mut params = RunParams::new(scenario, opts);
        params.warnings = warnings;
        let mut writer = TrajectoryWriter::new(out, format, model, &params)
            .with_context(|| format!("writing {name}"))?;
        // Rows go out as they are computed; the stop and the notes are written last.
        let mut keep = Keep {
            inner: &mut writer,
            kept: keep.then(Collected::default),
        };
        let run = model.build().simulate_into(scenario, opts, &mut keep);
        let kept = keep.kept.take();
        let end = match run {
            Ok(end) => end,
            Err(SimError::Sink(e)) if !is_non_finite(&e) => {
                return Err(
                    anyhow::Error::from(SimError::Sink(e)).context(format!("writing {name}"))
                )
            }
            Err(e) => {
                return Err(anyhow::Error::from(e).context(format!(
                    "simulating {} ({})",
                    model.id(),
                    model.equation()
                )))
            }
        };
        let mut notes: Vec<String> = stop_note(model, end.stop, writer.last_turn(), scenario, opts)
            .into_iter()
            .collect();
        notes.extend(times_note(writer.rows(), end.stop, opts));
        notes.extend(hop_doubt_note(end.hop_doubt));
        writer
            .finish(&end, &notes)
            .with_context(|| format!("writing {name}"))?;
        Ok((notes, kept))
    }
}

/// The options of `model`'s run and its warnings, each checked:
/// everything the model refuses is refused here, before any output (nothing
/// reaches stdout).
fn prepare(
    args: &SimulateArgs,
    model: ModelKind,
    scenario: &Scenario,
) -> Result<(ModelKind, SimOptions, Vec<String>)> {
    if args.turns.is_some() && !model.is_turn_model() {
        bail!(
            "--turns (config key `turns`) applies only to the turn models {}, not to {}",
            id_list(&turn_models()),
            model.id()
        );
    }
    let mut opts = options(args)?;
    if !args.scenario.atol_given() {
        opts.tolerances.atol = default_atol(model, scenario);
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
    model.build().check(scenario, &opts)?;
    // The same checks, in the same order, as a sweep's `warnings` column.
    let warnings: Vec<String> = run_warnings(model, scenario, &opts)
        .iter()
        .map(ToString::to_string)
        .collect();
    Ok((model, opts, warnings))
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
