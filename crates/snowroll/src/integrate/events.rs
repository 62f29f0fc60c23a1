//! Finding the events of one accepted step.
//!
//! The signs of the event functions at the ends of the step say whether a
//! function crossed zero in its direction. Each crossing is then located on
//! the dense output, so each evaluation of the event function costs one
//! polynomial evaluation, not a step. The Illinois variant of regula falsi
//! keeps a bracket (so it cannot leave the step) and converges
//! superlinearly; it stops when the bracket is as narrow as `f64` allows.
//!
//! A function that is exactly zero where the step starts (at `t0`, where a
//! `Reset` left it, or where the previous step ended on its zero) counts
//! with the sign it has [`NUDGE_ULPS`] into the step: the start itself is
//! never an event, and a reset onto the event surface (a bouncing ball)
//! still finds the next crossing when one step spans the whole excursion.

use super::dense::Polynomial;
use super::peaks::crossing_before_extremum;
use super::{OdeSystem, MAX_EVENTS};

/// How far into a step, in ulps of `|t| + h`, an event function that starts
/// the step at exactly zero is looked at to tell which way it leaves zero
/// (SUNDIALS' root finding uses the same distance). A crossing closer than
/// that to the start of the step is not seen.
const NUDGE_ULPS: f64 = 100.0;

/// The event functions that can fire in this run ([`OdeSystem::event_armed`]),
/// in index order: the step loop keeps their values in slots `0..len`, slot
/// `j` holding event `index[j]`, and never evaluates the others.
#[derive(Debug, Clone, Copy)]
pub(super) struct Armed {
    index: [usize; MAX_EVENTS],
    len: usize,
}

impl Armed {
    /// The armed events among the first `n_events` (at most [`MAX_EVENTS`]) of `system`.
    pub fn new<S: OdeSystem<N>, const N: usize>(system: &S, n_events: usize) -> Self {
        let mut armed = Self {
            index: [0; MAX_EVENTS],
            len: 0,
        };
        for i in (0..n_events).filter(|&i| system.event_armed(i)) {
            armed.index[armed.len] = i;
            armed.len += 1;
        }
        armed
    }

    /// How many events are armed.
    pub fn len(&self) -> usize {
        self.len
    }

    /// The event index of each slot, in slot order.
    pub fn indices(&self) -> &[usize] {
        &self.index[..self.len]
    }
}

/// What the event functions at the two ends of a step call for.
#[derive(Debug, Clone, Copy)]
pub(super) struct StepEnds {
    /// Some function changed sign in its direction.
    crossed: bool,
    /// Some function started at exactly zero and may have crossed.
    from_zero: bool,
}

impl StepEnds {
    /// Whether the dense output is needed to find this step's events.
    pub fn needs_dense(self) -> bool {
        self.crossed || self.from_zero
    }
}

/// Evaluates the armed event functions at the end `(t_new, y_new)` of a
/// step into `g_new`, and compares them with their values `g_old` at its
/// start (both by slot).
pub(super) fn scan_step_ends<S: OdeSystem<N>, const N: usize>(
    system: &S,
    armed: &Armed,
    t_new: f64,
    y_new: &[f64; N],
    g_old: &[f64],
    g_new: &mut [f64; MAX_EVENTS],
) -> StepEnds {
    let mut ends = StepEnds {
        crossed: false,
        from_zero: false,
    };
    for (j, (&i, &before)) in armed.indices().iter().zip(g_old).enumerate() {
        g_new[j] = system.event(i, t_new, y_new);
        let direction = system.event_direction(i);
        if before == 0.0 {
            ends.from_zero |= direction.may_end_crossing(g_new[j]);
        } else {
            ends.crossed |= direction.crosses(before, g_new[j]);
        }
    }
    ends
}

/// Located events of one step: `(time, index)`, earliest first.
#[derive(Debug, Clone, Copy)]
pub(super) struct Found {
    events: [(f64, usize); MAX_EVENTS],
    len: usize,
}

impl Found {
    /// Whether no event was found.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The events, earliest first (simultaneous ones in index order).
    pub fn as_slice(&self) -> &[(f64, usize)] {
        &self.events[..self.len]
    }
}

/// Locates every crossing in `(t_lo, t_new]`, part of the step whose dense
/// output is `p`, given the armed events' values `g_lo` at `t_lo` and
/// `g_new` at `t_new` (by slot); for the slots in `suspects` (bit j for
/// slot j) that do not cross at the ends, also a crossing before an
/// extremum inside the step (`peaks.rs`). The events found carry their
/// event index.
pub(super) fn crossings<S: OdeSystem<N>, const N: usize>(
    system: &S,
    armed: &Armed,
    p: &Polynomial<'_, N>,
    (t_lo, g_lo): (f64, &[f64]),
    t_new: f64,
    g_new: &[f64; MAX_EVENTS],
    suspects: u32,
) -> Found {
    let t_nudge = (t_lo + NUDGE_ULPS * f64::EPSILON * (t_lo.abs() + p.h)).min(0.5 * (t_lo + t_new));
    let mut y_nudge = None;
    let mut found = Found {
        events: [(f64::INFINITY, 0); MAX_EVENTS],
        len: 0,
    };
    for (j, (&i, &before)) in armed.indices().iter().zip(g_lo).enumerate() {
        let direction = system.event_direction(i);
        // Where the bracket starts, and the function's value there.
        let (t_start, g_start) = if before != 0.0 {
            (t_lo, before)
        } else if direction.may_end_crossing(g_new[j]) {
            let y = y_nudge.get_or_insert_with(|| p.at(t_nudge));
            (t_nudge, system.event(i, t_nudge, y))
        } else {
            continue;
        };
        if direction.crosses(g_start, g_new[j]) {
            let te = locate(t_start, t_new, g_start, g_new[j], |tt| {
                system.event(i, tt, &p.at(tt))
            });
            found.events[found.len] = (te, i);
            found.len += 1;
        } else if suspects & (1 << j) != 0 {
            if let Some(te) = crossing_before_extremum(system, p, i, (t_start, g_start), t_new) {
                found.events[found.len] = (te, i);
                found.len += 1;
            }
        }
    }
    // A stable sort: simultaneous events keep their index order.
    found.events[..found.len].sort_by(|a, b| a.0.total_cmp(&b.0));
    found
}

/// Time in `[t_lo, t_hi]` where `g` changes sign, given `g(t_lo) = g_lo` and
/// `g(t_hi) = g_hi` of opposite signs (or one of them zero).
///
/// Returns the end of the final bracket on the far side of the crossing, so
/// that the event function evaluated there has already crossed (this keeps a
/// stopped or reset integration from seeing the same crossing twice).
pub(super) fn locate(
    mut t_lo: f64,
    mut t_hi: f64,
    mut g_lo: f64,
    mut g_hi: f64,
    mut g: impl FnMut(f64) -> f64,
) -> f64 {
    if g_lo == 0.0 {
        return t_lo;
    }
    /// Illinois iterations; a crossing not found by then is bisected.
    const ILLINOIS: usize = 200;
    /// Iterations allowed in all: enough for bisection alone to shrink any
    /// bracket of finite times to a few ulps (about 2100 halvings take
    /// 1e308 to the smallest subnormal), so the loop never gives up on a
    /// crossing it has bracketed. Before, it returned the bracket's end
    /// after the Illinois iterations (issue 33, item 4: a crossing 1e-50 s
    /// into a step of 1e-4 s, where the function is 1e92 times smaller on
    /// one side than on the other, needs hundreds of Illinois steps; the
    /// end of the step was returned and `--x-end 1e-100` reported reached
    /// at x = 1.6e-8 m). Crossings found within the Illinois iterations
    /// are found exactly as before.
    const MAX_ITERATIONS: usize = 2400;
    // Side that was kept last: -1 low, +1 high, 0 none yet.
    let mut side = 0i8;
    // The sign on the low side, fixed: the Illinois halvings of `g_lo` may
    // take it to zero (1e-300 halved 80 times), and a sign read from it
    // then put points past the crossing on the low side.
    let low_negative = g_lo < 0.0;
    for k in 0..MAX_ITERATIONS {
        let width = t_hi - t_lo;
        if width <= 4.0 * f64::EPSILON * t_lo.abs().max(t_hi.abs()).max(f64::MIN_POSITIVE) {
            break;
        }
        let mut t_mid = (t_lo * g_hi - t_hi * g_lo) / (g_hi - g_lo);
        if k >= ILLINOIS || !(t_mid > t_lo && t_mid < t_hi) {
            t_mid = 0.5 * (t_lo + t_hi);
        }
        let g_mid = g(t_mid);
        if g_mid == 0.0 {
            return t_mid;
        }
        if (g_mid < 0.0) == low_negative {
            t_lo = t_mid;
            g_lo = g_mid;
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            t_hi = t_mid;
            g_hi = g_mid;
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
    }
    t_hi
}

#[cfg(test)]
mod tests {
    use super::locate;

    /// Bracket end-points of f64 around the root: the locator's promise.
    const TIME_TOL: f64 = 4.0 * f64::EPSILON;

    #[test]
    fn finds_simple_and_tangent_like_roots() {
        let root = std::f64::consts::FRAC_PI_3;
        let t = locate(
            0.0,
            2.0,
            (0.0f64 - root).sin(),
            (2.0f64 - root).sin(),
            |t| (t - root).sin(),
        );
        assert!((t - root).abs() <= TIME_TOL * 2.0, "{t} vs {root}");
        // A flat crossing (cubic) still converges.
        let t = locate(0.0, 1.0, -0.3f64.powi(3), 0.7f64.powi(3), |t| {
            (t - 0.3).powi(3)
        });
        assert!((t - 0.3).abs() < 1e-5, "{t}");
    }

    /// Issue 33, item 4: x(t) = t² − 1e-100 crosses at t = 1e-50, bracketed
    /// by a step [0, 1e-4] where |g| is 1e92 times larger at the far end.
    /// The root is known in closed form; it must be found to the
    /// locator's tolerance, not the step's end returned (which it was).
    #[test]
    fn regression_33_a_crossing_far_below_the_step_is_found() {
        for (root, h) in [(1e-50, 1e-4), (1e-150, 1.0), (3e-20, 10.0)] {
            let g = |t: f64| t * t - root * root;
            let t = locate(0.0, h, g(0.0), g(h), g);
            assert!(
                (t - root).abs() <= 4.0 * TIME_TOL * root,
                "root {root} in [0, {h}]: found {t}"
            );
        }
    }
}
