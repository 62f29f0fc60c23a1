//! The figure of one run or of several models' runs of one scenario
//! (`snowroll simulate --plot`, `snowroll turns --plot`, Python's
//! `result.plot()` reads the same columns): panels of [`Chart`]s stacked
//! into one image by [`render_panels_svg`](crate::plot::render_panels_svg),
//! one curve per model in each panel, the legend beside the plot as in the
//! report. The panels only read samples and rows; they never run anything.
//!
//! A trajectory ([`run_panels`]): a/(g sin α), v and x against t; the normal
//! force N and the friction the rolling needs, |F|/N, where the run computed
//! them; and, for each model whose run recorded the energy ledger, its terms
//! as shares of the potential energy released. A turn table
//! ([`turn_panels`]): per turn, the mean acceleration in the turn and with
//! its collision, and its least and greatest acceleration, over g sin α; the
//! speed at the start of each turn; the least N/(M g) of each turn.

use snowroll::trajectory::{LedgerRow, Sample};
use snowroll::{ModelKind, TurnRow};

use crate::loss_figures::{ledger_series, SUM_NAME};
use crate::plot::{Axis, Chart, Series, Style};

/// One model's run: its samples and, when it recorded one, its ledger (one
/// row per sample).
#[derive(Debug, Clone, Copy)]
pub struct RunCurves<'a> {
    /// The model.
    pub model: ModelKind,
    /// The samples, in time order.
    pub samples: &'a [Sample],
    /// The ledger of each sample; empty when the run recorded none.
    pub ledger: &'a [LedgerRow],
}

/// One model's turn table.
#[derive(Debug, Clone, Copy)]
pub struct TurnCurves<'a> {
    /// The turn model.
    pub model: ModelKind,
    /// One row per completed turn.
    pub rows: &'a [TurnRow],
}

/// The time axis of a run's panels.
fn time_axis() -> Axis {
    Axis::linear("time t", "s").column("t_s")
}

/// A panel with one series per run, `y(sample)` against t, keeping the
/// samples where `y` gives a value.
fn per_model(
    name: &str,
    title: &str,
    y_axis: Axis,
    runs: &[RunCurves<'_>],
    y: impl Fn(&Sample) -> Option<f64>,
) -> Chart {
    let mut chart = Chart::new(name, title, time_axis(), y_axis);
    for run in runs {
        let points = run
            .samples
            .iter()
            .filter_map(|s| y(s).map(|v| (s.t_s, v)))
            .collect();
        chart = chart.with_series(Series::new(run.model.id(), points));
    }
    chart
}

/// The panels of the runs `runs` of one scenario whose slope gives
/// `g_along` = g sin α (m/s²): see the module's documentation. N and |F|/N
/// appear when some sample of some run has a finite value; a ledger panel
/// for each run that recorded a ledger.
pub fn run_panels(runs: &[RunCurves<'_>], g_along: f64) -> Vec<Chart> {
    let mut panels = vec![
        per_model(
            "run-acceleration",
            "Acceleration over g sin α",
            Axis::linear("a/(g sin α)", "1").column("a_over_g_sin_alpha"),
            runs,
            |s| Some(s.a_m_s2 / g_along),
        ),
        per_model(
            "run-speed",
            "Speed down the slope",
            Axis::linear("speed v", "m/s").column("v_m_s"),
            runs,
            |s| Some(s.v_m_s),
        ),
        per_model(
            "run-distance",
            "Distance rolled",
            Axis::linear("distance x", "m").column("x_m"),
            runs,
            |s| Some(s.x_m),
        ),
    ];
    let any = |f: &dyn Fn(&Sample) -> bool| runs.iter().any(|r| r.samples.iter().any(f));
    if any(&|s| s.normal_n.is_finite()) {
        panels.push(per_model(
            "run-normal-force",
            "Normal force of the slope",
            Axis::linear("normal force N", "N").column("normal_n"),
            runs,
            |s| s.normal_n.is_finite().then_some(s.normal_n),
        ));
    }
    if any(&|s| s.friction_ratio.is_some_and(f64::is_finite)) {
        panels.push(per_model(
            "run-friction-ratio",
            "Friction that rolling without slipping needs",
            Axis::linear("|F|/N", "1").column("friction_ratio"),
            runs,
            |s| s.friction_ratio.filter(|r| r.is_finite()),
        ));
    }
    for run in runs.iter().filter(|r| !r.ledger.is_empty()) {
        panels.push(ledger_panel(run));
    }
    panels
}

/// The ledger of `run` as shares of the released energy against time, the
/// terms of the report's ledger figure and their sum; samples before any
/// energy was released are left out (a share of nothing).
fn ledger_panel(run: &RunCurves<'_>) -> Chart {
    let rows: Vec<(f64, &LedgerRow)> = run
        .samples
        .iter()
        .zip(run.ledger)
        .filter(|(_, l)| l.released_j > 0.0)
        .map(|(s, l)| (s.t_s, l))
        .collect();
    let mut chart = Chart::new(
        "run-ledger-shares",
        &format!("Where the released energy goes: {}", run.model.equation()),
        time_axis(),
        Axis::linear("share of the potential energy released", "1").column("share"),
    );
    let collisions = rows
        .iter()
        .any(|(_, l)| l.collision_j != 0.0 || l.created_j != 0.0);
    for series in ledger_series(&rows, collisions) {
        chart = chart.with_series(series);
    }
    debug_assert!(chart.series.iter().any(|s| s.name == SUM_NAME));
    chart
}

/// A per-turn acceleration of a turn row, m/s².
type OfRow = fn(&TurnRow) -> f64;

/// How each per-turn quantity of the first panel of [`turn_panels`] is
/// drawn: name, style, the acceleration of a row.
const TURN_ACCELERATIONS: [(&str, Style, OfRow); 4] = [
    ("mean in the turn", Style::Line, |r| r.mean_a_turn_m_s2),
    ("mean with its collision", Style::Dashed, |r| {
        r.mean_a_with_collision_m_s2
    }),
    ("least in the turn", Style::Dotted, |r| r.min_a_m_s2),
    ("greatest in the turn", Style::LongDashed, |r| r.max_a_m_s2),
];

/// The panels of the turn tables `runs` of one scenario whose slope gives
/// `g_along` = g sin α (m/s²): the per-turn means and extremes of the
/// acceleration over g sin α (one colour per model, one dash per quantity),
/// the speed at the start of each turn, and each turn's least N/(M g).
pub fn turn_panels(runs: &[TurnCurves<'_>], g_along: f64) -> Vec<Chart> {
    let turn_axis = || Axis::linear("turn k", "1").column("turn");
    let mut means = Chart::new(
        "turns-acceleration-per-turn",
        "Acceleration per turn, over g sin α",
        turn_axis(),
        Axis::linear("a/(g sin α)", "1").column("a_over_g_sin_alpha"),
    );
    for run in runs {
        let first = means.series.len();
        for (k, (what, style, of)) in TURN_ACCELERATIONS.iter().enumerate() {
            let points = run
                .rows
                .iter()
                .map(|r| (r.turn as f64, of(r) / g_along))
                .collect();
            let mut s = Series::new(&format!("{}: {what}", run.model.id()), points).style(*style);
            if k > 0 {
                s = s.in_colour_of(first);
            }
            means = means.with_series(s);
        }
    }
    let per_turn = |name: &str, title: &str, y_axis: Axis, of: fn(&TurnRow) -> f64| {
        let mut chart = Chart::new(name, title, turn_axis(), y_axis);
        for run in runs {
            let points = run.rows.iter().map(|r| (r.turn as f64, of(r))).collect();
            chart = chart.with_series(Series::new(run.model.id(), points));
        }
        chart
    };
    vec![
        means,
        per_turn(
            "turns-speed-per-turn",
            "Speed at the start of each turn",
            Axis::linear("speed v at the turn's start", "m/s").column("v_start_m_s"),
            |r| r.v_start_m_s,
        ),
        per_turn(
            "turns-least-normal-per-turn",
            "Least normal force of each turn",
            Axis::linear("least N/(M g) in the turn", "1").column("min_normal_over_mg"),
            |r| r.min_normal_over_mg,
        ),
    ]
}
