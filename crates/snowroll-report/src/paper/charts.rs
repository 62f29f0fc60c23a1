//! The charts of the report's model figures, before captions: every model
//! against time, the approach to the terminal accelerations, the turn
//! models' first turns, their long-run means and their energy ledger.

use super::looks::{circular_models, group_label, label, look, same_equation_groups, styled};
use super::{log_times, run, APPROACH_FLOOR, N_TIMES, TURNS_SHOWN, T_END, X_FAR};
use crate::notation;
use crate::plot::{Axis, Chart, Marker, Series, Style};
use crate::{Lab, LedgerPoint, ReportError, TurnDigest};
use snowroll::models::ModelKind;
use snowroll::scenario::Scenario;
use snowroll::trajectory::{Sampling, SimOptions, Trajectory};

/// Mid-turn time and in-turn mean acceleration of each turn up to `t_max`.
fn turn_means(table: &TurnDigest, t_max: f64, g: f64) -> Vec<(f64, f64)> {
    table
        .head
        .iter()
        .take_while(|r| r.t_end_s <= t_max)
        .map(|r| (0.5 * (r.t_start_s + r.t_end_s), r.mean_a_turn_m_s2 / g))
        .collect()
}

/// The runs of every circular model on the logarithmic time grid, grouped by
/// equation, with the largest disagreement inside each group.
pub(super) struct CircularRuns {
    /// One trajectory per group (its first model's).
    pub(super) drawn: Vec<(Vec<ModelKind>, Trajectory)>,
    /// For groups of more than one model: the group and the largest
    /// |Δa|/(g sin α) between its runs at the grid's times.
    pub(super) agreement: Vec<(Vec<ModelKind>, f64)>,
}

impl CircularRuns {
    pub(super) fn new(lab: &Lab, opts: &SimOptions) -> Result<Self, ReportError> {
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
    pub(super) fn caption(&self) -> String {
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

/// Acceleration, speed and radius of every model against time.
pub(super) fn model_charts(
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
    );
    let mut speed = Chart::new(
        "speed-all-models",
        "Speed of every model",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("speed v", "m/s").column("v_m_s"),
    );
    let mut radius = Chart::new(
        "radius-all-models",
        "Radius of the log",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("radius r", "m").column("r_m"),
    );
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
pub(super) fn approach_chart(lab: &Lab, opts: &SimOptions) -> Result<Chart, ReportError> {
    let g = lab.scenario().g_along();
    let mut approach = Chart::new(
        "approach-to-terminal",
        "Approach to the terminal acceleration",
        Axis::log("distance x", "m").column("x_m"),
        Axis::log("|a − a∞| / (g sin α)", "1").column("deviation_over_g_sin_alpha"),
    );
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
pub(super) fn in_turn_chart(lab: &Lab, opts: &SimOptions) -> Result<Chart, ReportError> {
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
    );
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let traj = run(kind, lab, &first_turns)?;
        let series = Series::from_samples(&label(kind), &traj.samples, |p| p.t_s, |p| p.a_m_s2 / g);
        chart = chart.with_series(styled(series, kind));
    }
    Ok(chart)
}

/// The long-run means of the turn model against the number of turns.
pub(super) fn means_chart(paper: &TurnDigest) -> Chart {
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
pub(super) fn energy_ledger_chart(paper: &TurnDigest) -> Chart {
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

/// Every chart of the report before captions.
pub(super) struct Charts {
    pub(super) accel: Chart,
    pub(super) speed: Chart,
    pub(super) radius: Chart,
    pub(super) approach: Chart,
    pub(super) in_turn: Chart,
    pub(super) means: Chart,
    pub(super) ledger: Chart,
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
