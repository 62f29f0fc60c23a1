//! Locating the zero of an event function inside one step.
//!
//! The event function is evaluated on the dense output, so each evaluation
//! costs one polynomial evaluation, not a step. The Illinois variant of
//! regula falsi keeps a bracket (so it cannot leave the step) and converges
//! superlinearly; it stops when the bracket is as narrow as `f64` allows.

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
    // Side that was kept last: -1 low, +1 high, 0 none yet.
    let mut side = 0i8;
    for _ in 0..200 {
        let width = t_hi - t_lo;
        if width <= 4.0 * f64::EPSILON * t_lo.abs().max(t_hi.abs()).max(f64::MIN_POSITIVE) {
            break;
        }
        let mut t_mid = (t_lo * g_hi - t_hi * g_lo) / (g_hi - g_lo);
        if !(t_mid > t_lo && t_mid < t_hi) {
            t_mid = 0.5 * (t_lo + t_hi);
        }
        let g_mid = g(t_mid);
        if g_mid == 0.0 {
            return t_mid;
        }
        if (g_mid < 0.0) == (g_lo < 0.0) {
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
}
