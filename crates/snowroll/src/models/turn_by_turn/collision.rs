//! The step of each new layer at the end of a turn of §3.4: three ways to
//! climb it (`--collision note|charged|pivot`, `docs/contact-forces.md` §6).

use crate::portable::Portable as _;
use std::f64::consts::PI;

use crate::models::exact_geometry::exact_turn_coefficients;
pub use crate::trajectory::CollisionModel;
use crate::units::{Meters, MetersPerSecond, MetersPerSecondSquared, Radians};

/// The speed after the `charged` collision (`docs/contact-forces.md` §6.2):
/// eq. (89), then the potential energy of the jump by b paid from the
/// kinetic energy `(3/4) m_{k+1} v′²` of the new turn,
/// `v′² = v_note′² − (4/3) g b cos α`. `None` when that is not positive: the
/// log cannot climb the step (`stuck`).
pub fn charged_collision_speed(
    r_k: Meters,
    b: Meters,
    g_normal: MetersPerSecondSquared,
    v_end: MetersPerSecond,
) -> Option<MetersPerSecond> {
    let v_note = super::collision_speed(r_k, b, v_end);
    let v2 = v_note * v_note - 4.0 / 3.0 * g_normal * b;
    (v2 > 0.0).then(|| v2.sqrt())
}

/// The start of turn k + 1 after a collision at θ = 2π of the rolling log
/// of radius `r_k`, from `θ̇` there: `(θ̇′, v′)`, θ̇′ = v′/r_{k+1} with v′
/// by eq. (89) (`note`, [`super::collision_speed`]) or
/// [`charged_collision_speed`] (`charged`, whose v′ is then reported as
/// θ̇′ r_{k+1}). `None` when the log is stuck at the step, and for `pivot`,
/// whose collision is its impact at θ_c ([`PivotImpact`]). One function for
/// the run (`TurnSystem`) and for the turns it computes ahead, so that the
/// two predict the same starts by construction.
pub(crate) fn after_collision(
    rule: CollisionModel,
    r_k: Meters,
    b: Meters,
    g_normal: MetersPerSecondSquared,
    omega_end: f64,
) -> Option<(f64, MetersPerSecond)> {
    let r_next = r_k + b;
    match rule {
        CollisionModel::Note => {
            let v = super::collision_speed(r_k, b, r_k * omega_end);
            Some((v / r_next, v))
        }
        CollisionModel::Charged => {
            let omega = charged_collision_speed(r_k, b, g_normal, r_k * omega_end)? / r_next;
            Some((omega, omega * r_next))
        }
        CollisionModel::Pivot => None,
    }
}

/// The impact of the `pivot` collision at the end of turn k
/// (`docs/contact-forces.md` §6.3), per unit m_k, with the exact mass
/// properties of the disk plus the annular sector at θ_c.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PivotImpact {
    /// θ_c = 2π − δ, δ = arccos(r/(r + b)): where the outer corner of the
    /// new layer's leading edge meets the snow surface, rad.
    pub theta_c: Radians,
    /// δ = 2π − θ_c, rad.
    pub delta: Radians,
    /// d = √(2rb + b²), distance of the impact line E ahead of C, m.
    pub d: Meters,
    /// Mass of the body over m_k, `1 + μθ_c`.
    pub mass: f64,
    /// Moment of inertia about C over m_k, `3r²/2 + c₁θ_c − c₂ sin θ_c`, m².
    pub inertia_c: f64,
    /// First moment about C over m_k, `S_x = −e₂(1 − cos θ_c)`, m.
    pub s_x: f64,
    /// `S_y = r(1 + μθ_c) − e₂ sin θ_c`, m.
    pub s_y: f64,
    /// Moment of inertia about E over m_k, `I_E = I_C − 2 d S_x + M d²`, m².
    pub inertia_e: f64,
    /// Distance of the centre of mass from E, ρ_E, m.
    pub rho_e: Meters,
    /// Angle of `r_cm − E` from the slope normal, positive backwards, ψ₀, rad.
    pub psi0: Radians,
}

impl PivotImpact {
    /// The impact geometry and mass properties of turn k (radius `r`, snow depth `b`).
    pub fn new(r: Meters, b: Meters) -> Self {
        let k = exact_turn_coefficients(r, b);
        let delta = (r / (r + b)).acos_p();
        let theta_c = 2.0 * PI - delta;
        let d = (2.0 * r * b + b * b).sqrt();
        let (s, c) = theta_c.sin_cos_p();
        let mass = 1.0 + k.accretion * theta_c;
        let inertia_c = 1.5 * r * r + k.c1 * theta_c - k.c2 * s;
        let s_x = -k.e2 * (1.0 - c);
        let s_y = r * mass - k.e2 * s;
        let inertia_e = inertia_c - 2.0 * d * s_x + mass * d * d;
        let (ex, ey) = (s_x / mass - d, s_y / mass);
        Self {
            theta_c,
            delta,
            d,
            mass,
            inertia_c,
            s_x,
            s_y,
            inertia_e,
            rho_e: ex.hypot_p(ey),
            psi0: (-ex).atan2_p(ey),
        }
    }

    /// θ̇ just after the impact from θ̇ just before: angular momentum about
    /// the impact line E conserved, `θ̇₊ = θ̇₋ (I_C − d S_x)/I_E`.
    pub fn omega_after(&self, omega_before: f64) -> f64 {
        omega_before * (self.inertia_c - self.d * self.s_x) / self.inertia_e
    }

    /// Angular acceleration of the pivot about E at rotation φ = θ − θ_c,
    /// `I_E φ̈ = M g ρ_E sin(α − ψ)`, ψ = ψ₀ − φ, written with G = g sin α and
    /// C = g cos α: `g sin(α − ψ) = G cos ψ − C sin ψ`, rad/s².
    pub fn angular_acceleration(&self, phi: Radians, g_along: f64, g_normal: f64) -> f64 {
        let (s, c) = (self.psi0 - phi).sin_cos_p();
        self.mass * self.rho_e * (g_along * c - g_normal * s) / self.inertia_e
    }

    /// `(N_E, F_E)` per unit m_k during the pivot at `(φ, φ̇)`:
    /// `N_E = M [C + ρ_E (φ̈ sin ψ − φ̇² cos ψ)]`,
    /// `F_E = M [G − ρ_E (φ̈ cos ψ + φ̇² sin ψ)]`, m/s².
    pub fn contact_per_mass(
        &self,
        phi: Radians,
        omega: f64,
        g_along: f64,
        g_normal: f64,
    ) -> (f64, f64) {
        let alpha = self.angular_acceleration(phi, g_along, g_normal);
        let (s, c) = (self.psi0 - phi).sin_cos_p();
        let w2 = omega * omega;
        (
            self.mass * (g_normal + self.rho_e * (alpha * s - w2 * c)),
            self.mass * (g_along - self.rho_e * (alpha * c + w2 * s)),
        )
    }

    /// θ̇ at the start of turn k + 1 from θ̇ at the end of the pivot (θ = 2π,
    /// the centre above E): the notch of angle δ behind E is filled with the
    /// strip of snow [x_C, x_E] as a plastic accretion at rest at the contact
    /// (angular momentum about E conserved, `I_E → (3/2) m_{k+1} r_{k+1}²`),
    /// and the lift of that snow, `ΔV = C[Δm(R + b/2) − Q sin δ] − G[Δm d/2 − Q(1 − cos δ)]`
    /// (Δm = ρl δ D₂/2, Q = ρl D₃/3, R = r + b), is paid from the kinetic
    /// energy (`docs/contact-forces.md` §6.3). `None` when nothing is left: `stuck`.
    pub fn omega_next(
        &self,
        r: Meters,
        b: Meters,
        omega_end: f64,
        g_along: f64,
        g_normal: f64,
    ) -> Option<f64> {
        let dv = self.notch_lift(r, b, g_along, g_normal);
        let inertia_new = Self::inertia_next(r, b);
        let omega_fill = self.omega_fill(r, b, omega_end);
        let w2 = omega_fill * omega_fill - 2.0 * dv / inertia_new;
        (w2 > 0.0).then(|| w2.sqrt())
    }

    /// The moment of inertia of the log of turn k + 1 about its contact line
    /// over m_k, `(3/2)(m_{k+1}/m_k) r_{k+1}²` with `m_{k+1}/m_k = (R/r)²`, m².
    pub fn inertia_next(r: Meters, b: Meters) -> f64 {
        let big_r = r + b;
        1.5 * (big_r * big_r / (r * r)) * big_r * big_r
    }

    /// θ̇ once the notch is filled, before its lift is paid: angular momentum
    /// about E conserved, `θ̇_fill = θ̇_end I_E/I_{k+1}`, rad/s.
    pub fn omega_fill(&self, r: Meters, b: Meters, omega_end: f64) -> f64 {
        omega_end * self.inertia_e / Self::inertia_next(r, b)
    }

    /// The potential energy of the notch's snow lifted into place, over m_k,
    /// `ΔV = C[Δm(R + b/2) − Q sin δ] − G[Δm d/2 − Q(1 − cos δ)]`
    /// ([`PivotImpact::omega_next`]), J/kg.
    pub fn notch_lift(&self, r: Meters, b: Meters, g_along: f64, g_normal: f64) -> f64 {
        let big_r = r + b;
        // Per unit m_k = πρl r²: ρl/m_k = 1/(πr²).
        let per_mk = 1.0 / (PI * r * r);
        let d2 = big_r * big_r - r * r;
        let d3 = big_r.powi(3) - r.powi(3);
        let dm = per_mk * self.delta * d2 / 2.0;
        let q = per_mk * d3 / 3.0;
        let (s, c) = self.delta.sin_cos_p();
        g_normal * (dm * (big_r + b / 2.0) - q * s) - g_along * (dm * self.d / 2.0 - q * (1.0 - c))
    }

    /// The potential energy of the pivot over m_k relative to its start, at
    /// rotation φ about E: `M ρ_E [(C cos ψ + G sin ψ) − (C cos ψ₀ + G sin ψ₀)]`,
    /// ψ = ψ₀ − φ (= M g ρ_E [cos(ψ − α) − cos(ψ₀ − α)]; its −d/dφ is the
    /// torque of [`PivotImpact::angular_acceleration`]), J/kg.
    pub fn pivot_potential(&self, phi: Radians, g_along: f64, g_normal: f64) -> f64 {
        let (s, c) = (self.psi0 - phi).sin_cos_p();
        let (s0, c0) = self.psi0.sin_cos_p();
        self.mass * self.rho_e * (g_normal * (c - c0) + g_along * (s - s0))
    }
}
