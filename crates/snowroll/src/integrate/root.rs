//! Locating a sign change of a function in a bracket: the Illinois variant
//! of regula falsi, which keeps a bracket (so it cannot leave the step) and
//! converges superlinearly; it stops when the bracket is as narrow as `f64`
//! allows. Used for the events' crossings (`events.rs`) and for the
//! crossings before an extremum (`peaks.rs`).

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
