//! The loss terms per unit mass at one state (`docs/snowball-and-losses.md`
//! §2.1), which the right-hand side and the balance of any body both add:
//! below `rhs` and `balance`, so that neither reads the other for them.

use crate::losses::Losses;
use crate::physics::Growth;
use crate::scenario::Scenario;

/// The loss terms per unit mass at one state, m/s².
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct LossesPerMass {
    /// F_d/M.
    pub(super) drag: f64,
    /// F_c/M.
    pub(super) compaction: f64,
}

/// F_d/M and F_c/M of a body of size and growth `gr` at speed `v`
/// (`docs/snowball-and-losses.md` §2.1): `F_d = ½ ρ_a C_d A v|v|` with the
/// frontal area A of [`crate::losses::frontal_area`], `F_c/M = e_c λ`.
pub(super) fn losses_per_mass(s: &Scenario, gr: &Growth, l: &Losses, v: f64) -> LossesPerMass {
    LossesPerMass {
        drag: l.drag_factor() * crate::losses::frontal_area(s, gr.r) * v * v.abs() / gr.mass,
        compaction: l.compaction_energy * gr.lambda,
    }
}
