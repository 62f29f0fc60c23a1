//! §3 without truncation in b/r: the exact mass properties of the log with a
//! partial ring of snow, and the in-turn equation of motion they give.
//!
//! The note keeps only the first order in b/r0 (eqs. (38), (43), (48), (56),
//! (62)); [`SectorBody`] computes the same quantities exactly for a disk of
//! radius r plus an annular sector `r < r′ < r + b` over the angle θ. The
//! equation of motion from energy conservation with these exact `I_C(θ)` and
//! `V(θ)` ([`exact_turn_coefficients`]) makes eq. (88), with the corrected
//! (87), an identity of the integrated motion (`docs/errata.md`, (88) vs (73)). Torque and
//! energy differ only at O(b³) in this geometry (`docs/turn-model.md`, "Torque and energy in the first turn"); the
//! energy form is used (`docs/turn-model.md`, Conventions).

mod dynamics;
mod mass_properties;

pub use dynamics::exact_turn_coefficients;
pub use mass_properties::{RingMoments, SectorBody};
