//! Formulae shared by the circular models of §2: the radius law, the
//! kinetic and potential energies of the always-circular log.

use std::f64::consts::PI;

use crate::scenario::Scenario;
use crate::units::{Joules, Kilograms, Meters, MetersPerSecond};

/// Radius after rolling a distance `x`, eq. (8): `π r² = π r0² + b x`.
pub fn radius_at(s: &Scenario, x: Meters) -> Meters {
    let r0 = s.initial_radius();
    (r0 * r0 + s.snow_depth() * x / PI).sqrt()
}

/// Mass after rolling `x`, eq. (8): `m = m0 + ρ b l x` (= π ρ l r²), kg.
pub fn mass_at(s: &Scenario, x: Meters) -> Kilograms {
    s.initial_mass() + s.density() * s.snow_depth() * s.length() * x
}

/// Kinetic energy of the circular log, eq. (7):
/// `T = 3πρl r² v²/4 + ρ l b² v²/(8π)` (the second term is the radial growth `ṙ = bv/(2πr)`, eq. (1)).
pub fn kinetic_energy(s: &Scenario, x: Meters, v: MetersPerSecond) -> Joules {
    let (rho, l, b) = (s.density(), s.length(), s.snow_depth());
    let r = radius_at(s, x);
    3.0 * PI * rho * l * r * r * v * v / 4.0 + rho * l * b * b * v * v / (8.0 * PI)
}

/// Potential energy of log plus collected snow, relative to the start, eq. (10):
/// `V = ρlg[(2πr³ + b²x) cos α + (bx² − 2πr²x) sin α]/2 − m0 g r0 cos α`.
///
/// Evaluated in the algebraically equal form
/// `ρlg[(π(r³ − r0³) + b²x/2) cos α − (bx²/2 + πr0²x) sin α]` (using
/// `2πr² = 2πr0² + 2bx`, eq. (8)), which does not cancel when `x` is large
/// or `b` small.
pub fn potential_energy(s: &Scenario, x: Meters) -> Joules {
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
        * ((PI * r3_minus_r03 + b * b * x / 2.0) * alpha.cos()
            - (b * x * x / 2.0 + PI * r0 * r0 * x) * alpha.sin())
}

/// Mechanical energy `E = T + V` of eq. (11) (zero for a start from rest).
pub fn mechanical_energy(s: &Scenario, x: Meters, v: MetersPerSecond) -> Joules {
    kinetic_energy(s, x, v) + potential_energy(s, x)
}
