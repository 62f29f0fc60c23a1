//! The smallest and largest value of a smooth function over one turn, for
//! the range of the acceleration within a turn: a coarse grid brackets each
//! extreme, Brent's method (parabolic steps with golden-section fallback,
//! Brent 1973, ch. 5) refines it, or Newton's method where the function
//! comes with its derivatives ([`refine_min_jet`]).

use super::jet::Jet;

/// Golden-section fraction `(3 − √5)/2`.
const GOLDEN: f64 = 0.381_966_011_250_105_1;
/// Most refinement steps (Brent's method needs ~10 here; golden section alone 40).
const MAX_STEPS: usize = 60;
/// Probe step, as a fraction of the bracket, that tells whether an extreme
/// found at an end of the interval is a boundary extreme.
const PROBE: f64 = 1e-6;

/// The smallest value of `f` near its minimum in `[lo, hi]` (f unimodal
/// there), located to `x_tol` (absolute) in the argument: `(x, f(x))` of the
/// smallest value evaluated.
pub(super) fn brent_min(
    f: impl Fn(f64) -> f64,
    mut lo: f64,
    mut hi: f64,
    x_tol: f64,
) -> (f64, f64) {
    let mut x = lo + GOLDEN * (hi - lo);
    let (mut w, mut v) = (x, x);
    let mut fx = f(x);
    let (mut fw, mut fv) = (fx, fx);
    // Step taken last (d) and the one before (e).
    let (mut d, mut e) = (0.0f64, 0.0f64);
    for _ in 0..MAX_STEPS {
        let mid = 0.5 * (lo + hi);
        let tol1 = x_tol;
        let tol2 = 2.0 * tol1;
        if (x - mid).abs() <= tol2 - 0.5 * (hi - lo) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol1 {
            // Parabola through (v, fv), (w, fw), (x, fx).
            let r = (x - w) * (fx - fv);
            let q0 = (x - v) * (fx - fw);
            let mut p = (x - v) * q0 - (x - w) * r;
            let mut q = 2.0 * (q0 - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            let e_old = e;
            e = d;
            if p.abs() < (0.5 * q * e_old).abs() && p > q * (lo - x) && p < q * (hi - x) {
                d = p / q;
                let u = x + d;
                if u - lo < tol2 || hi - u < tol2 {
                    d = tol1.copysign(mid - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= mid { lo - x } else { hi - x };
            d = GOLDEN * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let fu = f(u);
        if fu <= fx {
            if u >= x {
                lo = x;
            } else {
                hi = x;
            }
            (v, fv) = (w, fw);
            (w, fw) = (x, fx);
            (x, fx) = (u, fu);
        } else {
            if u < x {
                lo = u;
            } else {
                hi = u;
            }
            if fu <= fw || w.to_bits() == x.to_bits() {
                (v, fv) = (w, fw);
                (w, fw) = (u, fu);
            } else if fu <= fv || v.to_bits() == x.to_bits() || v.to_bits() == w.to_bits() {
                (v, fv) = (u, fu);
            }
        }
    }
    (x, fx)
}

/// `(min, max)` of `f` over `[lo, hi]`: `grid` intervals bracket each
/// extreme (endpoints included), Brent's method refines it to `x_tol`.
pub(super) fn range_on(
    f: impl Fn(f64) -> f64,
    lo: f64,
    hi: f64,
    grid: usize,
    x_tol: f64,
) -> (f64, f64) {
    let step = (hi - lo) / grid as f64;
    let at = |i: usize| lo + i as f64 * step;
    let (mut i_min, mut i_max) = (0, 0);
    let (mut f_min, mut f_max) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..=grid {
        let fi = f(at(i));
        if fi < f_min {
            (f_min, i_min) = (fi, i);
        }
        if fi > f_max {
            (f_max, i_max) = (fi, i);
        }
    }
    let (_, refined_min) = refine_min(&f, lo, step, grid, i_min, f_min, x_tol);
    let refined_max = -refine_min(|x| -f(x), lo, step, grid, i_max, -f_max, x_tol).1;
    (f_min.min(refined_min), f_max.max(refined_max))
}

/// The smallest value of `g` near point `i` of the grid `lo + j step`,
/// `j = 0..=grid`, where `g_i` is the smallest sampled value: Brent's method
/// over the two neighbouring intervals; an end point that `g` increases away
/// from is itself the extreme. Returns `(θ, g(θ))` of the smallest value
/// found, never above `g_i`.
pub(super) fn refine_min(
    g: impl Fn(f64) -> f64,
    lo: f64,
    step: f64,
    grid: usize,
    i: usize,
    g_i: f64,
    x_tol: f64,
) -> (f64, f64) {
    let at = |j: usize| lo + j as f64 * step;
    let inward = if i == 0 {
        Some(PROBE * step)
    } else if i == grid {
        Some(-PROBE * step)
    } else {
        None
    };
    match inward {
        Some(dx) if g(at(i) + dx) >= g_i => (at(i), g_i),
        _ => {
            let (x, gx) = brent_min(g, at(i.saturating_sub(1)), at((i + 1).min(grid)), x_tol);
            // `g_i.min(gx)` as a value: the grid point wins a tie.
            if gx < g_i {
                (x, gx)
            } else {
                (at(i), g_i)
            }
        }
    }
}

/// Newton steps of [`refine_min_jet`] before it leaves the minimum to
/// Brent's method (from a grid point it needs three or four).
const MAX_NEWTON: usize = 8;
/// Newton's step below which [`refine_min_jet`] stops, rad: the minimum of
/// the local quadratic, `g − g′²/(2g″)`, is then off by ~|g‴| · 1e-15/6.
const NEWTON_STEP_TOL: f64 = 1e-5;

/// [`refine_min`] by Newton's method on `g′ = 0` from the jets `g(θ)`
/// ([`Jet`]), given the samples `samples[j] = g(lo + j step)` and the
/// index `i` of the smallest: from `hint` where it lies within the two
/// intervals next to `i` (where a like extreme was found before), else from
/// the vertex of the parabola through the samples around `i`, steps
/// `−g′/g″` while `g″ > 0` and the steps stay within the two intervals next
/// to `i`; once a step is below
/// [`NEWTON_STEP_TOL`] the value is the local quadratic's minimum. Where
/// Newton's method does not apply (g not convex there, a step leaving the
/// bracket) Brent's method on the values takes over, to `x_tol`. An end of
/// the grid that `g` increases away from (`g′` pointing inward) is itself
/// the extreme. `known`, `(θ, g(θ))` with its derivatives where another
/// refinement already evaluated it, starts Newton's method there instead of
/// `hint`, with no evaluation of its own (where it lies in the same
/// intervals). Returns `(θ, value)`, the value never above `samples[i]`.
pub(super) fn refine_min_jet(
    g: impl Fn(f64) -> Jet,
    (lo, step): (f64, f64),
    samples: &[f64],
    i: usize,
    (hint, known): (Option<f64>, Option<(f64, Jet)>),
    x_tol: f64,
) -> (f64, f64) {
    let grid = samples.len() - 1;
    let g_i = samples[i];
    let at = |j: usize| lo + j as f64 * step;
    let (a, b) = (at(i.saturating_sub(1)), at((i + 1).min(grid)));
    let interior = i > 0 && i < grid;
    let mut x = at(i);
    let mut first = None;
    if let Some((theta, jet)) = known.filter(|(t, _)| *t >= a && *t <= b && interior) {
        (x, first) = (theta, Some(jet));
    } else if let Some(h) = hint.filter(|h| *h >= a && *h <= b && interior) {
        x = h;
    } else if interior {
        // The parabola's vertex, within the bracket (a start within
        // ~h³|g‴/g″| of the minimum, so that Newton needs a step or two).
        let (before, after) = (samples[i - 1], samples[i + 1]);
        let curvature = before - 2.0 * g_i + after;
        if curvature > 0.0 {
            x += (0.5 * (before - after) / curvature).clamp(-1.0, 1.0) * step;
        }
    }
    for n in 0..MAX_NEWTON {
        let j = first.take().unwrap_or_else(|| g(x));
        if n == 0 && ((i == 0 && j.d >= 0.0) || (i == grid && j.d <= 0.0)) {
            return (x, g_i);
        }
        if j.dd.is_nan() || j.dd <= 0.0 {
            break;
        }
        let dx = -j.d / j.dd;
        if dx.abs() <= NEWTON_STEP_TOL {
            let value = j.v + 0.5 * j.d * dx;
            return if value < g_i {
                (x + dx, value)
            } else {
                (at(i), g_i)
            };
        }
        let next = x + dx;
        if !(next >= a && next <= b) {
            break;
        }
        x = next;
    }
    let (x, gx) = brent_min(|x| g(x).v, a, b, x_tol);
    if gx < g_i {
        (x, gx)
    } else {
        (at(i), g_i)
    }
}

/// The index of the smallest of `values` (the first of equal ones).
pub(super) fn least(values: &[f64]) -> usize {
    let mut best = 0;
    for (i, &v) in values.iter().enumerate() {
        if v < values[best] {
            best = i;
        }
    }
    best
}

/// The first θ in `(lo, hi]` where `n(θ) ≤ 0`, given `n(lo) > 0 ≥ n(hi)` and
/// one crossing between them: bisection until `lo` and `hi` are adjacent
/// doubles (at most ~60 halvings for θ ≤ 2π); the end with `n ≤ 0`.
pub(super) fn first_root(n: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return hi;
        }
        if n(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Value error at an abscissa error of 1e-9 on curvature O(1), plus rounding.
    const VALUE_TOL: f64 = 1e-15;

    #[test]
    fn finds_interior_and_boundary_extremes() {
        use std::f64::consts::PI;
        // min −1 at 2.5, max 1 at 2.5 ± π (2.5 − π is outside [0, 2π]).
        let f = |x: f64| -(x - 2.5).cos();
        let (lo, hi) = range_on(f, 0.0, 2.0 * PI, 16, 1e-9);
        assert!((lo + 1.0).abs() < VALUE_TOL, "{lo}");
        assert!((hi - 1.0).abs() < VALUE_TOL, "{hi}");
        // Monotone: the extremes are the endpoints.
        let (lo, hi) = range_on(|x| x * x, 0.0, 2.0, 16, 1e-9);
        assert!(lo.abs() < VALUE_TOL && (hi - 4.0).abs() < VALUE_TOL);
        // An asymmetric minimum where parabolic steps matter.
        let g = |x: f64| (x - 1.3).powi(4) + (x - 1.3).powi(2) + x.sin() * 1e-3;
        let direct = (0..=2_000_000)
            .map(|i| g(i as f64 * 1e-6))
            .fold(f64::INFINITY, f64::min);
        let (_, refined) = brent_min(g, 1.0, 1.6, 1e-10);
        assert!(refined <= direct + VALUE_TOL, "{refined} vs {direct}");
    }
}
