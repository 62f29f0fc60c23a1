//! The contact section of `snowroll paper` (issue 10, `docs/contact-forces.md`):
//! the smallest μ that keeps each model rolling (§5), the smallest normal
//! force per turn for several slopes against the late-turn limit
//! cos α − ½ sin α (§4.2), and what each collision variant of §6 does to the
//! long-run means and to the hop (§6.4). Every number is computed here from
//! the library's runs; the closed forms stand beside them.

use std::f64::consts::PI;

use super::claims::{mu_min_rows, Edit};
use super::{ClaimId, Figure, Lab, ReportError, Table};
use crate::plot::{Axis, Chart, Series, Style};
use snowroll::models::{run_turns, CollisionModel, ModelKind};
use snowroll::scenario::Scenario;
use snowroll::trajectory::{OnHop, Sampling, SimOptions, StopReason};

/// Turns of the runs of the per-turn figure and of the collision table
/// (the runs of claim `fn10-hop-threshold` have as many).
const CONTACT_TURNS: u64 = 2000;

/// Points kept per curve of the per-turn figure (spread evenly in log k).
const CURVE_POINTS: usize = 300;

/// Options of a turn run of `turns` turns with `collision` and `on_hop`.
fn turn_opts(turns: u64, collision: CollisionModel, on_hop: OnHop) -> SimOptions {
    SimOptions {
        t_end: 1e9,
        turns: Some(turns),
        sampling: Sampling::Ends,
        collision,
        on_hop,
        ..SimOptions::default()
    }
}

/// `s` on slope `alpha_deg`, from rest.
fn on_slope(s: &Scenario, alpha_deg: f64) -> Result<Scenario, ReportError> {
    Ok(super::claims::edited(
        s,
        Edit {
            alpha_deg: Some(alpha_deg),
            v0: Some(0.0),
            ..Edit::default()
        },
    )?)
}

/// A number for a table cell, or "—" when there is none.
fn cell(x: Option<f64>, digits: usize) -> String {
    x.map_or_else(|| "—".to_string(), |v| format!("{v:.digits$}"))
}

/// The table of the smallest μ per model over the default run (§5).
///
/// # Errors
/// [`ReportError`] when a run fails.
pub(super) fn mu_min_table(lab: &Lab) -> Result<Table, ReportError> {
    let rows = mu_min_rows(lab)?;
    let s = lab.scenario();
    Ok(Table {
        title: "The smallest μ that keeps each model rolling".to_string(),
        caption: format!(
            "μ_min = the largest |F|/N over the default run (α = {:.2}°, from v0 = {} m/s, 100 s; \
             the turn models: the per-turn maxima of the turns completed in 100 s, from the energy integral of each turn). \
             With --mu below it the run stops with slip. Closed forms of docs/contact-forces.md §5 beside them; \
             claim {claim} checks the circular ODE models against them. \
             For the turn models the closed form is the late-turn limit; the early turns need more (§5.3).",
            s.slope_angle().to_degrees(),
            s.initial_speed(),
            claim = ClaimId::SlipMuMin
        ),
        header: [
            "model",
            "equation",
            "μ_min (program)",
            "where",
            "closed form",
            "formula",
        ]
        .map(String::from)
        .to_vec(),
        rows: rows
            .iter()
            .map(|r| {
                vec![
                    r.kind.id().to_string(),
                    r.kind.equation().to_string(),
                    cell(r.mu_min, 6),
                    r.at.clone(),
                    cell(r.closed_form, 6),
                    r.formula.to_string(),
                ]
            })
            .collect(),
    })
}

/// The slopes of the per-turn figure, degrees: both sides of α* = arctan 2.
fn figure_slopes() -> [f64; 6] {
    let star = 2.0_f64.atan().to_degrees();
    [30.0, 50.0, 60.0, star - 1.0, star + 1.0, 70.0]
}

/// The smallest N/(M g) of each turn of `turns` (eq. (73)) for several
/// slopes, from rest, against the late-turn limit cos α − ½ sin α (§4.2).
/// The runs go on past N = 0 (`--on-hop continue`), so that the curves of
/// the steep slopes show where and how far they cross zero.
///
/// # Errors
/// [`ReportError`] when a run fails.
pub(super) fn min_normal_figure(lab: &Lab) -> Result<Figure, ReportError> {
    let mut chart = Chart::new(
        "contact-min-normal-per-turn",
        "Smallest normal force of each turn, N/(M g)",
        Axis::log("turn k + 1", "1").column("turn_plus_one"),
        Axis::linear("min N/(M g) in the turn", "1").column("min_normal_over_mg"),
    );
    let opts = turn_opts(CONTACT_TURNS, CollisionModel::Note, OnHop::Continue);
    let mut first_negative = Vec::new();
    for alpha_deg in figure_slopes() {
        let s = on_slope(lab.scenario(), alpha_deg)?;
        let table = run_turns(ModelKind::Turns, &s, &opts)?;
        let keep = super::log_spread(table.rows.len() as u64, CURVE_POINTS);
        let points: Vec<(f64, f64)> = keep
            .iter()
            .map(|&k| {
                let r = &table.rows[k as usize];
                (r.turn as f64 + 1.0, r.min_normal_over_mg)
            })
            .collect();
        let (sa, ca) = s.slope_angle().sin_cos();
        let limit = ca - 0.5 * sa;
        let ends = [1.0, table.rows.len().max(1) as f64];
        let curve = chart.series.len();
        chart = chart
            .with_series(Series::new(&format!("α = {alpha_deg:.3}°"), points))
            .with_series(
                Series::new(
                    &format!(
                        "α = {alpha_deg:.3}°: cos α − ½ sin α = {}",
                        crate::notation::fixed(limit, 4)
                    ),
                    ends.iter().map(|&k| (k, limit)).collect(),
                )
                .style(Style::Dashed)
                .in_colour_of(curve),
            );
        if let Some(r) = table.rows.iter().find(|r| r.min_normal_over_mg <= 0.0) {
            first_negative.push(format!("{alpha_deg:.3}°: turn {}", r.turn));
        }
    }
    let star = 2.0_f64.atan().to_degrees();
    Ok(Figure::new(
        chart,
        &format!(
            "The smallest N/(M g) within each turn of the turn model (eq. (73), collisions by eq. (89)), from rest, {CONTACT_TURNS} turns, on six slopes; dashed: the late-turn limit cos α − ½ sin α of the project's notes on contact forces §4.2 for each. \
             It falls towards the limit turn after turn; the limit is negative past α* = arctan 2 = {star:.3}°, so there the log hops in some turn. \
             The runs go on past N = 0 (--on-hop continue) to show the whole curve; N first reaches 0 in {}.",
            if first_negative.is_empty() {
                "no turn".to_string()
            } else {
                first_negative.join(", ")
            }
        ),
    )
    .param("model", ModelKind::Turns.id())
    .param("snow_depth", lab.scenario().snow_depth())
    .param("r0", lab.scenario().initial_radius())
    .param("alpha_deg", "30, 50, 60, α* − 1, α* + 1, 70")
    .param("collision", CollisionModel::Note.id())
    .param("on_hop", OnHop::Continue.id())
    .param("turns", CONTACT_TURNS)
    .param("v0", 0)
    .supports(&[ClaimId::Fn10HopThreshold]))
}

/// The kebab-case id of a stop reason (as in the outputs).
fn reason_id(reason: StopReason) -> String {
    serde_json::to_value(reason)
        .ok()
        .and_then(|v| v.as_str().map(String::from))
        .unwrap_or_else(|| reason.describe().to_string())
}

/// How a hop run ended, for a table cell.
fn hop_outcome(stop: &snowroll::trajectory::Stop, turns: u64) -> String {
    match (stop.reason, stop.turn) {
        (StopReason::Turns, _) => format!("no hop in {turns} turns"),
        (reason, Some(k)) => format!(
            "{} in turn {} at θ = {:.3} rad",
            reason_id(reason),
            k.turn,
            k.theta_rad
        ),
        (reason, None) => reason_id(reason),
    }
}

/// What each collision variant (`--collision note|charged|pivot`, §6) does to
/// the long-run means and to the hop, computed by the program, with the
/// closed forms of §4.2 and §6.4 beside them.
///
/// # Errors
/// [`ReportError`] when a run fails.
pub(super) fn collision_table(lab: &Lab) -> Result<Table, ReportError> {
    let s = lab.scenario();
    let (gs, b) = (s.g_along(), s.snow_depth());
    let k = CONTACT_TURNS as f64;
    // §4.2: v² at the start of turn K ≈ A K² + B K, A = πGb/2.
    let a_coef = PI * gs * b / 2.0;
    let star = 2.0_f64.atan().to_degrees();
    let from_rest = on_slope(s, s.slope_angle().to_degrees())?;
    let above = on_slope(s, star + 1.0)?;
    let below = on_slope(s, star - 1.0)?;
    let mut rows = Vec::new();
    for collision in CollisionModel::ALL {
        // The means: the hop ignored (the pivot log leaves the edge at the first step, §6.3).
        let long = run_turns(
            ModelKind::Turns,
            &from_rest,
            &turn_opts(CONTACT_TURNS, collision, OnHop::Continue),
        )?;
        let v2 = long
            .rows
            .last()
            .map_or(f64::NAN, |r| r.v_after_m_s * r.v_after_m_s);
        let ratio = v2 / (a_coef * k * k);
        let closed = closed_form_ratio(collision, s, a_coef, k);
        let last = long.summary.overall();
        // With pivot the impact happens inside the turn, at θ_c (§6.3), so
        // a "mean within the turn" would include it: not the §6.4 quantity.
        let mean_turn = last
            .map(|c| c.window_mean_a_turn_over_g)
            .filter(|_| collision != CollisionModel::Pivot);
        let mean_with = last.map(|c| c.window_mean_a_with_collision_over_g);
        let hop = |scenario: &Scenario| -> Result<String, ReportError> {
            let t = run_turns(
                ModelKind::Turns,
                scenario,
                &turn_opts(CONTACT_TURNS, collision, OnHop::Stop),
            )?;
            Ok(hop_outcome(&t.stop, CONTACT_TURNS))
        };
        rows.push(vec![
            collision.id().to_string(),
            format!("{ratio:.7}"),
            cell(closed, 7),
            cell(mean_turn, 5),
            cell(mean_with, 5),
            hop(&from_rest)?,
            hop(&below)?,
            hop(&above)?,
            hop_condition(collision).to_string(),
        ]);
    }
    Ok(collision_table_of(s, star, rows))
}

/// §4.2: the closed form 1 + B/(A K) of v²(K)/(A K²) for `collision` after
/// K = `k` turns, with A = `a_coef` = πGb/2; `None` for pivot, which has none.
fn closed_form_ratio(collision: CollisionModel, s: &Scenario, a_coef: f64, k: f64) -> Option<f64> {
    let (b, r0) = (s.snow_depth(), s.initial_radius());
    let (gs, gc) = (s.g_along(), s.g_normal());
    match collision {
        CollisionModel::Note => {
            Some(1.0 + (PI * gs * r0 - (14.0 * PI * gs + 24.0 * gc) * b / 39.0) / (a_coef * k))
        }
        CollisionModel::Charged => {
            Some(1.0 + (PI * gs * r0 - (14.0 * PI * gs + 36.0 * gc) * b / 39.0) / (a_coef * k))
        }
        CollisionModel::Pivot => None,
    }
}

/// The closed-form hop condition of `collision` (§4.3, §6.3), for the table.
fn hop_condition(collision: CollisionModel) -> &'static str {
    match collision {
        CollisionModel::Note => "in a turn, late turns: tan α > 2 (α* = 63.435°); within K turns tan α > tan α_K (§4.3)",
        CollisionModel::Charged => "as note (c_C = 3/2 + 12/(13π) in α_K, §4.3)",
        CollisionModel::Pivot => "at the edge of the new layer once v₊² > g r cos α (§6.3): on every slope after a few turns",
    }
}

/// The collision table around its `rows`: title, the caption with the
/// scenario's numbers, and the header; `star` is α* = arctan 2, deg.
fn collision_table_of(s: &Scenario, star: f64, rows: Vec<Vec<String>>) -> Table {
    let (g, b, r0) = (s.gravity(), s.snow_depth(), s.initial_radius());
    Table {
        title: "How the step of each new layer changes the long run and the hop".to_string(),
        caption: format!(
            "The turn model (eq. (73)) from rest with each --collision variant (the project's notes on contact forces §6): note is eq. (89); charged also pays the potential energy m g b cos α of the jump; pivot lets the log pivot over the edge of the new layer. \
             Long-run columns: {CONTACT_TURNS} turns at α = {:.2}° with the hop ignored (--on-hop continue); v²(K) is the speed squared at the start of turn K = {CONTACT_TURNS} over its leading term πGbK²/2, beside 1 + B/(A K) of §4.2 (A = πGb/2, B = πG r0 − (14πG + 24C) b/39 for note, 36C for charged); \
             the means of a/(g sin α) are over the last decade of turns, against the limits 1/3 (within turns) and 1/4 (with the collisions), the same for every variant to leading order (§6.4); \
             with pivot the impact falls inside the turn (at θ_c, §6.3), so only the mean with the collisions compares. \
             Hop columns: the same runs stopping at N = 0 (--on-hop stop) at α, at α* − 1° and at α* + 1° (α* = arctan 2 = {star:.3}°). g = {g} m/s², b = {b} m, r0 = {r0} m.",
            s.slope_angle().to_degrees(),
        ),
        header: vec![
            "collision".to_string(),
            "v²(K)/(πGbK²/2)".to_string(),
            "closed form 1 + B/(A K)".to_string(),
            "mean a/G in turns (→ 1/3)".to_string(),
            "mean a/G with collisions (→ 1/4)".to_string(),
            format!("hop at α = {:.2}°", s.slope_angle().to_degrees()),
            format!("hop at α* − 1° = {:.3}°", star - 1.0),
            format!("hop at α* + 1° = {:.3}°", star + 1.0),
            "hop condition (closed form)".to_string(),
        ],
        rows,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// §4.2: the last turn's minimum of N/(M g) approaches cos α − ½ sin α
    /// to O(b/r_K) ≈ 5e-4 (§4.3; tolerance 1e-3, as claim
    /// fn10-hop-threshold); the curve (every 2000 turns, the limit as the
    /// dashed line beside it) crosses 0 only above α* = arctan 2.
    #[test]
    fn the_figure_approaches_the_late_turn_limit_and_crosses_zero_only_past_arctan_2() {
        let figure = min_normal_figure(&Lab::default()).unwrap();
        let series = &figure.chart.series;
        assert_eq!(series.len(), 2 * figure_slopes().len());
        for (pair, alpha_deg) in series.chunks(2).zip(figure_slopes()) {
            let (curve, limit) = (&pair[0], &pair[1]);
            let (sa, ca) = alpha_deg.to_radians().sin_cos();
            let want = ca - 0.5 * sa;
            // The same closed form, up to the rounding of the angle: 1e-14.
            assert!(limit.points.iter().all(|p| (p.1 - want).abs() < 1e-14));
            let last = curve.points.last().unwrap();
            assert!((last.0 - CONTACT_TURNS as f64).abs() < 0.5, "{last:?}");
            assert!(
                (last.1 - want).abs() < 1e-3,
                "{alpha_deg}: {} vs {want}",
                last.1
            );
            let hops = curve.points.iter().any(|p| p.1 <= 0.0);
            assert_eq!(hops, alpha_deg.to_radians().tan() > 2.0, "{alpha_deg}");
        }
    }

    /// The collision table against §4.2 and §6.4: v²(K) over πGbK²/2 within
    /// 1e-4 of 1 + B/(AK) for note and charged (the rest is O(K⁻²) ≈ 2e-5 at
    /// K = 2000, doc §4.2); the last-decade means within 2e-3 of 1/3 and 1/4
    /// (O(1/K) corrections over turns 200…2000, ~1e-3); note and charged hop
    /// only above α*, pivot at its first step on the default slope (§6.3).
    #[test]
    fn the_collision_table_matches_the_closed_forms_of_section_6_4() {
        let table = collision_table(&Lab::default()).unwrap();
        assert_eq!(table.rows.len(), 3);
        let num = |s: &str| s.parse::<f64>().unwrap();
        for row in &table.rows {
            assert!((num(&row[4]) - 0.25).abs() < 2e-3, "{row:?}");
            if row[0] != "pivot" {
                assert!((num(&row[3]) - 1.0 / 3.0).abs() < 2e-3, "{row:?}");
                assert!((num(&row[1]) - num(&row[2])).abs() < 1e-4, "{row:?}");
                assert!(
                    row[5].starts_with("no hop") && row[6].starts_with("no hop"),
                    "{row:?}"
                );
                assert!(row[7].starts_with("hop in turn"), "{row:?}");
            } else {
                // §6.4: pivot's v² differs from charged's at O(K^{1/2})/K² only.
                let charged = num(&table.rows[1][1]);
                assert!((num(&row[1]) - charged).abs() < 1e-4, "{row:?}");
                assert_eq!(row[3], "—");
                assert!(row[5].starts_with("hop in turn 0"), "{row:?}");
            }
        }
    }

    /// §5: every model has a row; the lift models need the most friction
    /// at rest (§5.2); the turn models need more than the late-turn limit
    /// in their early turns (§5.3), which is below tan α/(3 − 3 tan²α/4)
    /// only for tan α < 2.
    #[test]
    fn the_mu_table_has_every_model_and_the_orderings_of_section_5() {
        let lab = Lab::default();
        let table = mu_min_table(&lab).unwrap();
        assert_eq!(table.rows.len(), ModelKind::ALL.len());
        let num = |s: &str| s.parse::<f64>().unwrap();
        for row in &table.rows {
            let kind: ModelKind = row[0].parse().unwrap();
            match kind {
                ModelKind::Energy | ModelKind::EnergyThin | ModelKind::QuasiCircularLift => {
                    assert_eq!(row[3], "t = 0.000 s", "{row:?}");
                }
                ModelKind::Turns | ModelKind::TurnsExact => {
                    assert!(num(&row[2]) > num(&row[4]), "{row:?}");
                }
                _ => {}
            }
        }
    }

    #[test]
    fn log_spread_keeps_the_ends_in_order() {
        let k = super::super::log_spread(2000, 300);
        assert_eq!(k.first(), Some(&0));
        assert_eq!(k.last(), Some(&1999));
        assert!(k.windows(2).all(|w| w[0] < w[1]));
    }
}
