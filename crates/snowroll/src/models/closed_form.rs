//! Closed-form solutions: Loney's solution of eq. (4) (fn. 4), generalised
//! to every circular equation of motion without a lift term.
//!
//! With `u = v²`, `2a = du/dx` and `s = π r² = π r0² + b x` (eq. (8)), an
//! equation `a = 2G/3 − c_v b v²/s` becomes the linear equation
//! `du/dx + 2c_v b u/s = 4G/3`, whose solution from `u(0) = v0²` is
//!
//! `u(x) = v0² (s0/s)^p + 4G/(3(1+p)) · (s0/b) [s/s0 − (s0/s)^p]`, p = 2c_v,
//!
//! (fn. 4 for c_v = 7/6, p = 7/3: `u = 2G s/(5b) + K/s^{7/3}`) and
//! `a(x) = G·2/(3(1+p)) [1 + p (s0/s)^{p+1}] − (p/2)(b/s0) v0² (s0/s)^{p+1}`,
//! which tends to `2G/(3(1+p))` (G/5 for eq. (4)). The coefficient of the
//! decaying term is `7bK/6` for eq. (4), not `7bK/3` as printed (`docs/errata.md`, fn. 4).
//! Time follows from `t(x) = ∫ dx/√u` by quadrature, and x(t) by inverting it.
//!
//! The ball on its natural swath 2r follows the same law with 2/3 replaced
//! by 5/7 and c_v = 23/14 for its `torque-cm` (`docs/snowball-and-losses.md`
//! §1.4): `u = (G s/(3b)) [1 − (s0/s)^{30/7}]` from rest, the closed form of
//! the letter in The Physics Teacher 57, p. 436 (2019), a → G/6.

use std::f64::consts::PI;

use super::contact::{circular_forces, ContactForces};
use super::{CircularModel, Derivation, Model, ModelKind};
use crate::error::SimError;
use crate::quadrature;
use crate::scenario::Scenario;
use crate::trajectory::{
    OnHop, RunEnd, Sample, SampleSink, Sampling, SimOptions, Stop, StopReason,
};
use crate::units::{Meters, MetersPerSecond, MetersPerSecondSquared, Seconds};

/// Samples of the closed form when every "step" is asked for.
const DEFAULT_SAMPLES: usize = 500;

/// Relative accuracy of the quadrature for t(x): near f64 rounding.
const QUAD_RTOL: f64 = 1e-14;

/// The exact solution of `a = 2G/3 − c_v b v²/(π r²)` for one scenario.
///
/// ```
/// use snowroll::{DragOnlyClosedForm, Scenario};
/// let s = Scenario::default();
/// let loney = DragOnlyClosedForm::new(&s, 7.0 / 6.0); // eq. (4), fn. 4
/// // From rest the acceleration starts at 2/3 g sin α ...
/// assert!((loney.acceleration(0.0) / s.g_along() - 2.0 / 3.0).abs() < 1e-14);
/// // ... and tends to g sin α / 5.
/// assert!((loney.acceleration(1e7) / s.g_along() - 0.2).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DragOnlyClosedForm {
    g_along: f64,
    b: f64,
    s0: f64,
    v0: f64,
    /// p = 2 c_v.
    p: f64,
    /// 1/(1 + k) as (num, den): (2, 3) for the log, (5, 7) for the ball.
    push: (f64, f64),
}

impl DragOnlyClosedForm {
    /// The solution for drag coefficient `drag` (= c_v; 7/6 for eq. (4),
    /// 23/14 for the ball's `torque-cm`) on the scenario's shape (the area
    /// law: a ball with a fixed swath width does not follow it).
    pub fn new(s: &Scenario, drag: f64) -> Self {
        let r0 = s.initial_radius();
        Self {
            g_along: s.g_along(),
            b: s.snow_depth(),
            s0: PI * r0 * r0,
            v0: s.initial_speed(),
            p: 2.0 * drag,
            push: s.shape().push_ratio(),
        }
    }

    /// ε = b x / s0, so that s = s0 (1 + ε).
    fn eps(&self, x: Meters) -> f64 {
        self.b * x / self.s0
    }

    /// `u = v²` at distance `x`, written to stay accurate as b → 0:
    /// `(s0/b)[s/s0 − (s0/s)^p] = x q(ε)` with `q(ε) = (ε − expm1(−p ln1p ε))/ε`, q(0) = 1 + p.
    pub fn speed_squared(&self, x: Meters) -> f64 {
        let e = self.eps(x);
        let p = self.p;
        let q = if e == 0.0 {
            1.0 + p
        } else {
            (e - (-p * e.ln_1p()).exp_m1()) / e
        };
        self.v0 * self.v0 * (-p * e.ln_1p()).exp()
            + 2.0 * self.push.0 * self.g_along / (self.push.1 * (1.0 + p)) * x * q
    }

    /// Speed at distance `x`, m/s.
    pub fn speed(&self, x: Meters) -> MetersPerSecond {
        self.speed_squared(x).sqrt()
    }

    /// Acceleration at distance `x`, `a = ½ du/dx` (module doc), m/s².
    pub fn acceleration(&self, x: Meters) -> MetersPerSecondSquared {
        let p = self.p;
        let decay = (-(p + 1.0) * self.eps(x).ln_1p()).exp(); // (s0/s)^{p+1}
        self.push.0 * self.g_along / (self.push.1 * (1.0 + p)) * (1.0 + p * decay)
            - 0.5 * p * self.b / self.s0 * self.v0 * self.v0 * decay
    }

    /// Time to roll from `x_a` to `x_b`, s: `∫ dx/√u`, integrated in
    /// `w = √x` (`dx = 2w dw`), which removes the `1/√x` singularity of a
    /// start from rest.
    pub fn time_between(&self, x_a: Meters, x_b: Meters) -> Seconds {
        let mut f = |w: f64| {
            let v = self.speed(w * w);
            if v > 0.0 {
                2.0 * w / v
            } else {
                // w = 0 from rest: the limit of 2w/v is 2/√(4G/3) (log).
                2.0 / (2.0 * self.push.0 * self.g_along / self.push.1).sqrt()
            }
        };
        quadrature::integrate(&mut f, x_a.sqrt(), x_b.sqrt(), QUAD_RTOL, 0.0)
    }

    /// Time to reach `x` from the start, s.
    pub fn time_at(&self, x: Meters) -> Seconds {
        self.time_between(0.0, x)
    }

    /// Position at time `t`, found by safeguarded Newton steps on
    /// `t(x) = t` starting from a known point `(x_a, t_a)` with `t_a <= t`.
    ///
    /// # Errors
    /// [`SimError::Inversion`] if no bracket or no convergence (not expected:
    /// t(x) is smooth and increasing).
    pub fn position_after(
        &self,
        x_a: Meters,
        t_a: Seconds,
        t: Seconds,
    ) -> Result<Meters, SimError> {
        if t <= t_a {
            return Ok(x_a);
        }
        let fail = SimError::Inversion { t };
        // Bracket [lo, hi] with t(lo) <= t <= t(hi), each time known from the
        // nearest point already integrated, so every quadrature covers only
        // the interval it adds.
        let (mut lo, mut t_lo) = (x_a, t_a);
        let mut step = (self.speed(x_a) * (t - t_a)).max(self.g_along * (t - t_a).powi(2) / 3.0);
        let (mut hi, mut t_hi) = (x_a, t_a);
        for _ in 0..200 {
            hi = lo + step;
            t_hi = t_lo + self.time_between(lo, hi);
            if t_hi >= t {
                break;
            }
            (lo, t_lo) = (hi, t_hi);
            step *= 2.0;
        }
        if t_hi < t {
            return Err(fail);
        }
        // Safeguarded Newton (dt/dx = 1/v), each t(x) integrated from lo.
        let mut x = lo + (hi - lo) * (t - t_lo) / (t_hi - t_lo);
        for _ in 0..100 {
            let tx = t_lo + self.time_between(lo, x);
            let f = tx - t;
            if f > 0.0 {
                hi = x;
            } else {
                (lo, t_lo) = (x, tx);
            }
            let mut next = x - f * self.speed(x);
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            if (next - x).abs() <= 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE)
                || hi - lo <= 4.0 * f64::EPSILON * hi
            {
                return Ok(next);
            }
            x = next;
        }
        Ok(x)
    }
}

/// Points of the scan for contact events over [0, x_limit]: geometric in
/// s = πr² (the closed form is a sum of powers of s/s0, so it varies on a
/// scale proportional to s), uniform in x when b = 0.
const EVENT_SCAN: usize = 400;

/// The first x in [0, `x_limit`] where the log of `cf` hops (N = 0, when
/// `opts.on_hop` stops) or slips (|F| = μN, when `opts.mu` is set), with
/// the reason; `forces_at(x)` gives the contact forces there. A scan of
/// [`EVENT_SCAN`] points in s brackets the first sign change of each event
/// function, bisection locates it to rounding. (Like the integrator's
/// events, a crossing and recrossing between two scan points, a band
/// narrower than 2.3 % of s, would be missed.)
fn first_contact_event(
    cf: &DragOnlyClosedForm,
    opts: &SimOptions,
    x_limit: Meters,
    forces_at: impl Fn(f64) -> ContactForces,
) -> Option<(Meters, StopReason)> {
    let hop = opts.on_hop == OnHop::Stop;
    // Positive where an event has fired.
    let fired = |x: f64| {
        let f = forces_at(x);
        let h = if hop { -f.normal_n } else { f64::NEG_INFINITY };
        let s = opts.mu.map_or(f64::NEG_INFINITY, |mu| f.slip_margin(mu));
        (h, s)
    };
    let reason = |(h, s): (f64, f64)| {
        if h >= 0.0 {
            Some(StopReason::Hop)
        } else if s >= 0.0 {
            Some(StopReason::Slip)
        } else {
            None
        }
    };
    if !hop && opts.mu.is_none() {
        return None;
    }
    if let Some(r) = reason(fired(0.0)) {
        return Some((0.0, r));
    }
    let s_ratio = 1.0 + cf.eps(x_limit);
    let at = |j: usize| {
        let frac = j as f64 / EVENT_SCAN as f64;
        if cf.b > 0.0 {
            (cf.s0 / cf.b) * (s_ratio.powf(frac) - 1.0)
        } else {
            x_limit * frac
        }
    };
    let mut lo = 0.0;
    for j in 1..=EVENT_SCAN {
        let hi = if j == EVENT_SCAN { x_limit } else { at(j) };
        if let Some(r) = reason(fired(hi)) {
            let (mut a, mut b) = (lo, hi);
            while b - a > 4.0 * f64::EPSILON * b {
                let mid = 0.5 * (a + b);
                if reason(fired(mid)).is_some() {
                    b = mid;
                } else {
                    a = mid;
                }
            }
            // The reason at the located point (both may fire in one interval).
            return Some((b, reason(fired(b)).unwrap_or(r)));
        }
        lo = hi;
    }
    None
}

/// Loney's closed form of eq. (4) (fn. 4), evaluated without an ODE solver.
/// Its contact forces are those of eq. (4) (`circular_forces`); a run stops
/// where the log hops or slips, as the ODE models do.
///
/// ```
/// use snowroll::{LoneyModel, Model, Sampling, Scenario, SimOptions};
/// let opts = SimOptions { sampling: Sampling::Times(vec![0.0, 1.0, 10.0]), ..Default::default() };
/// let traj = LoneyModel.simulate(&Scenario::default(), &opts)?;
/// assert_eq!(traj.samples.len(), 3);
/// # Ok::<(), snowroll::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LoneyModel;

impl Model for LoneyModel {
    fn kind(&self) -> ModelKind {
        ModelKind::Loney
    }

    /// With losses (or the energy ledger) Loney's closed form no longer
    /// holds: the run integrates its equation, eq. (4), with the losses
    /// (`docs/snowball-and-losses.md` §2.1) and still reports itself as `loney`.
    fn simulate_into(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError> {
        self.check(scenario, opts)?;
        if opts.losses.records_ledger() {
            return CircularModel::new(Derivation::TorqueAboutCentre)
                .simulate_into(scenario, opts, sink);
        }
        // Loney's solution is that of eq. (4): its contact forces are those of
        // the circular model of eq. (4) on the closed-form trajectory. On the
        // ball, that of its `torque-cm` (c_v = 23/14).
        let eq4 = Derivation::TorqueAboutCentre.coefficients_for(scenario.shape());
        let cf = DragOnlyClosedForm::new(scenario, eq4.drag);
        let forces_at =
            |x: f64| circular_forces(&eq4, scenario, x, cf.speed(x), cf.acceleration(x));
        let end = planned_end(&cf, opts, forces_at)?;
        let r0 = scenario.initial_radius();
        let b = scenario.snow_depth();
        let sample = |t: f64, x: f64| {
            let (v, a) = (cf.speed(x), cf.acceleration(x));
            let forces = forces_at(x);
            Sample {
                t_s: t,
                x_m: x,
                v_m_s: v,
                a_m_s2: a,
                r_m: (r0 * r0 + b * x / PI).sqrt(),
                mass_kg: crate::physics::mass_at(scenario, x),
                normal_n: forces.normal_n,
                friction_n: forces.friction_n,
                friction_ratio: forces.friction_ratio(),
            }
        };
        let times = sample_times(&opts.sampling, end.t);
        let stop = send_samples(&cf, &end, times, opts.max_rows, sample, sink)?;
        Ok(RunEnd {
            stop,
            stats: Default::default(),
        })
    }
}

/// Where a run of the closed form ends, known before any sample is sent.
#[derive(Debug, Clone, Copy)]
struct PlannedEnd {
    /// Time of the stop, s.
    t: Seconds,
    /// Position of the stop when it is known in advance (x_end, a hop or a
    /// slip); `None` for a run that ends at `t_end`.
    x: Option<Meters>,
    /// Why the run ends there.
    reason: StopReason,
}

/// Where the run of `cf` ends: at `t_end`, or at `x_end` if that comes
/// first, or at the first hop or slip before either ([`first_contact_event`]
/// with the contact forces `forces_at`).
///
/// # Errors
/// [`SimError::Inversion`] if the position at `t_end` cannot be found.
fn planned_end(
    cf: &DragOnlyClosedForm,
    opts: &SimOptions,
    forces_at: impl Fn(f64) -> ContactForces,
) -> Result<PlannedEnd, SimError> {
    let distance_first = opts.x_end.filter(|&x_end| cf.time_at(x_end) <= opts.t_end);
    let x_limit = match distance_first {
        Some(x_end) => x_end,
        None => cf.position_after(0.0, 0.0, opts.t_end)?,
    };
    let (t, x, reason) = match first_contact_event(cf, opts, x_limit, forces_at) {
        Some((x, reason)) => (cf.time_at(x), Some(x), reason),
        None => match distance_first {
            Some(x_end) => (cf.time_at(x_end), Some(x_end), StopReason::Distance),
            None => (opts.t_end, None, StopReason::EndTime),
        },
    };
    Ok(PlannedEnd { t, x, reason })
}

/// The sample times of `sampling` on a run that stops at `t_stop`,
/// generated one at a time (a grid is never held whole): [`DEFAULT_SAMPLES`]
/// even steps when every "step" is asked for.
fn sample_times(sampling: &Sampling, t_stop: Seconds) -> Box<dyn Iterator<Item = f64> + '_> {
    match sampling {
        Sampling::Times(ts) => Box::new(ts.iter().copied().take_while(move |&t| t <= t_stop)),
        Sampling::Every(dt) => {
            let dt = *dt;
            Box::new((0..).map_while(move |i| Sampling::grid_time(dt, i, t_stop)))
        }
        Sampling::Steps => {
            Box::new((0..=DEFAULT_SAMPLES).map(move |i| t_stop * i as f64 / DEFAULT_SAMPLES as f64))
        }
        Sampling::Ends => Box::new([0.0, t_stop].into_iter()),
    }
}

/// Sends the sample `sample(t, x)` of each time of `times` to `sink`, each
/// position found from the previous sample's by [`DragOnlyClosedForm::position_after`]
/// (or known: the planned stop's), and returns where the run stopped: at
/// `end`, or at the last sample sent once `max_rows` have been.
///
/// # Errors
/// [`SimError::Sink`] when the sink fails, [`SimError::Inversion`] when a
/// position cannot be found.
fn send_samples(
    cf: &DragOnlyClosedForm,
    end: &PlannedEnd,
    times: impl Iterator<Item = f64>,
    max_rows: u64,
    sample: impl Fn(f64, f64) -> Sample,
    sink: &mut dyn SampleSink,
) -> Result<Stop, SimError> {
    let (mut x_a, mut t_a) = (0.0, 0.0);
    for (rows, t) in (0u64..).zip(times) {
        if rows >= max_rows {
            return Ok(Stop {
                reason: StopReason::RowLimit,
                t_s: t_a,
                x_m: x_a,
                v_m_s: cf.speed(x_a),
                turn: None,
            });
        }
        let x = match end.x {
            Some(x) if t >= end.t => x,
            _ => cf.position_after(x_a, t_a, t)?,
        };
        sink.sample(&sample(t, x), None).map_err(SimError::Sink)?;
        (x_a, t_a) = (x, t);
    }
    let x_stop = match end.x {
        Some(x) => x,
        None => cf.position_after(x_a, t_a, end.t)?,
    };
    Ok(Stop {
        reason: end.reason,
        t_s: end.t,
        x_m: x_stop,
        v_m_s: cf.speed(x_stop),
        turn: None,
    })
}
