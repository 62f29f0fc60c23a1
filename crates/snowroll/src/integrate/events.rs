//! Finding the events of one accepted step.
//!
//! The signs of the event functions at the ends of the step say whether a
//! function crossed zero in its direction. Each crossing is then located on
//! the dense output, so each evaluation of the event function costs one
//! polynomial evaluation, not a step (`root.rs`).
//!
//! A function that is exactly zero where the step starts (at `t0`, where a
//! `Reset` left it, or where the previous step ended on its zero) counts
//! with the sign it has [`NUDGE_ULPS`] into the step: the start itself is
//! never an event, and a reset onto the event surface (a bouncing ball)
//! still finds the next crossing when one step spans the whole excursion.

use super::armed::Armed;
use super::dense::Polynomial;
use super::peaks::crossing_before_extremum;
use super::root::locate;
use super::{OdeSystem, MAX_EVENTS};

/// How far into a step, in ulps of `|t| + h`, an event function that starts
/// the step at exactly zero is looked at to tell which way it leaves zero
/// (SUNDIALS' root finding uses the same distance). A crossing closer than
/// that to the start of the step is not seen.
const NUDGE_ULPS: f64 = 100.0;

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
