//! One adaptive integrator with event location, shared by every ODE model.
//!
//! # Why it is written here
//! The models need Dormand–Prince 8(5,3) (Hairer's DOP853) with its 7th-order
//! dense output, several event functions at once with a direction filter,
//! event times located on the dense output to near machine precision, and an
//! action per event (`Stop`, `Continue`, or `Reset` the state and go on: the
//! collision at the end of each turn of §3.4). The Rust ODE crates measured on
//! this problem did not provide that: `differential-equations` 0.7's `Event`
//! misses event times by ~1e-4 s at rtol 1e-10 and takes one condition,
//! `ode_solvers` 0.6 has no event location, and `diffsol` 0.18 has no direction
//! filter, allocates state on the heap and builds slowly. So the stepper is
//! written once, generic over `const N: usize` with `[f64; N]` state (no heap
//! in the step loop), with the tableau as data (`tableau.rs`), Hairer's error
//! norm and step-size controller (`control.rs`), and Illinois root finding
//! on the dense output (`events.rs`).
//!
//! # Use
//! A model implements [`OdeSystem`]; [`integrate`] runs it from `(t0, y0)`
//! to `t_end` or to a stopping event, and reports every accepted step and
//! every event to an [`Observer`], which decides what is recorded (nothing,
//! every step, or values at requested times from the dense output).
//!
//! # Example: a ball dropped from 1 m, stopped when it reaches the floor
//! ```
//! use snowroll::integrate::{integrate, Direction, NoObserver, OdeSystem, Termination, Tolerances};
//!
//! /// y = [height, velocity]; one event: the height falling through zero.
//! struct Drop { g: f64 }
//! impl OdeSystem<2> for Drop {
//!     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
//!         *dy = [y[1], -self.g];
//!     }
//!     fn event_count(&self) -> usize { 1 }
//!     fn event(&self, _i: usize, _t: f64, y: &[f64; 2]) -> f64 { y[0] }
//!     fn event_direction(&self, _i: usize) -> Direction { Direction::Falling }
//! }
//!
//! let g = 9.81;
//! let end = integrate(&mut Drop { g }, 0.0, [1.0, 0.0], 10.0, &Tolerances::default(), &mut NoObserver)?;
//! assert_eq!(end.termination, Termination::Event { index: 0 });
//! // Free fall: the floor is reached at t = sqrt(2 h / g), located on the dense output.
//! assert!((end.t - (2.0 / g).sqrt()).abs() < 1e-12);
//! # Ok::<(), snowroll::SimError>(())
//! ```

mod armed;
mod control;
mod dense;
mod dop853;
mod entry;
mod events;
mod peaks;
mod root;
mod tableau;
mod taylor;

pub use dense::DenseStep;
pub use entry::integrate;

/// Most event functions one system may have (they live in fixed buffers,
/// so the step loop does not allocate).
pub const MAX_EVENTS: usize = 8;

/// Highest order of a Taylor step ([`OdeSystem::taylor_coefficients`] is
/// asked for at most this many coefficients after `c[0]`).
pub const TAYLOR_MAX_ORDER: usize = 30;

use crate::error::ParamError;

/// Which sign changes of an event function trigger the event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From negative to non-negative.
    Rising,
    /// From positive to non-positive.
    Falling,
    /// Either way.
    Either,
}

impl Direction {
    /// Whether the change from `before` to `after` is a crossing in this direction.
    pub fn crosses(self, before: f64, after: f64) -> bool {
        let rising = before < 0.0 && after >= 0.0;
        let falling = before > 0.0 && after <= 0.0;
        match self {
            Direction::Rising => rising,
            Direction::Falling => falling,
            Direction::Either => rising || falling,
        }
    }

    /// Whether a step that starts with the function at exactly zero and
    /// ends at `after` can hold a crossing in this direction.
    pub(crate) fn may_end_crossing(self, after: f64) -> bool {
        match self {
            Direction::Rising => after >= 0.0,
            Direction::Falling => after <= 0.0,
            Direction::Either => true,
        }
    }
}

/// What the integrator does once an event has been located.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EventAction<const N: usize> {
    /// End the integration at the event.
    Stop,
    /// Record the event and go on unchanged.
    Continue,
    /// Replace the state at the event time by this one and go on from there.
    Reset([f64; N]),
}

/// A system `dy/dt = f(t, y)` with `N` components and optional event functions.
///
/// `rhs` cannot fail and does not allocate: every assumption it makes was
/// checked when the model was built.
pub trait OdeSystem<const N: usize> {
    /// Writes `f(t, y)` into `dy`.
    fn rhs(&self, t: f64, y: &[f64; N], dy: &mut [f64; N]);

    /// How many leading components of the state the step-size control
    /// sees (default: all N). The rest are quadratures, `y_i = ∫ f_i dt` of
    /// functions of the controlled state, carried along on the steps the
    /// controlled components choose (as CVODES's quadratures without error
    /// control): adding them does not change those steps, and a smooth
    /// integrand is integrated to the same order and tolerance.
    fn controlled_components(&self) -> usize {
        N
    }

    /// Whether [`Self::taylor_coefficients`] gives the Taylor coefficients
    /// of the solution (default: no). Then [`integrate`] takes Taylor-series
    /// steps (`taylor.rs`) instead of DOP853's: for a smooth right-hand side
    /// whose coefficients follow from a short recurrence, a step of order 20
    /// costs a few hundred multiply-adds and goes several times further than
    /// a DOP853 step, and its series is the dense output.
    fn has_taylor(&self) -> bool {
        false
    }

    /// Writes the Taylor coefficients `c[k] = y⁽ᵏ⁾(t)/k!`, k = 0..c.len(),
    /// of the solution through `(t, y)` (so `c[0] = y`, `c[1] = f(t, y)`);
    /// `c.len()` is at most [`TAYLOR_MAX_ORDER`] + 1. Called only where
    /// [`Self::has_taylor`] is true.
    fn taylor_coefficients(&self, _t: f64, _y: &[f64; N], _c: &mut [[f64; N]]) {}

    /// Number of event functions.
    fn event_count(&self) -> usize {
        0
    }

    /// Value of event function `index` at `(t, y)`; the event happens where it crosses zero.
    fn event(&self, _index: usize, _t: f64, _y: &[f64; N]) -> f64 {
        0.0
    }

    /// Whether event function `index` can fire at all in this run (default:
    /// yes). Asked once, when the integration starts: an event that cannot
    /// fire (a slip with no friction coefficient given, an end distance not
    /// asked for, a hop where the normal force is known to stay positive)
    /// is never evaluated, so the step loop pays nothing for it.
    fn event_armed(&self, _index: usize) -> bool {
        true
    }

    /// Which crossings of event function `index` count.
    fn event_direction(&self, _index: usize) -> Direction {
        Direction::Either
    }

    /// Whether event function `index` may pass zero in its direction and
    /// turn back within one step (a narrow maximum of a `Rising` function,
    /// a narrow minimum of a `Falling` one): then each step is also searched
    /// for such an extremum, at the cost of one more evaluation of the
    /// event function per step (`peaks.rs`). Default: only sign changes
    /// between the ends of a step count.
    fn event_may_turn(&self, _index: usize) -> bool {
        false
    }

    /// What to do at a located event of function `index` (events are offered in time order).
    fn on_event(&self, _index: usize, _t: f64, _y: &[f64; N]) -> EventAction<N> {
        EventAction::Stop
    }

    /// Called after the observer has seen the event, to update the system
    /// (e.g. the turn number after a collision); `event` carries the action
    /// [`Self::on_event`] chose.
    fn commit_event(&mut self, _event: &EventRecord<N>) {}
}

/// A located event.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EventRecord<const N: usize> {
    /// Index of the event function.
    pub index: usize,
    /// Time of the zero crossing, s.
    pub t: f64,
    /// State at the crossing (before any reset).
    pub y_before: [f64; N],
    /// State the integration goes on from (equal to `y_before` unless reset).
    pub y_after: [f64; N],
    /// The action the system chose.
    pub action: EventAction<N>,
}

/// Receives what the integrator does, step by step, with read access to the system.
pub trait Observer<S: ?Sized, const N: usize> {
    /// The initial state, once, before the first step.
    fn start(&mut self, _system: &S, _t0: f64, _y0: &[f64; N]) {}

    /// Whether `step` will need the dense output on `(t_old, t_new]` (it costs
    /// three more evaluations of `f`). Asked once for every accepted step,
    /// with the whole step, before it is cut at any event.
    fn wants_dense(&self, _t_old: f64, _t_new: f64) -> bool {
        false
    }

    /// One accepted step, or a piece of it: a step is cut at each located
    /// event, so the pieces and the events arrive in time order, each piece
    /// starting where the previous one (or the event's `y_after`) left off.
    fn step(&mut self, _system: &S, _step: &DenseStep<'_, N>) {}

    /// One located event, after the step piece that ends at it and before
    /// [`OdeSystem::commit_event`] updates the system.
    fn event(&mut self, _system: &S, _event: &EventRecord<N>) {}

    /// Whether the observer wants the integration to end now (a full
    /// output, a failed writer). Asked once before every step: the run then
    /// ends with [`Termination::Stopped`] at the last state it reported.
    fn stop_requested(&self) -> bool {
        false
    }
}

/// An observer that records nothing.
#[derive(Debug, Default, Clone, Copy)]
pub struct NoObserver;

impl<S: ?Sized, const N: usize> Observer<S, N> for NoObserver {}

/// Smallest absolute tolerance: with a state component at zero the error is
/// divided by atol alone, and below ~1e-30 that overflows for ordinary
/// accelerations.
pub const MIN_ATOL: f64 = 1e-30;

/// Tolerances and limits of one integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance per component. Default 1e-10.
    pub rtol: f64,
    /// Absolute tolerance per component, in the component's unit. Default 1e-12.
    pub atol: f64,
    /// Largest step, in the time unit. Default: unbounded.
    pub max_step: f64,
    /// Most accepted plus rejected steps, plus located events; the run
    /// ends there with [`Termination::StepLimit`]. Default 10^8.
    pub max_steps: u64,
}

impl Default for Tolerances {
    fn default() -> Self {
        Self {
            rtol: 1e-10,
            atol: 1e-12,
            max_step: f64::INFINITY,
            max_steps: 100_000_000,
        }
    }
}

impl Tolerances {
    /// Checks that the tolerances are usable: the one check of rtol, atol
    /// and max_step ([`SimOptions::validate`](crate::SimOptions::validate)
    /// calls it too).
    ///
    /// # Errors
    /// [`ParamError::InvalidParameter`] naming the first bad tolerance.
    pub fn validate(&self) -> Result<(), ParamError> {
        let check = |name: &'static str, value: f64, ok: bool, expected: &'static str| {
            if ok {
                Ok(())
            } else {
                Err(ParamError::InvalidParameter {
                    name,
                    value,
                    expected,
                })
            }
        };
        check(
            "rtol",
            self.rtol,
            self.rtol.is_finite() && self.rtol >= 1e-15 && self.rtol < 1.0,
            "1e-15 <= rtol < 1",
        )?;
        check(
            "atol",
            self.atol,
            self.atol.is_finite() && self.atol >= MIN_ATOL,
            "atol >= 1e-30 (a smaller atol makes the error of a zero component overflow)",
        )?;
        check(
            "max_step",
            self.max_step,
            self.max_step > 0.0,
            "max_step > 0 (may be infinite)",
        )?;
        check(
            "max_steps",
            self.max_steps as f64,
            self.max_steps >= 1,
            "max_steps >= 1",
        )?;
        Ok(())
    }
}

/// Why an integration ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Termination {
    /// It reached the requested end time.
    EndTime,
    /// Event function `index` asked to stop.
    Event {
        /// Index of the event function.
        index: usize,
    },
    /// It used up [`Tolerances::max_steps`] steps and events.
    StepLimit,
    /// The observer asked it to stop ([`Observer::stop_requested`]).
    Stopped,
}

/// Step and evaluation counts of one integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Evaluations of the right-hand side.
    pub evaluations: u64,
    /// Taylor coefficients computed, per component, summed over the Taylor
    /// steps (0 for DOP853 steps): the order of each step. Order k of the
    /// recurrence costs O(k) multiply-adds.
    pub taylor_terms: u64,
}

/// The end of an integration: final time and state, why it ended, and cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome<const N: usize> {
    /// Final time.
    pub t: f64,
    /// Final state.
    pub y: [f64; N],
    /// Why it ended.
    pub termination: Termination,
    /// Step and evaluation counts.
    pub stats: Stats,
}
