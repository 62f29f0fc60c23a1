//! Hairer's step-size control for DOP853: the first step's guess and the
//! controller that shrinks a rejected step and grows an accepted one.

// The initial guess updates the state component by component, as Hairer
// writes it.
#![allow(clippy::needless_range_loop)]

use super::{OdeSystem, Tolerances};
use crate::error::{ParamError, SimError};
use crate::portable::Portable as _;

// Hairer's DOP853 controller constants (his defaults).
/// Safety factor on the predicted step.
const SAFETY: f64 = 0.9;
/// The step may shrink at most by 1/FAC1 ... (largest 1/fac = 1/0.333).
const FAC_MIN: f64 = 0.333;
/// ... and grow at most by FAC_MAX per step.
const FAC_MAX: f64 = 6.0;

/// `err^(1/8)`, the controller's power of the error (Hairer's `FAC11`; the
/// exponent is 1/(q + 1) for the error estimator of order q = 7),
/// as three square roots: exact to rounding and far cheaper than `powf`.
pub(super) fn eighth_root(err: f64) -> f64 {
    err.sqrt().sqrt().sqrt()
}

/// Hairer's initial step guess (DOP853's `HINIT`) for an 8th-order
/// method, forward in time: `h` such that `h^8 max(‖f‖, ‖f'‖) = 0.01`
/// in the scaled norm, at most 100 times the explicit-Euler guess.
pub(super) fn initial_step<S: OdeSystem<N>, const N: usize>(
    system: &S,
    tol: &Tolerances,
    controlled: usize,
    (t, y): (f64, &[f64; N]),
    f0: &[f64; N],
) -> f64 {
    let (mut dnf, mut dny) = (0.0, 0.0);
    for n in 0..controlled {
        let sk = tol.atol + tol.rtol * y[n].abs();
        dnf += (f0[n] / sk).powi(2);
        dny += (y[n] / sk).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 || !dnf.is_finite() {
        1e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(tol.max_step);
    let mut y1 = *y;
    for n in 0..N {
        y1[n] += h * f0[n];
    }
    let mut f1 = [0.0; N];
    system.rhs(t + h, &y1, &mut f1);
    let mut der2 = 0.0;
    for n in 0..controlled {
        let sk = tol.atol + tol.rtol * y[n].abs();
        der2 += ((f1[n] - f0[n]) / sk).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf_p(1.0 / 8.0)
    };
    let guess = (100.0 * h).min(h1).min(tol.max_step);
    // Hairer's formulae overflow when f or y dwarf the tolerances (e.g.
    // g = 1e300): fall back to a small step and let the controller grow it.
    if guess.is_finite() && guess > 0.0 {
        guess
    } else {
        1e-6_f64.min(tol.max_step)
    }
}

/// Hairer's step-size controller: the step to try next, shrunk after a
/// rejection and grown (boundedly) after an acceptance.
pub(super) struct StepControl {
    /// The step to try next.
    pub(super) h: f64,
    /// Whether the last trial was rejected (the next accepted step then may
    /// not grow).
    pub(super) last_rejected: bool,
}

impl StepControl {
    /// Whether the trial step with error norm `err` is accepted. If so,
    /// returns `err^(1/8)` for [`StepControl::grow`]; if not, shrinks the
    /// step: by 10 when the error is not finite (a stage left the domain of
    /// `f`, e.g. overflow), else by `min(1/FAC_MIN, err^(1/8)/SAFETY)`.
    pub(super) fn judge(&mut self, err: f64) -> Option<f64> {
        if !err.is_finite() {
            self.h *= 0.1;
            self.last_rejected = true;
            return None;
        }
        let fac11 = eighth_root(err);
        if err > 1.0 {
            self.h /= (1.0 / FAC_MIN).min(fac11 / SAFETY);
            self.last_rejected = true;
            return None;
        }
        Some(fac11)
    }

    /// The step after an accepted one with `err^(1/8) = fac11`: `h SAFETY /
    /// err^(1/8)`, its ratio to `h` within `[FAC_MIN, FAC_MAX]`, at most
    /// `max_step`, and not larger than `h` right after a rejection.
    /// (Hairer's Lund stabilisation exponent beta is 0 for DOP853, so the
    /// previous error does not enter.)
    pub(super) fn grow(&mut self, fac11: f64, max_step: f64) {
        let fac = (fac11 / SAFETY).clamp(1.0 / FAC_MAX, 1.0 / FAC_MIN);
        let mut h_new = (self.h / fac).min(max_step);
        if self.last_rejected {
            h_new = h_new.min(self.h);
        }
        self.last_rejected = false;
        self.h = h_new;
    }
}

/// Rejects a start or end time the loop cannot work with.
pub(super) fn check_times<const N: usize>(
    t0: f64,
    y0: &[f64; N],
    t_end: f64,
) -> Result<(), SimError> {
    let bad = |name, value, expected| {
        Err(SimError::Param(ParamError::InvalidParameter {
            name,
            value,
            expected,
        }))
    };
    if !t0.is_finite() {
        return bad("t0", t0, "a finite start time");
    }
    if !(t_end.is_finite() && t_end >= t0) {
        return bad("t_end", t_end, "a finite end time, not before the start");
    }
    if !y0.iter().all(|v| v.is_finite()) {
        return Err(SimError::NonFiniteState { t: t0 });
    }
    Ok(())
}
