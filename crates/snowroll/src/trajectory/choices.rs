//! The closed choices of a run: how a turn model climbs onto the new layer
//! ([`CollisionModel`]), and what a run does where the log would hop
//! ([`OnHop`]).

use std::fmt;

use serde::{Deserialize, Serialize};

#[cfg(doc)]
use super::StopReason;

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

/// What a run does where the normal force reaches zero (`--on-hop`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum OnHop {
    /// Stop with [`StopReason::Hop`] (default): past N = 0 the log flies and
    /// the rolling models no longer apply.
    #[default]
    #[cfg_attr(
        feature = "clap",
        value(
            help = "Stop with reason `hop` (default): past N = 0 the log flies and the rolling models no longer apply"
        )
    )]
    Stop,
    /// Go on as if contact were kept (N < 0 would have to pull the log onto
    /// the snow): for exploring the model past its validity, e.g. the
    /// long-run means of a steep slope.
    Continue,
}

impl OnHop {
    /// Every variant, the default first.
    pub const ALL: [OnHop; 2] = [OnHop::Stop, OnHop::Continue];

    /// The kebab-case id.
    pub fn id(self) -> &'static str {
        match self {
            OnHop::Stop => "stop",
            OnHop::Continue => "continue",
        }
    }
}

impl fmt::Display for OnHop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}
