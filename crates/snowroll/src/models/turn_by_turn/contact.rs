//! Contact forces within a turn of §3.4 (`docs/contact-forces.md` §3).
//!
//! During turn k the body (disk of radius r = r_k plus the annular sector
//! of the snow picked up) rotates rigidly about the contact line C at rate
//! θ̇, so its momentum is `p = θ̇ (S_y, −S_x)` with the first moment about C,
//! per unit m_k, `S_x/m_k = −e₂(1 − cos θ)`, `S_y/m_k = r(1 + μθ) − e₂ sin θ`.
//! Differentiating along the motion and using the momentum balance of the
//! accreting body (`N = dp_y/dt + M C`, `F = M G − dp_x/dt`):
//!
//! `N/m_k = (1 + μθ) C + e₂ [θ̈ (1 − cos θ) + θ̇² sin θ]`
//!
//! `F/m_k = (1 + μθ) G − θ̈ [r(1 + μθ) − e₂ sin θ] − θ̇² (e₁ − e₂ cos θ)`
//!
//! with the coefficients μ, e₁, e₂ of [`InTurnCoefficients`](super::InTurnCoefficients)
//! (μ r = e₁ in both variants) and θ̈ the model's own (eq. (64), the
//! energy equation). Exact for the `Exact` variant, first order in b/r for
//! `Paper`. As b → 0: N = m C, F = m G/3 (App. A).

use super::{extremes, TurnDynamics};
use crate::models::contact::ContactForces;
use crate::units::Radians;

/// Grid intervals over a turn that bracket the extremes of N(θ) and of
/// |F|/N(θ): each has one minimum and one maximum per turn in late turns
/// (N ≈ C + (G/2) sin θ, §4.2), so 32 intervals of 0.2 rad leave margin for
/// the skewed early turns.
const FORCE_GRID: usize = 32;
/// Absolute tolerance in θ of the refined extremes, rad (the value at the
/// extreme is then off by ~f″ · 1e-16).
const FORCE_THETA_TOL: f64 = 1e-8;

impl TurnDynamics {
    /// `(N, F)` per unit `m_k` at `(θ, θ̇)`, m/s² (module doc, `docs/contact-forces.md` §3).
    pub fn contact_per_mass(&self, theta: Radians, omega: f64) -> (f64, f64) {
        let k = &self.coeffs;
        let (s, c) = theta.sin_cos();
        let alpha = self.angular_acceleration(theta, omega);
        let w2 = omega * omega;
        let grown = 1.0 + k.accretion * theta;
        let normal = grown * self.g_normal + k.e2 * (alpha * (1.0 - c) + w2 * s);
        let friction =
            grown * self.g_along - alpha * (self.r * grown - k.e2 * s) - w2 * (k.e1 - k.e2 * c);
        (normal, friction)
    }

    /// N and F on a log of start mass `m_k` (kg) at `(θ, θ̇)`.
    pub fn contact_forces(&self, m_k: f64, theta: Radians, omega: f64) -> ContactForces {
        let (n, f) = self.contact_per_mass(theta, omega);
        ContactForces {
            normal_n: m_k * n,
            friction_n: m_k * f,
        }
    }

    /// `(N, F)` per unit `m_k` at θ on the energy integral of a turn started
    /// with `θ̇(0) = omega0` (θ̇² clamped at 0 past a stall).
    fn contact_on_orbit(&self, theta: Radians, omega0: f64) -> (f64, f64) {
        let omega = self.omega_squared(theta, omega0).max(0.0).sqrt();
        self.contact_per_mass(theta, omega)
    }

    /// Over a turn started with `θ̇(0) = omega0`, for θ ∈ [0, `theta_max`],
    /// from the energy integral (no integration): the extremes of N and of
    /// |F|/N. The ratio is infinite if N reaches 0.
    pub fn contact_range(&self, omega0: f64, theta_max: Radians) -> ContactRange {
        let mu = self.coeffs.accretion;
        let g = self.g_along.hypot(self.g_normal);
        let on_orbit = |theta| self.contact_on_orbit(theta, omega0);
        let (n_min, _) = extremes::range_on(
            |theta| on_orbit(theta).0,
            0.0,
            theta_max,
            FORCE_GRID,
            FORCE_THETA_TOL,
        );
        let (n_over_mg_min, _) = extremes::range_on(
            |theta| on_orbit(theta).0 / ((1.0 + mu * theta) * g),
            0.0,
            theta_max,
            FORCE_GRID,
            FORCE_THETA_TOL,
        );
        let max_friction_ratio = if n_min <= 0.0 {
            f64::INFINITY
        } else {
            extremes::range_on(
                |theta| {
                    let (n, f) = on_orbit(theta);
                    f.abs() / n
                },
                0.0,
                theta_max,
                FORCE_GRID,
                FORCE_THETA_TOL,
            )
            .1
        };
        ContactRange {
            min_normal_per_mk: n_min,
            min_normal_over_mg: n_over_mg_min,
            max_friction_ratio,
        }
    }
}

impl TurnDynamics {
    /// The first θ in [0, `theta_max`] where |F| reaches μN on the energy
    /// integral of a turn started with `θ̇(0) = omega0`, if any: a grid of
    /// 32 intervals brackets a crossing, or the neighbourhood of
    /// the largest sampled |F| − μN holds a narrow peak (golden section finds
    /// its top); bisection then refines the crossing to 1e-8 rad.
    /// The slip event of a turn is `θ − θ_slip`, so that a peak of |F|/N
    /// barely above μ, narrower than a step, is not stepped over.
    pub fn first_slip(&self, omega0: f64, mu: f64, theta_max: Radians) -> Option<Radians> {
        let margin = |theta: f64| {
            let (n, f) = self.contact_on_orbit(theta, omega0);
            f.abs() - mu * n
        };
        let h = theta_max / FORCE_GRID as f64;
        let bisect = |mut lo: f64, mut hi: f64| {
            while hi - lo > FORCE_THETA_TOL {
                let mid = 0.5 * (lo + hi);
                if margin(mid) >= 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            hi
        };
        if margin(0.0) >= 0.0 {
            return Some(0.0);
        }
        let mut best = (0.0, f64::NEG_INFINITY);
        for i in 1..=FORCE_GRID {
            let theta = i as f64 * h;
            let m = margin(theta);
            if m >= 0.0 {
                return Some(bisect(theta - h, theta));
            }
            if m > best.1 {
                best = (theta, m);
            }
        }
        // No sampled point slips: look for a narrow peak around the largest sample.
        let (mut a, mut b) = ((best.0 - h).max(0.0), (best.0 + h).min(theta_max));
        const INV_PHI: f64 = 0.618_033_988_749_894_9;
        while b - a > FORCE_THETA_TOL {
            let (c, d) = (b - INV_PHI * (b - a), a + INV_PHI * (b - a));
            if margin(c) > margin(d) {
                b = d;
            } else {
                a = c;
            }
        }
        let top = 0.5 * (a + b);
        (margin(top) >= 0.0).then(|| bisect((best.0 - h).max(0.0), top))
    }
}

/// Extremes of the contact forces over (part of) a turn, [`TurnDynamics::contact_range`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactRange {
    /// Smallest N per unit m_k, m/s².
    pub min_normal_per_mk: f64,
    /// Smallest N/(M g), M = m_k(1 + μθ) the mass there.
    pub min_normal_over_mg: f64,
    /// Largest |F|/N.
    pub max_friction_ratio: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::TurnVariant;

    /// Rounding of a few operations on numbers of order g.
    const ROUNDING: f64 = 1e-13;

    #[test]
    fn b_to_zero_gives_the_snowless_forces() {
        let (g, c) = (4.905, 8.496_0);
        for variant in [TurnVariant::Paper, TurnVariant::Exact] {
            let turn = TurnDynamics::new(variant, 0.1, 0.0, g, c);
            for (theta, omega) in [(0.0, 0.0), (1.0, 3.0), (4.7, 20.0)] {
                let (n, f) = turn.contact_per_mass(theta, omega);
                assert!((n - c).abs() < ROUNDING * c);
                assert!((f - g / 3.0).abs() < ROUNDING * g);
            }
        }
    }

    /// Late turns, §4.2: with (b/π)θ̇² = G/2 the normal force is C + (G/2) sin θ
    /// to O(b/r). Tolerance: b/r = 1e-4 here, times coefficients of order 10 g.
    #[test]
    fn late_turn_normal_force_is_c_plus_half_g_sin_theta() {
        let (g, c, b, r) = (4.905, 8.496_0, 0.01, 100.0);
        let turn = TurnDynamics::new(TurnVariant::Exact, r, b, g, c);
        let omega = (std::f64::consts::PI * g / (2.0 * b)).sqrt();
        for theta in [0.5, 2.0, 4.712_388_98, 5.5] {
            let (n, _) = turn.contact_per_mass(theta, omega);
            let want = c + 0.5 * g * f64::sin(theta);
            assert!((n - want).abs() < 1e-2, "θ = {theta}: {n} vs {want}");
        }
    }
}
