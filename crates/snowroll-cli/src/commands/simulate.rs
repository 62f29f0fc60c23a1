//! `snowroll simulate`: one model, one scenario, one trajectory.

use anyhow::{anyhow, Context, Result};
use snowroll::integrate::Tolerances;
use snowroll::{
    write_trajectory, ModelKind, ParamError, RunParams, Sampling, Scenario, ScenarioFile,
    SimOptions, StopReason, Trajectory,
};

use crate::args::SimulateArgs;
use crate::config;
use crate::sink::Sink;

/// Merges flags over the config file, runs the model, writes the trajectory.
pub fn run(flags: SimulateArgs) -> Result<()> {
    let args = match &flags.config {
        Some(path) => {
            let file = config::load(path)?;
            flags.over(file)
        }
        None => flags,
    };
    let model = args.model.ok_or_else(|| {
        anyhow!(
            "no model given: pass --model ID (or set `model` in the config file), ID one of {}",
            ModelKind::ALL.map(ModelKind::id).join(", ")
        )
    })?;
    let scenario = scenario(&args)?;
    let opts = options(&args)?;
    opts.validate()?;
    let format = args.format.unwrap_or_default();

    // Open the destination before the run, so that a bad path fails at once.
    let mut sink = Sink::open(args.output.as_deref())?;
    let name = sink.name();
    let traj = model
        .build()
        .simulate(&scenario, &opts)
        .with_context(|| format!("simulating {} ({})", model.id(), model.equation()))?;
    let params = RunParams::new(&scenario, &opts);
    write_trajectory(&mut sink, format, &traj, &params)
        .map_err(anyhow::Error::from)
        .and_then(|()| Ok(sink.commit()?))
        .with_context(|| format!("writing {name}"))?;
    if let Some(note) = stop_note(&traj, &scenario) {
        eprintln!("note: {note}");
    }
    Ok(())
}

/// The scenario: each parameter from the arguments, else the library default.
fn scenario(a: &SimulateArgs) -> Result<Scenario, ParamError> {
    let d = ScenarioFile::default();
    Scenario::new(ScenarioFile {
        slope_deg: a.alpha_deg.unwrap_or(d.slope_deg),
        snow_depth_m: a.snow_depth.unwrap_or(d.snow_depth_m),
        r0_m: a.r0.unwrap_or(d.r0_m),
        g_m_s2: a.g.unwrap_or(d.g_m_s2),
        density_kg_m3: a.density.unwrap_or(d.density_kg_m3),
        length_m: a.length.unwrap_or(d.length_m),
        v0_m_s: a.v0.unwrap_or(d.v0_m_s),
    })
}

/// The run options: each from the arguments, else the library default.
fn options(a: &SimulateArgs) -> Result<SimOptions> {
    let d = SimOptions::default();
    let sampling = match (&a.times, a.dt) {
        (Some(times), None) => Sampling::Times(times.clone()),
        (None, Some(dt)) => Sampling::Every(dt),
        (None, None) => d.sampling.clone(),
        // clap and `config::load` each reject both; reachable only by a bug.
        (Some(_), Some(_)) => return Err(anyhow!("`times` and `dt` conflict, give one of them")),
    };
    Ok(SimOptions {
        t_end: a.t_end.unwrap_or(d.t_end),
        x_end: a.x_end.or(d.x_end),
        tolerances: Tolerances {
            rtol: a.rtol.unwrap_or(d.tolerances.rtol),
            atol: a.atol.unwrap_or(d.tolerances.atol),
            ..d.tolerances
        },
        sampling,
        ..d
    })
}

/// One line for stderr when the run ended before its end time.
fn stop_note(traj: &Trajectory, scenario: &Scenario) -> Option<String> {
    let stop = traj.stop;
    if stop.reason == StopReason::EndTime {
        return None;
    }
    let mut note = format!(
        "run stopped at t = {} s, x = {} m: {}",
        stop.t_s,
        stop.x_m,
        stop.reason.describe()
    );
    if stop.reason == StopReason::DoesNotStart {
        let threshold = traj.model.derivation().and_then(|d| {
            d.coefficients()
                .stall_slope(scenario.snow_depth(), scenario.initial_radius())
        });
        if let Some(alpha) = threshold {
            note.push_str(&format!(
                "; from rest this model needs alpha > {:.4} degrees",
                alpha.to_degrees()
            ));
        }
    }
    Some(note)
}
