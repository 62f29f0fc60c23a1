//! The entry of the integrator: checks the arguments, then runs DOP853's
//! step loop (`dop853.rs`) or Taylor steps (`taylor.rs`) with the same
//! event handling and observer.

use super::control::check_times;
use super::dop853::Integrator;
use super::{Observer, OdeSystem, Outcome, Termination, Tolerances, MAX_EVENTS};
use crate::error::SimError;

/// Integrates `system` from `(t0, y0)` forward to `t_end`, locating the
/// system's events on the dense output and applying their actions, and
/// reports each accepted step (cut at events) and each event to `observer`,
/// in time order. The steps are DOP853's, or Taylor-series steps where the
/// system gives its Taylor coefficients ([`OdeSystem::has_taylor`],
/// `taylor.rs`).
///
/// An event function that is exactly zero where a step starts (at `t0`,
/// where a `Reset` left it, or where the previous step ended on its zero)
/// does not trigger there: it counts with the sign it takes just after the
/// start (100 ulps of `|t| + h` into the step), so an event at `t0` is not reported and a reset
/// onto the event surface (a bouncing ball) finds the next crossing even
/// when one step spans the whole excursion. Events are found from sign
/// changes between the ends of each step, so a function that crosses zero
/// twice within one step is not seen, unless a `Continue` event in between
/// changed it (after `Continue` events the rest of the step is searched
/// again, so a counter in the event function works) or the system marks
/// the event with [`OdeSystem::event_may_turn`] (then an extremum inside
/// the step is searched for as well, `peaks.rs`). Simultaneous events
/// are offered in index order; after a `Reset` the others of the same step
/// are dropped, and the integration restarts from the new state.
///
/// Two limits end the run early without an error, at the last state the
/// observer saw: `tol.max_steps` steps and events
/// ([`Termination::StepLimit`]), and the observer's own request
/// ([`Observer::stop_requested`], asked before every step:
/// [`Termination::Stopped`]).
///
/// # Errors
/// [`ParamError::InvalidParameter`](crate::ParamError::InvalidParameter) for bad tolerances or a start or end
/// time that is not finite (or `t_end < t0`),
/// [`SimError::StepSizeTooSmall`] when the step underflows (a singularity),
/// [`SimError::NonFiniteState`] when the state is or becomes non-finite, and
/// [`SimError::TooManyEvents`] past [`MAX_EVENTS`] event functions.
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
    check_times(t0, &y0, t_end)?;
    let n_events = system.event_count();
    if n_events > MAX_EVENTS {
        return Err(SimError::TooManyEvents {
            count: n_events,
            max: MAX_EVENTS,
        });
    }
    let taylor = system.has_taylor();
    let mut it = Integrator::new(system, tol, n_events);
    observer.start(&*it.system, t0, &y0);
    if t_end <= t0 {
        return Ok(it.outcome(t0, y0, Termination::EndTime));
    }
    if taylor {
        it.run_taylor(t0, y0, t_end, observer)
    } else {
        it.run(t0, y0, t_end, observer)
    }
}
