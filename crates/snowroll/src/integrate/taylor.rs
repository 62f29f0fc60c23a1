//! Taylor-series steps, for systems that give the Taylor coefficients of
//! their solution ([`OdeSystem::has_taylor`]).
//!
//! # Why
//! On the smooth right-hand sides of the circular models at tight
//! tolerances, DOP853 is bound by latency: each of its 12 stages waits for
//! the one before (eq. (4) to 100 s at rtol 1e-10: 84 steps, 1008
//! evaluations). A Taylor step computes the coefficients of x(t) and v(t)
//! to order p by a recurrence on truncated power series (about 1.5 k
//! multiply-adds for order k, most of them not waiting for the order
//! before), and a step of order 25 goes about four times as far as a DOP853
//! step: the same run takes 20 steps, and each step's series is its own
//! dense output.
//!
//! # Order and step (Jorba and Zou's rule)
//! With `ε = SHARPNESS × rtol`, the order is `p = ⌈0.7 (−ln ε)⌉` (within
//! 8..=[`TAYLOR_MAX_ORDER`]), and the step `h = ε^(1/p) ρ`, where
//! `ρ = min over k ∈ {p − 1, p} of ‖c_k‖^(−1/k)` estimates the radius of
//! convergence from the last two coefficients, each component scaled by
//! `atol/rtol + |y_n|` (the mixed norm of DOP853: relative where |y| is
//! large, absolute where it is small). The last term kept is then about ε
//! of the state, and the series' tail beyond it shrinks geometrically, so
//! there is no error estimate to reject a step on: every step is accepted.
//!
//! # Accuracy against DOP853 at the same tolerance
//! DOP853's error estimate is pessimistic by about four orders on these
//! problems (eq. (4) to 100 s at rtol 1e-10: global error 1.3e-14), so the
//! Taylor target is [`SHARPNESS`] = 1e-5 of the tolerance, which makes the
//! Taylor path at least as accurate as DOP853 at every rtol the tests use
//! (eq. (4), rtol 1e-10: 1.4e-16 against fn. 4's closed form, DOP853
//! 1.3e-14).

use super::dense::horner;
use super::dop853::{Integrator, Interrupt, STAGES};
use super::{Observer, OdeSystem, Outcome, Termination, Tolerances, TAYLOR_MAX_ORDER};
use crate::error::SimError;
use crate::portable::Portable as _;

/// The Taylor step's local target as a fraction of the tolerance (module doc).
pub(super) const SHARPNESS: f64 = 1e-5;
/// Lowest order used (at loose tolerances).
const MIN_ORDER: usize = 8;

/// The order for the tolerances `tol`: `⌈0.7 (−ln ε)⌉`, ε = SHARPNESS × rtol:
/// the cheapest per unit time measured on eq. (4) at ε = 1e-15 (`batch`, µs
/// per trajectory: order 18 7.2, 21 6.7, 25 6.1, 28 6.1 to 6.3, 30 6.1 to
/// 6.3). Jorba and Zou's `−½ ln ε + 1` is for a cost that grows as p²; ours
/// is bound by the recurrence's chain, which grows as p, at these orders.
pub(super) fn order_for(tol: &Tolerances) -> usize {
    let eps = SHARPNESS * tol.rtol;
    ((0.7 * -eps.ln_p()).ceil() as usize).clamp(MIN_ORDER, TAYLOR_MAX_ORDER)
}

/// `ρ` of the module doc: the radius of convergence estimated from the last
/// two coefficients of `c` (orders p − 1 and p), the first `controlled`
/// components each scaled by `atol/rtol + |y_n|`. Infinite when both are
/// zero (a polynomial solution, exact in one step).
fn radius<const N: usize>(
    c: &[[f64; N]],
    y: &[f64; N],
    tol: &Tolerances,
    controlled: usize,
) -> f64 {
    let p = c.len() - 1;
    let floor = tol.atol / tol.rtol;
    // ln ρ = min over k of −ln‖c_k‖/k: two logarithms and one exponential.
    let mut ln_rho = f64::INFINITY;
    for k in [p - 1, p] {
        let mut norm = 0.0f64;
        for n in 0..controlled {
            norm = norm.max(c[k][n].abs() / (floor + y[n].abs()));
        }
        if norm > 0.0 {
            ln_rho = ln_rho.min(-norm.ln_p() / k as f64);
        }
    }
    ln_rho.exp_p()
}

impl<S: OdeSystem<N>, const N: usize> Integrator<'_, S, N> {
    /// The step loop of Taylor steps from `(t, y)` to `t_end`: the
    /// coefficients at each step's start, the step from them (module doc),
    /// the new state by Horner's rule, and the accepted step's events and
    /// report as DOP853's ([`Integrator::accept`], with the series as the
    /// dense output).
    pub(super) fn run_taylor<O: Observer<S, N>>(
        &mut self,
        mut t: f64,
        mut y: [f64; N],
        t_end: f64,
        observer: &mut O,
    ) -> Result<Outcome<N>, SimError> {
        let order = order_for(&self.tol);
        let eps_root = (SHARPNESS * self.tol.rtol).powf_p(1.0 / order as f64);
        let mut c = [[0.0; N]; TAYLOR_MAX_ORDER + 1];
        let c = &mut c[..=order];
        self.restart(t, &y);
        loop {
            if observer.stop_requested() {
                return Ok(self.outcome(t, y, Termination::Stopped));
            }
            if self.steps_spent() >= self.tol.max_steps {
                return Ok(self.outcome(t, y, Termination::StepLimit));
            }
            self.system.taylor_coefficients(t, &y, c);
            self.stats.taylor_terms += order as u64;
            let mut h =
                (eps_root * radius(c, &y, &self.tol, self.controlled)).min(self.tol.max_step);
            // A NaN step (coefficients that are not finite) counts as too small.
            if 0.1 * h <= t.abs() * f64::EPSILON || h.is_nan() {
                return Err(SimError::StepSizeTooSmall { t, h });
            }
            // The step that would land within 1% of the end lands on it.
            let last = t + 1.01 * h >= t_end;
            if last {
                h = t_end - t;
            }
            let t_new = if last { t_end } else { t + h };
            let y_new = horner(c, h);
            self.stats.accepted += 1;
            if !y_new.iter().all(|v| v.is_finite()) {
                return Err(SimError::NonFiniteState { t: t_new });
            }
            if self.peaks.watching() {
                // The slopes of the watched events need f at both ends.
                self.k[0] = c[1];
                self.system.rhs(t_new, &y_new, &mut self.k[STAGES]);
                self.stats.evaluations += 1;
            }
            match self.accept(observer, (t, &y), (t_new, &y_new), h, Some(c)) {
                None => {}
                Some(Interrupt::Finish(outcome)) => return Ok(outcome),
                Some(Interrupt::Reset(te, y_after)) => {
                    (t, y) = (te, y_after);
                    if let Some(outcome) = self.reset_to(t, &y, t_end)? {
                        return Ok(outcome);
                    }
                    continue;
                }
            }
            t = t_new;
            y = y_new;
            let n = self.armed.len();
            self.g_old[..n].copy_from_slice(&self.g_new[..n]);
            self.peaks.advance();
            if last {
                return Ok(self.outcome(t, y, Termination::EndTime));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The orders chosen at the tolerances the program uses: 25 at the
    /// default rtol 1e-10 (ε = 1e-15), more at tighter ones, bounded.
    #[test]
    fn order_grows_with_the_tolerance_and_stays_bounded() {
        let at = |rtol| {
            order_for(&Tolerances {
                rtol,
                ..Tolerances::default()
            })
        };
        assert_eq!(at(1e-10), 25);
        assert!(at(1e-6) < at(1e-10) && at(1e-10) < at(1e-14));
        assert!(at(1e-15) <= TAYLOR_MAX_ORDER && at(0.5) >= MIN_ORDER);
    }

    /// e^t: c_k = 1/k!, so ρ from orders p − 1, p is (w (p−1)!)^(1/(p−1))
    /// and (w p!)^(1/p) with the weight w = 1 + atol/rtol at y = 1; the
    /// smaller, (w (p−1)!)^(1/(p−1)), is taken.
    #[test]
    fn radius_of_the_exponential_series() {
        let tol = Tolerances::default();
        let p = 12;
        let mut c = [[0.0; 1]; 13];
        let mut fact = 1.0;
        for (k, ck) in c.iter_mut().enumerate() {
            if k > 0 {
                fact *= k as f64;
            }
            ck[0] = 1.0 / fact;
        }
        let w = 1.0 + tol.atol / tol.rtol;
        let fact_p1: f64 = (1..p).map(|k| k as f64).product();
        let want = (w * fact_p1).powf(1.0 / (p - 1) as f64);
        let got = radius(&c, &[1.0], &tol, 1);
        assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
        // A polynomial solution: no radius.
        assert!(radius(&[[1.0], [2.0], [0.0], [0.0]], &[1.0], &tol, 1).is_infinite());
    }
}
