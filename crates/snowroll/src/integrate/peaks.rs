//! Events whose function may touch zero and turn back within one step
//! ([`OdeSystem::event_may_turn`]): a narrow peak of |F|/N just above μ (a
//! slip) or a narrow dip of N just below 0 (a hop) leaves both ends of the
//! step on the same side of zero, so the signs at the ends do not see it.
//!
//! For such an event the slope dg/dt is estimated at the end of every step
//! (a forward difference along `y′ = f`, one more evaluation of the event
//! function), and the cubic Hermite interpolant of `(g, dg/dt)` at the two
//! ends of the step is asked whether g has an interior extremum in the
//! event's direction (a maximum for `Rising`, a minimum for `Falling`). If
//! it has, golden-section search on the dense output finds the extremum of
//! g itself in the step; if that is past zero, the crossing before it is
//! located as any other (`root.rs`).

use super::armed::Armed;
use super::dense::Polynomial;
use super::root::locate;
use super::{Direction, OdeSystem, MAX_EVENTS};

/// Forward-difference step of the slope, as a fraction of the step length:
/// truncation error ~ this × h |g″| against |g′| ~ |g|/h, rounding ~ 1e-16
/// |g|/(this × h): both far below the slopes' own size. The slope only
/// decides whether to search; the search uses g itself.
const SLOPE_STEP: f64 = 1e-7;
/// Golden-section fraction `(√5 − 1)/2`.
const INV_PHI: f64 = 0.618_033_988_749_894_9;
/// Width, as a fraction of the step, at which the search for the extremum
/// stops: the value there is then off by ~g″ (1e-10 h)², far below any
/// margin that matters (`locate` finds the crossing to rounding after).
const SEARCH_TOL: f64 = 1e-10;

/// The slopes of the watched events at the two ends of the current step
/// (by slot of [`Armed`]).
pub(super) struct Peaks {
    /// The armed events, slot by slot.
    armed: Armed,
    /// Which slots are watched (bit j for slot j).
    watched: u32,
    /// dg/dt at the start of the step.
    slope_old: [f64; MAX_EVENTS],
    /// dg/dt at its end.
    slope_new: [f64; MAX_EVENTS],
}

impl Peaks {
    /// Watches the armed events of `system` that ask for it.
    pub fn new<S: OdeSystem<N>, const N: usize>(system: &S, armed: Armed) -> Self {
        let watched = (armed.indices().iter().enumerate())
            .filter(|&(_, &i)| system.event_may_turn(i))
            .fold(0u32, |mask, (j, _)| mask | (1 << j));
        Self {
            armed,
            watched,
            slope_old: [0.0; MAX_EVENTS],
            slope_new: [0.0; MAX_EVENTS],
        }
    }

    /// Whether any event is watched (else the slopes are never needed).
    pub fn watching(&self) -> bool {
        self.watched != 0
    }

    /// The slopes at `(t, y)` where `y′ = f` and the events are `g`, with
    /// the step `h` about to be taken (or just taken), into `out`.
    fn slopes<S: OdeSystem<N>, const N: usize>(
        &self,
        system: &S,
        (t, y, f): (f64, &[f64; N], &[f64; N]),
        g: &[f64],
        h: f64,
        out: &mut [f64; MAX_EVENTS],
    ) {
        let dt = SLOPE_STEP * h.abs();
        let mut ahead = *y;
        for (a, fi) in ahead.iter_mut().zip(f) {
            *a += dt * fi;
        }
        for (j, (slope, &i)) in out.iter_mut().zip(self.armed.indices()).enumerate() {
            if self.watched & (1 << j) != 0 {
                *slope = (system.event(i, t + dt, &ahead) - g[j]) / dt;
            }
        }
    }

    /// At the start of the integration or after a reset: the slopes at the
    /// start are not known yet (the first step computes them with its own h).
    pub fn restart(&mut self) {
        self.slope_old = [f64::NAN; MAX_EVENTS];
    }

    /// At the end of an accepted step of length `h` from `(t, y)` to
    /// `(t_new, y_new)`, with `f = y′` at each (`[start, end]`) and the event
    /// values `g_old`, `g_new` at its ends (by slot): the watched slots
    /// whose Hermite interpolant has an interior extremum in their
    /// direction (bit j for slot j).
    pub fn suspects<S: OdeSystem<N>, const N: usize>(
        &mut self,
        system: &S,
        [start, end]: [(f64, &[f64; N], &[f64; N]); 2],
        (g_old, g_new): (&[f64], &[f64]),
        h: f64,
    ) -> u32 {
        if self.watched == 0 {
            return 0;
        }
        if self.slope_old.iter().any(|d| d.is_nan()) {
            let mut out = [0.0; MAX_EVENTS];
            self.slopes(system, start, g_old, h, &mut out);
            self.slope_old = out;
        }
        let mut out = [0.0; MAX_EVENTS];
        self.slopes(system, end, g_new, h, &mut out);
        self.slope_new = out;
        let mut found = 0;
        for (j, (&g0, &g1)) in g_old.iter().zip(g_new).enumerate() {
            if self.watched & (1 << j) == 0 {
                continue;
            }
            let sign = match system.event_direction(self.armed.indices()[j]) {
                Direction::Rising => 1.0,
                Direction::Falling => -1.0,
                Direction::Either => continue,
            };
            let (d0, d1) = (sign * self.slope_old[j] * h, sign * out[j] * h);
            if hermite_has_interior_max(sign * g0, d0, sign * g1, d1) {
                found |= 1 << j;
            }
        }
        found
    }

    /// The end's slopes become the next step's start's.
    pub fn advance(&mut self) {
        self.slope_old = self.slope_new;
    }
}

/// Whether the cubic `p` on s ∈ [0, 1] with `p(0) = g0`, `p′(0) = d0`,
/// `p(1) = g1`, `p′(1) = d1` has an interior local maximum.
fn hermite_has_interior_max(g0: f64, d0: f64, g1: f64, d1: f64) -> bool {
    // p′(s) = d0 + 2 c s + 3 e s², p″(s) = 2c + 6 e s.
    let c = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
    let e = 2.0 * (g0 - g1) + d0 + d1;
    let is_max = |s: f64| s > 0.0 && s < 1.0 && 2.0 * c + 6.0 * e * s < 0.0;
    if e == 0.0 {
        return c != 0.0 && is_max(-d0 / (2.0 * c));
    }
    let disc = c * c - 3.0 * e * d0;
    if disc < 0.0 {
        return false;
    }
    let root = disc.sqrt();
    is_max((-c + root) / (3.0 * e)) || is_max((-c - root) / (3.0 * e))
}

/// The crossing of event `i` (direction `sign` = +1 rising, −1 falling)
/// before the extremum of its function in `(t_lo, t_hi]` on the dense
/// output `p`, if the extremum is past zero; `g_lo` its value at `t_lo`.
pub(super) fn crossing_before_extremum<S: OdeSystem<N>, const N: usize>(
    system: &S,
    p: &Polynomial<'_, N>,
    i: usize,
    (t_lo, g_lo): (f64, f64),
    t_hi: f64,
) -> Option<f64> {
    let sign = match system.event_direction(i) {
        Direction::Rising => 1.0,
        Direction::Falling => -1.0,
        Direction::Either => return None,
    };
    let g = |tt: f64| system.event(i, tt, &p.at(tt));
    let (mut a, mut b) = (t_lo, t_hi);
    // Never below a few ulps of t: a step of 1e-9 s at t = 89 s asks for
    // 1e-19 s, which no two times near 89 differ by, and the search never
    // ended (an unwinding roll nearing its hop, issue 35).
    let ulps = 4.0 * f64::EPSILON * t_lo.abs().max(t_hi.abs()).max(f64::MIN_POSITIVE);
    let tol = (SEARCH_TOL * (t_hi - t_lo)).max(ulps);
    let (mut c, mut d) = (b - INV_PHI * (b - a), a + INV_PHI * (b - a));
    let (mut gc, mut gd) = (sign * g(c), sign * g(d));
    while b - a > tol {
        if gc > gd {
            (b, d, gd) = (d, c, gc);
            c = b - INV_PHI * (b - a);
            gc = sign * g(c);
        } else {
            (a, c, gc) = (c, d, gd);
            d = a + INV_PHI * (b - a);
            gd = sign * g(d);
        }
    }
    let (t_top, g_top) = if gc > gd { (c, gc) } else { (d, gd) };
    (g_top >= 0.0 && sign * g_lo < 0.0).then(|| locate(t_lo, t_top, g_lo, sign * g_top, g))
}

#[cfg(test)]
mod tests {
    use super::hermite_has_interior_max;

    #[test]
    fn hermite_sees_interior_maxima_only() {
        // −(s − ½)² − 0.01: a maximum at ½, both ends below it.
        assert!(hermite_has_interior_max(-0.26, 1.0, -0.26, -1.0));
        // Monotone rising, and a minimum in the middle.
        assert!(!hermite_has_interior_max(-1.0, 1.0, 0.0, 1.0));
        assert!(!hermite_has_interior_max(0.0, -1.0, 0.0, 1.0));
        // Both slopes positive, but the cubic rises, falls and rises again.
        assert!(hermite_has_interior_max(0.0, 3.0, 0.0, 3.0));
    }
}
