//! `snowroll paper`: runs every claim of [`CLAIMS`] and the scenarios behind
//! the figures, and assembles the [`Report`].
//!
//! The figures only read results: trajectories of every model on the lab's
//! scenario, the long multi-turn runs the claims already computed, and their
//! per-turn tables.

use super::notation;
use super::{
    where_turn_models_part_ways, Animation, ClaimResult, Figure, FirstTurn, Lab, Metadata, Report,
    ReportError, Table, CLAIMS,
};
use super::{LedgerPoint, TurnDigest};
use crate::plot::{Axis, Chart, Legend, Marker, Series, Style};
use snowroll::models::THIN_SNOW_MAX_B_OVER_R0;
use snowroll::models::{Coefficients, Derivation, ModelKind};
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
    super::log_grid(T_FIRST, T_END, N_TIMES)
}

fn run(kind: ModelKind, lab: &Lab, opts: &SimOptions) -> Result<Trajectory, ReportError> {
    Ok(kind.build().simulate(lab.scenario(), opts)?)
}

/// Mid-turn time and in-turn mean acceleration of each turn up to `t_max`.
fn turn_means(table: &TurnDigest, t_max: f64, g: f64) -> Vec<(f64, f64)> {
    table
        .head
        .iter()
        .take_while(|r| r.t_end_s <= t_max)
        .map(|r| (0.5 * (r.t_start_s + r.t_end_s), r.mean_a_turn_m_s2 / g))
        .collect()
}

/// The equation a circular model integrates, as its coefficients: Loney's
/// closed form (fn. 4) solves eq. (4), so it has eq. (4)'s.
fn equation_of(kind: ModelKind) -> Option<Coefficients> {
    match kind {
        ModelKind::Loney => Some(Derivation::TorqueAboutCentre.coefficients()),
        _ => kind.derivation().map(Derivation::coefficients),
    }
}

/// The circular models grouped by equation, in the order of the note: models
/// with the same equation of motion (eq. (15) and eqs. (32)+(36); eq. (4) and
/// Loney's fn. 4) draw one curve under one legend entry.
pub(crate) fn same_equation_groups(kinds: &[ModelKind]) -> Vec<Vec<ModelKind>> {
    let mut groups: Vec<Vec<ModelKind>> = Vec::new();
    for &k in kinds {
        let eq = equation_of(k);
        match groups
            .iter_mut()
            .find(|g| eq.is_some() && equation_of(g[0]) == eq)
        {
            Some(group) => group.push(k),
            None => groups.push(vec![k]),
        }
    }
    groups
}

/// Legend entry of a model: its id and equation alias.
fn label(k: ModelKind) -> String {
    format!("{} ({})", k.id(), k.alias())
}

/// Legend entry of a group of models with one equation: `a (eq15) = b (eq32+36)`.
fn group_label(group: &[ModelKind]) -> String {
    group
        .iter()
        .map(|&k| label(k))
        .collect::<Vec<_>>()
        .join(" = ")
}

/// Line style and marker of each model: every group of models with one
/// equation looks different apart from colour, so that curves that lie
/// close (all start near 2G/3; three tend to G/3; G/5, 2G/9 and G/6 are
/// near each other) stay apart for readers who cannot tell the colours apart.
fn look(k: ModelKind) -> (Style, Option<Marker>) {
    match k {
        ModelKind::TorqueCm | ModelKind::Loney => (Style::Line, Some(Marker::Circle)),
        ModelKind::TorqueContact => (Style::Dashed, None),
        ModelKind::Energy => (Style::Dashed, Some(Marker::Circle)),
        ModelKind::EnergyThin | ModelKind::QuasiCircularLift => {
            (Style::LongDashed, Some(Marker::Triangle))
        }
        ModelKind::LagrangianPrinted => (Style::Dotted, None),
        ModelKind::QuasiCircular => (Style::Dotted, Some(Marker::Square)),
        ModelKind::Turns => (Style::LongDashed, None),
        ModelKind::TurnsExact => (Style::LongDashed, Some(Marker::Square)),
        ModelKind::Snowless => (Style::Line, None),
    }
}

/// `series` drawn in the look of `k`.
fn styled(series: Series, k: ModelKind) -> Series {
    let (style, marker) = look(k);
    let series = series.style(style);
    match marker {
        Some(m) => series.marker(m),
        None => series,
    }
}

/// The runs of every circular model on the logarithmic time grid, grouped by
/// equation, with the largest disagreement inside each group.
struct CircularRuns {
    /// One trajectory per group (its first model's).
    drawn: Vec<(Vec<ModelKind>, Trajectory)>,
    /// For groups of more than one model: the group and the largest
    /// |Δa|/(g sin α) between its runs at the grid's times.
    agreement: Vec<(Vec<ModelKind>, f64)>,
}

impl CircularRuns {
    fn new(lab: &Lab, opts: &SimOptions) -> Result<Self, ReportError> {
        let g = lab.scenario().g_along();
        let timed = SimOptions {
            t_end: T_END,
            sampling: Sampling::Times(log_times()),
            ..opts.clone()
        };
        let mut drawn = Vec::new();
        let mut agreement = Vec::new();
        for group in same_equation_groups(&circular_models()) {
            let first = run(group[0], lab, &timed)?;
            if group.len() > 1 {
                let mut worst: f64 = 0.0;
                for &other in &group[1..] {
                    let traj = run(other, lab, &timed)?;
                    for (p, q) in first.samples.iter().zip(&traj.samples) {
                        worst = worst.max((p.a_m_s2 - q.a_m_s2).abs() / g);
                    }
                }
                agreement.push((group.clone(), worst));
            }
            drawn.push((group, first));
        }
        Ok(Self { drawn, agreement })
    }

    /// One sentence per group of the caption: which equations are one and
    /// how closely their runs agree on the grid.
    fn caption(&self) -> String {
        self.agreement
            .iter()
            .map(|(group, worst)| {
                let names = group
                    .iter()
                    .map(|k| k.equation())
                    .collect::<Vec<_>>()
                    .join(" and ");
                let agree = if *worst == 0.0 {
                    "are identical".to_string()
                } else {
                    format!("differ by at most {} g sin α", notation::number(*worst, 1))
                };
                format!(
                    "{names} are one equation, drawn once under one legend entry \
                     (their runs {agree} at the {N_TIMES} times of the grid, 1 ms to 100 s)."
                )
            })
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// The circular models (§2, App. A, fn. 4), in the order of the note.
fn circular_models() -> Vec<ModelKind> {
    ModelKind::ALL
        .into_iter()
        .filter(|k| k.is_circular())
        .collect()
}

/// Acceleration, speed and radius of every model against time.
fn model_charts(
    s: &Scenario,
    runs: &CircularRuns,
    long_runs: [(&TurnDigest, ModelKind); 2],
) -> [Chart; 3] {
    let g = s.g_along();
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
    for (group, traj) in &runs.drawn {
        let (k, name) = (group[0], group_label(group));
        let of = |y: fn(&snowroll::trajectory::Sample, f64) -> f64| {
            let series = Series::from_samples(&name, &traj.samples, |p| p.t_s, |p| y(p, g));
            styled(series, k)
        };
        accel = accel.with_series(of(|p, g| p.a_m_s2 / g));
        speed = speed.with_series(of(|p, _| p.v_m_s));
        radius = radius.with_series(of(|p, _| p.r_m));
    }
    for (table, kind) in long_runs {
        // Markers of the turn means: circles for turns, squares for turns-exact.
        let marker = look(kind).1.unwrap_or(Marker::Circle);
        let name = format!("{}, mean per turn", label(kind));
        accel = accel.with_series(
            Series::new(&name, turn_means(table, T_END, g))
                .style(Style::Markers)
                .marker(marker),
        );
        let speeds: Vec<(f64, f64)> = table
            .head
            .iter()
            .take_while(|r| r.t_start_s <= T_END)
            .map(|r| (r.t_start_s, r.v_start_m_s))
            .collect();
        let name = format!("{}, start of each turn", label(kind));
        speed = speed.with_series(styled(Series::new(&name, speeds), kind));
        let radii: Vec<(f64, f64)> = table
            .head
            .iter()
            .take_while(|r| r.t_start_s <= T_END)
            .map(|r| {
                (
                    r.t_start_s,
                    s.initial_radius() + r.turn as f64 * s.snow_depth(),
                )
            })
            .collect();
        let name = format!("{}, rₖ = r₀ + k b", label(kind));
        radius = radius.with_series(
            Series::new(&name, radii)
                .style(Style::Markers)
                .marker(marker),
        );
    }
    [accel, speed, radius]
}

/// |a − a∞|/G against x for every circular model with its own terminal
/// value (one curve per equation).
fn approach_chart(lab: &Lab, opts: &SimOptions) -> Result<Chart, ReportError> {
    let g = lab.scenario().g_along();
    let mut approach = Chart::new(
        "approach-to-terminal",
        "Approach to the terminal acceleration",
        Axis::log("distance x", "m").column("x_m"),
        Axis::log("|a − a∞| / (g sin α)", "1").column("deviation_over_g_sin_alpha"),
    )
    .with_legend(Legend::LowerLeft);
    let far = SimOptions {
        t_end: 1e8,
        x_end: Some(X_FAR),
        sampling: Sampling::Steps,
        ..opts.clone()
    };
    for group in same_equation_groups(&circular_models()) {
        let kind = group[0];
        if kind == ModelKind::Snowless {
            continue;
        }
        let a_term = kind.terminal_fraction().unwrap_or(f64::NAN);
        let traj = run(kind, lab, &far)?;
        let points: Vec<(f64, f64)> = traj
            .samples
            .iter()
            .map(|p| (p.x_m, (p.a_m_s2 / g - a_term).abs()))
            .filter(|&(x, d)| x > 0.0 && d > APPROACH_FLOOR)
            .collect();
        let name = format!(
            "{}, a∞ = {} G",
            group_label(&group),
            notation::fixed(a_term, 4)
        );
        approach = approach.with_series(styled(Series::new(&name, points), kind));
    }
    Ok(approach)
}

/// The acceleration of both turn models over their first turns.
fn in_turn_chart(lab: &Lab, opts: &SimOptions) -> Result<Chart, ReportError> {
    let g = lab.scenario().g_along();
    let first_turns = SimOptions {
        turns: Some(TURNS_SHOWN),
        t_end: 1e6,
        sampling: Sampling::Every(0.002),
        ..opts.clone()
    };
    let mut chart = Chart::new(
        "turns-acceleration",
        "Acceleration over the first turns (with a collision at each full turn)",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("a / (g sin α)", "1").column("a_over_g_sin_alpha"),
    )
    .with_legend(Legend::LowerRight);
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let traj = run(kind, lab, &first_turns)?;
        let series = Series::from_samples(&label(kind), &traj.samples, |p| p.t_s, |p| p.a_m_s2 / g);
        chart = chart.with_series(styled(series, kind));
    }
    Ok(chart)
}

/// The long-run means of the turn model against the number of turns.
fn means_chart(paper: &TurnDigest) -> Chart {
    let checkpoints = &paper.summary.checkpoints;
    let k_span: Vec<f64> = checkpoints.iter().map(|c| c.turns as f64).collect();
    let flat = |v: f64| -> Vec<(f64, f64)> { k_span.iter().map(|&k| (k, v)).collect() };
    let of = |f: fn(&snowroll::models::TurnCheckpoint) -> f64| -> Vec<(f64, f64)> {
        checkpoints.iter().map(|c| (c.turns as f64, f(c))).collect()
    };
    Chart::new(
        "turns-long-run-means",
        "Long-run mean acceleration of the turn-by-turn model",
        Axis::log("turns completed K", "1").column("turns"),
        Axis::linear("mean a / (g sin α)", "1").column("mean_a_over_g_sin_alpha"),
    )
    .with_legend(Legend::UpperRight)
    .with_series(Series::new(
        "in turn, mean over turns K/10 … K",
        of(|c| c.window_mean_a_turn_over_g),
    ))
    .with_series(Series::new(
        "with collisions, mean over turns K/10 … K",
        of(|c| c.window_mean_a_with_collision_over_g),
    ))
    .with_series(
        Series::new(
            "in turn, mean over all K turns",
            of(|c| c.mean_a_turn_over_g),
        )
        .style(Style::Markers),
    )
    .with_series(
        Series::new(
            "with collisions, mean over all K turns",
            of(|c| c.mean_a_with_collision_over_g),
        )
        .style(Style::Markers)
        .marker(Marker::Square),
    )
    .with_series(Series::new("note, eq. (79): 4/9", flat(4.0 / 9.0)).style(Style::Dashed))
    .with_series(Series::new("1/3", flat(1.0 / 3.0)).style(Style::LongDashed))
    .with_series(Series::new("1/4", flat(0.25)).style(Style::Dotted))
}

/// Energy ledger of the turn model as shares of the energy released within
/// the turns (T_end − T_beg of each turn, energy being conserved in the turn,
/// summed over turns as the long run went by, [`TurnDigest::ledger`]): the
/// kinetic energy after the collision and what the collisions removed. From
/// rest the two add up to what was released (eqs. (82), (85), (86), (89)
/// telescope), so the shares sum to 1.
fn energy_ledger_chart(paper: &TurnDigest) -> Chart {
    let share = |f: fn(&LedgerPoint) -> f64| -> Vec<(f64, f64)> {
        paper
            .ledger
            .iter()
            .filter(|p| p.released_j > 0.0)
            .map(|p| (p.turns as f64, f(p) / p.released_j))
            .collect()
    };
    Chart::new(
        "turns-energy-ledger",
        "Energy ledger of the turn-by-turn model, as shares",
        Axis::log("turns completed", "1").column("turns"),
        Axis::linear("share of the energy released in the turns", "1").column("share"),
    )
    .with_legend(Legend::UpperRight)
    .with_series(Series::new(
        "kinetic energy after the collision",
        share(|p| p.kinetic_j),
    ))
    .with_series(
        Series::new("lost in the collisions (sum)", share(|p| p.lost_j)).style(Style::Dashed),
    )
    .with_series(
        Series::new("sum of the shares", share(|p| p.kinetic_j + p.lost_j))
            .style(Style::Markers)
            .marker(Marker::Square),
    )
}

/// What the long run of `paper` means physically: its last radius and the
/// distance rolled, m (rₖ = r₀ + k b; x = Σ 2π rₖ over the turns).
fn long_run_extent(paper: &TurnDigest, s: &Scenario) -> (f64, f64) {
    let k = paper.turns as f64;
    let (r0, b) = (s.initial_radius(), s.snow_depth());
    (
        r0 + k * b,
        std::f64::consts::TAU * (k * r0 + b * k * (k - 1.0) / 2.0),
    )
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

/// The figures of the report, each with its caption and the claims it
/// supports, in the order they are shown.
fn figures(
    charts: Charts,
    runs: &CircularRuns,
    paper: &TurnDigest,
    lab: &Lab,
    opts: &SimOptions,
) -> Vec<Figure> {
    let file = ScenarioFile::from(*lab.scenario());
    // Each figure's footer names the scenario; the full list is in the metadata.
    let short = |f: Figure| {
        f.param("alpha_deg", file.alpha_deg)
            .param("snow_depth", file.snow_depth)
            .param("r0", file.r0)
            .param("v0", file.v0)
            .param("rtol", format!("{:e}", opts.tolerances.rtol))
    };
    // The terminal values in the caption come from the library's coefficients.
    let terminal_values = same_equation_groups(&circular_models())
        .iter()
        .filter_map(|group| {
            group[0].terminal_fraction().map(|f| {
                let eqs = group.iter().map(|k| k.equation()).collect::<Vec<_>>();
                format!("{} for {}", notation::fixed(f, 4), eqs.join(" = "))
            })
        })
        .collect::<Vec<_>>()
        .join(", ");
    let overall = paper.summary.overall();
    let in_turn_mean = overall.map_or(f64::NAN, |c| c.window_mean_a_turn_over_g);
    let with_collisions = overall.map_or(f64::NAN, |c| c.window_mean_a_with_collision_over_g);
    let same = runs.caption();
    let extent = long_run_extent(paper, lab.scenario());
    let kinetic_share = paper
        .ledger
        .last()
        .map_or(f64::NAN, |p| p.kinetic_j / p.released_j);
    let Charts {
        accel,
        speed,
        radius,
        approach,
        in_turn,
        means,
        ledger,
    } = charts;
    vec![
        Figure::new(accel, &format!("a/(g sin α) against time for every model from rest on the default slope. The circular models of §2 each tend to their own terminal value ({terminal_values}); the turn-by-turn models (markers: the mean over each turn) settle near {} within a turn over the last decade of the long run. {same} Curves that lie close differ in dash pattern and markers as well as colour.", notation::fixed(in_turn_mean, 4))).supports(&["circular-analyses-differ", "terminal-accelerations", "eq35-terminal-third", "loney-limit-fifth", "multi-turn-never-settles"]),
        Figure::new(speed, &format!("Speed against time. After the first seconds every model's speed grows linearly, at its terminal acceleration. {same}")).supports(&["terminal-accelerations"]),
        Figure::new(radius, "Radius against time: π r² = π r₀² + b x (eq. (8)); the turn models grow by b per full turn.").supports(&["eq70-mass-after-first-turn"]),
        Figure::new(approach, &format!("How fast each circular model approaches its terminal acceleration: |a − a∞| against x, one curve per equation (eq. (4) stands for Loney's fn. 4, its closed form). Models with only the v² term approach as a power, ∝ r⁻ᵖ with p = 2(1 + 2cᵥ) (x{} for eq. (4), fn. 4); the snow-lifting term of eqs. (14), (15), (21), (36) slows this to 1/r. The dips near x = 10 m are where a − a∞ changes sign; curves stop at {}, the accuracy of the integration.", notation::superscript("-10/3"), notation::number(APPROACH_FLOOR, 1))).supports(&["eq36-slows-approach", "eq33-35-terminal-argument", "loney-limit-fifth"]),
        Figure::new(in_turn, "The acceleration of the turn-by-turn model over its first turns: it starts each turn near 2G/3, dips within the turn, and the speed drops at each collision (eq. (89)). eq. (73) is the note's O(b/r) equation, exact geometry the full mass properties.").supports(&["multi-turn-never-settles", "first-turn-58-64-69", "eq89-collision", "eq73-truncates-exact"]),
        Figure::new(means, &format!("Mean acceleration over many turns, against the number of turns K: over the last decade of {} turns it is {} G within turns and {} G including the collisions, not the note's 4G/9 (eq. (79)).", paper.summary.turns, notation::fixed(in_turn_mean, 4), notation::fixed(with_collisions, 4))).supports(&["multi-turn-mean-four-ninths", "multi-turn-never-settles"]),
        Figure::new(ledger, &format!("Where the energy goes in the turn-by-turn model (eq. (73)), as shares of the energy released within the turns: the kinetic energy after each collision and what the collisions removed add up to 1 (squares). After {} turns the log keeps a share of {} as kinetic energy; the collisions took the rest. The long run is a mathematical limit, not a hill: after {} turns the log has r = {} m and has rolled x = {} m.", paper.summary.turns, notation::fixed(kinetic_share, 3), paper.summary.turns, notation::number(extent.0, 2), notation::number(extent.1, 2))).supports(&["eq88-energy-balance", "eq89-collision", "collision-potential-jump"]),
    ]
    .into_iter()
    .map(short)
    .collect()
}

/// Every chart of the report before captions.
struct Charts {
    accel: Chart,
    speed: Chart,
    radius: Chart,
    approach: Chart,
    in_turn: Chart,
    means: Chart,
    ledger: Chart,
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
    let runs = CircularRuns::new(lab, &opts)?;
    let paper = lab.long_run(false)?;
    let exact = lab.long_run(true)?;
    let [accel, speed, radius] = model_charts(
        s,
        &runs,
        [(paper, ModelKind::Turns), (exact, ModelKind::TurnsExact)],
    );

    tick("approach to the terminal accelerations");
    let approach = approach_chart(lab, &opts)?;

    tick("turn-by-turn model");
    let in_turn = in_turn_chart(lab, &opts)?;
    let charts = Charts {
        accel,
        speed,
        radius,
        approach,
        in_turn,
        means: means_chart(paper),
        ledger: energy_ledger_chart(paper),
    };

    tick("the snowball");
    let snowball = super::snowball::snowball_figure(lab, &log_times())?;

    tick("the losses");
    let mut losses = super::loss_figures::speed_with_losses_figures(lab)?;
    losses.push(super::loss_figures::ledger_shares_figure(lab)?);

    tick("regime map");
    let regime = super::claims::regime_figure(lab)?;

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
    let ball = super::snowball::ball_animation(lab, FRAMES)?;

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
        animations: vec![animation, ball],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 3 px of the 600 px figure: curves closer than this look like one.
    const HIDDEN_TOL: f64 = 0.005;

    fn lab() -> Lab {
        Lab::new(Scenario::default(), 100)
    }

    #[test]
    fn models_with_one_equation_are_grouped_and_agree() {
        let groups = same_equation_groups(&circular_models());
        let grouped: Vec<&Vec<ModelKind>> = groups.iter().filter(|g| g.len() > 1).collect();
        assert_eq!(
            grouped,
            [
                &vec![ModelKind::TorqueCm, ModelKind::Loney],
                &vec![ModelKind::EnergyThin, ModelKind::QuasiCircularLift]
            ]
        );
        // Same equation, so the runs differ only by the integration error
        // (rtol 1e-10 on v; Loney's quadrature at 1e-14): 1e-6 G is far above
        // that and far below a pixel (about 2e-3 G on the figure).
        let runs = CircularRuns::new(&lab(), &SimOptions::default()).unwrap();
        assert_eq!(runs.agreement.len(), 2);
        for (group, worst) in &runs.agreement {
            assert!(*worst < 1e-6, "{group:?}: {worst}");
        }
        let caption = runs.caption();
        assert!(
            caption.contains("eq. (15) and eqs. (32)+(36) are one equation"),
            "{caption}"
        );
    }

    #[test]
    fn every_listed_curve_can_be_seen() {
        let lab = lab();
        let opts = SimOptions::default();
        let runs = CircularRuns::new(&lab, &opts).unwrap();
        let long = [
            (lab.long_run(false).unwrap(), ModelKind::Turns),
            (lab.long_run(true).unwrap(), ModelKind::TurnsExact),
        ];
        let [accel, speed, _] = model_charts(lab.scenario(), &runs, long);
        let approach = approach_chart(&lab, &opts).unwrap();
        for chart in [&accel, &speed, &approach] {
            let hidden = chart.indistinct_pairs(HIDDEN_TOL);
            assert!(hidden.is_empty(), "{}: {hidden:?}", chart.name);
            // One legend entry per curve: no name twice.
            let mut names: Vec<&str> = chart.series.iter().map(|s| s.name.as_str()).collect();
            names.sort_unstable();
            names.dedup();
            assert_eq!(names.len(), chart.series.len(), "{}", chart.name);
        }
        // The check has teeth: drawn all alike, curves hide one another
        // (every model starts from rest near 2G/3).
        let mut alike = accel.clone();
        for s in &mut alike.series {
            s.style = Style::Line;
            s.marker = None;
        }
        assert!(!alike.indistinct_pairs(HIDDEN_TOL).is_empty());
    }
}
