//! One row per completed turn of §3.4, and the long-run statistics of the
//! acceleration that eqs. (77)–(79) leave open (`docs/errata.md`, (78)–(79)).
//!
//! The rows come from the integrator's events (v before and after each
//! collision) and, for the range of a within a turn, from the energy
//! integral of the turn (no dense output is needed).
//!
//! What to expect (leading order in 1/k, checked in `tests/turns.rs`): with
//! r_k ≈ kb, the energy over a turn gives `(3/4 + 2b/r) v_end² ≈ (3/4) v_beg² + 2πG r`
//! and the collision `v_after² ≈ v_end²(1 − 2b/3r)`, so `v_beg² → (πGb/2) k²`
//! and each turn lasts `2πr/v`: the mean acceleration tends to G/3 within a
//! turn and to G/4 with the collisions (not the 4G/9 of eq. (79)), while
//! `a(θ) ≈ (2/3)G − (G/3)(1 − cos θ)` keeps ranging over [0, 2G/3] (eq. (77)).

use serde::{Deserialize, Serialize};

use super::{
    collision_speed, kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, CollisionModel,
    TurnModel, TurnSystem, TurnVariant, EVENT_TURN_END,
};
use crate::error::{ParamError, SimError, SinkError};
use crate::integrate::{EventRecord, Observer, Stats};
use crate::models::ode::{run_observed, stop_at, OdeModel, RowBudget, RunObserver};
use crate::models::ModelKind;
use crate::scenario::Scenario;
use crate::trajectory::{LedgerRow, SimOptions, Stop};
use crate::units::{Joules, Meters, MetersPerSecond, MetersPerSecondSquared, Seconds};

/// One completed turn k. Column names carry their units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnRow {
    /// Turn number k, 0-based.
    pub turn: u64,
    /// Time the turn starts, s.
    pub t_start_s: Seconds,
    /// Position of the contact line at the start, `X_k` (eq. (74)), m.
    pub x_start_m: Meters,
    /// Speed of the nominal centre at the start (after the previous collision), m/s.
    pub v_start_m_s: MetersPerSecond,
    /// Time the turn ends (θ = 2π), s.
    pub t_end_s: Seconds,
    /// Speed just before the collision, `r_k θ̇(2π)`, m/s.
    pub v_end_m_s: MetersPerSecond,
    /// Speed just after the collision, eq. (89) (also for the last turn of a
    /// run stopped by a turn count, as if the run went on), m/s.
    pub v_after_m_s: MetersPerSecond,
    /// Kinetic energy the collision removes, `T_end [1 − (r_{k+1}² + 2r_k²)/(3r_{k+1}²)]`
    /// with `T_end = m_{k+1}(r_{k+1}²/2 + r_k²) θ̇²/2` (eqs. (85), (86)), J.
    pub collision_loss_j: Joules,
    /// Mean acceleration within the turn, `(v_end − v_start)/(t_end − t_start)`, m/s².
    pub mean_a_turn_m_s2: MetersPerSecondSquared,
    /// Smallest acceleration within the turn, m/s².
    pub min_a_m_s2: MetersPerSecondSquared,
    /// Largest acceleration within the turn, m/s².
    pub max_a_m_s2: MetersPerSecondSquared,
    /// Mean acceleration including the collision's jump,
    /// `(v_after − v_start)/(t_end − t_start)`, m/s².
    pub mean_a_with_collision_m_s2: MetersPerSecondSquared,
    /// Smallest normal force within the turn (while rolling; up to θ_c with
    /// `--collision pivot`), from the energy integral (`docs/contact-forces.md` §3, §4), N.
    pub min_normal_n: f64,
    /// The same minimum as a fraction of M g, M the mass at that point, 1.
    pub min_normal_over_mg: f64,
    /// Largest |F|/N within the turn (the smallest μ that keeps it rolling, §5), 1;
    /// `None` (undefined: an empty CSV cell, a JSON `null`) when N ≤ 0 somewhere in the turn.
    pub max_friction_ratio: Option<f64>,
}

/// Means of the acceleration up to turn K, as fractions of G = g sin α.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnCheckpoint {
    /// K: the statistics cover completed turns k < K.
    pub turns: u64,
    /// Time-weighted mean of a within turns, over all turns k < K,
    /// `Σ(v_end − v_start)/Σ(t_end − t_start)`, over G.
    pub mean_a_turn_over_g: f64,
    /// Mean of a including the collisions, over all turns k < K,
    /// `(v_after(K−1) − v_start(0))/t_end(K−1)`, over G.
    pub mean_a_with_collision_over_g: f64,
    /// First turn of the last decade, ⌊K/10⌋.
    pub window_first_turn: u64,
    /// Time-weighted mean of a within turns over the last decade ⌊K/10⌋ ≤ k < K, over G.
    pub window_mean_a_turn_over_g: f64,
    /// Mean of a including collisions over the last decade, over G.
    pub window_mean_a_with_collision_over_g: f64,
    /// Smallest a within a turn over the last decade, over G.
    pub window_min_a_over_g: f64,
    /// Largest a within a turn over the last decade, over G.
    pub window_max_a_over_g: f64,
}

/// Long-run statistics of a run: checkpoints at K = 1, 2, 5, 10, 20, 50, …
/// and at the last completed turn.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TurnSummary {
    /// G = g sin α, the unit of every `_over_g` value, m/s².
    pub g_along_m_s2: f64,
    /// Number of completed turns.
    pub turns: u64,
    /// How the means converge with K; the last entry covers every turn.
    pub checkpoints: Vec<TurnCheckpoint>,
}

impl TurnSummary {
    /// The statistics of `rows` (consecutive turns from k = 0).
    pub fn new(rows: &[TurnRow], g_along: f64) -> Self {
        // Prefix sums of the in-turn velocity gain, so that any window costs O(1).
        let mut gain = Vec::with_capacity(rows.len() + 1);
        gain.push(0.0);
        let mut sum = 0.0;
        for row in rows {
            sum += row.v_end_m_s - row.v_start_m_s;
            gain.push(sum);
        }
        let window = |from: usize, to: usize| {
            let (first, last) = (&rows[from], &rows[to - 1]);
            let dt = last.t_end_s - first.t_start_s;
            let in_turn = (gain[to] - gain[from]) / dt / g_along;
            let with = (last.v_after_m_s - first.v_start_m_s) / dt / g_along;
            (in_turn, with)
        };
        let checkpoints = checkpoint_turns(rows.len())
            .into_iter()
            .map(|k| {
                let first = k / 10;
                let (mean_turn, mean_with) = window(0, k);
                let (w_turn, w_with) = window(first, k);
                let (lo, hi) = rows[first..k]
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| {
                        (lo.min(r.min_a_m_s2), hi.max(r.max_a_m_s2))
                    });
                TurnCheckpoint {
                    turns: k as u64,
                    mean_a_turn_over_g: mean_turn,
                    mean_a_with_collision_over_g: mean_with,
                    window_first_turn: first as u64,
                    window_mean_a_turn_over_g: w_turn,
                    window_mean_a_with_collision_over_g: w_with,
                    window_min_a_over_g: lo / g_along,
                    window_max_a_over_g: hi / g_along,
                }
            })
            .collect();
        Self {
            g_along_m_s2: g_along,
            turns: rows.len() as u64,
            checkpoints,
        }
    }

    /// The checkpoint covering every turn, if any turn was completed.
    pub fn overall(&self) -> Option<&TurnCheckpoint> {
        self.checkpoints.last()
    }
}

/// Whether `k` is one of 1, 2, 5, 10, 20, 50, …
fn is_decade_checkpoint(k: u64) -> bool {
    let mut decade = 1u64;
    loop {
        if [1, 2, 5].iter().any(|&m| decade.checked_mul(m) == Some(k)) {
            return true;
        }
        match decade.checked_mul(10) {
            Some(d) if d <= k => decade = d,
            _ => return false,
        }
    }
}

/// The state of the run where a window starts (turn `first`), and the
/// extremes of a over the turns seen since.
#[derive(Debug, Clone, Copy)]
struct WindowStart {
    first: u64,
    /// Σ(v_end − v_start) over the turns before `first`, m/s.
    gain_before: f64,
    t_start: f64,
    v_start: f64,
    min_a: f64,
    max_a: f64,
}

/// [`TurnSummary`] computed row by row in memory O(log n): running sums,
/// and one [`WindowStart`] per turn where a checkpoint's window may start
/// (0, 1, 2, 5, 10, …, and ⌊N/10⌋ for the N turns asked for).
///
/// For a run that completes the turns it was asked for, the result is that
/// of [`TurnSummary::new`] on all the rows, bit for bit (the same sums in
/// the same order). After an early stop at n turns, the window of the
/// last checkpoint starts at the largest of those turns not past ⌊n/10⌋
/// (its `window_first_turn` says which).
#[derive(Debug, Clone)]
pub(crate) struct SummaryBuilder {
    g_along: f64,
    wanted: Option<u64>,
    turns: u64,
    gain: f64,
    starts: Vec<WindowStart>,
    last: Option<TurnRow>,
    checkpoints: Vec<TurnCheckpoint>,
}

impl SummaryBuilder {
    pub(crate) fn new(g_along: f64, wanted: Option<u64>) -> Self {
        Self {
            g_along,
            wanted,
            turns: 0,
            gain: 0.0,
            starts: Vec::new(),
            last: None,
            checkpoints: Vec::new(),
        }
    }

    /// Adds turn `self.turns` (rows come in order from k = 0).
    pub(crate) fn push(&mut self, row: &TurnRow) {
        let k = self.turns;
        if k == 0 || is_decade_checkpoint(k) || self.wanted.is_some_and(|n| n / 10 == k) {
            self.starts.push(WindowStart {
                first: k,
                gain_before: self.gain,
                t_start: row.t_start_s,
                v_start: row.v_start_m_s,
                min_a: f64::INFINITY,
                max_a: f64::NEG_INFINITY,
            });
        }
        for w in &mut self.starts {
            w.min_a = w.min_a.min(row.min_a_m_s2);
            w.max_a = w.max_a.max(row.max_a_m_s2);
        }
        self.gain += row.v_end_m_s - row.v_start_m_s;
        self.turns = k + 1;
        self.last = Some(*row);
        if is_decade_checkpoint(self.turns) {
            self.checkpoint();
        }
    }

    /// The checkpoint over the `self.turns` turns seen.
    fn checkpoint(&mut self) {
        let (Some(last), Some(all)) = (self.last, self.starts.first()) else {
            return;
        };
        let g = self.g_along;
        let window = |w: &WindowStart| {
            let dt = last.t_end_s - w.t_start;
            (
                (self.gain - w.gain_before) / dt / g,
                (last.v_after_m_s - w.v_start) / dt / g,
            )
        };
        let wanted_first = self.turns / 10;
        let decade = self
            .starts
            .iter()
            .rev()
            .find(|w| w.first <= wanted_first)
            .unwrap_or(all);
        let (mean_turn, mean_with) = window(all);
        let (w_turn, w_with) = window(decade);
        self.checkpoints.push(TurnCheckpoint {
            turns: self.turns,
            mean_a_turn_over_g: mean_turn,
            mean_a_with_collision_over_g: mean_with,
            window_first_turn: decade.first,
            window_mean_a_turn_over_g: w_turn,
            window_mean_a_with_collision_over_g: w_with,
            window_min_a_over_g: decade.min_a / g,
            window_max_a_over_g: decade.max_a / g,
        });
    }

    /// The summary of the turns seen, with the last checkpoint at the last turn.
    pub(crate) fn finish(mut self) -> TurnSummary {
        if self.checkpoints.last().map(|c| c.turns) != Some(self.turns) {
            self.checkpoint();
        }
        TurnSummary {
            g_along_m_s2: self.g_along,
            turns: self.turns,
            checkpoints: self.checkpoints,
        }
    }
}

/// 1, 2, 5, 10, 20, 50, … below `n`, then `n` (empty when n = 0).
fn checkpoint_turns(n: usize) -> Vec<usize> {
    let mut out = Vec::new();
    let mut decade = 1usize;
    'outer: loop {
        for m in [1, 2, 5] {
            let k = m * decade;
            if k >= n {
                break 'outer;
            }
            out.push(k);
        }
        decade = match decade.checked_mul(10) {
            Some(d) => d,
            None => break,
        };
    }
    if n > 0 {
        out.push(n);
    }
    out
}

/// Receives the rows of a turn run one at a time, as each turn ends
/// ([`TurnModel::run_table_into`]), so a run of any length needs memory for
/// one row.
pub trait TurnSink {
    /// One completed turn.
    ///
    /// # Errors
    /// A [`SinkError`] ends the run at once; it comes back as [`SimError::Sink`].
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError>;

    /// The energy ledger at the end of the turn whose row comes next, just
    /// before its collision (`docs/snowball-and-losses.md` §3.2), for a run
    /// that records one ([`Losses::records_ledger`](crate::Losses::records_ledger)).
    /// Ignored unless overridden.
    ///
    /// # Errors
    /// As [`turn`](Self::turn).
    fn ledger(&mut self, _row: &LedgerRow) -> Result<(), SinkError> {
        Ok(())
    }
}

/// Gathers every row in memory (without the ledger).
impl TurnSink for Vec<TurnRow> {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.push(*row);
        Ok(())
    }
}

/// Gathers the rows and the ledger in memory (the sink behind [`run_turns`]).
#[derive(Default)]
struct Gathered {
    rows: Vec<TurnRow>,
    ledger: Vec<LedgerRow>,
}

impl TurnSink for Gathered {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.rows.push(*row);
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.ledger.push(*row);
        Ok(())
    }
}

/// How a turn run ended, once its rows have gone to the sink.
#[derive(Debug, Clone, PartialEq)]
pub struct TurnRunEnd {
    /// Which model ran.
    pub model: ModelKind,
    /// How the run ended.
    pub stop: Stop,
    /// Long-run statistics of the rows, computed as they went by.
    pub summary: TurnSummary,
    /// Integrator counts.
    pub stats: Stats,
}

/// The per-turn table of a run of a turn model.
#[derive(Debug, Clone, PartialEq)]
pub struct TurnTable {
    /// Which model produced it.
    pub model: ModelKind,
    /// One row per completed turn, in order.
    pub rows: Vec<TurnRow>,
    /// The energy ledger at the end of each turn, before its collision, for
    /// a run that records one; empty otherwise.
    pub ledger: Vec<LedgerRow>,
    /// How the run ended.
    pub stop: Stop,
    /// Long-run statistics of the rows.
    pub summary: TurnSummary,
    /// Integrator counts.
    pub stats: Stats,
}

/// Makes one [`TurnRow`] per turn-end event and sends it on, with the
/// ledger just before its collision when the run records one.
///
/// It runs through [`run_observed`], as every ODE model does, but not
/// through [`run_ode`]'s [`Recorder`], which records at the times
/// [`Sampling`](crate::Sampling) asks for rather than at the turn ends,
/// counts samples rather than turns, and would change what is recorded.
///
/// [`Recorder`]: crate::models::ode::Recorder
/// [`run_ode`]: crate::models::ode::run_ode
struct TableObserver<'a> {
    sink: &'a mut dyn TurnSink,
    summary: SummaryBuilder,
    /// Rows sent, against [`SimOptions::max_rows`], and the sink's failure.
    budget: RowBudget,
    /// Time the current turn started, s.
    t_start: f64,
    /// Speed at the start of the current turn, m/s.
    v_start: f64,
}

impl Observer<TurnSystem, 2> for TableObserver<'_> {
    fn start(&mut self, system: &TurnSystem, t0: f64, y0: &[f64; 2]) {
        self.t_start = t0;
        self.v_start = system.dynamics().radius() * y0[1];
    }

    fn event(&mut self, system: &TurnSystem, event: &EventRecord<2>) {
        if event.index != EVENT_TURN_END || self.stop_requested() {
            return;
        }
        let dynamics = system.dynamics();
        let (r, b) = (dynamics.radius(), system.snow_depth());
        let r_next = r + b;
        let omega_end = event.y_before[1];
        let v_end = r * omega_end;
        let (v_after, collision_loss) = match system.collision() {
            CollisionModel::Note => {
                // The collision keeps (r_{k+1}² + 2r_k²)/(3r_{k+1}²) of T_end (eqs. (85), (86), (89)).
                let t_end_kinetic = kinetic_energy_at_turn_end(system.rho_l(), r, b, v_end);
                (
                    collision_speed(r, b, v_end),
                    t_end_kinetic * 2.0 * b * (2.0 * r + b) / (3.0 * r_next * r_next),
                )
            }
            collision => {
                // Kinetic energy before (rolling about C, or pivoting about E)
                // minus after (eq. (82) for turn k + 1); 0 speed when stuck.
                let v_after = system.omega_next(omega_end).unwrap_or(0.0) * r_next;
                let before = if collision == CollisionModel::Pivot {
                    0.5 * system.start_mass()
                        * system.pivot_impact().inertia_e
                        * omega_end
                        * omega_end
                } else {
                    kinetic_energy_at_turn_end(system.rho_l(), r, b, v_end)
                };
                let after = kinetic_energy_at_turn_start(system.rho_l(), r_next, v_after);
                (v_after, before - after)
            }
        };
        let omega0 = self.v_start / r;
        // The contact forces while rolling: up to θ_c with `--collision pivot`.
        let ((a_min, a_max), contact) = match system.collision() {
            CollisionModel::Pivot => (
                dynamics.acceleration_range(omega0),
                dynamics.contact_range(omega0, system.pivot_impact().theta_c),
            ),
            _ => {
                let both = dynamics.turn_extremes(omega0);
                ((both.a_min, both.a_max), both.contact)
            }
        };
        let m_k = system.start_mass();
        let dt = event.t - self.t_start;
        let row = TurnRow {
            turn: system.turn(),
            t_start_s: self.t_start,
            x_start_m: system.turn_start_x(),
            v_start_m_s: self.v_start,
            t_end_s: event.t,
            v_end_m_s: v_end,
            v_after_m_s: v_after,
            collision_loss_j: collision_loss,
            mean_a_turn_m_s2: (v_end - self.v_start) / dt,
            min_a_m_s2: a_min,
            max_a_m_s2: a_max,
            mean_a_with_collision_m_s2: (v_after - self.v_start) / dt,
            min_normal_n: m_k * contact.min_normal_per_mk,
            min_normal_over_mg: contact.min_normal_over_mg,
            max_friction_ratio: contact.max_friction_ratio,
        };
        let sent = match system.ledger(event.t, &event.y_before) {
            Some(ledger) => self.sink.ledger(&ledger),
            None => Ok(()),
        }
        .and_then(|()| self.sink.turn(&row));
        if self.budget.book(sent) {
            self.summary.push(&row);
        }
        self.t_start = event.t;
        self.v_start = v_after;
    }

    fn stop_requested(&self) -> bool {
        self.budget.full()
    }
}

impl RunObserver<TurnSystem, 2> for TableObserver<'_> {
    fn budget(&mut self) -> &mut RowBudget {
        &mut self.budget
    }
}

impl TurnModel {
    /// Runs the model and sends one row per completed turn to `sink` as
    /// each turn ends, with the long-run statistics computed on the way
    /// (memory O(log n) in the number of turns; `opts.sampling` is
    /// ignored). A run asked for more turns than `opts.max_rows` is refused
    /// before it starts; without a turn count it stops at `opts.max_rows`
    /// rows ([`StopReason::RowLimit`](crate::StopReason::RowLimit)).
    ///
    /// # Errors
    /// As [`Model::simulate_into`](crate::Model::simulate_into), and
    /// [`ParamError::TooManyRows`] for too many turns.
    pub fn run_table_into(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn TurnSink,
    ) -> Result<TurnRunEnd, SimError> {
        crate::models::Model::check(self, scenario, opts)?;
        if let Some(n) = opts.turns.filter(|&n| n > opts.max_rows) {
            return Err(ParamError::TooManyRows {
                rows: n as f64,
                max_rows: opts.max_rows,
            }
            .into());
        }
        let mut system = TurnSystem::new(self.variant, scenario, opts);
        let mut observer = TableObserver {
            sink,
            summary: SummaryBuilder::new(scenario.g_along(), opts.turns),
            budget: RowBudget::new(opts.max_rows),
            t_start: 0.0,
            v_start: 0.0,
        };
        let y0 = Self::initial_state(scenario);
        if let Some(reason) = system.start(&y0) {
            // Stopped at its start: no turn was completed, so no row goes out.
            return Ok(TurnRunEnd {
                model: self.variant.kind(),
                stop: stop_at(&system, reason, 0.0, &y0),
                summary: observer.summary.finish(),
                stats: Stats::default(),
            });
        }
        let end = run_observed(&mut system, y0, opts, &mut observer)?;
        Ok(TurnRunEnd {
            model: self.variant.kind(),
            stop: end.stop,
            summary: observer.summary.finish(),
            stats: end.stats,
        })
    }

    /// Runs the model and returns one row per completed turn (the samples
    /// of [`Model::simulate`](crate::Model::simulate) are not recorded;
    /// `opts.sampling` is ignored): [`run_table_into`](Self::run_table_into)
    /// gathering the rows in memory.
    ///
    /// # Errors
    /// As [`run_table_into`](Self::run_table_into).
    pub fn run_table(&self, scenario: &Scenario, opts: &SimOptions) -> Result<TurnTable, SimError> {
        let mut gathered = Gathered::default();
        let end = self.run_table_into(scenario, opts, &mut gathered)?;
        Ok(TurnTable {
            model: end.model,
            rows: gathered.rows,
            ledger: gathered.ledger,
            stop: end.stop,
            summary: end.summary,
            stats: end.stats,
        })
    }
}

/// The variant of turn model `kind`, or the error that names the turn models.
fn variant_of(kind: ModelKind) -> Result<TurnVariant, ParamError> {
    TurnVariant::of(kind).ok_or_else(|| ParamError::UnknownModel {
        given: kind.id().to_string(),
        expected: ModelKind::ALL
            .iter()
            .filter(|k| k.is_turn_model())
            .map(|k| format!("{} ({})", k.id(), k.alias()))
            .collect::<Vec<_>>()
            .join(", "),
    })
}

/// Runs the turn model `kind` (`turns` or `turns-exact`) and returns its
/// per-turn table with the long-run statistics.
///
/// ```
/// use snowroll::{run_turns, ModelKind, Scenario, SimOptions};
/// let opts = SimOptions { turns: Some(100), t_end: 1e6, ..SimOptions::default() };
/// let table = run_turns(ModelKind::Turns, &Scenario::default(), &opts)?;
/// assert_eq!(table.rows.len(), 100);
/// // Each collision slows the log down (eq. (89)).
/// assert!(table.rows.iter().all(|r| r.v_after_m_s < r.v_end_m_s));
/// # Ok::<(), snowroll::SimError>(())
/// ```
///
/// # Errors
/// [`ParamError::UnknownModel`] (inside [`SimError::Param`]) when `kind` is
/// not a turn model; otherwise as [`TurnModel::run_table_into`].
pub fn run_turns(
    kind: ModelKind,
    scenario: &Scenario,
    opts: &SimOptions,
) -> Result<TurnTable, SimError> {
    TurnModel::new(variant_of(kind)?).run_table(scenario, opts)
}

/// [`run_turns`] with the rows sent to `sink` as they are computed
/// ([`TurnModel::run_table_into`]).
///
/// # Errors
/// As [`run_turns`], and [`SimError::Sink`] when the sink fails.
pub fn run_turns_into(
    kind: ModelKind,
    scenario: &Scenario,
    opts: &SimOptions,
    sink: &mut dyn TurnSink,
) -> Result<TurnRunEnd, SimError> {
    TurnModel::new(variant_of(kind)?).run_table_into(scenario, opts, sink)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decade_checkpoints_are_recognised() {
        let found: Vec<u64> = (0..=1000).filter(|&k| is_decade_checkpoint(k)).collect();
        assert_eq!(found, [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000]);
        assert!(is_decade_checkpoint(5_000_000_000_000_000_000));
        assert!(!is_decade_checkpoint(u64::MAX));
    }

    #[test]
    fn checkpoints_are_1_2_5_per_decade_then_the_end() {
        assert!(checkpoint_turns(0).is_empty());
        assert_eq!(checkpoint_turns(1), vec![1]);
        assert_eq!(checkpoint_turns(7), vec![1, 2, 5, 7]);
        assert_eq!(checkpoint_turns(100), vec![1, 2, 5, 10, 20, 50, 100]);
    }
}
