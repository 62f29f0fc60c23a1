//! Where a run on the fast path ends: at `t_end` (Newton's method on the
//! time integral of a panel, or on the series of `series.rs`) or at `x_end`.

use super::series::Series;
use super::{Form, SpeedSquared, MAX_NEWTON, MAX_PANELS, NEWTON_RTOL};
use crate::models::Coefficients;
use crate::scenario::Scenario;
use crate::trajectory::StopReason;

use super::ContactCheck;

/// Where a circular run ends, from the closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastEnd {
    /// Why it ended: [`StopReason::EndTime`] or [`StopReason::Distance`].
    pub reason: StopReason,
    /// Time, s.
    pub t: f64,
    /// Distance, m.
    pub x: f64,
    /// Speed, m/s.
    pub v: f64,
}

/// The end of the run of `c` in `scenario` to `t_end` or `x_end`, whichever
/// comes first, or `None` where the fast path does not apply (see the
/// module doc): the caller then integrates the ODE.
pub fn circular_end(
    c: &Coefficients,
    scenario: &Scenario,
    t_end: f64,
    x_end: Option<f64>,
    contact: ContactCheck,
) -> Option<FastEnd> {
    // An unwinding roll (b < 0, `docs/unwinding.md`): u(x) of (F1) holds
    // while s > 0, but the time's panels and series, and the stall test,
    // are built for a cross-section that grows; its runs take the ODE path,
    // which also stops them at the core.
    if c.accretes && scenario.unwinds() {
        return None;
    }
    let u = SpeedSquared::new(c, scenario, contact)?;
    if !u.never_stalls() {
        return None;
    }
    // The start is not a quadrature node.
    if !u.contact_holds(0.0, u.u0) {
        return None;
    }
    let (reason, t, x) = u.run_end(t_end, x_end)?;
    finish(&u, reason, t, x)
}

impl SpeedSquared {
    /// Why, when and where the run ends: at `t_end` or at `x_end`, whichever
    /// comes first (contact forces checked on the way, `contact_ok`), or
    /// `None` if the time cannot be integrated or inverted.
    pub(super) fn run_end(&self, t_end: f64, x_end: Option<f64>) -> Option<(StopReason, f64, f64)> {
        let u = self;
        if let Form::Constant = u.form {
            return Some(constant_end(u, t_end, x_end));
        }
        let w_end = x_end.map_or(f64::INFINITY, f64::sqrt);
        // Where the series (T2) of `series.rs` takes over from the quadrature.
        let series = u.series();
        let w_switch = series.map_or(f64::INFINITY, |sr| u.x_of_z(sr.z1).sqrt());
        let w_stop = w_end.min(w_switch);
        // From rest, t(z1) is known in closed form (T3): no quadrature at all
        // unless the run ends before z1.
        let from_rest = series
            .and_then(|sr| sr.t_z1)
            .filter(|&t1| t1 < t_end && w_end > w_switch);
        let start = from_rest.map_or((0.0, 0.0), |t1| (w_stop, t1));
        let t_lo = match u.walk_panels(start, w_stop, t_end)? {
            Walk::Arrived(t) => t,
            Walk::Passed(w) => return Some((StopReason::EndTime, t_end, w * w)),
        };
        let Some(sr) = series.filter(|_| w_end > w_switch) else {
            return Some((StopReason::Distance, t_lo, x_end?));
        };
        series_end(u, &sr, t_lo, from_rest.is_some(), t_end, x_end)
    }

    /// Integrates t over the panels of w (the first ending at
    /// `first_panel`, each next twice as long) from `(w, t)` = `start` to
    /// `w_stop`: [`Walk::Passed`] with the w where t reaches `t_end` on the
    /// way (Newton's method in its panel), else [`Walk::Arrived`] with t at
    /// `w_stop`. `None` if a panel's time is not finite or too many panels.
    pub(super) fn walk_panels(&self, start: (f64, f64), w_stop: f64, t_end: f64) -> Option<Walk> {
        let (mut lo, mut t_lo) = start;
        let mut hi = self.first_panel();
        // From a start past the first panel, the next panel end beyond it.
        while hi > 0.0 && hi <= lo {
            hi *= 2.0;
        }
        let mut panels = 0;
        while lo < w_stop {
            panels += 1;
            if panels > MAX_PANELS {
                return None;
            }
            hi = hi.min(w_stop);
            let dt = self.time_between(lo, hi);
            if !dt.is_finite() {
                return None;
            }
            if t_lo + dt >= t_end {
                return solve_time(self, lo, t_lo, hi, dt, t_end).map(Walk::Passed);
            }
            t_lo += dt;
            lo = hi;
            hi *= 2.0;
        }
        Some(Walk::Arrived(t_lo))
    }
}

/// The w ≥ `w_a` where t = `t`, given t(`w_a`) = `t_a` < `t`: the panels
/// from `w_a` on, then Newton's method in the panel that holds it.
pub(super) fn solve_time_from(u: &SpeedSquared, w_a: f64, t_a: f64, t: f64) -> Option<f64> {
    match u.walk_panels((w_a, t_a), f64::INFINITY, t)? {
        Walk::Passed(w) => Some(w),
        Walk::Arrived(_) => None,
    }
}

/// Where a walk over the panels of w ended (`SpeedSquared::walk_panels`).
#[derive(Debug, Clone, Copy)]
pub(super) enum Walk {
    /// t reached the time asked for at this w.
    Passed(f64),
    /// The walk reached its end w at this t, s.
    Arrived(f64),
}

/// The end of the run at time `t`, distance `x` for `reason`, if the
/// contact forces held throughout and every number is finite.
fn finish(u: &SpeedSquared, reason: StopReason, t: f64, x: f64) -> Option<FastEnd> {
    let v = u.at(x).sqrt();
    let ok = u.contact_ok.get() && u.contact_holds(x, v * v);
    (ok && t.is_finite() && x.is_finite() && v.is_finite()).then_some(FastEnd { reason, t, x, v })
}

/// Without snow collected the acceleration is the constant P:
/// x = v0 t + P t²/2, and x_end is reached at t = 2X/(v0 + √(v0² + 2PX)).
fn constant_end(u: &SpeedSquared, t_end: f64, x_end: Option<f64>) -> (StopReason, f64, f64) {
    let x_t = u.constant_position(t_end);
    match x_end {
        Some(xe) if xe <= x_t => (StopReason::Distance, u.constant_time(xe), xe),
        _ => (StopReason::EndTime, t_end, x_t),
    }
}

/// The rest of the run from the series (T2) of `series.rs`, given
/// `t_lo` = t(z1) < `t_end`. Without quadrature nodes before z1 (a start
/// from rest, `from_rest`), the contact forces are checked from the start.
fn series_end(
    u: &SpeedSquared,
    sr: &Series,
    t_lo: f64,
    from_rest: bool,
    t_end: f64,
    x_end: Option<f64>,
) -> Option<(StopReason, f64, f64)> {
    let z_from = if from_rest { 1.0 } else { sr.z1 };
    let z_x_end = x_end.map(|x| 1.0 + u.b * x / u.s0);
    if let Some(z) = z_x_end {
        let t = t_lo + sr.time_from_z1(z);
        if t < t_end {
            u.contact_ok
                .set(u.contact_ok.get() && u.contact_holds_between(z_from, z));
            return Some((StopReason::Distance, t, x_end?));
        }
    }
    let z = sr.solve_time(t_lo, t_end)?;
    let z = z_x_end.map_or(z, |ze| z.min(ze));
    u.contact_ok
        .set(u.contact_ok.get() && u.contact_holds_between(z_from, z));
    Some((StopReason::EndTime, t_end, u.x_of_z(z)))
}

/// The w in `[lo, hi]` where t = `t_end`, given t(lo) = `t_lo` and the
/// panel's time `dt`: Newton's method (t' = 2w/√u), kept in the bracket by
/// bisection, integrating each step from the last point.
pub(super) fn solve_time(
    u: &SpeedSquared,
    lo: f64,
    t_lo: f64,
    hi: f64,
    dt: f64,
    t_end: f64,
) -> Option<f64> {
    let (mut a, mut b) = (lo, hi);
    // Anchor: a point where t is known.
    let (mut wk, mut tk) = (lo, t_lo);
    let mut w = lo + (hi - lo) * ((t_end - t_lo) / dt).clamp(0.0, 1.0);
    for _ in 0..MAX_NEWTON {
        let t = tk + u.time_between(wk, w);
        (wk, tk) = (w, t);
        let g = t - t_end;
        if g < 0.0 {
            a = w;
        } else {
            b = w;
        }
        let next = w - g / u.dt_dw(w);
        if (next - w).abs() <= NEWTON_RTOL * w || b - a <= NEWTON_RTOL * b {
            return Some(next.clamp(a, b));
        }
        w = if next > a && next < b {
            next
        } else {
            0.5 * (a + b)
        };
    }
    None
}
