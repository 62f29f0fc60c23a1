//! The coefficients of the common in-turn form of §3 (`docs/turn-model.md`):
//! the record, and the note's values of eqs. (62), (76). The exact values
//! of the disk plus annular sector are `exact_geometry`'s; the turn-by-turn
//! run reads both. The record sits here, below `turn_by_turn` and
//! `exact_geometry`, so that neither depends on the other for it.

use std::f64::consts::PI;

use crate::units::Meters;

/// The coefficients of the common in-turn form (`turn_by_turn`'s dynamics), per unit `m_k`:
/// `I/m_k = 3r²/2 + c₁θ − c₂ sin θ` (m²),
/// `W/m_k = −G(rθ + e₁θ²/2 − e₂(1 − cos θ)) + C(e₃θ − e₂ sin θ)` (J/kg), and
/// accreted mass `m_s/m_k = μθ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InTurnCoefficients {
    /// c₁, m².
    pub c1: f64,
    /// c₂, m².
    pub c2: f64,
    /// e₁, m.
    pub e1: f64,
    /// e₂, m.
    pub e2: f64,
    /// e₃, m.
    pub e3: f64,
    /// μ, accreted mass per radian over m_k, 1/rad.
    pub accretion: f64,
}

impl InTurnCoefficients {
    /// Eq. (76) and eq. (62) with `r0 → r_k`: `c₁ = c₂ = 2br/π`,
    /// `e₁ = e₂ = e₃ = b/π`, `μ = b/(πr)` (eq. (38)).
    pub fn paper(r: Meters, b: Meters) -> Self {
        Self {
            c1: 2.0 * b * r / PI,
            c2: 2.0 * b * r / PI,
            e1: b / PI,
            e2: b / PI,
            e3: b / PI,
            accretion: b / (PI * r),
        }
    }
}
