//! fn. 7 in the setting of §3: a log started from rest on the turn models
//! always starts (its acceleration at θ = 0 is 2G/3, since no snow has been
//! lifted yet), but it may stall inside its first turn when the snow it
//! lifts outweighs the slope's pull (`docs/turn-model.md`, "Stall in the
//! first turn").

use super::{TurnDynamics, TurnVariant};
use crate::portable::Portable as _;
use crate::units::{Meters, Radians};

/// Grid intervals over (0, 2π] that bracket the maximum of Q/P: Q/P has a
/// single interior maximum (near θ = 4.4 rad for thin snow, lower for thick
/// snow), so 64 intervals of 0.1 rad leave ample margin.
const GRID: usize = 64;
/// Absolute tolerance in θ of the refined maximum: the value of Q/P at the
/// maximum is then off by ~(Q/P)″·(1e-10)² ≈ 1e-22, far below rounding.
const THETA_TOL: f64 = 1e-10;
/// Smallest θ of the search, rad: Q/P → (e₃ − e₂)/r0 ≤ 0 as θ → 0, so the
/// maximum is never this close to 0; starting here avoids 0/0.
const THETA_MIN: f64 = 1e-6;

/// The slope below which a log started from rest stalls inside its first
/// turn (fn. 7 in §3), for a turn model of variant `variant` with initial
/// radius `r0` and snow depth `b`; `None` without snow.
///
/// From rest, energy conservation within turn 0 gives
/// `θ̇²(θ) = −2W(θ)/I(θ)` with `I > 0` (the energy integral of
/// [`TurnDynamics::acceleration_on_orbit`] with θ̇₀ = 0),
/// so the log completes the turn exactly when `W(θ) < 0` on all of
/// (0, 2π]. Writing `W = −G P(θ) + C Q(θ)` (G = g sin α, C = g cos α) with
/// `P = r0θ + e₁θ²/2 − e₂(1 − cos θ)` and `Q = e₃θ − e₂ sin θ`:
///
/// `tan α* = max over 0 < θ ≤ 2π of Q(θ)/P(θ)`.
///
/// For the first-order coefficients of eq. (62) (`e₁ = e₂ = e₃ = b/π`) and
/// `ε = b/(π r0)` this is `max ε(θ − sin θ)/(θ + ε(θ²/2 − 1 + cos θ))`; to
/// leading order in ε, `tan α* ≈ (1 − cos θ₁) ε ≈ 1.2172 ε`, where
/// θ₁ ≈ 4.4934 is the first positive root of `tan θ = θ` (2.09° at the
/// defaults b = 0.01 m, r0 = 0.1 m).
///
/// ```
/// use snowroll::{first_turn_stall_slope, TurnVariant};
/// let alpha = first_turn_stall_slope(TurnVariant::Paper, 0.1, 0.01).unwrap();
/// assert!((alpha.to_degrees() - 2.0908).abs() < 1e-3);
/// assert!(first_turn_stall_slope(TurnVariant::Paper, 0.1, 0.0).is_none());
/// ```
pub fn first_turn_stall_slope(variant: TurnVariant, r0: Meters, b: Meters) -> Option<Radians> {
    if b <= 0.0 || r0 <= 0.0 || !b.is_finite() || !r0.is_finite() {
        return None;
    }
    // G = 1, C = 0 gives W = −P; G = 0, C = 1 gives W = Q.
    let along = TurnDynamics::new(variant, r0, b, 1.0, 0.0);
    let normal = TurnDynamics::new(variant, r0, b, 0.0, 1.0);
    let ratio = |theta: f64| normal.potential(theta).0 / -along.potential(theta).0;
    let (_, max) = super::extremes::range_on(
        ratio,
        THETA_MIN,
        2.0 * std::f64::consts::PI,
        GRID,
        THETA_TOL,
    );
    Some(max.max(0.0).atan_p())
}

/// The coefficients `(P, Q)` split of the in-turn potential, for tests.
#[cfg(test)]
fn split(c: &super::InTurnCoefficients, r0: f64, theta: f64) -> (f64, f64) {
    let p = r0 * theta + c.e1 * theta * theta / 2.0 - c.e2 * (1.0 - theta.cos_p());
    let q = c.e3 * theta - c.e2 * theta.sin_p();
    (p, q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The refined maximum against a fine grid: the grid misses the peak by
    /// at most (Q/P)″ h²/8 with h = 2π/10⁶, ~1e-13 relative.
    const GRID_TOL: f64 = 1e-9;

    #[test]
    fn stall_slope_is_the_largest_q_over_p() {
        for (r0, b) in [(0.1, 0.01), (0.15, 0.2), (0.1, 0.001)] {
            for variant in [TurnVariant::Paper, TurnVariant::Exact] {
                let c = TurnDynamics::new(variant, r0, b, 1.0, 1.0).coefficients();
                let direct = (1..=1_000_000)
                    .map(|i| {
                        let (p, q) = split(&c, r0, 2.0 * PI * f64::from(i) / 1e6);
                        q / p
                    })
                    .fold(f64::NEG_INFINITY, f64::max);
                let got = first_turn_stall_slope(variant, r0, b).unwrap().tan();
                assert!(got >= direct * (1.0 - GRID_TOL), "{variant:?} {r0} {b}");
                assert!(got <= direct * (1.0 + GRID_TOL), "{variant:?} {r0} {b}");
            }
        }
    }
}
