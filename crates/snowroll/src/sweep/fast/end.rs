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
    let u = SpeedSquared::new(c, scenario, contact)?;
    if !u.never_stalls() {
        return None;
    }
    // The start is not a quadrature node.
    if !u.contact_holds(0.0, u.u0) {
        return None;
    }
    if let Form::Constant = u.form {
        return constant_end(&u, t_end, x_end);
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
    let (mut lo, mut t_lo) = from_rest.map_or((0.0, 0.0), |t1| (w_stop, t1));
    let mut hi = u.first_panel();
    let mut panels = 0;
    while lo < w_stop {
        panels += 1;
        if panels > MAX_PANELS {
            return None;
        }
        hi = hi.min(w_stop);
        let dt = u.time_between(lo, hi);
        if !dt.is_finite() {
            return None;
        }
        if t_lo + dt >= t_end {
            let w = solve_time(&u, lo, t_lo, hi, dt, t_end)?;
            return finish(&u, StopReason::EndTime, t_end, w * w);
        }
        t_lo += dt;
        lo = hi;
        hi *= 2.0;
    }
    let Some(sr) = series.filter(|_| w_end > w_switch) else {
        let x = x_end?;
        return finish(&u, StopReason::Distance, t_lo, x);
    };
    series_end(&u, &sr, t_lo, from_rest.is_some(), t_end, x_end)
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
fn constant_end(u: &SpeedSquared, t_end: f64, x_end: Option<f64>) -> Option<FastEnd> {
    let (v0, p) = (u.u0.sqrt(), u.push);
    let x_t = v0 * t_end + 0.5 * p * t_end * t_end;
    match x_end {
        Some(xe) if xe <= x_t => finish(
            u,
            StopReason::Distance,
            2.0 * xe / (v0 + (u.u0 + 2.0 * p * xe).sqrt()),
            xe,
        ),
        _ => finish(u, StopReason::EndTime, t_end, x_t),
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
) -> Option<FastEnd> {
    let z_from = if from_rest { 1.0 } else { sr.z1 };
    let z_x_end = x_end.map(|x| 1.0 + u.b * x / u.s0);
    if let Some(z) = z_x_end {
        let t = t_lo + sr.time_from_z1(z);
        if t < t_end {
            u.contact_ok
                .set(u.contact_ok.get() && u.contact_holds_between(z_from, z));
            return finish(u, StopReason::Distance, t, x_end?);
        }
    }
    let z = sr.solve_time(t_lo, t_end)?;
    let z = z_x_end.map_or(z, |ze| z.min(ze));
    u.contact_ok
        .set(u.contact_ok.get() && u.contact_holds_between(z_from, z));
    finish(u, StopReason::EndTime, t_end, u.x_of_z(z))
}

/// The w in `[lo, hi]` where t = `t_end`, given t(lo) = `t_lo` and the
/// panel's time `dt`: Newton's method (t' = 2w/√u), kept in the bracket by
/// bisection, integrating each step from the last point.
fn solve_time(u: &SpeedSquared, lo: f64, t_lo: f64, hi: f64, dt: f64, t_end: f64) -> Option<f64> {
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
