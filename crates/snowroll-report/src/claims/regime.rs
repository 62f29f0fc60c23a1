//! The regime map of the turn model (issue 12): over slope α × snow depth b,
//! from rest, for [`MAP_TURNS`] turns, the log stalls in turn 0 below the
//! fn. 7 slope of `docs/turn-model.md`, hops above the slope of
//! `docs/contact-forces.md` §4.3 at which the normal force first reaches
//! zero within K turns, and rolls on between. The claim: the border the
//! simulation draws lies within one grid cell of both closed forms, in
//! every row of the map; and each border, bisected on the runs inside its
//! cell, lies within 1e-6° of the stall form (exact for eq. (73)) and
//! within 1e-3° of the hop form (first order in b/r_K).

use std::f64::consts::PI;

use super::circular::bisect;
use super::stall::{closed_form_tan, stalls_in_first_turn};
use super::{edited, holds_if, Edit, Finding, Lab};
use crate::plot::{ColorBy, PlotError, RegimeMap};
use crate::{ClaimId, Figure, ReportError};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::sweep::{Axis, AxisParam, Grid, Outcome, SweepRow, Values};
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// Turns of each run of the map. The hop angle of §4.3 expands the
/// late-turn speed u_k ≈ A k² + B k, which holds once k b ≫ r0: at 20 turns
/// and b/r0 = 0.025 the log, still far from that regime, hops only above
/// 66° against the form's 63.8°. At 200 turns K b/r0 ≥ 10 on the whole map
/// (the doc's table shows 0.06° agreement at K b/r0 = 2), and the 336 runs
/// still take a fraction of a second.
pub(crate) const MAP_TURNS: u64 = 200;

/// `regime-map-borders`: simulated border against the closed forms.
pub(super) const MAP_CELL: Criterion = Criterion {
    quantity: "|closed-form border − simulated border| in each row of the map, in grid cells",
    tolerance: Tolerance::Absolute {
        value: 1.0,
        unit: "grid cell",
    },
    reason: "the simulated border is only known to lie between two grid values (it is drawn at their midpoint, half a cell from either); the closed forms are first order in b/r, whose O((b/r)²) error (≤ 0.1° for the hop at K = 20, `docs/contact-forces.md` §4.3) is far below a cell",
};

/// `regime-map-borders`: each row's stall border, found by bisection on
/// the runs inside the map's cell, against the closed form.
pub(super) const MAP_STALL_BISECTED: Criterion = Criterion {
    quantity: "|stall slope by bisection on turns from rest − the fn. 7 closed form| in each row of the map",
    tolerance: Tolerance::Absolute {
        value: 1e-6,
        unit: "degree",
    },
    reason: "the closed form is the exact first-turn stall slope of eq. (73), max Q/P located to ~1e-12; the bisection runs to 1e-12° and the stall event is located to the integrator's tolerance (rtol 1e-10): a 1 % error in the lift of the snow moves the slope by ~0.01°",
};

/// `regime-map-borders`: each row's hop border, found by bisection.
pub(super) const MAP_HOP_BISECTED: Criterion = Criterion {
    quantity: "|hop slope within 200 turns by bisection on turns from rest − tan α_K of `docs/contact-forces.md` §4.3| in each row of the map",
    tolerance: Tolerance::Absolute {
        value: HOP_FORM_TOL_DEG,
        unit: "degree",
    },
    reason: HOP_FORM_REASON,
};

/// The hop form's tolerance, degrees (see [`HOP_FORM_REASON`]).
const HOP_FORM_TOL_DEG: f64 = 1e-3;
/// Why [`HOP_FORM_TOL_DEG`].
const HOP_FORM_REASON: &str = "tan α_K is first order in ε = b/r_(K−1), 4.6e-3 to 4.9e-3 on this map at K = 200: its O(ε²) remainder, ε² = 2.4e-5 rad = 1.4e-3°, bounds what it can miss (measured 2.7e-4° to 4.0e-4°, the form above the runs in every row); the bisection itself runs to 1e-12°";

/// The slope in `(lo, hi)`, degrees, at which the `turns` run from rest on
/// `s` changes from not `above` to `above`, by bisection to 1e-12°; NaN
/// unless `above` is false at `lo` and true at `hi`.
fn bisect_border(
    lab: &Lab,
    s: &Scenario,
    (lo, hi): (f64, f64),
    above: impl Fn(&Lab, &Scenario, f64) -> Result<bool, SimError>,
) -> Result<f64, SimError> {
    if !(lo.is_finite() && hi.is_finite()) || above(lab, s, lo)? || !above(lab, s, hi)? {
        return Ok(f64::NAN);
    }
    bisect(lo, hi, |deg| above(lab, s, deg))
}

/// Whether the `turns` run from rest on `s` at slope `deg` gets past its
/// first turn.
fn starts(lab: &Lab, s: &Scenario, deg: f64) -> Result<bool, SimError> {
    Ok(!stalls_in_first_turn(lab, ModelKind::Turns, s, deg, 1)?.0)
}

/// Whether the `turns` run from rest on `s` at slope `deg` hops within
/// [`MAP_TURNS`] turns.
fn hops(lab: &Lab, s: &Scenario, deg: f64) -> Result<bool, SimError> {
    let s = edited(
        s,
        Edit {
            alpha_deg: Some(deg),
            ..Edit::default()
        },
    )?;
    let traj = lab.run(
        ModelKind::Turns,
        &s,
        &SimOptions {
            t_end: 1e4,
            turns: Some(MAP_TURNS),
            sampling: Sampling::Ends,
            ..SimOptions::default()
        },
    )?;
    Ok(traj.stop.reason == StopReason::Hop)
}

/// Slopes of the map, degrees: 0.5° apart where the fn. 7 stall slopes lie
/// (0.5°–4° for these depths), 4° apart in the rolling region, 1° apart
/// from 58° to 80° around the hop slopes (63.4°–64.5°).
pub(crate) fn map_alphas() -> Vec<f64> {
    let stall = (1..=12).map(|k| 0.5 * f64::from(k));
    let rolling = (2..=14).map(|k| 4.0 * f64::from(k));
    let hop = (58..=80).map(f64::from);
    stall.chain(rolling).chain(hop).collect()
}

/// Snow depths of the map, m, for initial radius `r0`: b/r0 from 0.05 to
/// 0.2 (0.005 m to 0.02 m at the default r0 = 0.1 m). Both borders depend
/// on b/r0 only (ε = b/(π r0) for the stall, b/r_K for the hop), so the
/// map's slopes suit every r0. (At b/r0 = 0.025, K b/r0 = 5 only: the log
/// hops 1° above the form, 0.96 cells.)
pub(crate) fn map_depths(r0: f64) -> Vec<f64> {
    // r0/r0_default is exactly 1 at the default: its depths to the bit.
    let scale = r0 / ScenarioFile::default().r0;
    (2..=8).map(|k| 0.0025 * f64::from(k) * scale).collect()
}

/// The regime map's grid and its rows, one per grid point in grid order.
pub(crate) type MapRows = (Grid, Vec<SweepRow>);

/// The grid of the map (the `turns` model, α × b, the lab's other
/// parameters) and one row per point, run through the lab. Read it through
/// [`Lab::regime_map`], which runs it once.
pub(super) fn map_rows(lab: &Lab) -> Result<MapRows, SimError> {
    let base = ScenarioFile::from(*lab.scenario());
    let list = |param, values: Vec<f64>| Axis {
        param,
        values: Values::List(values),
    };
    let grid_err = |e: snowroll::sweep::GridError| {
        SimError::from(snowroll::error::ParamError::InvalidParameter {
            name: "regime map grid",
            value: f64::NAN,
            expected: match e {
                snowroll::sweep::GridError::TooLarge { .. } => "a smaller grid",
                _ => "a valid grid",
            },
        })
    };
    let grid = Grid::new(
        vec![ModelKind::Turns],
        vec![
            list(const { AxisParam::named("alpha_deg") }, map_alphas()),
            list(
                const { AxisParam::named("snow_depth") },
                map_depths(base.r0),
            ),
            list(const { AxisParam::named("r0") }, vec![base.r0]),
            list(const { AxisParam::named("g") }, vec![base.g]),
            list(const { AxisParam::named("v0") }, vec![0.0]),
            list(const { AxisParam::named("t_end") }, vec![1e4]),
        ],
    )
    .map_err(grid_err)?;
    let mut rows = Vec::with_capacity(grid.len() as usize);
    for i in 0..grid.len() {
        let mut point = grid.point(i)?;
        point.options.turns = Some(MAP_TURNS);
        let traj = lab.run(point.model, &point.scenario, &point.options);
        rows.push(SweepRow::new(
            &point,
            traj.as_ref().map_err(ToString::to_string),
        ));
    }
    Ok((grid, rows))
}

/// The simulated border of one row of the map: the midpoint between the
/// last slope with outcome `below` and the first with `above`, and that
/// cell's width; `None` unless the row is `below…below above…above`
/// around that point.
fn border(
    alphas: &[f64],
    outcomes: &[Outcome],
    is_above: impl Fn(Outcome) -> bool,
) -> Option<(f64, f64)> {
    let first = outcomes.iter().position(|&o| is_above(o))?;
    if first == 0 || !outcomes[first..].iter().all(|&o| is_above(o)) {
        return None;
    }
    let (a, b) = (alphas[first - 1], alphas[first]);
    Some((0.5 * (a + b), b - a))
}

/// The closed-form borders a map is judged against, degrees, as functions
/// of (b, r0): the first-turn stall slope and the hop slope within
/// [`MAP_TURNS`] turns.
pub(super) struct BorderForms {
    /// The stall slope, degrees.
    pub stall: fn(f64, f64) -> f64,
    /// The hop slope within [`MAP_TURNS`] turns, degrees.
    pub hop: fn(f64, f64) -> f64,
}

/// fn. 7's first-turn stall slope of `docs/turn-model.md`, typed in
/// [`closed_form_tan`]: `tan α* = max ε(θ − sin θ)/(θ + ε(θ²/2 − 1 + cos θ))`,
/// ε = b/(π r0); degrees.
fn stall_slope_deg(b: f64, r0: f64) -> f64 {
    closed_form_tan(b / (PI * r0)).atan().to_degrees()
}

/// The hop slope within K = [`MAP_TURNS`] turns of the `note` collision,
/// `docs/contact-forces.md` §4.3, typed here:
/// `tan α_K = (1 + ε c_C)/(½ − ε c_G)`, ε = b/r_(K−1), r_(K−1) = r0 + (K − 1) b,
/// c_C = 3/2 + 8/(13π), c_G = 1/π + 14/39 − 1; degrees.
fn hop_slope_deg(b: f64, r0: f64) -> f64 {
    let c_c = 1.5 + 8.0 / (13.0 * PI);
    let c_g = 1.0 / PI + 14.0 / 39.0 - 1.0;
    let eps = b / (r0 + (MAP_TURNS - 1) as f64 * b);
    ((1.0 + eps * c_c) / (0.5 - eps * c_g)).atan().to_degrees()
}

/// The closed forms of the claim, typed here (not the library's).
const TYPED_FORMS: BorderForms = BorderForms {
    stall: stall_slope_deg,
    hop: hop_slope_deg,
};

/// The regime map's borders against the closed forms.
pub(super) fn map_borders(lab: &Lab) -> Result<Finding, SimError> {
    borders_against(lab, &TYPED_FORMS)
}

/// The regime map's borders against the closed forms `forms`.
pub(super) fn borders_against(lab: &Lab, forms: &BorderForms) -> Result<Finding, SimError> {
    let (_, rows) = lab.regime_map()?;
    let alphas = map_alphas();
    let depths = map_depths(lab.scenario().initial_radius());
    let r0 = lab.scenario().initial_radius();
    let mut ok = true;
    let mut numbers = Vec::new();
    let mut worst = (0.0_f64, 0.0_f64);
    let mut worst_bisected = (0.0_f64, 0.0_f64);
    let mut lines = Vec::new();
    for (j, &b) in depths.iter().enumerate() {
        // Grid order: α is the slower axis, b the faster.
        let outcomes: Vec<Outcome> = (0..alphas.len())
            .map(|i| Outcome::of(&rows[i * depths.len() + j]))
            .collect();
        let (stall_closed, hop_closed) = ((forms.stall)(b, r0), (forms.hop)(b, r0));
        let stall = border(&alphas, &outcomes, |o| {
            !matches!(o, Outcome::Stalls { turn: 0 })
        });
        let hop = border(&alphas, &outcomes, |o| o == Outcome::Hops);
        let cells = |found: Option<(f64, f64)>, closed: f64| {
            found.map_or(f64::INFINITY, |(mid, width)| (closed - mid).abs() / width)
        };
        let (d_stall, d_hop) = (cells(stall, stall_closed), cells(hop, hop_closed));
        // Each border bisected inside its cell of the map.
        let row = edited(
            lab.scenario(),
            Edit {
                snow_depth: Some(b),
                v0: Some(0.0),
                ..Edit::default()
            },
        )?;
        let cell = |found: Option<(f64, f64)>| {
            found.map_or((f64::NAN, f64::NAN), |(mid, width)| {
                (mid - 0.5 * width, mid + 0.5 * width)
            })
        };
        let stall_bisected = bisect_border(lab, &row, cell(stall), starts)?;
        let hop_bisected = bisect_border(lab, &row, cell(hop), hops)?;
        let (e_stall, e_hop) = (
            MAP_STALL_BISECTED.deviation(stall_bisected, stall_closed),
            MAP_HOP_BISECTED.deviation(hop_bisected, hop_closed),
        );
        let bisected_ok = MAP_STALL_BISECTED.accepts_deviation(e_stall)
            && MAP_HOP_BISECTED.accepts_deviation(e_hop);
        worst_bisected = (worst_bisected.0.max(e_stall), worst_bisected.1.max(e_hop));
        numbers.extend([stall_bisected, hop_bisected]);
        // Between the two borders the log rolls on.
        let middle_ok = match (stall, hop) {
            (Some((s, _)), Some((h, _))) => alphas
                .iter()
                .zip(&outcomes)
                .filter(|(a, _)| **a > s && **a < h)
                .all(|(_, o)| *o == Outcome::RollsOn),
            _ => false,
        };
        let row_ok = MAP_CELL.accepts(d_stall, 0.0)
            && MAP_CELL.accepts(d_hop, 0.0)
            && middle_ok
            && bisected_ok;
        ok &= row_ok;
        worst = (worst.0.max(d_stall), worst.1.max(d_hop));
        numbers.extend([stall_closed, hop_closed]);
        lines.push(format!(
            "b = {b} m: stall {stall_closed:.9}° (bisected {stall_bisected:.9}°, map cell {}), hop {hop_closed:.6}° (bisected {hop_bisected:.6}°, map cell {})",
            stall.map_or("none".to_string(), |(m, _)| format!("{m:.3}°")),
            hop.map_or("none".to_string(), |(m, _)| format!("{m:.3}°")),
        ));
    }
    Ok(Finding {
        headline: Some(format!(
            "The closed-form stall and hop slopes border the simulated regime map: bisected, its borders lie within {}° and {}° of them",
            crate::notation::number(worst_bisected.0, 2),
            crate::notation::number(worst_bisected.1, 2)
        )),
        measured: format!(
            "turns from rest, {MAP_TURNS} turns, {} slopes × {} depths; the borders bisected in each row are at most {:.1e}° (stall) and {:.1e}° (hop) from the closed forms; the map's cells at most {:.2} cells (stall), {:.2} cells (hop); {}",
            alphas.len(),
            depths.len(),
            worst_bisected.0,
            worst_bisected.1,
            worst.0,
            worst.1,
            lines.join("; ")
        ),
        verdict: holds_if(ok, &numbers),
        evidence: format!(
            "in every row the runs stall in turn 0 below one slope, hop above another and roll on between; both simulated borders are within one grid cell of the closed forms, and bisected inside that cell the stall border is within {:e}° of the fn. 7 first-turn stall slope (`docs/turn-model.md`) and the hop border within {:e}° of tan α_K = (1 + ε c_C)/(½ − ε c_G), ε = b/r_(K−1) (`docs/contact-forces.md` §4.3): {}",
            MAP_STALL_BISECTED.value(),
            MAP_HOP_BISECTED.value(),
            if ok { "all rows pass" } else { "NOT every row passes" }
        ),
    })
}

/// The regime map of the turn model over slope × snow depth (the runs of
/// claim `regime-map-borders`), with the closed-form borders, for `paper`.
///
/// # Errors
/// [`ReportError`] when a run fails or the map cannot be made.
pub(crate) fn regime_figure(lab: &Lab) -> Result<Figure, ReportError> {
    let (grid, rows) = lab.regime_map()?;
    let map = RegimeMap::from_rows(
        grid,
        rows,
        const { AxisParam::named("alpha_deg") },
        const { AxisParam::named("snow_depth") },
        ColorBy::Outcome,
    )
    .map_err(|e| PlotError::Backend {
        chart: "regime-map-turns".to_string(),
        reason: e.to_string(),
    })?;
    let mut chart = map.to_chart("regime-map-turns");
    chart.title = format!("Regimes of turns from rest, {MAP_TURNS} turns");
    let r0 = lab.scenario().initial_radius();
    Ok(Figure::new(
        chart,
        &format!(
            "What the turn-by-turn log (eq. (73)) does from rest within {MAP_TURNS} turns, one marker per run: it stalls in its first turn on gentle slopes (fn. 7), hops on steep ones (fn. 10) and rolls on between. The lines are the closed forms: the first-turn stall slope and the hop slope within the turns reached, tan α_K = (1 + ε c_C)/(½ − ε c_G) (the project's notes on contact forces §4.3), with its late-turn limit tan α = 2. Every simulated border lies within one grid cell of its line (claim {claim}).",
            claim = ClaimId::RegimeMapBorders
        ),
    )
    .supports(&[ClaimId::RegimeMapBorders, ClaimId::Fn10HopThreshold, ClaimId::Fn7StallInFirstTurn])
    .param("r0", r0)
    .param("v0", 0.0)
    .param("turns", MAP_TURNS))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Verdict;
    use snowroll::models::CollisionModel;
    use snowroll::scenario::Scenario;
    use snowroll::sweep::hop_slope_within;

    /// The typed forms are the library's (which draws the figure's lines):
    /// rounding only.
    const SAME_FORM_TOL_DEG: f64 = 1e-9;

    #[test]
    fn the_typed_borders_are_the_librarys() {
        let r0 = Scenario::default().initial_radius();
        for b in map_depths(r0) {
            let stall = ModelKind::Turns
                .stall_threshold(b, r0)
                .map(|t| t.slope.to_degrees())
                .unwrap();
            let hop = hop_slope_within(b, r0, MAP_TURNS, CollisionModel::Note)
                .unwrap()
                .to_degrees();
            assert!((stall_slope_deg(b, r0) - stall).abs() < SAME_FORM_TOL_DEG);
            assert!((hop_slope_deg(b, r0) - hop).abs() < SAME_FORM_TOL_DEG);
        }
    }

    /// A wrong claim: the stall slope with ε = b/r0 (π times too large).
    fn wrong_stall(b: f64, r0: f64) -> f64 {
        closed_form_tan(b / r0).atan().to_degrees()
    }

    /// A wrong claim: the hop slope of the circular models, tan α = 2,
    /// 3° too low (the first-turn hop of a log started fast).
    fn wrong_hop(_: f64, _: f64) -> f64 {
        2f64.atan().to_degrees() - 3.0
    }

    #[test]
    fn regression_21_regime_map_borders_notice_wrong_closed_forms() {
        let lab = Lab::new(Scenario::default(), 10);
        assert_eq!(map_borders(&lab).unwrap().verdict, Verdict::Holds);
        for forms in [
            BorderForms {
                stall: wrong_stall,
                hop: hop_slope_deg,
            },
            BorderForms {
                stall: stall_slope_deg,
                hop: wrong_hop,
            },
        ] {
            assert_eq!(
                borders_against(&lab, &forms).unwrap().verdict,
                Verdict::Refuted
            );
        }
    }
}
