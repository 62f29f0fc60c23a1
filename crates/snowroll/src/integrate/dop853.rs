//! The DOP853 step loop: stages, Hairer's error norm, dense output, and
//! event handling. The step-size control is in `control.rs`.

// The stage loops index several tableau rows and the stage array with the
// same counters, as the method is written on paper; iterator chains would
// hide that correspondence.
#![allow(clippy::needless_range_loop)]

use super::armed::Armed;
use super::control::{initial_step, StepControl};
use super::dense::{DenseStep, Form, Polynomial, DENSE_TERMS};
use super::events::{crossings, scan_step_ends};
use super::peaks::Peaks;
use super::tableau::{A, B, C, D, E3, E5};
use super::{
    EventAction, EventRecord, Observer, OdeSystem, Outcome, Stats, Termination, Tolerances,
    MAX_EVENTS,
};
use crate::error::SimError;

/// Stages of the 8th-order solution.
pub(super) const STAGES: usize = 12;
/// Stages including the three extra ones of the dense output.
const STAGES_DENSE: usize = 16;

/// `Σ_j w[j] k[j]` over the non-zero weights, component by component.
///
/// Every caller passes a row of the tableau constants, so once this is
/// inlined the loop is unrolled and the zero entries (a third of `A`) drop
/// out at compile time; the inner loop over components vectorises.
#[inline(always)]
fn weighted_sum<const N: usize>(w: &[f64], k: &[[f64; N]; STAGES_DENSE]) -> [f64; N] {
    let mut acc = [0.0; N];
    for (&wj, kj) in w.iter().zip(k) {
        if wj != 0.0 {
            for n in 0..N {
                acc[n] += wj * kj[n];
            }
        }
    }
    acc
}

pub(super) struct Integrator<'s, S, const N: usize> {
    pub(super) system: &'s mut S,
    pub(super) tol: Tolerances,
    /// Stages: `k[0..12]` the twelve of the step, `k[12] = f(t + h, y_new)`
    /// (the first stage of the next step), `k[13..16]` the dense-output stages.
    pub(super) k: [[f64; N]; STAGES_DENSE],
    pub(super) stats: Stats,
    /// The leading components in the error norm
    /// ([`OdeSystem::controlled_components`]); the rest are quadratures.
    pub(super) controlled: usize,
    /// The event functions that can fire ([`OdeSystem::event_armed`]);
    /// the event values below are kept by their slots.
    pub(super) armed: Armed,
    /// Armed event values at the start of the current step (a small fixed
    /// buffer: no model has more than a handful of events).
    pub(super) g_old: [f64; MAX_EVENTS],
    /// Armed event values at the end of the current step.
    pub(super) g_new: [f64; MAX_EVENTS],
    /// Events located so far (they count towards `tol.max_steps`).
    pub(super) events_located: u64,
    /// The slopes of the events that may turn back within a step.
    pub(super) peaks: Peaks,
}

impl<S: OdeSystem<N>, const N: usize> Integrator<'_, S, N> {
    /// Evaluates stage `STAGE` at `t + C[STAGE] h`, from the argument
    /// `y + h Σ_{j<STAGE} A[STAGE][j] k_j`.
    #[inline(always)]
    fn stage<const STAGE: usize>(&mut self, t: f64, y: &[f64; N], h: f64) {
        let mut arg = *y;
        let sum = weighted_sum(&A[STAGE][..STAGE], &self.k);
        for n in 0..N {
            arg[n] += h * sum[n];
        }
        self.system.rhs(t + C[STAGE] * h, &arg, &mut self.k[STAGE]);
        self.stats.evaluations += 1;
    }

    /// One trial step from `(t, y)` with `k[0] = f(t, y)`: the 8th-order
    /// solution and Hairer's error norm
    /// `err = |h| err5 / sqrt(N (err5 + 0.01 err3))`, where `err5` and
    /// `err3` are the sums of squares of the scaled 5th- and 3rd-order
    /// estimators (DOP853's `ERR`).
    fn trial(&mut self, t: f64, y: &[f64; N], h: f64) -> ([f64; N], f64) {
        self.stage::<1>(t, y, h);
        self.stage::<2>(t, y, h);
        self.stage::<3>(t, y, h);
        self.stage::<4>(t, y, h);
        self.stage::<5>(t, y, h);
        self.stage::<6>(t, y, h);
        self.stage::<7>(t, y, h);
        self.stage::<8>(t, y, h);
        self.stage::<9>(t, y, h);
        self.stage::<10>(t, y, h);
        self.stage::<11>(t, y, h);
        let mut y_new = *y;
        let slope = weighted_sum(&B, &self.k);
        let est5 = weighted_sum(&E5, &self.k);
        let est3 = weighted_sum(&E3, &self.k);
        let (mut err5, mut err3) = (0.0, 0.0);
        for n in 0..N {
            y_new[n] += h * slope[n];
        }
        for n in 0..self.controlled {
            let scale = self.tol.atol + self.tol.rtol * y[n].abs().max(y_new[n].abs());
            let (e5, e3) = (est5[n] / scale, est3[n] / scale);
            err5 += e5 * e5;
            err3 += e3 * e3;
        }
        let mut denom = err5 + 0.01 * err3;
        if denom <= 0.0 {
            denom = 1.0;
        }
        let err = h.abs() * err5 * (1.0 / (self.controlled as f64 * denom)).sqrt();
        (y_new, err)
    }

    /// `k[12] = f(t_new, y_new)`: needed once a step is accepted, by the
    /// dense output and as the first stage of the next step (FSAL). Hairer
    /// evaluates it only after acceptance, so rejected steps cost 11
    /// evaluations, not 12.
    fn last_stage(&mut self, t_new: f64, y_new: &[f64; N]) {
        self.system.rhs(t_new, y_new, &mut self.k[STAGES]);
        self.stats.evaluations += 1;
    }

    /// Coefficients `F0..F6` of the dense output (see [`Polynomial`]) on the accepted step
    /// `(t, y) → (t + h, y_new)`; evaluates the three extra stages 13–15
    /// (Hairer's `CONT`, with `F_i = CONT(i + 1)`).
    fn dense_coefficients(
        &mut self,
        t: f64,
        y: &[f64; N],
        y_new: &[f64; N],
        h: f64,
    ) -> [[f64; N]; DENSE_TERMS] {
        self.stage::<13>(t, y, h);
        self.stage::<14>(t, y, h);
        self.stage::<15>(t, y, h);
        let mut f = [[0.0; N]; DENSE_TERMS];
        for n in 0..N {
            let dy = y_new[n] - y[n];
            let bspl = h * self.k[0][n] - dy;
            f[0][n] = dy;
            f[1][n] = bspl;
            f[2][n] = dy - h * self.k[STAGES][n] - bspl;
        }
        for (fi, d) in f[3..].iter_mut().zip(&D) {
            let sum = weighted_sum(d, &self.k);
            for n in 0..N {
                fi[n] = h * sum[n];
            }
        }
        f
    }

    /// The end of the run at `(t, y)`, with the counts so far.
    pub(super) fn outcome(&self, t: f64, y: [f64; N], termination: Termination) -> Outcome<N> {
        Outcome {
            t,
            y,
            termination,
            stats: self.stats,
        }
    }

    /// Hairer's initial step guess at `(t, y)` ([`initial_step`]), with
    /// its one evaluation of the right-hand side counted.
    pub(super) fn initial_step(&mut self, t: f64, y: &[f64; N]) -> f64 {
        let h = initial_step(
            &*self.system,
            &self.tol,
            self.controlled,
            (t, y),
            &self.k[0],
        );
        self.stats.evaluations += 1;
        h
    }
}

impl<'s, S: OdeSystem<N>, const N: usize> Integrator<'s, S, N> {
    /// The integrator of `system` under `tol`, its events armed and watched
    /// as the system says, nothing evaluated yet.
    pub(super) fn new(system: &'s mut S, tol: &Tolerances, n_events: usize) -> Self {
        let controlled = system.controlled_components().clamp(1, N);
        let armed = Armed::new(&*system, n_events);
        let peaks = Peaks::new(&*system, armed);
        Self {
            system,
            tol: *tol,
            k: [[0.0; N]; STAGES_DENSE],
            stats: Stats::default(),
            controlled,
            armed,
            g_old: [0.0; MAX_EVENTS],
            g_new: [0.0; MAX_EVENTS],
            events_located: 0,
            peaks,
        }
    }
}

/// Why an accepted step did not simply carry the integration to its end.
pub(super) enum Interrupt<const N: usize> {
    /// The run is over (a `Stop` event, or the step budget spent on events).
    Finish(Outcome<N>),
    /// A `Reset` event at this time: go on from this state.
    Reset(f64, [f64; N]),
}

impl<S: OdeSystem<N>, const N: usize> Integrator<'_, S, N> {
    /// Steps taken so far: accepted, rejected, and located events (what
    /// [`Tolerances::max_steps`] bounds).
    pub(super) fn steps_spent(&self) -> u64 {
        self.stats.accepted + self.stats.rejected + self.events_located
    }

    /// Starts (or, after a reset, restarts) the integration at `(t, y)`:
    /// the event values there and the first stage `k[0] = f(t, y)`.
    pub(super) fn restart(&mut self, t: f64, y: &[f64; N]) {
        for (g, &i) in self.g_old.iter_mut().zip(self.armed.indices()) {
            *g = self.system.event(i, t, y);
        }
        self.system.rhs(t, y, &mut self.k[0]);
        self.stats.evaluations += 1;
        self.peaks.restart();
    }

    /// Goes on from the state `y` a `Reset` event left at `t` (either step
    /// loop, DOP853's or the Taylor series'): the state must be finite, the
    /// integration restarts there ([`Integrator::restart`]), and a reset at
    /// or past `t_end` ends the run there.
    pub(super) fn reset_to(
        &mut self,
        t: f64,
        y: &[f64; N],
        t_end: f64,
    ) -> Result<Option<Outcome<N>>, SimError> {
        if !y.iter().all(|v| v.is_finite()) {
            return Err(SimError::NonFiniteState { t });
        }
        self.restart(t, y);
        Ok((t >= t_end).then(|| self.outcome(t, *y, Termination::EndTime)))
    }

    /// The step loop from `(t, y)` to `t_end`: trial steps, the
    /// controller's verdict, and for each accepted step its events and its
    /// report to the observer ([`Integrator::accept`]).
    pub(super) fn run<O: Observer<S, N>>(
        &mut self,
        mut t: f64,
        mut y: [f64; N],
        t_end: f64,
        observer: &mut O,
    ) -> Result<Outcome<N>, SimError> {
        self.restart(t, &y);
        let mut control = StepControl {
            h: self.initial_step(t, &y),
            last_rejected: false,
        };
        loop {
            if observer.stop_requested() {
                return Ok(self.outcome(t, y, Termination::Stopped));
            }
            if self.steps_spent() >= self.tol.max_steps {
                return Ok(self.outcome(t, y, Termination::StepLimit));
            }
            // Hairer's test, plus a NaN step (from a right-hand side that is
            // NaN at the start) counting as too small.
            let h = control.h;
            if 0.1 * h <= t.abs() * f64::EPSILON || h.is_nan() {
                return Err(SimError::StepSizeTooSmall { t, h });
            }
            // The step that would land within 1% of the end lands on it.
            let last = t + 1.01 * h >= t_end;
            if last {
                control.h = t_end - t;
            }
            let h = control.h;
            let (y_new, err) = self.trial(t, &y, h);
            let Some(fac11) = control.judge(err) else {
                self.stats.rejected += 1;
                continue;
            };
            self.stats.accepted += 1;
            let t_new = if last { t_end } else { t + h };
            if !y_new.iter().all(|v| v.is_finite()) {
                return Err(SimError::NonFiniteState { t: t_new });
            }
            self.last_stage(t_new, &y_new);
            match self.accept(observer, (t, &y), (t_new, &y_new), h, None) {
                None => {}
                Some(Interrupt::Finish(outcome)) => return Ok(outcome),
                Some(Interrupt::Reset(te, y_after)) => {
                    // Start afresh from the new state, with the step size
                    // that was just accepted (the controller shrinks it if
                    // the new state needs that).
                    (t, y) = (te, y_after);
                    if let Some(outcome) = self.reset_to(t, &y, t_end)? {
                        return Ok(outcome);
                    }
                    control.last_rejected = false;
                    continue;
                }
            }
            // Advance (FSAL: stage 12 is f(t_new, y_new)).
            self.k[0] = self.k[STAGES];
            t = t_new;
            y = y_new;
            let n = self.armed.len();
            self.g_old[..n].copy_from_slice(&self.g_new[..n]);
            self.peaks.advance();
            if last {
                return Ok(self.outcome(t, y, Termination::EndTime));
            }
            control.grow(fac11, self.tol.max_step);
        }
    }

    /// Finishes the accepted step `(t, y) → (t_new, y_new)` of length `h`
    /// (with `k[12]` evaluated): finds its events, builds the dense output
    /// if they or the observer need it, and reports the step to the
    /// observer, cut at each event ([`Integrator::handle_events`]). Leaves
    /// the event values at `t_new` in `g_new`.
    pub(super) fn accept<O: Observer<S, N>>(
        &mut self,
        observer: &mut O,
        (t, y): (f64, &[f64; N]),
        (t_new, y_new): (f64, &[f64; N]),
        h: f64,
        taylor: Option<&[[f64; N]]>,
    ) -> Option<Interrupt<N>> {
        // Events: which functions changed sign in the allowed direction?
        let n = self.armed.len();
        let ends = scan_step_ends(
            &*self.system,
            &self.armed,
            t_new,
            y_new,
            &self.g_old[..n],
            &mut self.g_new,
        );
        let suspects = self.peaks.suspects(
            &*self.system,
            [(t, y, &self.k[0]), (t_new, y_new, &self.k[STAGES])],
            (&self.g_old[..n], &self.g_new[..n]),
            h,
        );
        let search = ends.needs_dense() || suspects != 0;
        // Asked on every accepted step, so the observer sees each full step.
        let wanted = observer.wants_dense(t, t_new);
        // A Taylor step's polynomial is its series; DOP853's costs three
        // more evaluations, made only when needed.
        let coefficients = match taylor {
            None if search || wanted => Some(self.dense_coefficients(t, y, y_new, h)),
            _ => None,
        };
        let form = match (taylor, &coefficients) {
            (Some(c), _) => (search || wanted).then_some(Form::Taylor(c)),
            (None, Some(f)) => Some(Form::Hairer { y, f }),
            (None, None) => None,
        };
        let dense = form.map(|form| Polynomial { t, h, form });
        // Start of the part of the step not yet shown to the observer.
        let mut seen = (t, *y);
        if let (true, Some(p)) = (search, dense) {
            let end = (t_new, y_new);
            if let Some(interrupt) = self.handle_events(observer, &p, &mut seen, end, suspects) {
                return Some(interrupt);
            }
        }
        let (t_seen, y_seen) = seen;
        if t_new > t_seen {
            let piece = DenseStep::new((t_seen, &y_seen), (t_new, y_new), dense);
            observer.step(&*self.system, &piece);
        }
        None
    }

    /// Locates the events of the accepted step whose dense output is `p`
    /// on `(seen.0, t_new]`, in time order, and applies their actions: the
    /// observer gets the piece of the step up to each event, then the
    /// event, then the system commits it. `seen` moves to the last event
    /// shown. A `Stop` ends the run and a `Reset` ends the step (the other
    /// events of the step are dropped); after `Continue` events the rest of
    /// the step is searched again, as `commit_event` may have changed the
    /// event functions.
    fn handle_events<O: Observer<S, N>>(
        &mut self,
        observer: &mut O,
        p: &Polynomial<'_, N>,
        seen: &mut (f64, [f64; N]),
        (t_new, y_new): (f64, &[f64; N]),
        suspects: u32,
    ) -> Option<Interrupt<N>> {
        let n_events = self.armed.len();
        // Where the search for crossings starts, and the event values there.
        let mut g_lo = self.g_old;
        loop {
            let found = crossings(
                &*self.system,
                &self.armed,
                p,
                (seen.0, &g_lo[..n_events]),
                t_new,
                &self.g_new,
                suspects,
            );
            if found.is_empty() {
                return None;
            }
            for &(te, i) in found.as_slice() {
                self.events_located += 1;
                let ye = p.at(te);
                let action = self.system.on_event(i, te, &ye);
                let y_after = match action {
                    EventAction::Reset(r) => r,
                    EventAction::Stop | EventAction::Continue => ye,
                };
                if te > seen.0 {
                    let piece = DenseStep::new((seen.0, &seen.1), (te, &ye), Some(*p));
                    observer.step(&*self.system, &piece);
                    *seen = (te, ye);
                }
                let record = EventRecord {
                    index: i,
                    t: te,
                    y_before: ye,
                    y_after,
                    action,
                };
                observer.event(&*self.system, &record);
                self.system.commit_event(&record);
                match action {
                    EventAction::Continue => {}
                    EventAction::Stop => {
                        let end = Termination::Event { index: i };
                        return Some(Interrupt::Finish(self.outcome(te, ye, end)));
                    }
                    EventAction::Reset(_) => return Some(Interrupt::Reset(te, y_after)),
                }
            }
            if seen.0 >= t_new {
                return None;
            }
            // Every event so far continued, but `commit_event` may have
            // changed the event functions (a turn counter): search the rest
            // of the step again with their current values. Events count
            // towards the step budget, so a cascade cannot hang.
            if self.steps_spent() >= self.tol.max_steps {
                let (t_seen, y_seen) = *seen;
                return Some(Interrupt::Finish(self.outcome(
                    t_seen,
                    y_seen,
                    Termination::StepLimit,
                )));
            }
            for (j, &i) in self.armed.indices().iter().enumerate() {
                g_lo[j] = self.system.event(i, seen.0, &seen.1);
                self.g_new[j] = self.system.event(i, t_new, y_new);
            }
        }
    }
}
