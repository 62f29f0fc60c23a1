//! Exact mass properties of a disk with a partial ring of snow (§3, eqs.
//! (37)–(43), (48), (56) without truncation in b/r).
//!
//! The body is a solid disk of radius `r` (the log at the start of a turn)
//! plus an annular sector `r < r′ < r + b` spanning the angle `θ′ ∈ [0, θ]`
//! measured back from the contact line, all of density ρ and length l. Its
//! element at `(r′, θ′)` sits at `(x − r′ sin θ′, r − r′ cos θ′)` when the
//! contact line is at `(x, 0)`. Every integral reduces to `D_n = (r + b)ⁿ − rⁿ`.

use crate::portable::Portable as _;
use std::f64::consts::PI;

use crate::units::{Joules, Kilograms, Meters, Radians};

/// `D_n = (r + b)ⁿ − rⁿ` for n = 2, 3, 4, expanded so that nothing cancels
/// when b ≪ r.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingMoments {
    /// `D₂ = b(2r + b)`, m².
    pub d2: f64,
    /// `D₃ = b(3r² + 3rb + b²)`, m³.
    pub d3: f64,
    /// `D₄ = b(4r³ + 6r²b + 4rb² + b³)`, m⁴.
    pub d4: f64,
}

impl RingMoments {
    /// The moments of the ring `r < r′ < r + b`.
    pub fn new(r: Meters, b: Meters) -> Self {
        Self {
            d2: b * (2.0 * r + b),
            d3: b * (3.0 * r * r + 3.0 * r * b + b * b),
            d4: b * (4.0 * r * r * r + 6.0 * r * r * b + 4.0 * r * b * b + b * b * b),
        }
    }
}

/// A disk of radius `r` with an annular sector of snow of thickness `b` over
/// the angle θ (§3, first turn with `r = r0`; turn k of §3.4 with `r = r_k`).
///
/// All quantities are exact (no truncation in b/r); the note's first-order
/// forms are eqs. (38), (43), (48), (56).
///
/// ```
/// use snowroll::SectorBody;
/// use std::f64::consts::PI;
/// let body = SectorBody::new(0.1, 0.01, 400.0); // r0, b, ρl
/// // After a full turn the body is a disk of radius r0 + b (eq. (70) as corrected):
/// let m1 = PI * 400.0 * 0.11_f64.powi(2);
/// assert!((body.mass(2.0 * PI) - m1).abs() < 1e-12 * m1);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectorBody {
    r: Meters,
    b: Meters,
    rho_l: f64,
    moments: RingMoments,
}

impl SectorBody {
    /// Core radius `r`, m; ring thickness `b`, m; mass per area of
    /// cross-section times length, `ρl`, kg/m.
    pub fn new(r: Meters, b: Meters, rho_l: f64) -> Self {
        Self {
            r,
            b,
            rho_l,
            moments: RingMoments::new(r, b),
        }
    }

    /// Ring thickness b, m.
    pub fn thickness(&self) -> Meters {
        self.b
    }

    /// The ring moments `D_n`.
    pub fn moments(&self) -> RingMoments {
        self.moments
    }

    /// Mass of the disk, `m = πρl r²`, eq. (37).
    pub fn core_mass(&self) -> Kilograms {
        PI * self.rho_l * self.r * self.r
    }

    /// Accreted mass `m_s = ρlθD₂/2`, eq. (38) before truncation.
    pub fn accreted_mass(&self, theta: Radians) -> Kilograms {
        self.rho_l * theta * self.moments.d2 / 2.0
    }

    /// Total mass `M(θ) = ρl(πr² + θD₂/2)`.
    pub fn mass(&self, theta: Radians) -> Kilograms {
        self.core_mass() + self.accreted_mass(theta)
    }

    /// Centre of mass relative to the contact line, `(x_cm − x, y_cm)`, from
    /// `M(x_cm − x) = −ρlD₃(1 − cos θ)/3` and `M(y_cm − r) = −ρlD₃ sin θ/3`
    /// (eqs. (39)–(43) before truncation).
    pub fn centre_of_mass(&self, theta: Radians) -> (Meters, Meters) {
        let m = self.mass(theta);
        let first_moment = self.rho_l * self.moments.d3 / 3.0;
        (
            -first_moment * (1.0 - theta.cos_p()) / m,
            self.r - first_moment * theta.sin_p() / m,
        )
    }

    /// Moment of inertia about the contact line, eq. (56) before truncation:
    /// `I_C = (3/2)πρl r⁴ + ρlθ(r²D₂/2 + D₄/4) − (2/3)ρl r D₃ sin θ`.
    pub fn inertia_contact(&self, theta: Radians) -> f64 {
        let (r, d) = (self.r, self.moments);
        self.rho_l
            * (1.5 * PI * r.powi(4) + theta * (r * r * d.d2 / 2.0 + d.d4 / 4.0)
                - 2.0 * r * d.d3 * theta.sin_p() / 3.0)
    }

    /// Moment of inertia about the axis of the disk, `πρl r⁴/2 + ρlθD₄/4`.
    pub fn inertia_axis(&self, theta: Radians) -> f64 {
        self.rho_l * (PI * self.r.powi(4) / 2.0 + theta * self.moments.d4 / 4.0)
    }

    /// Moment of inertia about the centre of mass (parallel-axis theorem from
    /// [`SectorBody::inertia_contact`]); eq. (48) gives it to first order.
    pub fn inertia_cm(&self, theta: Radians) -> f64 {
        let (dx, y) = self.centre_of_mass(theta);
        self.inertia_contact(theta) - self.mass(theta) * (dx * dx + y * y)
    }

    /// Potential energy relative to θ = 0 (§3.2, eqs. (60)–(62) before
    /// truncation), with the contact line moved by `x = rθ` and the accreted
    /// snow taken from the slope strip `[0, x]` whose centroid is at
    /// `(x/2, −b/2)` (`docs/turn-model.md`, Conventions):
    /// `V = C[M y_cm − m r + m_s b/2] − G[M x_cm − m_s x/2]`, with
    /// `G = g sin α`, `C = g cos α` in m/s².
    pub fn potential_energy(&self, theta: Radians, g_along: f64, g_normal: f64) -> Joules {
        let (r, b) = (self.r, self.b);
        let m_s = self.accreted_mass(theta);
        let first_moment = self.rho_l * self.moments.d3 / 3.0;
        let x = r * theta;
        // M y_cm − m r = m_s r − ρlD₃ sin θ/3; M x_cm = M x − ρlD₃(1 − cos θ)/3.
        let height = m_s * (r + b / 2.0) - first_moment * theta.sin_p();
        let along = (self.core_mass() + m_s / 2.0) * x - first_moment * (1.0 - theta.cos_p());
        g_normal * height - g_along * along
    }

    /// Kinetic energy of the rigid body rolling at rate `ω` about the
    /// contact line, `I_C ω²/2` (eq. (59)).
    pub fn kinetic_energy(&self, theta: Radians, omega: f64) -> Joules {
        self.inertia_contact(theta) * omega * omega / 2.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// D_n from the expanded forms against the definition, where b ~ r so
    /// that the direct difference does not cancel.
    const MOMENT_TOL: f64 = 1e-14;

    #[test]
    fn ring_moments_match_their_definition() {
        let (r, b) = (0.3, 0.2);
        let m = RingMoments::new(r, b);
        for (n, got) in [(2, m.d2), (3, m.d3), (4, m.d4)] {
            let want = (r + b).powi(n) - r.powi(n);
            assert!((got - want).abs() <= MOMENT_TOL * want, "D{n}");
        }
    }
}
