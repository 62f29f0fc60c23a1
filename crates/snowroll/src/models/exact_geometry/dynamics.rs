//! The exact in-turn equation of motion in the coefficient form of
//! [`InTurnCoefficients`], from the mass properties of [`SectorBody`].

use std::f64::consts::PI;

use super::mass_properties::RingMoments;
use crate::models::in_turn::InTurnCoefficients;
use crate::units::Meters;

/// The coefficients of `I/m_k` and `W/m_k` for the disk of radius `r` plus
/// the annular sector of thickness `b`, exactly (`m_k = πρl r²`):
///
/// * from `I_C = (3/2)πρl r⁴ + ρlθ(r²D₂/2 + D₄/4) − (2/3)ρl r D₃ sin θ`:
///   `c₁ = (r²D₂/2 + D₄/4)/(πr²)`, `c₂ = 2D₃/(3πr)`;
/// * from `V = C[m_s(r + b/2) − ρlD₃ sin θ/3] − G[(m_k + m_s/2) rθ − ρlD₃(1 − cos θ)/3]`
///   ([`SectorBody::potential_energy`](super::SectorBody::potential_energy)):
///   `e₁ = D₂/(2πr)`, `e₂ = D₃/(3πr²)`, `e₃ = D₂(2r + b)/(4πr²)`;
/// * `m_s/m_k = θD₂/(2πr²)`.
///
/// To first order in b these are the note's `2br/π` and `b/π` (eqs. (56), (62)).
pub fn exact_turn_coefficients(r: Meters, b: Meters) -> InTurnCoefficients {
    let d = RingMoments::new(r, b);
    let r2 = r * r;
    InTurnCoefficients {
        c1: (r2 * d.d2 / 2.0 + d.d4 / 4.0) / (PI * r2),
        c2: 2.0 * d.d3 / (3.0 * PI * r),
        e1: d.d2 / (2.0 * PI * r),
        e2: d.d3 / (3.0 * PI * r2),
        e3: d.d2 * (2.0 * r + b) / (4.0 * PI * r2),
        accretion: d.d2 / (2.0 * PI * r2),
    }
}
