//! Regimes of a sweep: what each row's log did ([`Outcome`]) and where the
//! closed forms put the borders between regimes ([`boundaries`]), in the
//! plane of two swept parameters.
//!
//! The borders drawn are the ones the program derives without simulating:
//!
//! - **stall** (fn. 7): below [`ModelKind::stall_threshold`] a circular
//!   model with lift does not start (`tan α* = 3(λ₁ b r0 + λ₂ b²/3)/(2π r0²)`,
//!   [`Coefficients::stall_slope`](crate::models::Coefficients::stall_slope))
//!   and a turn model stalls in turn 0 (`docs/turn-model.md`);
//! - **hop** (fn. 10, `docs/contact-forces.md` §4.2–4.3): a turn model hops in
//!   late turns iff `tan α > 2`, and within K turns iff
//!   `tan α > (1 + ε c_C)/(½ − ε c_G)`, `ε = b/r_{K−1}`, for the `note`
//!   and `charged` collisions;
//! - **slip** (`docs/contact-forces.md` §5): where |F|/N is largest at the
//!   start (the snowless log, the models with lift, eq. (32)),
//!   `μ = (G − a₀)/(C + b a₀/(2π r0))` with `a₀ = a(0, v0)`; for the turn
//!   models the late-turn limit `μ = 4 tan α/(3(4 − tan²α))` (early turns
//!   need slightly more).

use crate::portable::Portable as _;
use std::f64::consts::PI;
use std::fmt;

use super::axis::{AxisParam, Values};
use super::grid::{Grid, Point};
use super::row::SweepRow;
use crate::models::{CollisionModel, ModelKind};
use crate::params::Settings;
use crate::scenario::{Scenario, ScenarioFile};
use crate::trajectory::StopReason;

/// What the log did in one row of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Outcome {
    /// a(0) ≤ 0: the log cannot lift the snow (fn. 7).
    NeverStarts,
    /// The speed returned to zero in turn `turn` (0-based; for a circular
    /// model the full turns rolled before the stall).
    Stalls {
        /// The turn of the stall.
        turn: u64,
    },
    /// Reached the end time, distance or number of turns still rolling.
    RollsOn,
    /// The normal force reached zero (fn. 10).
    Hops,
    /// The friction needed reached μ N.
    Slips,
    /// Could not climb the step onto a new layer (`--collision charged|pivot`).
    Stuck,
    /// The run failed (the row's `error` says why).
    Failed,
}

impl Outcome {
    /// The outcome of a row.
    pub fn of(row: &SweepRow) -> Outcome {
        if row.error.is_some() {
            return Outcome::Failed;
        }
        match row.stop {
            None => Outcome::Failed,
            // At terminal velocity the body still rolls on; an unwinding
            // roll that reached its core rolled all the way.
            Some(
                StopReason::EndTime
                | StopReason::Distance
                | StopReason::Turns
                | StopReason::Terminal
                | StopReason::Unwound,
            ) => Outcome::RollsOn,
            // Cut short by a limit of the program: no verdict on the physics.
            Some(StopReason::StepLimit | StopReason::RowLimit) => Outcome::Failed,
            Some(StopReason::DoesNotStart) => Outcome::NeverStarts,
            Some(StopReason::Stalled) => Outcome::Stalls {
                turn: row.turns.unwrap_or(0),
            },
            Some(StopReason::Hop) => Outcome::Hops,
            Some(StopReason::Slip) => Outcome::Slips,
            Some(StopReason::Stuck) => Outcome::Stuck,
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Outcome::NeverStarts => f.write_str("never starts"),
            Outcome::Stalls { turn } => write!(f, "stalls in turn {turn}"),
            Outcome::RollsOn => f.write_str("rolls on"),
            Outcome::Hops => f.write_str("hops"),
            Outcome::Slips => f.write_str("slips"),
            Outcome::Stuck => f.write_str("stuck at a step"),
            Outcome::Failed => f.write_str("run failed"),
        }
    }
}

/// A closed-form border between two regimes, as a curve in the plane of the
/// map's two parameters (values in the parameters' own units, degrees for α).
#[derive(Debug, Clone, PartialEq)]
pub struct Boundary {
    /// What it is, with its source, e.g. `stall slope (fn. 7), energy`.
    pub label: String,
    /// The curve, `(x, y)` in the map's parameters.
    pub points: Vec<(f64, f64)>,
}

/// Points along the other axis at which a border is evaluated.
const CURVE_POINTS: usize = 201;

/// `c_C` of the early-turn hop angle, `docs/contact-forces.md` §4.3:
/// `3/2 + 8/(13π)` for the note's collision, `3/2 + 12/(13π)` for `charged`.
fn hop_c_c(collision: CollisionModel) -> Option<f64> {
    match collision {
        CollisionModel::Note => Some(1.5 + 8.0 / (13.0 * PI)),
        CollisionModel::Charged => Some(1.5 + 12.0 / (13.0 * PI)),
        CollisionModel::Pivot => None,
    }
}

/// `c_G = 1/π + 14/39 − 1` of the early-turn hop angle (§4.3).
const HOP_C_G: f64 = 1.0 / PI + 14.0 / 39.0 - 1.0;

/// The slope above which a turn model hops within `k_turns` turns
/// (`docs/contact-forces.md` §4.3): `tan α_K = (1 + ε c_C)/(½ − ε c_G)`,
/// `ε = b/r_{K−1}`, `r_{K−1} = r0 + (K − 1) b`; radians. `None` for the
/// `pivot` collision (no closed form) or `k_turns = 0`.
pub fn hop_slope_within(b: f64, r0: f64, k_turns: u64, collision: CollisionModel) -> Option<f64> {
    let c_c = hop_c_c(collision)?;
    if k_turns == 0 {
        return None;
    }
    let eps = b / (r0 + (k_turns - 1) as f64 * b);
    Some(((1.0 + eps * c_c) / (0.5 - eps * HOP_C_G)).atan_p())
}

/// The smallest μ that keeps `model` rolling, where a closed form gives it
/// (see the module doc): at the start for the snowless log, the circular
/// models with lift and eq. (32); in late turns for the turn models (none
/// for tan α ≥ 2, where they hop). `None` elsewhere.
pub fn slip_mu(model: ModelKind, s: &Scenario) -> Option<f64> {
    let alpha = s.slope_angle();
    if !model.is_circular() {
        let t = alpha.tan_p();
        return (t < 2.0).then(|| 4.0 * t / (3.0 * (4.0 - t * t)));
    }
    let c = model.derivation()?.coefficients();
    let largest_at_start =
        !c.accretes || c.lift != 0.0 || c.lift_b2 != 0.0 || c.drag <= 1.0 || s.snow_depth() == 0.0;
    if !largest_at_start {
        return None;
    }
    let b = if c.accretes { s.snow_depth() } else { 0.0 };
    let r0 = s.initial_radius();
    let a0 = c.acceleration(s, 0.0, s.initial_speed());
    let mu = (s.g_along() - a0) / (s.g_normal() + b * a0 / (2.0 * PI * r0));
    (a0 > 0.0 && mu.is_finite() && mu > 0.0).then_some(mu)
}

/// The smallest and largest of the values of an axis, each computed as the
/// map places it.
fn value_range(values: &Values) -> (f64, f64) {
    (0..values.len())
        .map(|k| values.get(k))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
}

/// The slope angle's axis, one of every map that has borders.
const ALPHA: AxisParam = AxisParam::named("alpha_deg");

/// The friction coefficient's axis: its border is the slip border.
const MU: AxisParam = AxisParam::named("mu");

/// The plane of a map: α on one axis, `other` on the other, which the
/// borders sample at [`CURVE_POINTS`] values from `lo` to `hi` (evenly in
/// its logarithm when it spans two decades or more).
struct Plane {
    other: AxisParam,
    alpha_is_x: bool,
    lo: f64,
    hi: f64,
    along: Vec<f64>,
}

impl Plane {
    /// The plane of `x` and `y`, if one is α and the other a swept axis.
    fn of(grid: &Grid, x: AxisParam, y: AxisParam) -> Option<Plane> {
        let (other, alpha_is_x) = match (x, y) {
            (ALPHA, p) => (p, true),
            (p, ALPHA) => (p, false),
            _ => return None,
        };
        let other_axis = grid.axes().iter().find(|a| a.param == other)?;
        let (lo, hi) = value_range(&other_axis.values);
        let log = lo > 0.0 && hi / lo >= 100.0;
        let along = (0..CURVE_POINTS)
            .map(|i| {
                let f = i as f64 / (CURVE_POINTS - 1) as f64;
                if log {
                    lo * (hi / lo).powf_p(f)
                } else {
                    lo + (hi - lo) * f
                }
            })
            .collect();
        Some(Plane {
            other,
            alpha_is_x,
            lo,
            hi,
            along,
        })
    }

    /// The map point of slope `alpha_deg` and value `v` of the other axis.
    fn place(&self, alpha_deg: f64, v: f64) -> (f64, f64) {
        if self.alpha_is_x {
            (alpha_deg, v)
        } else {
            (v, alpha_deg)
        }
    }
}

/// One model's borders: its first grid point (`base`) with the other axis
/// set to a value, and the label of each border.
struct ModelBorders<'a> {
    model: ModelKind,
    base: Point,
    plane: &'a Plane,
    several: bool,
}

impl ModelBorders<'_> {
    /// `what`, with the model's id when the map shows several models.
    fn named(&self, what: &str) -> String {
        if self.several {
            format!("{what}, {}", self.model.id())
        } else {
            what.to_string()
        }
    }

    /// The base scenario with the other axis at `v` (unchanged for an axis
    /// of the run rather than of the scenario); `None` if it is invalid.
    fn with(&self, v: f64) -> Option<Scenario> {
        let mut s = Settings {
            scenario: ScenarioFile::from(self.base.scenario),
            ..Settings::default()
        };
        if self.plane.other != ALPHA {
            self.plane.other.set(&mut s, v).ok()?;
        }
        Scenario::new(s.scenario).ok()
    }

    /// fn. 7: the stall slope along the other axis.
    fn stall(&self) -> Option<Boundary> {
        let points: Vec<(f64, f64)> = self
            .plane
            .along
            .iter()
            .filter_map(|&v| {
                let s = self.with(v)?;
                let t = self
                    .model
                    .stall_threshold_in(&s, &self.base.options.losses)?;
                Some(self.plane.place(t.slope.to_degrees(), v))
            })
            .collect();
        (points.len() > 1).then(|| Boundary {
            label: self.named("stall slope (fn. 7)"),
            points,
        })
    }

    /// The turn models' hop: fn. 10's late-turn slope tan α = 2, and the
    /// hop within the turns the rows reached (§4.3).
    fn hop(&self, rows: &[SweepRow]) -> Vec<Boundary> {
        let (plane, model) = (self.plane, self.model);
        let late = 2f64.atan_p().to_degrees();
        let mut out = vec![Boundary {
            label: self.named("hop, late turns: tan α = 2 (fn. 10)"),
            points: vec![plane.place(late, plane.lo), plane.place(late, plane.hi)],
        }];
        // At each value of the other axis, K = the turns of the furthest run
        // there that rolled on.
        let mut values: Vec<f64> = rows
            .iter()
            .filter(|r| r.model == model)
            .map(|r| r.param(plane.other))
            .collect();
        values.sort_by(f64::total_cmp);
        values.dedup_by(|a, b| a.to_bits() == b.to_bits());
        let early: Vec<(f64, f64)> = values
            .iter()
            .filter_map(|&v| {
                let k = rows
                    .iter()
                    .filter(|r| r.model == model && r.param(plane.other).to_bits() == v.to_bits())
                    .filter(|r| Outcome::of(r) == Outcome::RollsOn)
                    .filter_map(|r| r.turns)
                    .max()?;
                let s = self.with(v)?;
                let a = hop_slope_within(
                    s.snow_depth(),
                    s.initial_radius(),
                    k + 1,
                    self.base.options.collision,
                )?;
                Some(plane.place(a.to_degrees(), v))
            })
            .collect();
        if early.len() > 1 {
            out.push(Boundary {
                label: self.named("hop within the turns reached (§4.3)"),
                points: early,
            });
        }
        out
    }

    /// Slip: μ as a function of α over the α axis (§5).
    fn slip(&self, grid: &Grid) -> Option<Boundary> {
        let alpha_axis = grid.axes().iter().find(|a| a.param == ALPHA)?;
        let (a_lo, a_hi) = value_range(&alpha_axis.values);
        let points: Vec<(f64, f64)> = (0..CURVE_POINTS)
            .filter_map(|i| {
                let deg = a_lo + (a_hi - a_lo) * i as f64 / (CURVE_POINTS - 1) as f64;
                let mut f = ScenarioFile::from(self.base.scenario);
                f.alpha_deg = deg;
                let mu = slip_mu(self.model, &Scenario::new(f).ok()?)?;
                Some(self.plane.place(deg, mu))
            })
            .collect();
        let what = if self.model.is_circular() {
            "slip: μ = |F|/N at the start (§5)"
        } else {
            "slip, late turns (§5.3)"
        };
        (points.len() > 1).then(|| Boundary {
            label: self.named(what),
            points,
        })
    }
}

/// The closed-form borders of `grid`'s models in the plane `(x, y)` of two
/// swept parameters, one of which must be α (otherwise none are drawn).
/// Parameters off the plane take the values of the model's first grid point;
/// `rows` supply the number of turns the turn models reached (for the
/// early-turn hop angle).
pub fn boundaries(grid: &Grid, rows: &[SweepRow], x: AxisParam, y: AxisParam) -> Vec<Boundary> {
    let mut out = Vec::new();
    let Some(plane) = Plane::of(grid, x, y) else {
        return out;
    };
    let per_model = grid.len() / grid.models().len().max(1) as u64;
    for (m, &model) in grid.models().iter().enumerate() {
        let Ok(base) = grid.point(m as u64 * per_model) else {
            continue;
        };
        let borders = ModelBorders {
            model,
            base,
            plane: &plane,
            several: grid.models().len() > 1,
        };
        out.extend(borders.stall());
        if !model.is_circular() && plane.other != MU {
            out.extend(borders.hop(rows));
        }
        if plane.other == MU {
            out.extend(borders.slip(grid));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding only: each form is a handful of operations.
    const TOL: f64 = 1e-12;

    #[test]
    fn hop_angle_tends_to_arctan_2_and_matches_the_table_of_section_4_3() {
        // docs/contact-forces.md §4.3, closed-form column: K = 20 → 64.2246°,
        // K = 2000 → 63.4469° (b = 0.01, r0 = 0.1), to the table's 1e-4°.
        let k20 = hop_slope_within(0.01, 0.1, 20, CollisionModel::Note)
            .unwrap()
            .to_degrees();
        assert!((k20 - 64.2246).abs() < 1e-4, "{k20}");
        let k2000 = hop_slope_within(0.01, 0.1, 2000, CollisionModel::Note)
            .unwrap()
            .to_degrees();
        assert!((k2000 - 63.4469).abs() < 1e-4, "{k2000}");
        // No snow: ε = 0 and tan α = 2 exactly.
        let bare = hop_slope_within(0.0, 0.1, 5, CollisionModel::Note).unwrap();
        assert!((bare.tan() - 2.0).abs() < TOL);
        assert!(hop_slope_within(0.01, 0.1, 20, CollisionModel::Pivot).is_none());
    }

    #[test]
    fn slip_mu_closed_forms() {
        // Snowless cylinder: μ = tan α/3 (§5.1).
        let s = Scenario::default();
        let t = s.slope_angle().tan();
        let mu = slip_mu(ModelKind::Snowless, &s).unwrap();
        assert!((mu - t / 3.0).abs() < TOL * mu);
        // eq. (32): μ = tan α/(3 + b tan α/(π r0)) (§5.2).
        let mu = slip_mu(ModelKind::QuasiCircular, &s).unwrap();
        let want = t / (3.0 + 0.01 * t / (PI * 0.1));
        assert!((mu - want).abs() < TOL * want, "{mu} {want}");
        // Turn models, late turns: 4 tan α/(3(4 − tan²α)) = 0.2099 at 30°.
        let mu = slip_mu(ModelKind::Turns, &s).unwrap();
        assert!((mu - 4.0 * t / (3.0 * (4.0 - t * t))).abs() < TOL);
        // eq. (4): |F|/N grows along the run, no closed form at the start.
        assert!(slip_mu(ModelKind::TorqueCm, &s).is_none());
    }
}
