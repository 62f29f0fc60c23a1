//! One output schema for every model: samples, the stop, the options.

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::error::{ParamError, SinkError};
use crate::integrate::{Stats, Tolerances};
use crate::losses::Losses;
use crate::model_kind::ModelKind;
use crate::units::{
    Kilograms, Meters, MetersPerSecond, MetersPerSecondSquared, Newtons, Radians, Seconds,
};

/// The state of the log at one time. Column names carry their units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// Time since the start, s.
    pub t_s: Seconds,
    /// Distance rolled down the slope (of the contact line / nominal centre), m.
    pub x_m: Meters,
    /// Speed down the slope, m/s.
    pub v_m_s: MetersPerSecond,
    /// Acceleration dv/dt, m/s².
    pub a_m_s2: MetersPerSecondSquared,
    /// Radius (nominal radius for the turn models), m.
    pub r_m: Meters,
    /// Mass of log plus snow as the model counts it, kg.
    pub mass_kg: Kilograms,
    /// Normal force N of the slope on the log, from the momentum balance of
    /// the accreting body (`docs/contact-forces.md` §1–§3), N.
    pub normal_n: Newtons,
    /// Friction force F that rolling without slipping needs, positive up the
    /// slope (`docs/contact-forces.md` §1–§3), N.
    pub friction_n: Newtons,
    /// |F|/N: the smallest coefficient of static friction that keeps this
    /// sample rolling; `None` (undefined) when N ≤ 0, the log having left
    /// the ground: an empty CSV cell, a JSON `null`.
    pub friction_ratio: Option<f64>,
}

/// Extra state of the turn-by-turn models (§3), one per sample.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnState {
    /// Turn number k, 0-based (`docs/turn-model.md`, Conventions).
    pub turn: u64,
    /// Angle rolled in this turn, rad, in [0, 2π].
    pub theta_rad: Radians,
    /// Rotation rate dθ/dt, rad/s.
    pub omega_rad_s: f64,
}

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum StopReason {
    /// Reached `t_end`.
    EndTime,
    /// Reached `x_end`.
    Distance,
    /// Completed the requested number of turns.
    Turns,
    /// The speed returned to zero (the log would have to shed snow to roll back, `docs/turn-model.md`, Conventions).
    Stalled,
    /// The acceleration at the start is not positive: the log cannot lift the snow (fn. 7).
    DoesNotStart,
    /// The normal force reached zero: the log leaves the ground (fn. 10,
    /// `docs/contact-forces.md` §4; with `--collision pivot` also at the edge of
    /// the new layer, §6.3).
    Hop,
    /// |F| reached μ N: rolling without slipping needs more friction than
    /// `mu` (`docs/contact-forces.md` §5).
    Slip,
    /// With `--collision charged|pivot`, the kinetic energy after the impact
    /// cannot lift the log onto the new layer (`docs/contact-forces.md` §6.2, §6.3).
    Stuck,
    /// The integrator used up its step budget ([`Tolerances::max_steps`]);
    /// the samples up to there are kept.
    StepLimit,
    /// The run recorded [`SimOptions::max_rows`] samples, the most allowed;
    /// the samples up to there are kept.
    RowLimit,
    /// The snowless log with drag reached its terminal velocity: |a| fell to
    /// [`Losses::terminal_tol`](crate::Losses::terminal_tol) of the initial
    /// drive (`docs/snowball-and-losses.md` §2.2).
    Terminal,
}

impl StopReason {
    /// A sentence for people.
    pub fn describe(self) -> &'static str {
        match self {
            StopReason::EndTime => "reached the end time",
            StopReason::Distance => "reached the end distance",
            StopReason::Turns => "completed the requested number of turns",
            StopReason::Stalled => "the speed returned to zero (stall)",
            StopReason::DoesNotStart => {
                "the log does not start: a(0) <= 0, it cannot lift the snow (fn. 7)"
            }
            StopReason::Hop => "the normal force reached zero: the log hops (fn. 10)",
            StopReason::Slip => {
                "the friction needed reached mu times the normal force: the log slips"
            }
            StopReason::Stuck => "the log cannot climb the step onto the new layer of snow (stuck)",
            StopReason::StepLimit => {
                "the integrator used up its step budget (max_steps); the rows computed so far are kept"
            }
            StopReason::RowLimit => {
                "the run recorded max_rows rows, the most allowed; the rows computed so far are kept"
            }
            StopReason::Terminal => {
                "the acceleration fell below the terminal tolerance: terminal velocity reached"
            }
        }
    }

    /// Whether the run ended on a limit of the program rather than on its
    /// physics or its requested end.
    pub fn is_limit(self) -> bool {
        matches!(self, StopReason::StepLimit | StopReason::RowLimit)
    }
}

/// Where and why the run ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Stop {
    /// Why.
    pub reason: StopReason,
    /// Time, s.
    pub t_s: Seconds,
    /// Position, m.
    pub x_m: Meters,
    /// Speed, m/s.
    pub v_m_s: MetersPerSecond,
    /// For the turn models, turn, θ and θ̇ at the stop.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub turn: Option<TurnState>,
}

impl Stop {
    /// Where, for people: `t = … s, x = … m, v = … m/s` and, for the turn
    /// models, `, turn k, theta = … rad, omega = … rad/s`.
    pub fn place(&self) -> String {
        let mut s = format!(
            "t = {} s, x = {} m, v = {} m/s",
            self.t_s, self.x_m, self.v_m_s
        );
        if let Some(k) = self.turn {
            s.push_str(&format!(
                ", turn {} (0-based), theta = {} rad, omega = {} rad/s",
                k.turn, k.theta_rad, k.omega_rad_s
            ));
        }
        s
    }
}

/// How a run ended: where and why, and what it cost. What
/// [`Model::simulate_into`](crate::Model::simulate_into) returns once its
/// samples have gone to the sink.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunEnd {
    /// How the run ended.
    pub stop: Stop,
    /// Integrator counts (zero for closed forms).
    pub stats: Stats,
}

/// Receives the samples of a run one at a time, as they are computed, so a
/// run of any length needs memory for one sample only
/// ([`Model::simulate_into`](crate::Model::simulate_into)).
pub trait SampleSink {
    /// One sample, with the turn state for the turn models (`None` for the others).
    ///
    /// # Errors
    /// A [`SinkError`] ends the run at once; the model returns it as
    /// [`SimError::Sink`](crate::SimError::Sink).
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError>;

    /// The energy ledger of the sample that comes next, for a run that
    /// records one ([`Losses::records_ledger`](crate::Losses::records_ledger));
    /// sent just before that [`sample`](Self::sample). Ignored by default.
    ///
    /// # Errors
    /// As [`sample`](Self::sample).
    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        let _ = row;
        Ok(())
    }
}

/// The samples of a run gathered in memory: the sink behind
/// [`Model::simulate`](crate::Model::simulate).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Collected {
    /// Samples in time order.
    pub samples: Vec<Sample>,
    /// The turn states of the samples that had one.
    pub turn_states: Vec<TurnState>,
    /// The ledger rows of the samples that had one.
    pub ledger: Vec<LedgerRow>,
}

impl SampleSink for Collected {
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError> {
        self.samples.push(*sample);
        if let Some(k) = turn {
            self.turn_states.push(*k);
        }
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.ledger.push(*row);
        Ok(())
    }
}

impl Collected {
    /// The trajectory of `model` made of these samples and `end`.
    pub fn into_trajectory(self, model: ModelKind, end: RunEnd) -> Trajectory {
        Trajectory {
            model,
            samples: self.samples,
            turn_states: self.turn_states,
            stop: end.stop,
            stats: end.stats,
            ledger: self.ledger,
        }
    }
}

/// The result of one simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// Which model produced it.
    pub model: ModelKind,
    /// Samples in time order, as asked for by [`Sampling`].
    pub samples: Vec<Sample>,
    /// For the turn models, the turn state of each sample; empty otherwise.
    pub turn_states: Vec<TurnState>,
    /// How the run ended.
    pub stop: Stop,
    /// Integrator counts (zero for closed forms).
    pub stats: Stats,
    /// The energy ledger of each sample when the run records one
    /// ([`Losses::records_ledger`](crate::Losses::records_ledger)); empty otherwise.
    pub ledger: Vec<LedgerRow>,
}

/// The energy ledger at one sample, J (`docs/snowball-and-losses.md` §3):
/// `kinetic + drag + rolling + compaction + model + collision − created
/// = initial + released`, the zero of potential energy being the note's
/// (eqs. (9)–(10)): body plus all the snow it will collect, at the start.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LedgerRow {
    /// Kinetic energy K, eq. (7), J.
    pub kinetic_j: f64,
    /// Potential energy released since the start, −V (eq. (10)), J.
    pub released_j: f64,
    /// Work done against air drag, ∫ F_d v dt, J.
    pub drag_j: f64,
    /// Work done against rolling resistance, ∫ c_rr N v dt, J.
    pub rolling_j: f64,
    /// Work of compacting the snow picked up, ∫ e_c dM, J.
    pub compaction_j: f64,
    /// Energy the model's own equation destroys (negative: creates), W_model
    /// of §3.1: 0 for `energy` and `snowless`, the inelastic pick-up for the
    /// torque models, J.
    pub model_j: f64,
    /// Kinetic energy lost in the collisions of the turn models, J.
    pub collision_j: f64,
    /// Energy created by the note's collision (eq. (89): the free jump onto
    /// the new layer), J.
    pub created_j: f64,
    /// `kinetic + drag + rolling + compaction + model + collision − created
    /// − released − initial`: zero but for the integration error, J.
    pub residual_j: f64,
}

/// Which samples a run records.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Sampling {
    /// The start and every accepted step (closed forms: 500 even steps).
    #[default]
    Steps,
    /// Exactly these times, s (strictly ascending, non-negative, none after
    /// `t_end`: [`SimOptions::validate`] refuses those), from the dense
    /// output; times after an earlier stop (distance, stall) are not
    /// written, and the command line notes how many.
    Times(Vec<Seconds>),
    /// A regular grid 0, dt, 2dt, … up to the stop, s.
    Every(Seconds),
    /// Only the start and the end (fastest).
    Ends,
}

/// Default of [`SimOptions::max_rows`]: 10^8 rows, about 10 GB of CSV.
pub const DEFAULT_MAX_ROWS: u64 = 100_000_000;

impl Sampling {
    /// Point `i` of the regular grid `0, dt, 2dt, …` that ends at `t_end`, s;
    /// `None` past the end. A point within a few ulps of `t_end` (on either
    /// side) is moved onto it, so a grid that divides the run evenly ends
    /// exactly there.
    ///
    /// The point is `i` times the decimal that `dt` prints as (its shortest
    /// round-trip form), rounded once to the nearest `f64`: with `dt = 0.1`
    /// point 3 is `0.3`, not the `0.30000000000000004` of `3.0 * 0.1`. It lies
    /// within about one ulp of `i * dt`, and the grid never decreases with
    /// `i` (rounding to nearest is monotone); it increases strictly wherever
    /// `dt` is larger than the spacing of `f64` near the point.
    pub fn grid_time(dt: Seconds, i: usize, t_end: Seconds) -> Option<Seconds> {
        let t = decimal_multiple(dt, i);
        let near_end = (t - t_end).abs() <= 4.0 * f64::EPSILON * t_end;
        (t <= t_end || near_end).then_some(if near_end { t_end } else { t })
    }

    /// The number of samples this sampling records on a run that reaches
    /// `t_end`, when it is known before the run: the count of `Times`, and
    /// `⌊t_end/dt⌋ + 1` for `Every` (a float: it may exceed every integer).
    /// `None` for `Steps` (the step count is found while running); 2 for `Ends`.
    pub fn known_rows(&self, t_end: Seconds) -> Option<f64> {
        match self {
            Sampling::Times(ts) => Some(ts.len() as f64),
            Sampling::Every(dt) => Some((t_end / dt).floor() + 1.0),
            Sampling::Steps => None,
            Sampling::Ends => Some(2.0),
        }
    }

    /// Checks times and grid spacing.
    ///
    /// # Errors
    /// [`ParamError::InvalidTimes`] for non-finite, negative, descending or repeated
    /// times; [`ParamError::InvalidParameter`] for a grid spacing `dt <= 0`.
    pub fn validate(&self) -> Result<(), ParamError> {
        match self {
            Sampling::Times(ts) => {
                if ts.iter().any(|t| !t.is_finite() || *t < 0.0) {
                    return Err(ParamError::InvalidTimes {
                        reason: "every time must be finite and >= 0 s",
                    });
                }
                if ts.windows(2).any(|w| w[1] < w[0]) {
                    return Err(ParamError::InvalidTimes {
                        reason: "times must be in ascending order",
                    });
                }
                if ts.windows(2).any(|w| w[1] <= w[0]) {
                    return Err(ParamError::InvalidTimes {
                        reason: "a time is repeated: each time may be asked for once",
                    });
                }
                Ok(())
            }
            Sampling::Every(dt) if !(dt.is_finite() && *dt > 0.0) => {
                Err(ParamError::InvalidParameter {
                    name: "dt (s)",
                    value: *dt,
                    expected: "dt > 0 s",
                })
            }
            _ => Ok(()),
        }
    }
}

/// `i · dt` computed on the decimal that `dt` prints as: `dt = m · 10^e` with
/// integer `m` (the shortest digits that round-trip), then `(i m) · 10^e`
/// rounded once to the nearest `f64`. Falls back to `i as f64 * dt` for a
/// `dt` that is not finite and positive, or whose product does not fit.
fn decimal_multiple(dt: f64, i: usize) -> f64 {
    let plain = i as f64 * dt;
    if !(dt.is_finite() && dt > 0.0) {
        return plain;
    }
    // `{:e}` prints the shortest digits that round-trip: "2.5e-3", "1e-1".
    let text = format!("{dt:e}");
    let Some((digits, exp)) = text.split_once('e') else {
        return plain;
    };
    let (whole, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let (Ok(m), Ok(e)) = (format!("{whole}{frac}").parse::<u128>(), exp.parse::<i32>()) else {
        return plain;
    };
    let Some(im) = m.checked_mul(i as u128) else {
        return plain;
    };
    let e = e - frac.len() as i32;
    // Both factors exact in f64 (im < 2^53, 10^k exact up to k = 22): one
    // multiplication or division rounds once, correctly.
    if im < (1u128 << 53) && e.unsigned_abs() <= 22 {
        let p = 10f64.powi(e.abs());
        let x = im as f64;
        return if e < 0 { x / p } else { x * p };
    }
    // Otherwise the standard library's correctly rounded decimal parser.
    format!("{im}e{e}").parse().unwrap_or(plain)
}

/// How a turn model climbs onto the new layer of snow at the end of a turn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum CollisionModel {
    /// Eq. (89): angular momentum about the contact line conserved at θ = 2π;
    /// the centre jumps up by b at no potential-energy cost (the note's; default).
    #[default]
    Note,
    /// Eq. (89), then the potential energy `m_{k+1} g b cos α` of the jump is
    /// paid from the kinetic energy (`docs/contact-forces.md` §6.2).
    Charged,
    /// The corner of the new layer meets the snow at θ_c = 2π − arccos(r/(r + b));
    /// the log pivots about that edge (angular momentum about it conserved),
    /// then rolls on its new radius (`docs/contact-forces.md` §6.3).
    Pivot,
}

impl CollisionModel {
    /// Every variant, the default first.
    pub const ALL: [CollisionModel; 3] = [
        CollisionModel::Note,
        CollisionModel::Charged,
        CollisionModel::Pivot,
    ];

    /// The kebab-case id.
    pub fn id(self) -> &'static str {
        match self {
            CollisionModel::Note => "note",
            CollisionModel::Charged => "charged",
            CollisionModel::Pivot => "pivot",
        }
    }
}

impl fmt::Display for CollisionModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}

/// What a run does where the normal force reaches zero (`--on-hop`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum OnHop {
    /// Stop with [`StopReason::Hop`] (default): past N = 0 the log flies and
    /// the rolling models no longer apply.
    #[default]
    Stop,
    /// Go on as if contact were kept (N < 0 would have to pull the log onto
    /// the snow): for exploring the model past its validity, e.g. the
    /// long-run means of a steep slope.
    Continue,
}

impl OnHop {
    /// Every variant, the default first.
    pub const ALL: [OnHop; 2] = [OnHop::Stop, OnHop::Continue];

    /// The kebab-case id.
    pub fn id(self) -> &'static str {
        match self {
            OnHop::Stop => "stop",
            OnHop::Continue => "continue",
        }
    }
}

impl fmt::Display for OnHop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}

/// Options of one simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct SimOptions {
    /// End time, s. Default 100.
    pub t_end: Seconds,
    /// Stop when x reaches this distance, m. Default: none.
    pub x_end: Option<Meters>,
    /// Stop after this many full turns (turn models only). Default: none.
    pub turns: Option<u64>,
    /// Integrator tolerances. Default rtol 1e-10, atol 1e-12.
    pub tolerances: Tolerances,
    /// What to record. Default: every step.
    pub sampling: Sampling,
    /// Coefficient of static friction μ (dimensionless): the run stops with
    /// [`StopReason::Slip`] where |F| reaches μ N. Default: none (no slip check).
    pub mu: Option<f64>,
    /// What happens where N reaches 0. Default: [`OnHop::Stop`], the run
    /// stops with [`StopReason::Hop`] (nothing is computed past the model's validity).
    pub on_hop: OnHop,
    /// How the turn models climb the step of each new layer. Default: the
    /// note's eq. (89), [`CollisionModel::Note`].
    pub collision: CollisionModel,
    /// Most samples one run records, at least 1. Default
    /// [`DEFAULT_MAX_ROWS`]. A run whose count is known in advance
    /// ([`known_rows`](Self::known_rows)) and larger is refused by
    /// [`validate`](Self::validate); otherwise the run stops there with
    /// [`StopReason::RowLimit`].
    pub max_rows: u64,
    /// Air drag, rolling resistance, compaction, the ledger and the
    /// terminal-velocity stop. Default: no losses (fn. 5's idealisation).
    pub losses: Losses,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            t_end: 100.0,
            x_end: None,
            turns: None,
            tolerances: Tolerances::default(),
            sampling: Sampling::Steps,
            mu: None,
            on_hop: OnHop::Stop,
            collision: CollisionModel::Note,
            max_rows: DEFAULT_MAX_ROWS,
            losses: Losses::default(),
        }
    }
}

impl SimOptions {
    /// The number of samples this run records, when it is known before the
    /// run: [`Sampling::known_rows`] up to `t_end`, except for a grid
    /// (`Every`) with a turn count or an end distance, which gives `None`.
    /// Such a run stops after [`turns`](Self::turns) turns or at
    /// [`x_end`](Self::x_end), and how long that takes has no bound known
    /// in advance (a log that slows towards a stall may take any time), so
    /// the grid count up to `t_end` is then only an upper bound: the run is
    /// not refused, and stops at `max_rows` rows if it gets there.
    pub fn known_rows(&self) -> Option<f64> {
        let other_end = self.turns.is_some() || self.x_end.is_some();
        match &self.sampling {
            Sampling::Every(_) if other_end => None,
            sampling => sampling.known_rows(self.t_end),
        }
    }

    /// Checks every option.
    ///
    /// # Errors
    /// [`ParamError`] naming the first bad option.
    pub fn validate(&self) -> Result<(), ParamError> {
        let bad = |name, value, expected| ParamError::InvalidParameter {
            name,
            value,
            expected,
        };
        if !(self.t_end.is_finite() && self.t_end > 0.0) {
            return Err(bad("t_end (s)", self.t_end, "0 < t_end < infinity s"));
        }
        if let Some(x) = self.x_end {
            if !(x.is_finite() && x > 0.0) {
                return Err(bad("x_end (m)", x, "0 < x_end < infinity m"));
            }
        }
        if let Sampling::Times(ts) = &self.sampling {
            let after: Vec<f64> = ts.iter().copied().filter(|t| *t > self.t_end).collect();
            if let Some(&first) = after.first() {
                return Err(ParamError::TimesAfterEnd {
                    count: after.len(),
                    total: ts.len(),
                    first,
                    t_end: self.t_end,
                });
            }
        }
        if let Some(mu) = self.mu {
            if !(mu.is_finite() && mu > 0.0) {
                return Err(bad("mu", mu, "0 < mu < infinity"));
            }
        }
        self.losses.validate()?;
        if self.turns == Some(0) {
            return Err(bad("turns", 0.0, "turns >= 1"));
        }
        self.tolerances.validate()?;
        if self.max_rows == 0 {
            return Err(bad("max_rows", 0.0, "max_rows >= 1"));
        }
        self.sampling.validate()?;
        match self.known_rows() {
            Some(rows) if rows > self.max_rows as f64 => Err(ParamError::TooManyRows {
                rows,
                max_rows: self.max_rows,
            }),
            _ => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The decimal `i · q / 10^d` written out by integer arithmetic alone,
    /// e.g. (3, 1, 1) → "0.3": what a person means by point i of a grid of
    /// step q·10^−d.
    fn decimal(i: u64, q: u64, d: u32) -> String {
        let n = i * q;
        let scale = 10u64.pow(d);
        format!("{}.{:0width$}", n / scale, n % scale, width = d as usize)
    }

    #[test]
    fn grid_times_print_the_decimal_that_was_meant() {
        // dt = q · 10^−d for steps people type; each point must be the f64
        // nearest the exact decimal i·dt (parsed independently from its
        // digits), so it prints as that decimal.
        for (q, d) in [
            (1, 1),
            (1, 3),
            (5, 3),
            (2, 3),
            (1, 4),
            (3, 1),
            (25, 2),
            (7, 5),
        ] {
            let dt: f64 = decimal(1, q, d).parse().unwrap();
            for i in 0..20_000u64 {
                let want: f64 = decimal(i, q, d).parse().unwrap();
                let got = Sampling::grid_time(dt, i as usize, f64::MAX).unwrap();
                assert_eq!(got.to_bits(), want.to_bits(), "dt = {dt}, i = {i}");
            }
        }
        assert_eq!(
            Sampling::grid_time(0.1, 3, 100.0).unwrap().to_string(),
            "0.3"
        );
        assert_eq!(
            Sampling::grid_time(1e-4, 1, 100.0).unwrap().to_string(),
            "0.0001"
        );
    }

    #[test]
    fn grid_times_stay_within_an_ulp_of_i_dt_and_increase() {
        // Steps that are not short decimals (1/3, π/100) and a huge index:
        // the decimal route must stay within 2ε·t of the plain product i·dt
        // (dt's digits are within ε/2 of dt, relatively, and each of the two
        // products rounds once more by ε/2: 3ε/2 in all) and strictly increase.
        for dt in [1.0 / 3.0, std::f64::consts::PI / 100.0, 0.1, 2.5e-7, 1e3] {
            let mut last = -1.0;
            for i in (0..2_000usize).chain(1_000_000_000..1_000_000_100) {
                let t = Sampling::grid_time(dt, i, f64::MAX).unwrap();
                let plain = i as f64 * dt;
                let tol = 2.0 * f64::EPSILON * plain;
                assert!(
                    (t - plain).abs() <= tol,
                    "dt = {dt}, i = {i}: {t} vs {plain}"
                );
                assert!(t > last, "dt = {dt}, i = {i}: {t} after {last}");
                last = t;
            }
        }
    }

    #[test]
    fn grid_ends_exactly_at_t_end_and_not_beyond() {
        // 0.1 · 10 lands on 1 exactly; the next point is past the end.
        assert_eq!(Sampling::grid_time(0.1, 10, 1.0), Some(1.0));
        assert_eq!(Sampling::grid_time(0.1, 11, 1.0), None);
        // A point within rounding of t_end is moved onto it.
        assert_eq!(Sampling::grid_time(1.0 / 3.0, 3, 1.0), Some(1.0));
    }
}
