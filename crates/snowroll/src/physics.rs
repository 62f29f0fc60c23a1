//! Formulae shared by the circular models of §2: the kinetic and potential
//! energies of the always-circular log and of the always-round ball
//! (`docs/snowball-and-losses.md` §1.1–1.2), and the body's growth law of
//! [`Body`](crate::body::Body) for a scenario.

use crate::portable::Portable as _;
use std::f64::consts::PI;

use crate::scenario::{Scenario, Shape, Swath};
use crate::units::{Joules, Kilograms, Meters, MetersPerSecond};

pub use crate::body::Growth;

/// Radius after rolling a distance `x`, m ([`Body::radius_at`](crate::body::Body::radius_at)).
pub fn radius_at(s: &Scenario, x: Meters) -> Meters {
    s.body().radius_at(x)
}

/// Mass after rolling `x`, kg ([`Body::mass_at`](crate::body::Body::mass_at)).
pub fn mass_at(s: &Scenario, x: Meters) -> Kilograms {
    s.body().mass_at(x)
}

/// [`Growth`] at distance `x` ([`Body::growth_at`](crate::body::Body::growth_at)).
pub fn growth_at(s: &Scenario, x: Meters, accretes: bool) -> Growth {
    s.body().growth_at(x, accretes)
}

/// Kinetic energy of the round body, `T = ½ M (1 + k + r′²) v²` (eq. (7)
/// generalised, `docs/snowball-and-losses.md` §1.2; r′² v² = ṙ², eq. (1)).
/// For the log, eq. (7) as printed:
/// `T = 3πρl r² v²/4 + ρ l b² v²/(8π)`.
///
/// With a tube of its own mass (`docs/unwinding.md`, "The core"),
/// `T = ½ (M (1 + r′²) + I/r²) v²` with M and I of [`crate::body::Tube`].
pub fn kinetic_energy(s: &Scenario, x: Meters, v: MetersPerSecond) -> Joules {
    let (rho, l, b) = (s.density(), s.length(), s.snow_depth());
    if s.shape() == Shape::Sphere || s.core_mass().is_some() {
        let gr = growth_at(s, x, true);
        let j = gr.tube.map_or(s.shape().inertia_factor(), |t| t.inertia);
        return 0.5 * gr.mass * (1.0 + j + gr.dr_dx * gr.dr_dx) * v * v;
    }
    let r = radius_at(s, x);
    3.0 * PI * rho * l * r * r * v * v / 4.0 + rho * l * b * b * v * v / (8.0 * PI)
}

/// Potential energy of the ball plus the snow it collected, relative to the
/// start (`docs/snowball-and-losses.md` §1.2):
/// `V = C [M r − M0 r0 + (b/2)(M − M0)] − G ∫₀ˣ M dx′`, written without
/// differences of large numbers.
fn ball_potential_energy(s: &Scenario, x: Meters) -> Joules {
    let (rho, b) = (s.density(), s.snow_depth());
    let r0 = s.initial_radius();
    let r = radius_at(s, x);
    let m0 = s.initial_mass();
    // r³ − r0³ from the growth law, r − r0 from it without cancellation.
    let r3_minus = match s.swath() {
        Swath::Diameter => (b * x / PI) / (r + r0) * (r * r + r * r0 + r0 * r0),
        Swath::Fixed(w) => 3.0 * b * w * x / (4.0 * PI),
        Swath::Chord => (r - r0) * (r * r + r * r0 + r0 * r0),
    };
    let r_minus = r3_minus / (r * r + r * r0 + r0 * r0);
    let dm = 4.0 * PI * rho * r3_minus / 3.0;
    // M r − M0 r0 = (4/3)πρ (r⁴ − r0⁴).
    let r4_minus = r_minus * (r * r * r + r * r * r0 + r * r0 * r0 + r0 * r0 * r0);
    let lift = 4.0 * PI * rho * r4_minus / 3.0 + 0.5 * b * dm;
    let integral = match s.swath() {
        // ∫ M dx = 8π²ρ (r⁵ − r0⁵)/(15 b), with r − r0 = (b x/π)/(r + r0).
        Swath::Diameter => {
            let sum5 = r.powi(4) + r.powi(3) * r0 + r * r * r0 * r0 + r * r0.powi(3) + r0.powi(4);
            8.0 * PI * rho * x * sum5 / (15.0 * (r + r0))
        }
        Swath::Fixed(w) => m0 * x + rho * b * w * x * x / 2.0,
        Swath::Chord => chord_mass_integral(s, r),
    };
    s.g_normal() * lift - s.g_along() * integral
}

/// ∫₀ˣ M dx′ for a ball on the chord swath that has grown to `r`, kg m
/// (`docs/snowball-and-losses.md` §1.1): with s = √(b(2ρ − b)),
/// ρ = (s² + b²)/(2b) and dx/dρ = 2πρ²/(b s),
/// `∫ M dx = (π²ρ_d/(12 b⁷)) ∫ (s² + b²)⁵ ds` from s0 to s, expanded by
/// the binomial theorem; each `s^m − s0^m` is (s − s0) times a sum of
/// positive terms, so that nothing cancels near the start.
pub(crate) fn chord_mass_integral(s: &Scenario, r: Meters) -> f64 {
    let (rho, b, r0) = (s.density(), s.snow_depth(), s.initial_radius());
    let (sr, s0) = ((b * (2.0 * r - b)).sqrt(), (b * (2.0 * r0 - b)).sqrt());
    let ds = 2.0 * b * (r - r0) / (sr + s0);
    const BINOMIAL: [f64; 6] = [1.0, 5.0, 10.0, 10.0, 5.0, 1.0];
    let mut sum = 0.0;
    for (j, c) in BINOMIAL.iter().enumerate() {
        let m = 2 * j as i32 + 1;
        // (s^m − s0^m)/(s − s0) = Σ s^i s0^(m−1−i).
        let quotient: f64 = (0..m).map(|i| sr.powi(i) * s0.powi(m - 1 - i)).sum();
        sum += c * b.powi(10 - 2 * j as i32) * quotient / f64::from(m);
    }
    PI * PI * rho * ds * sum / (12.0 * b.powi(7))
}

/// Potential energy of body plus collected snow, relative to the start; for
/// the log eq. (10) (the ball: `ball_potential_energy`, §1.2 of
/// `docs/snowball-and-losses.md`):
/// `V = ρlg[(2πr³ + b²x) cos α + (bx² − 2πr²x) sin α]/2 − m0 g r0 cos α`.
///
/// Evaluated in the algebraically equal form
/// `ρlg[(π(r³ − r0³) + b²x/2) cos α − (bx²/2 + πr0²x) sin α]` (using
/// `2πr² = 2πr0² + 2bx`, eq. (8)), which does not cancel when `x` is large
/// or `b` small.
///
/// With a tube of its own mass (`docs/unwinding.md`, "The core"), the uniform
/// body's V plus that of the mass the tube adds at the centre,
/// `ΔM (C (r − r0) − G x)`, ΔM = m_c − M_u(r_c).
pub fn potential_energy(s: &Scenario, x: Meters) -> Joules {
    if s.core_mass().is_some() {
        let extra = s.body().tube_offset();
        let rise = radius_at(s, x) - s.initial_radius();
        return uniform_potential_energy(&s.uniform(), x)
            + extra * (s.g_normal() * rise - s.g_along() * x);
    }
    uniform_potential_energy(s, x)
}

/// [`potential_energy`] of a body of one material.
fn uniform_potential_energy(s: &Scenario, x: Meters) -> Joules {
    if s.shape() == Shape::Sphere {
        return ball_potential_energy(s, x);
    }
    let (rho, l, b, g, alpha) = (
        s.density(),
        s.length(),
        s.snow_depth(),
        s.gravity(),
        s.slope_angle(),
    );
    let r0 = s.initial_radius();
    let r = radius_at(s, x);
    // r − r0 = (bx/π)/(r + r0) without cancellation.
    let r3_minus_r03 = (b * x / PI) / (r + r0) * (r * r + r * r0 + r0 * r0);
    rho * l
        * g
        * ((PI * r3_minus_r03 + b * b * x / 2.0) * alpha.cos_p()
            - (b * x * x / 2.0 + PI * r0 * r0 * x) * alpha.sin_p())
}

/// Mechanical energy `E = T + V` of eq. (11) (zero for a start from rest).
pub fn mechanical_energy(s: &Scenario, x: Meters, v: MetersPerSecond) -> Joules {
    kinetic_energy(s, x, v) + potential_energy(s, x)
}
