//! The one adapter from an [`OdeSystem`] to a [`SampleSink`]: it runs the
//! integrator and sends samples as [`Sampling`] asks, one at a time (memory
//! O(1) in the number of samples). Every ODE model goes through [`run_ode`],
//! so the step loop exists once.

use crate::error::{SimError, SinkError};
use crate::integrate::{integrate, DenseStep, EventRecord, Observer, OdeSystem, Termination};
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
    /// Rows sent so far.
    rows: u64,
    max_rows: u64,
    /// Time of the last row sent, s.
    last_t: Option<f64>,
    /// The sink's failure, which ends the run.
    failed: Option<SinkError>,
}

impl<'a> Recorder<'a> {
    pub fn new(opts: &'a SimOptions, sink: &'a mut dyn SampleSink) -> Self {
        Self {
            sampling: &opts.sampling,
            next: 0,
            t_end: opts.t_end,
            sink,
            rows: 0,
            max_rows: opts.max_rows,
            last_t: None,
            failed: None,
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

    /// Whether no more rows may go out (the sink failed, or the limit).
    fn full(&self) -> bool {
        self.failed.is_some() || self.rows >= self.max_rows
    }

    fn push<const N: usize, M: OdeModel<N>>(&mut self, model: &M, t: f64, y: &[f64; N]) {
        if self.full() {
            return;
        }
        let turn = model.turn_state(t, y);
        // The ledger row goes first: the sink writes it with the sample.
        let sent = match model.ledger(t, y) {
            Some(row) => self.sink.ledger(&row),
            None => Ok(()),
        }
        .and_then(|()| self.sink.sample(&model.sample(t, y), turn.as_ref()));
        match sent {
            Ok(()) => {
                self.rows += 1;
                self.last_t = Some(t);
            }
            Err(e) => self.failed = Some(e),
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
            if t > t_hi || self.full() {
                break;
            }
            if let Some(y) = at(t) {
                self.push(model, t, &y);
            }
            self.next += 1;
        }
    }

    /// Finishes: for `Ends`, adds the final state.
    pub fn finish<const N: usize, M: OdeModel<N>>(&mut self, model: &M, t: f64, y: &[f64; N]) {
        if matches!(self.sampling, Sampling::Ends) && self.last_t.is_none_or(|lt| lt < t) {
            self.push(model, t, y);
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
        !self.full() && self.requested(self.next).is_some_and(|t| t <= t_new)
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

    fn stop_requested(&self) -> bool {
        self.full()
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
        stop: Stop {
            reason,
            t_s: 0.0,
            x_m: first.x_m,
            v_m_s: first.v_m_s,
            turn,
        },
        stats: Default::default(),
    })
}

/// Runs `system` from `y0` at t = 0 under `opts`, sending the samples to
/// `sink`, and reports how the run ended.
pub(crate) fn run_ode<const N: usize, M: OdeModel<N>>(
    system: &mut M,
    y0: [f64; N],
    opts: &SimOptions,
    sink: &mut dyn SampleSink,
) -> Result<RunEnd, SimError> {
    let mut recorder = Recorder::new(opts, sink);
    let outcome = integrate(system, 0.0, y0, opts.t_end, &opts.tolerances, &mut recorder)?;
    recorder.finish(system, outcome.t, &outcome.y);
    if let Some(e) = recorder.failed {
        return Err(SimError::Sink(e));
    }
    let reason = match outcome.termination {
        Termination::EndTime => StopReason::EndTime,
        Termination::Event { index } => system.stop_reason(index),
        Termination::StepLimit => StopReason::StepLimit,
        Termination::Stopped => StopReason::RowLimit,
    };
    let last = system.sample(outcome.t, &outcome.y);
    Ok(RunEnd {
        stop: Stop {
            reason,
            t_s: outcome.t,
            x_m: last.x_m,
            v_m_s: last.v_m_s,
            turn: system.turn_state(outcome.t, &outcome.y),
        },
        stats: outcome.stats,
    })
}
