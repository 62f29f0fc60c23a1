//! The short machine-readable code of each warning a run may give
//! ([`WarningCode`]): below the validity checks (`validity`) that give most
//! of them and the run's list of warnings (`warnings`) that gathers them.

use serde::Serialize;

/// What a warning is about. Its [`code`](WarningCode::code) is the text of
/// a sweep's `warnings` column.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum WarningCode {
    /// b/r0 beyond the model's range of validity ([`ModelKind::validity`](super::ModelKind::validity)).
    BOverR0,
    /// The snowless model given snow (it is the b = 0 limit).
    SnowIgnored,
    /// A ball's fixed swath wider than its diameter 2 r0 at the start.
    WideSwath,
    /// `turns` started from rest where it and `turns-exact` disagree about
    /// a stall in the first turn.
    #[serde(rename = "turn-0-stall")]
    Turn0Stall,
    /// Tolerances looser than the accuracy the note's claims are judged at
    /// ([`CLAIMS_ACCURACY`](super::CLAIMS_ACCURACY)).
    LooseTolerance,
}

impl WarningCode {
    /// Every code, in the order a run reports them.
    pub const ALL: [WarningCode; 5] = [
        WarningCode::BOverR0,
        WarningCode::SnowIgnored,
        WarningCode::WideSwath,
        WarningCode::Turn0Stall,
        WarningCode::LooseTolerance,
    ];

    /// The short code: kebab-case, no comma, no `;` (the separator of a
    /// sweep's `warnings` cell).
    pub fn code(self) -> &'static str {
        match self {
            WarningCode::BOverR0 => "b-over-r0",
            WarningCode::SnowIgnored => "snow-ignored",
            WarningCode::WideSwath => "wide-swath",
            WarningCode::Turn0Stall => "turn-0-stall",
            WarningCode::LooseTolerance => "loose-tolerance",
        }
    }
}
