//! The step of each new layer at the end of a turn of §3.4: three ways to
//! climb it (`--collision note|charged|pivot`, `docs/contact-forces.md` §6).

use std::fmt;

use serde::{Deserialize, Serialize};

/// How a turn model climbs onto the new layer of snow at the end of a turn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum CollisionModel {
    /// Eq. (89): angular momentum about the contact line conserved at θ = 2π;
    /// the centre jumps up by b at no potential-energy cost (the note's; default).
    #[default]
    Note,
    /// Eq. (89), then the potential energy `m_{k+1} g b cos α` of the jump is
    /// paid from the kinetic energy (`docs/contact-forces.md` §6.2).
    Charged,
    /// The corner of the new layer meets the snow at θ_c = 2π − arccos(r/(r + b));
    /// the log pivots about that edge (angular momentum about it conserved),
    /// then rolls on its new radius (`docs/contact-forces.md` §6.3).
    Pivot,
}

impl CollisionModel {
    /// Every variant, the default first.
    pub const ALL: [CollisionModel; 3] = [
        CollisionModel::Note,
        CollisionModel::Charged,
        CollisionModel::Pivot,
    ];

    /// The kebab-case id.
    pub fn id(self) -> &'static str {
        match self {
            CollisionModel::Note => "note",
            CollisionModel::Charged => "charged",
            CollisionModel::Pivot => "pivot",
        }
    }
}

impl fmt::Display for CollisionModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}
