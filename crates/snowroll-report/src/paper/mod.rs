//! `snowroll paper`: runs every claim of [`CLAIMS`] and the scenarios behind
//! the figures, and assembles the [`Report`].
//!
//! The figures only read results: trajectories of every model on the lab's
//! scenario, the long multi-turn runs the claims already computed, and their
//! per-turn tables.

mod charts;
mod figures;
mod looks;
mod parting;

use super::{tuned_to_default, Animation, ClaimResult, Lab, Metadata, Report, ReportError, CLAIMS};
use charts::{
    approach_chart, energy_ledger_chart, in_turn_chart, means_chart, model_charts, Charts,
    CircularRuns,
};
use figures::figures;
use parting::parting_table;
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::trajectory::{Sampling, SimOptions, Trajectory};

/// End of the runs shown against time, s.
const T_END: f64 = 100.0;
/// First time of the logarithmic time grid, s.
const T_FIRST: f64 = 1e-3;
/// Points of the logarithmic time grid.
const N_TIMES: usize = 300;
/// Distance of the approach figure, m (10⁷ r0 for the default r0).
const X_FAR: f64 = 1e6;
/// Smallest |a − a∞|/G drawn: below it the integration error (rtol
/// 1e-10 on v, accumulated over ~10³ steps) would be drawn instead of physics.
const APPROACH_FLOOR: f64 = 1e-10;
/// Turns shown in full in the in-turn acceleration figure and the animation.
const TURNS_SHOWN: u64 = 6;
/// Frames of the animation.
const FRAMES: usize = 600;

/// One step of the work, for a progress display.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress<'a> {
    /// Steps done so far.
    pub done: usize,
    /// Steps in all.
    pub total: usize,
    /// What is being done now.
    pub label: &'a str,
}

/// Number of progress steps of [`build_paper_report`].
pub fn paper_steps() -> usize {
    CLAIMS.len() + 8
}

/// The logarithmic time grid of the runs shown against time, s.
fn log_times() -> Vec<f64> {
    super::log_grid(T_FIRST, T_END, N_TIMES)
}

/// The run of model `kind` on the lab's scenario.
fn run(kind: ModelKind, lab: &Lab, opts: &SimOptions) -> Result<Trajectory, ReportError> {
    Ok(kind.build().simulate(lab.scenario(), opts)?)
}

/// The report's metadata: the scenario, the tolerances, the long runs.
fn metadata(lab: &Lab, opts: &SimOptions) -> Metadata {
    let file = ScenarioFile::from(*lab.scenario());
    Metadata::new("snowroll: McDonald's snowball/log note, reproduced and judged")
        .param("alpha_deg", file.alpha_deg)
        .param("snow_depth", file.snow_depth)
        .param("r0", file.r0)
        .param("g", file.g)
        .param("density", file.density)
        .param("length", file.length)
        .param("v0", file.v0)
        .param("rtol", format!("{:e}", opts.tolerances.rtol))
        .param("atol", format!("{:e}", opts.tolerances.atol))
        .param("long_run_turns", lab.turns())
}

/// Runs every claim and every figure's scenarios and assembles the report.
/// `progress` is called before each step.
///
/// # Errors
/// [`ReportError`] when a simulation or a figure fails.
pub fn build_paper_report(
    lab: &Lab,
    progress: &mut dyn FnMut(Progress<'_>),
) -> Result<Report, ReportError> {
    let total = paper_steps();
    let mut step = 0;
    let mut tick = |label: &str| {
        progress(Progress {
            done: step,
            total,
            label,
        });
        step += 1;
    };
    let opts = SimOptions::default();

    let claims = run_claims(lab, &mut tick)?;

    tick("where the turn models part ways");
    let parting = parting_table(lab)?;

    tick("contact forces: smallest μ, hop per turn, collision variants");
    let contact_tables = [
        super::contact::mu_min_table(lab)?,
        super::contact::collision_table(lab)?,
    ];
    let contact_figure = super::contact::min_normal_figure(lab)?;

    let (runs, charts) = model_charts_with_progress(lab, &opts, &mut tick)?;
    let paper = lab.long_run(false)?;

    tick("the snowball");
    let snowball = super::snowball::snowball_figure(lab, &log_times())?;

    tick("the losses");
    let mut losses = super::loss_figures::speed_with_losses_figures(lab)?;
    losses.push(super::loss_figures::ledger_shares_figure(lab)?);

    tick("regime map");
    let regime = super::claims::regime_figure(lab)?;

    tick("animation");
    let animations = animations(lab, &opts)?;

    Ok(Report {
        metadata: metadata(lab, &opts),
        claims,
        tables: [vec![parting], contact_tables.to_vec()].concat(),
        figures: figures(charts, &runs, paper, lab, &opts)
            .into_iter()
            .chain([snowball])
            .chain(losses)
            .chain([contact_figure, regime])
            .collect(),
        animations,
        explorer: false,
    })
}

/// Every claim of [`CLAIMS`] checked on `lab`, in table order, with a
/// progress step (the claim's id) before each.
fn run_claims(lab: &Lab, tick: &mut dyn FnMut(&str)) -> Result<Vec<ClaimResult>, ReportError> {
    let mut claims: Vec<ClaimResult> = Vec::with_capacity(CLAIMS.len());
    // On another scenario, the claims whose checks are set for the default
    // one are judged on a lab of their own, built when first needed.
    let default = Scenario::default();
    let mut default_lab: Option<Lab> = None;
    for check in CLAIMS {
        tick(check.claim.id.as_str());
        let reason = tuned_to_default(check.claim.id).filter(|_| *lab.scenario() != default);
        let result = match reason {
            None => check.run(lab)?,
            Some(reason) => {
                let own = default_lab.get_or_insert_with(|| Lab::new(default, lab.turns()));
                let mut r = check.run(own)?;
                r.measured = format!("on the default scenario ({reason}): {}", r.measured);
                r
            }
        };
        claims.push(result);
    }
    Ok(claims)
}

/// The circular runs and the charts of the model figures, in three progress
/// steps: every model against time, the approach to the terminal
/// accelerations, the turn-by-turn model.
fn model_charts_with_progress(
    lab: &Lab,
    opts: &SimOptions,
    tick: &mut dyn FnMut(&str),
) -> Result<(CircularRuns, Charts), ReportError> {
    tick("trajectories of every model");
    let runs = CircularRuns::new(lab, opts)?;
    let paper = lab.long_run(false)?;
    let exact = lab.long_run(true)?;
    let [accel, speed, radius] = model_charts(
        lab.scenario(),
        &runs,
        [(paper, ModelKind::Turns), (exact, ModelKind::TurnsExact)],
    );

    tick("approach to the terminal accelerations");
    let approach = approach_chart(lab, opts)?;

    tick("turn-by-turn model");
    let in_turn = in_turn_chart(lab, opts)?;
    let charts = Charts {
        accel,
        speed,
        radius,
        approach,
        in_turn,
        means: means_chart(paper),
        ledger: energy_ledger_chart(paper),
    };
    Ok((runs, charts))
}

/// The two animations: the log of the turn model over its first
/// [`TURNS_SHOWN`] turns (and two more), and the snowball; [`FRAMES`] frames each.
fn animations(lab: &Lab, opts: &SimOptions) -> Result<Vec<Animation>, ReportError> {
    let anim_traj = run(
        ModelKind::Turns,
        lab,
        &SimOptions {
            turns: Some(TURNS_SHOWN + 2),
            t_end: 1e6,
            sampling: Sampling::Every(0.005),
            ..opts.clone()
        },
    )?;
    let animation = Animation::from_trajectory(&anim_traj, lab.scenario(), FRAMES)?;
    let ball = super::snowball::ball_animation(lab, FRAMES)?;
    Ok(vec![animation, ball])
}
