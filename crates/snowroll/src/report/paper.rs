//! `snowroll paper`: runs every claim of [`CLAIMS`] and the scenarios behind
//! the figures, and assembles the [`Report`].
//!
//! The figures only read results: trajectories of every model on the lab's
//! scenario, the long multi-turn runs the claims already computed, and their
//! per-turn tables.

use super::{
    where_turn_models_part_ways, Animation, ClaimResult, Figure, FirstTurn, Lab, Metadata, Report,
    ReportError, Table, CLAIMS,
};
use crate::models::THIN_SNOW_MAX_B_OVER_R0;
use crate::models::{
    kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, ModelKind, TurnTable,
};
use crate::plot::{Axis, Chart, Legend, Series, Style};
use crate::scenario::ScenarioFile;
use crate::trajectory::{Sampling, SimOptions, Trajectory};

/// End of the runs shown against time, s.
const T_END: f64 = 100.0;
/// First time of the logarithmic time grid, s.
const T_FIRST: f64 = 1e-3;
/// Points of the logarithmic time grid.
const N_TIMES: usize = 300;
/// Distance of the approach figure, m (10⁷ r0 for the default r0).
const X_FAR: f64 = 1e6;
/// Smallest |a − a_term|/G drawn: below it the integration error (rtol
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
    CLAIMS.len() + 6
}

/// The table of where the turn models part ways (see [`where_turn_models_part_ways`]).
fn parting_table(lab: &Lab) -> Result<Table, ReportError> {
    let rows = where_turn_models_part_ways(lab.scenario())?;
    let outcome = |f: FirstTurn| match f {
        FirstTurn::Completed { v_end_m_s } => format!("rolls on, v = {v_end_m_s:.4} m/s"),
        FirstTurn::Stalled { t_s } => format!("stalls at t = {t_s:.3} s"),
    };
    Ok(Table {
        title: "Where the models part ways".to_string(),
        caption: format!(
            "The first-order turn model (turns, eq. (73)) against the exact geometry (turns-exact), from rest, in turn 0. \
             Their stall slopes (fn. 7 in §3) differ by a relative O(b/r0); for thick snow one stalls where the other rolls on. \
             snowroll simulate and snowroll turns warn on stderr when turns runs beyond b/r0 = {THIN_SNOW_MAX_B_OVER_R0} or where the two disagree about stalling."
        ),
        header: [
            "α (°)",
            "b (m)",
            "r0 (m)",
            "b/r0",
            "stall slope, turns (°)",
            "stall slope, turns-exact (°)",
            "turn 0, turns",
            "turn 0, turns-exact",
            "warnings for turns",
        ]
        .map(String::from)
        .to_vec(),
        rows: rows
            .iter()
            .map(|r| {
                vec![
                    format!("{:.0}", r.alpha_deg),
                    format!("{:.3}", r.snow_depth),
                    format!("{:.2}", r.r0),
                    format!("{:.3}", r.snow_depth / r.r0),
                    format!("{:.4}", r.stall_slope_deg.0),
                    format!("{:.4}", r.stall_slope_deg.1),
                    outcome(r.first_turn.0),
                    outcome(r.first_turn.1),
                    r.turns_warnings.to_string(),
                ]
            })
            .collect(),
    })
}

fn log_times() -> Vec<f64> {
    let (a, b) = (T_FIRST.ln(), T_END.ln());
    let mut times: Vec<f64> = (0..N_TIMES)
        .map(|i| (a + (b - a) * i as f64 / (N_TIMES - 1) as f64).exp())
        .collect();
    // exp(ln 100) may round above 100 s, past the end of the run: pin it.
    if let Some(last) = times.last_mut() {
        *last = T_END;
    }
    times
}

fn run(kind: ModelKind, lab: &Lab, opts: &SimOptions) -> Result<Trajectory, ReportError> {
    Ok(kind.build().simulate(lab.scenario(), opts)?)
}

/// Mid-turn time and in-turn mean acceleration of each turn up to `t_max`.
fn turn_means(table: &TurnTable, t_max: f64, g: f64) -> Vec<(f64, f64)> {
    table
        .rows
        .iter()
        .take_while(|r| r.t_end_s <= t_max)
        .map(|r| (0.5 * (r.t_start_s + r.t_end_s), r.mean_a_turn_m_s2 / g))
        .collect()
}

/// About `n` turn indices spread evenly in log k over the table.
fn log_spread(len: usize, n: usize) -> Vec<usize> {
    let mut out: Vec<usize> = (0..n)
        .map(|i| ((len as f64).powf(i as f64 / (n - 1) as f64) - 1.0).round() as usize)
        .filter(|&k| k < len)
        .collect();
    out.dedup();
    out
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
    let s = lab.scenario();
    let g = s.g_along();
    let opts = SimOptions::default();

    let mut claims: Vec<ClaimResult> = Vec::with_capacity(CLAIMS.len());
    for check in CLAIMS {
        tick(check.claim.id);
        claims.push(check.run(lab)?);
    }

    tick("where the turn models part ways");
    let parting = parting_table(lab)?;

    tick("contact forces: smallest μ, hop per turn, collision variants");
    let contact_tables = [
        super::contact::mu_min_table(lab)?,
        super::contact::collision_table(lab)?,
    ];
    let contact_figure = super::contact::min_normal_figure(lab)?;

    tick("trajectories of every model");
    let timed = SimOptions {
        t_end: T_END,
        sampling: Sampling::Times(log_times()),
        ..opts.clone()
    };
    let circular: Vec<ModelKind> = ModelKind::ALL
        .into_iter()
        .filter(|k| k.is_circular())
        .collect();
    let mut trajectories = Vec::new();
    for kind in &circular {
        trajectories.push(run(*kind, lab, &timed)?);
    }
    let paper = lab.long_run(false)?;
    let exact = lab.long_run(true)?;

    // Short legend entries (id and equation alias) keep the legends clear of the curves.
    let label = |k: ModelKind| format!("{} ({})", k.id(), k.alias());
    let style = |k: ModelKind| match k {
        ModelKind::Loney | ModelKind::QuasiCircular | ModelKind::EnergyThin => Style::Dashed,
        _ => Style::Line,
    };
    let mut accel = Chart::new(
        "acceleration-all-models",
        "Acceleration of every model",
        Axis::log("time t", "s").column("t_s"),
        Axis::linear("a / (g sin α)", "1").column("a_over_g_sin_alpha"),
    )
    .with_legend(Legend::LowerLeft);
    let mut speed = Chart::new(
        "speed-all-models",
        "Speed of every model",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("speed v", "m/s").column("v_m_s"),
    )
    .with_legend(Legend::UpperLeft);
    let mut radius = Chart::new(
        "radius-all-models",
        "Radius of the log",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("radius r", "m").column("r_m"),
    )
    .with_legend(Legend::UpperLeft);
    for traj in &trajectories {
        let k = traj.model;
        accel = accel.with_series(
            Series::from_samples(&label(k), &traj.samples, |p| p.t_s, |p| p.a_m_s2 / g)
                .style(style(k)),
        );
        speed = speed.with_series(
            Series::from_samples(&label(k), &traj.samples, |p| p.t_s, |p| p.v_m_s).style(style(k)),
        );
        radius = radius.with_series(
            Series::from_samples(&label(k), &traj.samples, |p| p.t_s, |p| p.r_m).style(style(k)),
        );
    }
    for (table, kind) in [(paper, ModelKind::Turns), (exact, ModelKind::TurnsExact)] {
        let name = format!("{}, mean per turn", label(kind));
        accel = accel
            .with_series(Series::new(&name, turn_means(table, T_END, g)).style(Style::Markers));
        let speeds: Vec<(f64, f64)> = table
            .rows
            .iter()
            .take_while(|r| r.t_start_s <= T_END)
            .map(|r| (r.t_start_s, r.v_start_m_s))
            .collect();
        speed = speed.with_series(
            Series::new(&format!("{}, start of each turn", label(kind)), speeds)
                .style(Style::Dashed),
        );
        let radii: Vec<(f64, f64)> = table
            .rows
            .iter()
            .take_while(|r| r.t_start_s <= T_END)
            .map(|r| {
                (
                    r.t_start_s,
                    s.initial_radius() + r.turn as f64 * s.snow_depth(),
                )
            })
            .collect();
        radius = radius.with_series(
            Series::new(&format!("{}, r_k = r0 + k b", label(kind)), radii).style(Style::Markers),
        );
    }

    tick("approach to the terminal accelerations");
    let mut approach = Chart::new(
        "approach-to-terminal",
        "Approach to the terminal acceleration",
        Axis::log("distance x", "m").column("x_m"),
        Axis::log("|a − a_term| / (g sin α)", "1").column("deviation_over_g_sin_alpha"),
    )
    .with_legend(Legend::LowerLeft);
    let far = SimOptions {
        t_end: 1e8,
        x_end: Some(X_FAR),
        sampling: Sampling::Steps,
        ..opts.clone()
    };
    for kind in circular
        .iter()
        .copied()
        .filter(|k| *k != ModelKind::Snowless && *k != ModelKind::Loney)
    {
        let a_term = kind.terminal_fraction().unwrap_or(f64::NAN);
        let traj = run(kind, lab, &far)?;
        let points: Vec<(f64, f64)> = traj
            .samples
            .iter()
            .map(|p| (p.x_m, (p.a_m_s2 / g - a_term).abs()))
            .filter(|&(x, d)| x > 0.0 && d > APPROACH_FLOOR)
            .collect();
        approach = approach.with_series(
            Series::new(&format!("{}, a_term = {a_term:.4} G", label(kind)), points)
                .style(style(kind)),
        );
    }

    tick("turn-by-turn model");
    let first_turns = SimOptions {
        turns: Some(TURNS_SHOWN),
        t_end: 1e6,
        sampling: Sampling::Every(0.002),
        ..opts.clone()
    };
    let turns_traj = run(ModelKind::Turns, lab, &first_turns)?;
    let exact_traj = run(ModelKind::TurnsExact, lab, &first_turns)?;
    let in_turn = Chart::new(
        "turns-acceleration",
        "Acceleration over the first turns (with a collision at each full turn)",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("a / (g sin α)", "1").column("a_over_g_sin_alpha"),
    )
    .with_legend(Legend::LowerRight)
    .with_series(Series::from_samples(
        &label(ModelKind::Turns),
        &turns_traj.samples,
        |p| p.t_s,
        |p| p.a_m_s2 / g,
    ))
    .with_series(
        Series::from_samples(
            &label(ModelKind::TurnsExact),
            &exact_traj.samples,
            |p| p.t_s,
            |p| p.a_m_s2 / g,
        )
        .style(Style::Dashed),
    );

    let mut means = Chart::new(
        "turns-long-run-means",
        "Long-run mean acceleration of the turn-by-turn model",
        Axis::log("turns completed K", "1").column("turns"),
        Axis::linear("mean a / (g sin α)", "1").column("mean_a_over_g_sin_alpha"),
    )
    .with_legend(Legend::UpperRight);
    let checkpoints = &paper.summary.checkpoints;
    let k_span: Vec<f64> = checkpoints.iter().map(|c| c.turns as f64).collect();
    let flat = |v: f64| -> Vec<(f64, f64)> { k_span.iter().map(|&k| (k, v)).collect() };
    means = means
        .with_series(Series::new(
            "in turn, mean over turns K/10 … K",
            checkpoints
                .iter()
                .map(|c| (c.turns as f64, c.window_mean_a_turn_over_g))
                .collect(),
        ))
        .with_series(Series::new(
            "with collisions, mean over turns K/10 … K",
            checkpoints
                .iter()
                .map(|c| (c.turns as f64, c.window_mean_a_with_collision_over_g))
                .collect(),
        ))
        .with_series(
            Series::new(
                "in turn, mean over all K turns",
                checkpoints
                    .iter()
                    .map(|c| (c.turns as f64, c.mean_a_turn_over_g))
                    .collect(),
            )
            .style(Style::Markers),
        )
        .with_series(
            Series::new(
                "with collisions, mean over all K turns",
                checkpoints
                    .iter()
                    .map(|c| (c.turns as f64, c.mean_a_with_collision_over_g))
                    .collect(),
            )
            .style(Style::Markers),
        )
        .with_series(Series::new("note, eq. (79): 4/9", flat(4.0 / 9.0)).style(Style::Dashed))
        .with_series(Series::new("1/3", flat(1.0 / 3.0)).style(Style::Dashed))
        .with_series(Series::new("1/4", flat(0.25)).style(Style::Dashed));

    // Energy ledger: potential energy released (T_end − T_beg within each
    // turn, energy being conserved in the turn), kinetic energy, and the
    // collisions' losses, summed over turns.
    let (b, r0) = (s.snow_depth(), s.initial_radius());
    let rho_l = s.density() * s.length();
    let mut released = 0.0;
    let mut lost = 0.0;
    let mut ledger_released = Vec::new();
    let mut ledger_lost = Vec::new();
    let mut ledger_kinetic = Vec::new();
    let keep = log_spread(paper.rows.len(), 200);
    let mut next = keep.iter().peekable();
    for row in &paper.rows {
        let k = row.turn as f64;
        let (r, r1) = (r0 + k * b, r0 + (k + 1.0) * b);
        released += kinetic_energy_at_turn_end(rho_l, r, b, row.v_end_m_s)
            - kinetic_energy_at_turn_start(rho_l, r, row.v_start_m_s);
        lost += row.collision_loss_j;
        if next.peek().is_some_and(|&&i| i == row.turn as usize) {
            next.next();
            let kk = k + 1.0;
            ledger_released.push((kk, released));
            ledger_lost.push((kk, lost));
            ledger_kinetic.push((kk, kinetic_energy_at_turn_start(rho_l, r1, row.v_after_m_s)));
        }
    }
    let ledger = Chart::new(
        "turns-energy-ledger",
        "Energy ledger of the turn-by-turn model",
        Axis::log("turns completed", "1").column("turns"),
        Axis::log("energy", "J").column("energy_j"),
    )
    .with_legend(Legend::UpperLeft)
    .with_series(Series::new(
        "potential energy released (sum over turns)",
        ledger_released,
    ))
    .with_series(
        Series::new("kinetic energy after the collision", ledger_kinetic).style(Style::Dashed),
    )
    .with_series(Series::new("lost in collisions (sum)", ledger_lost));

    tick("the snowball");
    let snowball = super::snowball::snowball_figure(lab, &log_times())?;

    tick("animation");
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
    let animation = Animation::from_trajectory(&anim_traj, s, FRAMES)?;

    let file = ScenarioFile::from(*s);
    let metadata = Metadata::new("snowroll: McDonald's snowball/log note, reproduced and judged")
        .param("alpha_deg", file.alpha_deg)
        .param("snow_depth", file.snow_depth)
        .param("r0", file.r0)
        .param("g", file.g)
        .param("density", file.density)
        .param("length", file.length)
        .param("v0", file.v0)
        .param("rtol", format!("{:e}", opts.tolerances.rtol))
        .param("atol", format!("{:e}", opts.tolerances.atol))
        .param("long_run_turns", lab.turns());
    // Each figure's footer names the scenario; the full list is in the metadata.
    let short = |f: Figure| {
        f.param("alpha_deg", file.alpha_deg)
            .param("b_m", file.snow_depth)
            .param("r0", file.r0)
            .param("v0", file.v0)
            .param("rtol", format!("{:e}", opts.tolerances.rtol))
    };
    // The terminal values in the caption come from the library's coefficients.
    let terminal_values = circular
        .iter()
        .filter_map(|k| {
            k.terminal_fraction()
                .map(|f| format!("{f:.4} for {}", k.equation()))
        })
        .collect::<Vec<_>>()
        .join(", ");
    let figures: Vec<Figure> = vec![
        Figure::new(accel, &format!("a/(g sin α) against time for every model from rest on the default slope. The circular models of §2 each tend to their own terminal value ({terminal_values}); the turn-by-turn models (markers: the mean over each turn) settle near {:.4} within a turn over the last decade of the long run.", paper.summary.overall().map_or(f64::NAN, |c| c.window_mean_a_turn_over_g))).supports(&["circular-analyses-differ", "terminal-accelerations", "eq35-terminal-third", "loney-limit-fifth", "multi-turn-never-settles"]),
        Figure::new(speed, "Speed against time. After the first seconds every model's speed grows linearly, at its terminal acceleration.").supports(&["terminal-accelerations"]),
        Figure::new(radius, "Radius against time: π r² = π r0² + b x (eq. (8)); the turn models grow by b per full turn.").supports(&["eq70-mass-after-first-turn"]),
        Figure::new(approach, "How fast each circular model approaches its terminal acceleration: |a − a_term| against x. Models with only the v² term approach as a power r^−2(1+2c_v) (x^−10/3 for eq. (4), fn. 4); the snow-lifting term of eqs. (14), (15), (21), (36) slows this to 1/r. The dips near x = 10 m are where a − a_term changes sign; curves stop at 1e-10, the accuracy of the integration.").supports(&["eq36-slows-approach", "eq33-35-terminal-argument", "loney-limit-fifth"]),
        Figure::new(in_turn, "The acceleration of the turn-by-turn model over its first turns: it starts each turn near 2G/3, dips within the turn, and the speed drops at each collision (eq. (89)). eq. (73) is the note's O(b/r) equation, exact geometry the full mass properties.").supports(&["multi-turn-never-settles", "first-turn-58-64-69", "eq89-collision", "eq73-truncates-exact"]),
        Figure::new(means, &format!("Mean acceleration over many turns, against the number of turns K: over the last decade of {} turns it is {:.4} G within turns and {:.4} G including the collisions, not the note's 4G/9 (eq. (79)).", paper.summary.turns, paper.summary.overall().map_or(f64::NAN, |c| c.window_mean_a_turn_over_g), paper.summary.overall().map_or(f64::NAN, |c| c.window_mean_a_with_collision_over_g))).supports(&["multi-turn-mean-four-ninths", "multi-turn-never-settles"]),
        Figure::new(ledger, "Where the energy goes in the turn-by-turn model (eq. (73)): the potential energy released within the turns equals the kinetic energy plus what the collisions removed.").supports(&["eq88-energy-balance", "eq89-collision", "collision-potential-jump"]),
        snowball,
    ]
    .into_iter()
    .map(short)
    .chain([contact_figure])
    .collect();
    Ok(Report {
        metadata,
        claims,
        tables: [vec![parting], contact_tables.to_vec()].concat(),
        figures,
        animation: Some(animation),
    })
}
