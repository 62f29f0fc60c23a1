//! The one adapter from an [`OdeSystem`] to what a run records: [`run_observed`]
//! runs the integrator with an observer that turns its steps and events into
//! rows ([`RunObserver`]), keeps the rows within [`SimOptions::max_rows`] and
//! the sink's failure in one [`RowBudget`], and maps the way the integration
//! ended to a [`Stop`]. Every ODE model goes through it, so the step loop's
//! bookkeeping exists once. Its usual observer is the [`Recorder`], which sends
//! samples to a [`SampleSink`] as [`Sampling`] asks, one at a time (memory O(1)
//! in the number of samples): that is [`run_ode`]. The turn table's observer
//! (`turn_by_turn/observer.rs`) is the other.

use crate::error::{SimError, SinkError};
use crate::integrate::{
    integrate, DenseStep, EventRecord, Observer, OdeSystem, Outcome, Termination,
};
use crate::trajectory::{
    LedgerRow, RunEnd, Sample, SampleSink, Sampling, SimOptions, Stop, StopReason, TurnState,
};

/// An ODE system that knows how to present its state.
pub(crate) trait OdeModel<const N: usize>: OdeSystem<N> {
    /// The sample of state `y` at time `t`.
    fn sample(&self, t: f64, y: &[f64; N]) -> Sample;

    /// The turn state, for turn models.
    fn turn_state(&self, _t: f64, _y: &[f64; N]) -> Option<TurnState> {
        None
    }

    /// The energy ledger at state `y`, for a run that records one.
    fn ledger(&self, _t: f64, _y: &[f64; N]) -> Option<LedgerRow> {
        None
    }

    /// The stop reason a stopping event `index` stands for.
    fn stop_reason(&self, event: usize) -> StopReason;
}

/// The rows a run has sent to its sink, against [`SimOptions::max_rows`],
/// and the sink's failure: what ends a run from the observer's side. Every
/// [`RunObserver`] keeps one.
#[derive(Debug)]
pub(crate) struct RowBudget {
    /// Rows sent so far.
    rows: u64,
    max_rows: u64,
    /// The sink's failure, which ends the run.
    failed: Option<SinkError>,
}

impl RowBudget {
    pub(crate) fn new(max_rows: u64) -> Self {
        Self {
            rows: 0,
            max_rows,
            failed: None,
        }
    }

    /// Whether no more rows may go out (the sink failed, or the limit):
    /// the observer's [`Observer::stop_requested`].
    pub(crate) fn full(&self) -> bool {
        self.failed.is_some() || self.rows >= self.max_rows
    }

    /// Whether the sink failed.
    pub(crate) fn failed(&self) -> bool {
        self.failed.is_some()
    }

    /// Books the sending of one row: counted if it went out, kept as the
    /// run's failure if not. Returns whether it went out.
    pub(crate) fn book(&mut self, sent: Result<(), SinkError>) -> bool {
        match sent {
            Ok(()) => {
                self.rows += 1;
                true
            }
            Err(e) => {
                self.failed = Some(e);
                false
            }
        }
    }
}

/// An observer of the integrator that records a run for [`run_observed`]:
/// it stops the run through its [`RowBudget`] and may add a last row once
/// the integration has ended.
pub(crate) trait RunObserver<M, const N: usize>: Observer<M, N> {
    /// The observer's rows and sink failure.
    fn budget(&mut self) -> &mut RowBudget;

    /// The integration ended at `(t, y)`; called before the sink's failure
    /// is looked at. Does nothing unless overridden.
    fn finish(&mut self, _system: &M, _t: f64, _y: &[f64; N]) {}
}

/// Sends samples to a [`SampleSink`] as a [`Sampling`] asks, and asks the
/// integrator to stop when the sink fails or [`SimOptions::max_rows`] rows
/// have gone out.
pub(crate) struct Recorder<'a> {
    sampling: &'a Sampling,
    /// Next requested time (index into the list or the grid).
    next: usize,
    /// Requested end of the run (grid sampling stops there).
    t_end: f64,
    sink: &'a mut dyn SampleSink,
    /// Rows sent, against [`SimOptions::max_rows`], and the sink's failure.
    budget: RowBudget,
    /// Time of the last row sent, s.
    last_t: Option<f64>,
}

impl<'a> Recorder<'a> {
    pub fn new(opts: &'a SimOptions, sink: &'a mut dyn SampleSink) -> Self {
        Self {
            sampling: &opts.sampling,
            next: 0,
            t_end: opts.t_end,
            sink,
            budget: RowBudget::new(opts.max_rows),
            last_t: None,
        }
    }

    /// The `next`-th requested time, if any.
    fn requested(&self, i: usize) -> Option<f64> {
        match self.sampling {
            Sampling::Times(ts) => ts.get(i).copied(),
            Sampling::Every(dt) => Sampling::grid_time(*dt, i, self.t_end),
            _ => None,
        }
    }

    fn push<const N: usize, M: OdeModel<N>>(&mut self, model: &M, t: f64, y: &[f64; N]) {
        if self.budget.full() {
            return;
        }
        let turn = model.turn_state(t, y);
        // The ledger row goes first: the sink writes it with the sample.
        let sent = match model.ledger(t, y) {
            Some(row) => self.sink.ledger(&row),
            None => Ok(()),
        }
        .and_then(|()| self.sink.sample(&model.sample(t, y), turn.as_ref()));
        if self.budget.book(sent) {
            self.last_t = Some(t);
        }
    }

    /// Samples all requested times up to and including `t_hi`, evaluated by `at`.
    fn drain<const N: usize, M: OdeModel<N>>(
        &mut self,
        model: &M,
        t_hi: f64,
        mut at: impl FnMut(f64) -> Option<[f64; N]>,
    ) {
        while let Some(t) = self.requested(self.next) {
            if t > t_hi || self.budget.full() {
                break;
            }
            if let Some(y) = at(t) {
                self.push(model, t, &y);
            }
            self.next += 1;
        }
    }
}

impl<const N: usize, M: OdeModel<N>> Observer<M, N> for Recorder<'_> {
    fn start(&mut self, model: &M, t0: f64, y0: &[f64; N]) {
        match self.sampling {
            Sampling::Steps | Sampling::Ends => self.push(model, t0, y0),
            Sampling::Times(_) | Sampling::Every(_) => self.drain(model, t0, |_| Some(*y0)),
        }
    }

    fn wants_dense(&self, _t_old: f64, t_new: f64) -> bool {
        !self.budget.full() && self.requested(self.next).is_some_and(|t| t <= t_new)
    }

    fn step(&mut self, model: &M, step: &DenseStep<'_, N>) {
        match self.sampling {
            Sampling::Steps => self.push(model, step.t_new, step.y_new),
            Sampling::Times(_) | Sampling::Every(_) => {
                self.drain(model, step.t_new, |t| step.eval(t));
            }
            Sampling::Ends => {}
        }
    }

    fn event(&mut self, _model: &M, _event: &EventRecord<N>) {}

    /// The sink failed, or the row limit is reached with another row still
    /// due: a list of times whose last one was the last row allowed runs on
    /// to its end (issue 33, item 4: `--times 0.5,1,2 --max-rows 3` stopped
    /// at the row limit).
    fn stop_requested(&self) -> bool {
        let more_due = match self.sampling {
            Sampling::Times(_) | Sampling::Every(_) => self.requested(self.next).is_some(),
            Sampling::Steps | Sampling::Ends => true,
        };
        self.budget.failed() || (self.budget.full() && more_due)
    }
}

impl<const N: usize, M: OdeModel<N>> RunObserver<M, N> for Recorder<'_> {
    fn budget(&mut self) -> &mut RowBudget {
        &mut self.budget
    }

    /// For `Ends`, adds the final state.
    fn finish(&mut self, model: &M, t: f64, y: &[f64; N]) {
        if matches!(self.sampling, Sampling::Ends) && self.last_t.is_none_or(|lt| lt < t) {
            self.push(model, t, y);
        }
    }
}

/// How a run stopped for `reason` at time `t`, where it was at `sample`
/// with turn state `turn`.
fn stop_from(reason: StopReason, t: f64, sample: &Sample, turn: Option<TurnState>) -> Stop {
    Stop {
        reason,
        t_s: t,
        x_m: sample.x_m,
        v_m_s: sample.v_m_s,
        turn,
    }
}

/// How a run of `system` stopped for `reason` at state `y`, time `t`.
pub(crate) fn stop_at<const N: usize, M: OdeModel<N>>(
    system: &M,
    reason: StopReason,
    t: f64,
    y: &[f64; N],
) -> Stop {
    stop_from(reason, t, &system.sample(t, y), system.turn_state(t, y))
}

/// The stop reason of an integration that ended by `termination`: the
/// system names its stopping events, and an observer's request to stop
/// means the rows ran out ([`StopReason::RowLimit`]; a failed sink never
/// gets this far).
fn stop_reason<const N: usize, M: OdeModel<N>>(system: &M, termination: Termination) -> StopReason {
    match termination {
        Termination::EndTime => StopReason::EndTime,
        Termination::Event { index } => system.stop_reason(index),
        Termination::StepLimit => StopReason::StepLimit,
        Termination::Stopped => StopReason::RowLimit,
    }
}

/// A run that stops at its start, `y0` at t = 0, for `reason`: the one
/// sample goes to `sink`.
pub(crate) fn stopped_at_start<const N: usize, M: OdeModel<N>>(
    system: &M,
    y0: [f64; N],
    reason: StopReason,
    sink: &mut dyn SampleSink,
) -> Result<RunEnd, SimError> {
    let first = system.sample(0.0, &y0);
    let turn = system.turn_state(0.0, &y0);
    if let Some(row) = system.ledger(0.0, &y0) {
        sink.ledger(&row).map_err(SimError::Sink)?;
    }
    sink.sample(&first, turn.as_ref()).map_err(SimError::Sink)?;
    Ok(RunEnd {
        stop: stop_from(reason, 0.0, &first, turn),
        stats: Default::default(),
        hop_doubt: None,
    })
}

/// Runs `system` from `y0` at t = 0 under `opts`, reporting the steps and
/// events to `observer`, and reports how the run ended.
///
/// # Errors
/// As [`integrate`], and [`SimError::Sink`] when the observer's sink failed.
pub(crate) fn run_observed<const N: usize, M: OdeModel<N>, O: RunObserver<M, N>>(
    system: &mut M,
    y0: [f64; N],
    opts: &SimOptions,
    observer: &mut O,
) -> Result<RunEnd, SimError> {
    let outcome = integrate(system, 0.0, y0, opts.t_end, &opts.tolerances, observer)?;
    end_observed(system, observer, outcome)
}

/// How a run observed by `observer` ended at `outcome` (of the integrator,
/// or of a path that computes the same events without it): the observer's
/// last word, its sink's failure, or the stop.
///
/// # Errors
/// [`SimError::Sink`] when the observer's sink failed.
pub(crate) fn end_observed<const N: usize, M: OdeModel<N>, O: RunObserver<M, N>>(
    system: &M,
    observer: &mut O,
    outcome: Outcome<N>,
) -> Result<RunEnd, SimError> {
    observer.finish(system, outcome.t, &outcome.y);
    if let Some(e) = observer.budget().failed.take() {
        return Err(SimError::Sink(e));
    }
    let reason = stop_reason(system, outcome.termination);
    Ok(RunEnd {
        stop: stop_at(system, reason, outcome.t, &outcome.y),
        stats: outcome.stats,
        hop_doubt: None,
    })
}

/// Runs `system` from `y0` at t = 0 under `opts`, sending the samples to
/// `sink` ([`Recorder`]), and reports how the run ended.
pub(crate) fn run_ode<const N: usize, M: OdeModel<N>>(
    system: &mut M,
    y0: [f64; N],
    opts: &SimOptions,
    sink: &mut dyn SampleSink,
) -> Result<RunEnd, SimError> {
    run_observed(system, y0, opts, &mut Recorder::new(opts, sink))
}
