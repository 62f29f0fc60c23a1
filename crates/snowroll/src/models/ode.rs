//! The one adapter from an [`OdeSystem`] to a [`Trajectory`]: it runs the
//! integrator and records samples as [`Sampling`] asks. Every ODE model goes
//! through [`run_ode`], so the step loop exists once.

use super::ModelKind;
use crate::error::SimError;
use crate::integrate::{integrate, DenseStep, EventRecord, Observer, OdeSystem, Termination};
use crate::trajectory::{
    LedgerRow, Sample, Sampling, SimOptions, Stop, StopReason, Trajectory, TurnState,
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

/// Records samples as a [`Sampling`] asks.
pub(crate) struct Recorder<'a> {
    sampling: &'a Sampling,
    /// Next requested time (index into the list or the grid).
    next: usize,
    /// Requested end of the run (grid sampling stops there).
    t_end: f64,
    pub samples: Vec<Sample>,
    pub turns: Vec<TurnState>,
    pub ledger: Vec<LedgerRow>,
}

impl<'a> Recorder<'a> {
    pub fn new(sampling: &'a Sampling, t_end: f64) -> Self {
        Self {
            sampling,
            next: 0,
            t_end,
            samples: Vec::new(),
            turns: Vec::new(),
            ledger: Vec::new(),
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
        self.samples.push(model.sample(t, y));
        if let Some(ts) = model.turn_state(t, y) {
            self.turns.push(ts);
        }
        if let Some(row) = model.ledger(t, y) {
            self.ledger.push(row);
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
            if t > t_hi {
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
        if matches!(self.sampling, Sampling::Ends) {
            let last_t = self.samples.last().map(|s| s.t_s);
            if last_t.is_none_or(|lt| lt < t) {
                self.push(model, t, y);
            }
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
        self.requested(self.next).is_some_and(|t| t <= t_new)
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
}

/// The trajectory of a run that stops at its start, `y0` at t = 0, for `reason`.
pub(crate) fn stopped_at_start<const N: usize, M: OdeModel<N>>(
    kind: ModelKind,
    system: &M,
    y0: [f64; N],
    reason: StopReason,
) -> Trajectory {
    let first = system.sample(0.0, &y0);
    Trajectory {
        model: kind,
        samples: vec![first],
        turn_states: system.turn_state(0.0, &y0).into_iter().collect(),
        stop: Stop {
            reason,
            t_s: 0.0,
            x_m: first.x_m,
            v_m_s: first.v_m_s,
            turn: system.turn_state(0.0, &y0),
        },
        stats: Default::default(),
        ledger: system.ledger(0.0, &y0).into_iter().collect(),
    }
}

/// Runs `system` from `y0` at t = 0 under `opts` and packages the result.
pub(crate) fn run_ode<const N: usize, M: OdeModel<N>>(
    kind: ModelKind,
    system: &mut M,
    y0: [f64; N],
    opts: &SimOptions,
) -> Result<Trajectory, SimError> {
    let mut recorder = Recorder::new(&opts.sampling, opts.t_end);
    let outcome = integrate(system, 0.0, y0, opts.t_end, &opts.tolerances, &mut recorder)?;
    recorder.finish(system, outcome.t, &outcome.y);
    let reason = match outcome.termination {
        Termination::EndTime => StopReason::EndTime,
        Termination::Event { index } => system.stop_reason(index),
    };
    let last = system.sample(outcome.t, &outcome.y);
    Ok(Trajectory {
        model: kind,
        samples: recorder.samples,
        turn_states: recorder.turns,
        stop: Stop {
            reason,
            t_s: outcome.t,
            x_m: last.x_m,
            v_m_s: last.v_m_s,
            turn: system.turn_state(outcome.t, &outcome.y),
        },
        stats: outcome.stats,
        ledger: recorder.ledger,
    })
}
