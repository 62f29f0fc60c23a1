//! Running a turn model: [`TurnModel`] as a [`Model`] (samples), and its
//! per-turn table ([`TurnModel::run_table_into`], [`run_turns`]), both
//! through the one run of the integrator in `models/ode.rs`.

use super::observer::TableObserver;
use super::{
    check_turn_losses, check_turn_scale, run_closed, HopDoubt, SummaryBuilder, TurnRow, TurnSink,
    TurnSummary, TurnSystem, TurnVariant,
};
use crate::error::{ParamError, SimError, SinkError};
use crate::integrate::Stats;
use crate::models::ode::{run_observed, run_ode, stop_at, stopped_at_start};
use crate::models::{Model, ModelKind};
use crate::scenario::Scenario;
use crate::trajectory::{LedgerRow, RunEnd, SampleSink, SimOptions, Stop};

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
    /// On the integrator's path of a run the closed form does not cover
    /// (`--collision pivot`), the first turn whose least normal force is
    /// within the integrator's error of 0, so that the first hop may depend
    /// on the tolerance (`docs/contact-forces.md`); `None` otherwise.
    pub hop_doubt: Option<HopDoubt>,
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
    /// On the integrator's path of a run the closed form does not cover
    /// (`--collision pivot`), the first turn whose least normal force is
    /// within the integrator's error of 0, so that the first hop may depend
    /// on the tolerance (`docs/contact-forces.md`); `None` otherwise.
    pub hop_doubt: Option<HopDoubt>,
}

/// The turn-by-turn model of §3.4 (ids `turns`, `turns-exact`).
///
/// ```
/// use snowroll::{Model, Scenario, SimOptions, StopReason, TurnModel, TurnVariant};
/// let opts = SimOptions { turns: Some(3), t_end: 1e3, ..SimOptions::default() };
/// let traj = TurnModel::new(TurnVariant::Paper).simulate(&Scenario::default(), &opts)?;
/// assert_eq!(traj.stop.reason, StopReason::Turns);
/// assert_eq!(traj.turn_states.last().unwrap().turn, 2);
/// # Ok::<(), snowroll::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TurnModel {
    variant: TurnVariant,
    method: TurnMethod,
}

/// How the per-turn table of a turn model is computed
/// (`docs/turn-model.md`, "The closed-form path"). Both give the same
/// table to the integrator's error (a test holds them to 1e-12 relative at
/// the integrator's tightest tolerance); the samples of
/// [`Model::simulate`](crate::Model::simulate) always come from the integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum TurnMethod {
    /// Each turn from its energy integral: θ̇(θ) in closed form, the time by
    /// quadrature, the stall, hop and slip angles by root finding, the
    /// collision algebraically. Runs it does not cover go to the
    /// integrator: `--collision pivot`, and a start from rest where the log
    /// does not surely start ([`TurnModel::method_for`] says which ran).
    /// The command line's help says the same in its own words (no link).
    #[cfg_attr(
        feature = "clap",
        value(
            help = "Each turn from its energy integral: θ̇(θ) in closed form, the time by quadrature, \
                      the stall, hop and slip angles by root finding, the collision algebraically. Runs \
                      it does not cover go to the integrator, and a note on stderr says so: \
                      `--collision pivot`, and a start from rest where the log does not surely start"
        )
    )]
    #[default]
    Closed,
    /// DOP853 with events and the collision as a reset (rtol, atol and
    /// max_steps apply).
    Ode,
}

impl TurnMethod {
    /// Every method, the default first.
    pub const ALL: [TurnMethod; 2] = [TurnMethod::Closed, TurnMethod::Ode];

    /// The method's word (`closed`, `ode`).
    pub fn id(self) -> &'static str {
        match self {
            TurnMethod::Closed => "closed",
            TurnMethod::Ode => "ode",
        }
    }
}

impl TurnModel {
    /// The model with the mass properties of `variant`, its table computed
    /// in closed form where that covers the run ([`TurnMethod::Closed`]).
    pub fn new(variant: TurnVariant) -> Self {
        Self {
            variant,
            method: TurnMethod::Closed,
        }
    }

    /// The same model with its table computed by `method`.
    pub fn with_method(self, method: TurnMethod) -> Self {
        Self { method, ..self }
    }

    /// Its variant.
    pub fn variant(&self) -> TurnVariant {
        self.variant
    }

    /// The method that computes the table of a run of `scenario` under
    /// `opts`: the one asked for, except that [`TurnMethod::Closed`] falls
    /// back to [`TurnMethod::Ode`] for what it does not cover.
    pub fn method_for(&self, scenario: &Scenario, opts: &SimOptions) -> TurnMethod {
        let system = TurnSystem::new(self.variant, scenario, opts);
        match self.method {
            TurnMethod::Closed if system.closed_form_covers(&Self::initial_state(scenario)) => {
                TurnMethod::Closed
            }
            _ => TurnMethod::Ode,
        }
    }

    /// The initial state `[θ, θ̇] = [0, v0/r0]`.
    fn initial_state(s: &Scenario) -> [f64; 2] {
        [0.0, s.initial_speed() / s.initial_radius()]
    }
}

impl Model for TurnModel {
    fn kind(&self) -> ModelKind {
        self.variant.kind()
    }

    /// The common checks, and the turn models' own: the scale of a turn
    /// ([`check_turn_scale`]) and the losses they do not take.
    fn check(&self, scenario: &Scenario, opts: &SimOptions) -> Result<(), SimError> {
        opts.validate()?;
        self.kind().check_shape(scenario)?;
        super::check_turn_unwinding(self.kind(), scenario)?;
        check_turn_scale(scenario, opts)?;
        check_turn_losses(self.kind(), opts)?;
        crate::models::check_tolerances(self.kind(), scenario, opts)?;
        Ok(())
    }

    fn simulate_into(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError> {
        self.check(scenario, opts)?;
        let mut system = TurnSystem::new(self.variant, scenario, opts);
        let y0 = Self::initial_state(scenario);
        system.track_exact_starts(&y0);
        if let Some(reason) = system.start(&y0) {
            return stopped_at_start(&system, y0, reason, sink);
        }
        let end = run_ode(&mut system, y0, opts, sink)?;
        Ok(RunEnd {
            hop_doubt: system.hop_doubt(),
            ..end
        })
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
        let summary = SummaryBuilder::new(scenario.g_along(), opts.turns);
        let mut observer = TableObserver::new(sink, summary, opts.max_rows);
        let y0 = Self::initial_state(scenario);
        let closed = self.method == TurnMethod::Closed && system.closed_form_covers(&y0);
        if !closed {
            system.track_exact_starts(&y0);
        }
        if let Some(reason) = system.start(&y0) {
            // Stopped at its start: no turn was completed, so no row goes out.
            return Ok(TurnRunEnd {
                model: self.variant.kind(),
                stop: stop_at(&system, reason, 0.0, &y0),
                summary: observer.into_summary(),
                stats: Stats::default(),
                hop_doubt: None,
            });
        }
        let end = if closed {
            run_closed(&mut system, y0, opts.t_end, &mut observer)?
        } else {
            run_observed(&mut system, y0, opts, &mut observer)?
        };
        Ok(TurnRunEnd {
            model: self.variant.kind(),
            stop: end.stop,
            summary: observer.into_summary(),
            stats: end.stats,
            hop_doubt: system.hop_doubt(),
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
            hop_doubt: end.hop_doubt,
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
