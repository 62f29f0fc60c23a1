//! The DOP853 step loop: stages, Hairer's error norm and controller, dense
//! output, and event handling.

// The stage loops index several tableau rows and the stage array with the
// same counters, as the method is written on paper; iterator chains would
// hide that correspondence.
#![allow(clippy::needless_range_loop)]

use super::events::locate;
use super::tableau::{A, B, C, D, E3, E5};
use super::{EventAction, EventRecord, Observer, OdeSystem, Outcome, Termination, Tolerances};
use crate::error::SimError;

/// Stages of the 8th-order solution.
const STAGES: usize = 12;
/// Stages including the three extra ones of the dense output.
const STAGES_DENSE: usize = 16;
/// Coefficient vectors of the dense polynomial.
const DENSE_TERMS: usize = 7;

// Hairer's DOP853 controller constants (his defaults).
/// Safety factor on the predicted step.
const SAFETY: f64 = 0.9;
/// The step may shrink at most by 1/FAC1 ... (largest 1/fac = 1/0.333).
const FAC_MIN: f64 = 0.333;
/// ... and grow at most by FAC_MAX per step.
const FAC_MAX: f64 = 6.0;
/// Exponent 1/(q+1) of the error estimator of order q = 7.
const EXPONENT: f64 = 1.0 / 8.0;

/// Step and evaluation counts of one integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Evaluations of the right-hand side.
    pub evaluations: u64,
}

/// One accepted step as the observer sees it: the interval `(t_old, t_new]`
/// and, when asked for, the 7th-order dense output on it.
#[derive(Debug)]
pub struct DenseStep<'a, const N: usize> {
    /// Start of the step.
    pub t_old: f64,
    /// End of the step (earlier than the full step if an event stopped or reset it).
    pub t_new: f64,
    /// State at `t_old`.
    pub y_old: &'a [f64; N],
    /// State at `t_new`.
    pub y_new: &'a [f64; N],
    h: f64,
    dense: Option<&'a [[f64; N]; DENSE_TERMS]>,
}

impl<const N: usize> DenseStep<'_, N> {
    /// The state at `t` in `[t_old, t_new]` from the dense output; `None` when
    /// the observer did not ask for dense output on this step.
    pub fn eval(&self, t: f64) -> Option<[f64; N]> {
        if t >= self.t_new {
            return Some(*self.y_new);
        }
        self.dense
            .map(|f| interpolate(f, self.y_old, (t - self.t_old) / self.h))
    }
}

/// Evaluates the dense polynomial at the fraction `s` of the step.
///
/// With `F0..F6` from [`Integrator::dense_coefficients`] the polynomial is
/// `y_old + s(F0 + (1−s)(F1 + s(F2 + (1−s)(F3 + s(F4 + (1−s)(F5 + s F6))))))`.
fn interpolate<const N: usize>(f: &[[f64; N]; DENSE_TERMS], y_old: &[f64; N], s: f64) -> [f64; N] {
    let mut y = [0.0; N];
    for (i, fi) in f.iter().rev().enumerate() {
        let factor = if i % 2 == 0 { s } else { 1.0 - s };
        for n in 0..N {
            y[n] = (y[n] + fi[n]) * factor;
        }
    }
    for n in 0..N {
        y[n] += y_old[n];
    }
    y
}

struct Integrator<'s, S, const N: usize> {
    system: &'s mut S,
    tol: Tolerances,
    k: [[f64; N]; STAGES_DENSE],
    stats: Stats,
}

impl<S: OdeSystem<N>, const N: usize> Integrator<'_, S, N> {
    fn eval(&mut self, t: f64, y: &[f64; N], out_stage: usize) {
        let mut dy = [0.0; N];
        self.system.rhs(t, y, &mut dy);
        self.k[out_stage] = dy;
        self.stats.evaluations += 1;
    }

    /// State `y + h Σ_{j<s} A[s][j] k_j`, the argument of stage `s`.
    fn stage_state(&self, y: &[f64; N], h: f64, s: usize) -> [f64; N] {
        let mut acc = [0.0; N];
        for j in 0..s {
            let a = A[s][j];
            if a != 0.0 {
                for n in 0..N {
                    acc[n] += a * self.k[j][n];
                }
            }
        }
        let mut out = *y;
        for n in 0..N {
            out[n] += h * acc[n];
        }
        out
    }

    /// One trial step from `(t, y)` with `k[0] = f(t, y)`: the 8th-order
    /// solution, with `k[12] = f(t + h, y_new)`, and Hairer's error norm
    /// (a blend of the 5th- and 3rd-order estimators, DOP853's `err`).
    fn trial(&mut self, t: f64, y: &[f64; N], h: f64) -> ([f64; N], f64) {
        for s in 1..STAGES {
            let ys = self.stage_state(y, h, s);
            self.eval(t + C[s] * h, &ys, s);
        }
        let mut y_new = *y;
        for n in 0..N {
            let mut acc = 0.0;
            for (j, b) in B.iter().enumerate() {
                acc += b * self.k[j][n];
            }
            y_new[n] += h * acc;
        }
        self.eval(t + h, &y_new, STAGES);
        let (mut err5, mut err3) = (0.0, 0.0);
        for n in 0..N {
            let scale = self.tol.atol + self.tol.rtol * y[n].abs().max(y_new[n].abs());
            let (mut e5, mut e3) = (0.0, 0.0);
            for j in 0..=STAGES {
                e5 += E5[j] * self.k[j][n];
                e3 += E3[j] * self.k[j][n];
            }
            err5 += (e5 / scale).powi(2);
            err3 += (e3 / scale).powi(2);
        }
        let mut denom = err5 + 0.01 * err3;
        if denom <= 0.0 {
            denom = 1.0;
        }
        let err = h.abs() * err5 * (1.0 / (N as f64 * denom)).sqrt();
        (y_new, err)
    }

    /// Coefficients `F0..F6` of the dense output on the accepted step
    /// `(t, y) → (t + h, y_new)`; needs the three extra stages 13–15.
    fn dense_coefficients(
        &mut self,
        t: f64,
        y: &[f64; N],
        y_new: &[f64; N],
        h: f64,
    ) -> [[f64; N]; DENSE_TERMS] {
        for s in STAGES + 1..STAGES_DENSE {
            let ys = self.stage_state(y, h, s);
            self.eval(t + C[s] * h, &ys, s);
        }
        let mut f = [[0.0; N]; DENSE_TERMS];
        for n in 0..N {
            let dy = y_new[n] - y[n];
            f[0][n] = dy;
            f[1][n] = h * self.k[0][n] - dy;
            f[2][n] = 2.0 * dy - h * (self.k[STAGES][n] + self.k[0][n]);
            for (i, d) in D.iter().enumerate() {
                let mut acc = 0.0;
                for (j, dj) in d.iter().enumerate() {
                    acc += dj * self.k[j][n];
                }
                f[3 + i][n] = h * acc;
            }
        }
        f
    }

    /// Hairer's initial step guess (DOP853's `HINIT`) for an 8th-order method.
    fn initial_step(&mut self, t: f64, y: &[f64; N], t_end: f64) -> f64 {
        let dir = (t_end - t).signum();
        let f0 = self.k[0];
        let (mut dnf, mut dny) = (0.0, 0.0);
        for n in 0..N {
            let sk = self.tol.atol + self.tol.rtol * y[n].abs();
            dnf += (f0[n] / sk).powi(2);
            dny += (y[n] / sk).powi(2);
        }
        let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            (dny / dnf).sqrt() * 0.01
        };
        h = h.min(self.tol.max_step);
        let mut y1 = *y;
        for n in 0..N {
            y1[n] += dir * h * f0[n];
        }
        let mut f1 = [0.0; N];
        self.system.rhs(t + dir * h, &y1, &mut f1);
        self.stats.evaluations += 1;
        let mut der2 = 0.0;
        for n in 0..N {
            let sk = self.tol.atol + self.tol.rtol * y[n].abs();
            der2 += ((f1[n] - f0[n]) / sk).powi(2);
        }
        let der2 = der2.sqrt() / h;
        let der12 = der2.abs().max(dnf.sqrt());
        let h1 = if der12 <= 1e-15 {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(1.0 / 8.0)
        };
        dir * (100.0 * h).min(h1).min(self.tol.max_step)
    }
}

/// Integrates `system` from `(t0, y0)` towards `t_end` with DOP853,
/// locating the system's events on the dense output and applying their
/// actions, and reports each accepted step and event to `observer`.
///
/// # Errors
/// [`SimError::StepSizeTooSmall`] when the step underflows (a singularity),
/// [`SimError::TooManySteps`] past `tol.max_steps`, and
/// [`SimError::NonFiniteState`] when the state stops being finite.
pub fn integrate<S, O, const N: usize>(
    system: &mut S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    tol: &Tolerances,
    observer: &mut O,
) -> Result<Outcome<N>, SimError>
where
    S: OdeSystem<N>,
    O: Observer<S, N>,
{
    tol.validate()?;
    let mut it = Integrator {
        system,
        tol: *tol,
        k: [[0.0; N]; STAGES_DENSE],
        stats: Stats::default(),
    };
    observer.start(&*it.system, t0, &y0);
    let (mut t, mut y) = (t0, y0);
    if t_end <= t0 || t_end.is_nan() {
        return Ok(Outcome {
            t,
            y,
            termination: Termination::EndTime,
            stats: it.stats,
        });
    }
    let n_events = it.system.event_count();
    // Event values at the start of the current step (a small fixed buffer:
    // no model has more than a handful of events).
    let mut g_old = [0.0; MAX_EVENTS];
    if n_events > MAX_EVENTS {
        return Err(SimError::TooManyEvents {
            count: n_events,
            max: MAX_EVENTS,
        });
    }
    for (i, g) in g_old.iter_mut().enumerate().take(n_events) {
        *g = it.system.event(i, t, &y);
    }
    it.eval(t, &y, 0);
    let mut h = it.initial_step(t, &y, t_end);
    let mut last_rejected = false;
    loop {
        if it.stats.accepted + it.stats.rejected >= tol.max_steps {
            return Err(SimError::TooManySteps {
                t,
                steps: tol.max_steps,
            });
        }
        if 0.1 * h.abs() <= t.abs() * f64::EPSILON {
            return Err(SimError::StepSizeTooSmall { t, h });
        }
        let mut last = false;
        if t + 1.01 * h >= t_end {
            h = t_end - t;
            last = true;
        }
        let (y_new, err) = it.trial(t, &y, h);
        if !err.is_finite() {
            // A stage left the domain of f (e.g. overflow): retry much smaller.
            it.stats.rejected += 1;
            h *= 0.1;
            last_rejected = true;
            continue;
        }
        let fac11 = err.powf(EXPONENT);
        if err > 1.0 {
            it.stats.rejected += 1;
            h /= (1.0 / FAC_MIN).min(fac11 / SAFETY);
            last_rejected = true;
            continue;
        }
        // Accepted.
        it.stats.accepted += 1;
        let t_new = if last { t_end } else { t + h };
        if !y_new.iter().all(|v| v.is_finite()) {
            return Err(SimError::NonFiniteState { t: t_new });
        }
        // Events: which functions changed sign in the allowed direction?
        let mut g_new = [0.0; MAX_EVENTS];
        let mut any = false;
        for i in 0..n_events {
            g_new[i] = it.system.event(i, t_new, &y_new);
            any |= it.system.event_direction(i).crosses(g_old[i], g_new[i]);
        }
        let need_dense = any || observer.wants_dense(t, t_new);
        let dense = if need_dense {
            Some(it.dense_coefficients(t, &y, &y_new, h))
        } else {
            None
        };
        if any {
            // Locate every triggered event on the dense output, earliest first.
            let mut found: [(f64, usize); MAX_EVENTS] = [(f64::INFINITY, 0); MAX_EVENTS];
            let mut n_found = 0;
            if let Some(f) = dense.as_ref() {
                for i in 0..n_events {
                    if it.system.event_direction(i).crosses(g_old[i], g_new[i]) {
                        let system = &*it.system;
                        let te = locate(t, t_new, g_old[i], g_new[i], |tt| {
                            let yy = interpolate(f, &y, (tt - t) / h);
                            system.event(i, tt, &yy)
                        });
                        found[n_found] = (te, i);
                        n_found += 1;
                    }
                }
            }
            found[..n_found].sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut handled = false;
            for &(te, i) in &found[..n_found] {
                let ye = match dense.as_ref() {
                    Some(f) => interpolate(f, &y, (te - t) / h),
                    None => y_new,
                };
                let action = it.system.on_event(i, te, &ye);
                let record = EventRecord {
                    index: i,
                    t: te,
                    y_before: ye,
                    y_after: match action {
                        EventAction::Reset(r) => r,
                        _ => ye,
                    },
                    action,
                };
                match action {
                    EventAction::Continue => {
                        observer.event(&*it.system, &record);
                        it.system
                            .commit_event(i, te, &record.y_before, &record.y_after);
                    }
                    EventAction::Stop | EventAction::Reset(_) => {
                        observer.step(
                            &*it.system,
                            &DenseStep {
                                t_old: t,
                                t_new: te,
                                y_old: &y,
                                y_new: &ye,
                                h,
                                dense: dense.as_ref(),
                            },
                        );
                        observer.event(&*it.system, &record);
                        it.system
                            .commit_event(i, te, &record.y_before, &record.y_after);
                        if matches!(action, EventAction::Stop) {
                            return Ok(Outcome {
                                t: te,
                                y: ye,
                                termination: Termination::Event { index: i },
                                stats: it.stats,
                            });
                        }
                        // Reset: start afresh from the new state at te.
                        t = te;
                        y = record.y_after;
                        for (j, g) in g_old.iter_mut().enumerate().take(n_events) {
                            *g = it.system.event(j, t, &y);
                        }
                        it.eval(t, &y, 0);
                        // Keep the step size but never step past the old step end.
                        h = h.min(tol.max_step);
                        last_rejected = false;
                        handled = true;
                        break;
                    }
                }
            }
            if handled {
                if t >= t_end {
                    return Ok(Outcome {
                        t,
                        y,
                        termination: Termination::EndTime,
                        stats: it.stats,
                    });
                }
                continue;
            }
        }
        observer.step(
            &*it.system,
            &DenseStep {
                t_old: t,
                t_new,
                y_old: &y,
                y_new: &y_new,
                h,
                dense: dense.as_ref(),
            },
        );
        // Advance (FSAL: stage 12 is f(t_new, y_new)).
        it.k[0] = it.k[STAGES];
        t = t_new;
        y = y_new;
        g_old[..n_events].copy_from_slice(&g_new[..n_events]);
        if last {
            return Ok(Outcome {
                t,
                y,
                termination: Termination::EndTime,
                stats: it.stats,
            });
        }
        // Hairer's controller: new step from the error, bounded in ratio.
        // (Hairer's Lund stabilisation exponent beta is 0 for DOP853, so the
        // previous error does not enter.)
        let fac = (fac11 / SAFETY).clamp(1.0 / FAC_MAX, 1.0 / FAC_MIN);
        let mut h_new = (h / fac).min(tol.max_step);
        if last_rejected {
            h_new = h_new.min(h);
        }
        last_rejected = false;
        h = h_new;
    }
}

/// Most event functions one system may have.
pub const MAX_EVENTS: usize = 8;
