//! Loney's solution of eq. (4) (fn. 4) as a model, [`LoneyModel`], and the
//! closed form of the drag-only equations `a = P − c_v b v²/(π r²)` as a
//! value, [`DragOnlyClosedForm`]: both are views of the one solver of the
//! parent module, [`SpeedSquared`].
//!
//! (F1) with L = M = k = 0 is fn. 4: with `p = 2c_v`,
//! `u(x) = v0² (s0/s)^p + 2P/(1+p) · (s0/b) [s/s0 − (s0/s)^p]`
//! (for c_v = 7/6, p = 7/3: `u = 2G s/(5b) + K/s^{7/3}`), and
//! `a(x) = 2P/(2(1+p)) [1 + p (s0/s)^{p+1}] − (p/2)(b/s0) v0² (s0/s)^{p+1}`,
//! which tends to `P/(1+p)` (G/5 for eq. (4)). The coefficient of the
//! decaying term is `7bK/6` for eq. (4), not `7bK/3` as printed
//! (`docs/errata.md`, fn. 4). Time is `t(x) = ∫ dx/√u`, and x(t) its
//! inverse (the parent module).
//!
//! The ball on its natural swath 2r follows the same law with P = 5G/7
//! instead of 2G/3 and c_v = 23/14 for its `torque-cm`
//! (`docs/snowball-and-losses.md` §1.4): `u = (G s/(3b)) [1 − (s0/s)^{30/7}]`
//! from rest, the closed form of the letter in The Physics Teacher 57,
//! p. 436 (2019), a → G/6.

use crate::portable::Portable as _;
use std::f64::consts::PI;

use super::clock::Clock;
use super::{ContactCheck, SpeedSquared};
use crate::error::{ParamError, SimError};
use crate::models::contact::{circular_forces, ContactForces};
use crate::models::{CircularModel, Coefficients, Derivation, Model, ModelKind};
use crate::scenario::Scenario;
use crate::trajectory::{
    OnHop, RunEnd, Sample, SampleSink, Sampling, SimOptions, Stop, StopReason,
};
use crate::units::{Meters, MetersPerSecond, MetersPerSecondSquared, Seconds};

/// Samples of the closed form when every "step" is asked for.
const DEFAULT_SAMPLES: usize = 500;

/// The closed form watches no contact events itself: [`LoneyModel`]
/// locates them on the closed form ([`first_contact_event`]).
const NO_CONTACT: ContactCheck = ContactCheck {
    stop_on_hop: false,
    mu: None,
};

/// The exact solution of `a = P − c_v b v²/(π r²)` (P = 2G/3 for the log,
/// 5G/7 for the ball) for one scenario: a view of [`SpeedSquared`].
///
/// ```
/// use snowroll::{DragOnlyClosedForm, Scenario};
/// let s = Scenario::default();
/// let loney = DragOnlyClosedForm::new(&s, 7.0 / 6.0)?; // eq. (4), fn. 4
/// // From rest the acceleration starts at 2/3 g sin α ...
/// assert!((loney.acceleration(0.0) / s.g_along() - 2.0 / 3.0).abs() < 1e-14);
/// // ... and tends to g sin α / 5.
/// assert!((loney.acceleration(1e7) / s.g_along() - 0.2).abs() < 1e-9);
/// # Ok::<(), snowroll::SimError>(())
/// ```
#[derive(Debug, Clone)]
pub struct DragOnlyClosedForm {
    u: SpeedSquared,
}

impl DragOnlyClosedForm {
    /// The solution for drag coefficient `drag` (= c_v; 7/6 for eq. (4),
    /// 23/14 for the ball's `torque-cm`) on the scenario's shape.
    ///
    /// # Errors
    /// [`ParamError::InvalidParameter`] for a `drag` that is negative or
    /// not finite; [`ParamError::ShapeNotSupported`] for a ball with a fixed
    /// swath, which does not follow the area law π r² = π r0² + b x.
    pub fn new(s: &Scenario, drag: f64) -> Result<Self, SimError> {
        ModelKind::Loney.check_shape(s)?;
        let bad_drag = ParamError::InvalidParameter {
            name: "drag",
            value: drag,
            expected: "a finite drag coefficient c_v >= 0",
        };
        if !(drag.is_finite() && drag >= 0.0) {
            return Err(bad_drag.into());
        }
        let c = Coefficients {
            accretes: true,
            drag,
            lift: 0.0,
            lift_b2: 0.0,
            inertia_b2: 0.0,
            drag_b3: 0.0,
            shape: s.shape(),
        };
        let u = SpeedSquared::new(&c, s, NO_CONTACT).ok_or(bad_drag)?;
        Ok(Self { u })
    }

    /// `u = v²` at distance `x`, m²/s².
    pub fn speed_squared(&self, x: Meters) -> f64 {
        self.u.at(x)
    }

    /// Speed at distance `x`, m/s.
    pub fn speed(&self, x: Meters) -> MetersPerSecond {
        self.u.at(x).sqrt()
    }

    /// Acceleration at distance `x`, `a = ½ du/dx` (module doc), m/s².
    pub fn acceleration(&self, x: Meters) -> MetersPerSecondSquared {
        self.u.acceleration(x)
    }

    /// Time to reach `x` from the start, s.
    ///
    /// # Errors
    /// [`SimError::TimeIntegral`] if the quadrature fails (not expected:
    /// the integrand is smooth in w = √x).
    pub fn time_at(&self, x: Meters) -> Result<Seconds, SimError> {
        self.u.clock()?.time_at(x)
    }

    /// Position at time `t` from the start, m.
    ///
    /// # Errors
    /// [`SimError::Inversion`] if t(x) = t has no solution found (not
    /// expected: t(x) is smooth and increasing).
    pub fn position_at(&self, t: Seconds) -> Result<Meters, SimError> {
        self.u.clock()?.position_after(0.0, 0.0, t)
    }
}

/// Points of the scan for contact events over [0, x_limit]: geometric in
/// s = πr² (the closed form is a sum of powers of s/s0, so it varies on a
/// scale proportional to s), uniform in x when b = 0.
const EVENT_SCAN: usize = 400;

/// The first x in [0, `x_limit`] where the body on the closed form `u`
/// hops (N = 0, when `opts.on_hop` stops) or slips (|F| = μN, when
/// `opts.mu` is set), with the reason; `forces_at(x)` gives the contact
/// forces there. A scan of [`EVENT_SCAN`] points in s brackets the first
/// sign change of each event function, bisection locates it to rounding.
/// (Like the integrator's events, a crossing and recrossing between two
/// scan points, a band narrower than 2.3 % of s, would be missed.)
fn first_contact_event(
    u: &SpeedSquared,
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
    let s_ratio = 1.0 + u.b * x_limit / u.s0;
    let at = |j: usize| {
        let frac = j as f64 / EVENT_SCAN as f64;
        if u.b > 0.0 {
            (u.s0 / u.b) * (s_ratio.powf_p(frac) - 1.0)
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

/// Loney's closed form of eq. (4) (fn. 4), evaluated without an ODE solver
/// by [`SpeedSquared`], the solver of the sweep's fast path. Its contact
/// forces are those of eq. (4) (`circular_forces`); a run stops where the
/// body hops or slips, as the ODE models do.
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
        // With the ledger, or for an unwinding roll (b < 0: the clock's
        // panels and series assume a growing cross-section, and the run must
        // stop at the core), the ODE of eq. (4).
        if opts.losses.records_ledger() || scenario.unwinds() {
            return CircularModel::new(Derivation::TorqueAboutCentre)
                .simulate_into(scenario, opts, sink);
        }
        // Loney's solution is that of eq. (4): its contact forces are those of
        // the circular model of eq. (4) on the closed-form trajectory. On the
        // ball, that of its `torque-cm` (c_v = 23/14).
        let eq4 = Derivation::TorqueAboutCentre.coefficients_for(scenario.shape());
        let u =
            SpeedSquared::new(&eq4, scenario, NO_CONTACT).ok_or(ParamError::ShapeNotSupported {
                model: ModelKind::Loney.id(),
                shape: scenario.shape().id(),
                reason: "the closed form needs the area law pi r^2 = pi r0^2 + b x",
            })?;
        let clock = u.clock()?;
        let forces_at =
            |x: f64| circular_forces(&eq4, scenario, x, u.at(x).sqrt(), u.acceleration(x));
        let end = planned_end(&u, &clock, opts, forces_at)?;
        let r0 = scenario.initial_radius();
        let b = scenario.snow_depth();
        let sample = |t: f64, x: f64| {
            let (v, a) = (u.at(x).sqrt(), u.acceleration(x));
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
        let stop = send_samples(&u, &clock, &end, times, opts.max_rows, sample, sink)?;
        Ok(RunEnd {
            stop,
            stats: Default::default(),
            hop_doubt: None,
        })
    }
}

/// Where a run of the closed form ends, known before any sample is sent.
#[derive(Debug, Clone, Copy)]
struct PlannedEnd {
    /// Time of the stop, s.
    t: Seconds,
    /// Position of the stop, m.
    x: Meters,
    /// Why the run ends there.
    reason: StopReason,
}

/// Where the run of `u` ends: at `t_end`, or at `x_end` if that comes
/// first (as the sweep's [`super::circular_end`] finds it), or at the first
/// hop or slip before either ([`first_contact_event`] with the contact
/// forces `forces_at`).
///
/// # Errors
/// [`SimError::Inversion`] if the position at `t_end` cannot be found,
/// [`SimError::TimeIntegral`] if the time of an event cannot.
fn planned_end(
    u: &SpeedSquared,
    clock: &Clock<'_>,
    opts: &SimOptions,
    forces_at: impl Fn(f64) -> ContactForces,
) -> Result<PlannedEnd, SimError> {
    let (reason, t, x) = u
        .run_end(opts.t_end, opts.x_end)
        .filter(|(_, t, x)| t.is_finite() && x.is_finite())
        .ok_or(SimError::Inversion { t: opts.t_end })?;
    Ok(match first_contact_event(u, opts, x, forces_at) {
        Some((x, reason)) => PlannedEnd {
            t: clock.time_at(x)?,
            x,
            reason,
        },
        None => PlannedEnd { t, x, reason },
    })
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
/// position found from the previous sample's by the `clock` (the planned
/// stop's at its time), and returns where the run stopped: at `end`, or at
/// the last sample sent once `max_rows` have been.
///
/// # Errors
/// [`SimError::Sink`] when the sink fails, [`SimError::Inversion`] when a
/// position cannot be found.
fn send_samples(
    u: &SpeedSquared,
    clock: &Clock<'_>,
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
                v_m_s: u.at(x_a).sqrt(),
                turn: None,
            });
        }
        let x = if t >= end.t {
            end.x
        } else {
            clock.position_after(x_a, t_a, t)?
        };
        sink.sample(&sample(t, x), None).map_err(SimError::Sink)?;
        (x_a, t_a) = (x, t);
    }
    Ok(Stop {
        reason: end.reason,
        t_s: end.t,
        x_m: end.x,
        v_m_s: u.at(end.x).sqrt(),
        turn: None,
    })
}
