//! `snowroll turns`: a turn model of §3.4 run for N turns, one row per
//! turn written as it ends ([`snowroll::TurnTableWriter`]), and at the end
//! of the output and on stderr the long-run means
//! of the acceleration that eqs. (77)–(79) leave open, as computed by the
//! library ([`TurnSummary`]).

use anyhow::{bail, Context, Result};
use snowroll::{
    default_atol, format_readable, run_warnings, ModelKind, Sampling, Scenario, SimError,
    SimOptions, TurnMethod, TurnModel, TurnRunEnd, TurnSummary, TurnVariant, WarningCode,
};
use snowroll_io::{RunParams, TurnTableWriter};

use snowroll_report::run_plot::{turn_panels, TurnCurves};

use super::figure::{self, KeepTurns};
use super::inputs::{self, id_list, is_non_finite, turn_models};
use crate::args::{TurnsArgs, TURNS_DEFAULT, TURNS_T_END_S};
use crate::config;
use crate::console::report;
use crate::sink::Sink;

/// The note's long-run mean acceleration over g sin α, eq. (79): 4/9.
/// Printed for comparison only; nothing is computed from it.
const NOTE_EQ79_MEAN_OVER_G: f64 = 4.0 / 9.0;

/// Merges flags over the config file, runs the turns, writes the table and
/// prints the summary.
pub fn run(flags: TurnsArgs) -> Result<()> {
    let args = match flags.output.config.clone() {
        Some(path) => {
            let file = config::load(&path, config::Origin::Turns)?;
            flags.over(file, &path)?
        }
        None => flags,
    };
    inputs::refuse_own_files(&args.output)?;
    let plot = figure::planned(&args.output)?;
    let model = turn_model(&args)?;
    let scenario = inputs::scenario(&args.scenario)?;
    let wanted = args.turns.unwrap_or(TURNS_DEFAULT);
    // Only the turn ends are recorded, whatever the sampling.
    let mut opts = inputs::options(&args.scenario, TURNS_T_END_S, Sampling::Ends, Some(wanted))?;
    if !args.scenario.atol_given() {
        opts.tolerances.atol = default_atol(model, &scenario);
    }
    inputs::check_row_count(&opts, Some(wanted as f64), &format!("--turns {wanted}"))?;
    // Everything the model refuses, before any output (nothing reaches stdout).
    model.build().check(&scenario, &opts)?;
    let format = inputs::format(&args.output)?;
    let (turn_model, method) = method(args.method, model, &scenario, &opts)?;
    let warnings = warnings(model, &scenario, &opts, method);

    // Open the destination before the run, so that a bad path fails at once.
    let mut sink = Sink::open(&args.output)?;
    let name = sink.name();
    let mut params = RunParams::new(&scenario, &opts);
    params.settings.per_turn = true;
    params.warnings = warnings;
    params.method = Some(method);
    let mut writer = TurnTableWriter::new(&mut sink, format, model, &params)
        .with_context(|| format!("writing {name}"))?;
    // Rows go out as each turn ends; the stop, the notes and the summary are
    // written last.
    let mut keep = KeepTurns {
        inner: &mut writer,
        kept: plot.map(|_| Vec::new()),
    };
    let run = turn_model.run_table_into(&scenario, &opts, &mut keep);
    let kept = keep.kept.take();
    let end = match run {
        Ok(end) => end,
        Err(SimError::Sink(e)) if !is_non_finite(&e) => {
            return Err(anyhow::Error::from(SimError::Sink(e)).context(format!("writing {name}")))
        }
        Err(e) => {
            return Err(anyhow::Error::from(e).context(format!(
                "running {} ({})",
                model.id(),
                model.equation()
            )))
        }
    };
    params.notes = snowroll_io::notes::turns_notes(&end, wanted, opts.t_end);
    let written = writer.finish(&end, &params.notes).map(drop);
    written
        .map_err(anyhow::Error::from)
        .and_then(|()| Ok(sink.commit()?))
        .with_context(|| format!("writing {name}"))?;
    for note in &params.notes {
        report!("note: {note}");
    }
    report!("{}", summary(&end).trim_end());
    if let (Some((path, format)), Some(rows)) = (plot, kept) {
        let panels = turn_panels(&[TurnCurves { model, rows: &rows }], scenario.g_along());
        let prov = figure::provenance(&[model], &args.scenario.params.given);
        figure::write(path, format, &panels, &prov)?;
    }
    Ok(())
}

/// The turn model asked for, `turns` (the note's, eqs. (73), (76)) when
/// none is; any other model is refused, naming the turn models.
fn turn_model(args: &TurnsArgs) -> Result<ModelKind> {
    let choices = turn_models();
    if args.scenario.model.is_none() {
        return Ok(ModelKind::Turns);
    }
    let models = inputs::models(&args.scenario, &choices)?;
    if let Some(&model) = models.iter().find(|m| !m.is_turn_model()) {
        bail!(
            "`snowroll turns` needs a turn model, one of {} (aliases {}), not {}",
            id_list(&choices),
            choices
                .iter()
                .map(|k| k.alias())
                .collect::<Vec<_>>()
                .join(", "),
            model.id()
        );
    }
    match models {
        [model] => Ok(*model),
        _ => bail!(
            "`snowroll turns` runs one model; --model {} names {}: run each alone",
            id_list(models).replace(", ", ","),
            models.len()
        ),
    }
}

/// The turn model of `model` with the method asked for (closed by
/// default), and the method that will compute the table: a note on stderr
/// when the closed form does not cover the run.
fn method(
    asked: Option<TurnMethod>,
    model: ModelKind,
    scenario: &Scenario,
    opts: &SimOptions,
) -> Result<(TurnModel, TurnMethod)> {
    let asked = asked.unwrap_or_default();
    let turn_model = TurnVariant::of(model)
        .map(|v| TurnModel::new(v).with_method(asked))
        .context("a turn model")?;
    let method = turn_model.method_for(scenario, opts);
    if method != asked {
        report!(
            "note: --method {} does not cover this run (--collision pivot, or a start from rest \
             that may not start); the table is computed by --method {}",
            asked.id(),
            method.id()
        );
    }
    Ok((turn_model, method))
}

/// The run's warnings (the checks of a sweep's `warnings` column), each
/// also on stderr; the closed form takes no tolerances, so loose ones are
/// no warning for it.
fn warnings(model: ModelKind, s: &Scenario, opts: &SimOptions, method: TurnMethod) -> Vec<String> {
    let warnings: Vec<String> = run_warnings(model, s, opts)
        .iter()
        .filter(|w| method == TurnMethod::Ode || w.code != WarningCode::LooseTolerance)
        .map(ToString::to_string)
        .collect();
    for w in &warnings {
        report!("warning: {w}");
    }
    warnings
}

/// The long-run statistics for people: overall means, the last decade,
/// convergence with K, and the note's claim beside them.
fn summary(end: &TurnRunEnd) -> String {
    let s: &TurnSummary = &end.summary;
    let mut text = format!(
        "summary of {} ({}): {} turns; accelerations as fractions of G = g sin(alpha) = {} m/s^2\n",
        end.model.id(),
        end.model.equation(),
        s.turns,
        format_readable(s.g_along_m_s2)
    );
    let Some(all) = s.overall() else {
        text.push_str("  no turn was completed\n");
        return text;
    };
    text.push_str(&format!(
        "  long-run mean a/G over all {} turns: in turn {:.6}, with collisions {:.6}\n",
        all.turns, all.mean_a_turn_over_g, all.mean_a_with_collision_over_g
    ));
    text.push_str(&format!(
        "  last decade (turns {}..{}): mean a/G in turn {:.6}, with collisions {:.6}; \
         a/G within a turn ranges over [{:.6}, {:.6}]\n",
        all.window_first_turn,
        all.turns - 1,
        all.window_mean_a_turn_over_g,
        all.window_mean_a_with_collision_over_g,
        all.window_min_a_over_g,
        all.window_max_a_over_g
    ));
    text.push_str(&format!(
        "  the note's eq. (79) estimate: 4/9 = {NOTE_EQ79_MEAN_OVER_G:.3}\n"
    ));
    text.push_str("  convergence with K (means over turns k < K; last decade: K/10 <= k < K):\n");
    text.push_str(&format!(
        "  {:>10}  {:>10}  {:>10}  |  {:>10}  {:>10}  {:>10}  {:>10}\n",
        "K", "in turn", "with coll.", "decade: in", "with coll.", "min a/G", "max a/G"
    ));
    for c in &s.checkpoints {
        text.push_str(&format!(
            "  {:>10}  {:>10.6}  {:>10.6}  |  {:>10.6}  {:>10.6}  {:>10.6}  {:>10.6}\n",
            c.turns,
            c.mean_a_turn_over_g,
            c.mean_a_with_collision_over_g,
            c.window_mean_a_turn_over_g,
            c.window_mean_a_with_collision_over_g,
            c.window_min_a_over_g,
            c.window_max_a_over_g
        ));
    }
    text
}
