//! The report's opening: what the program found, one line per claim,
//! grouped so that a physicist reads the refutations and corrections first.
//!
//! Each claim has a headline ([`headline`]): the finding in one sentence,
//! composed from its check's outcome. A check that measured the finding's
//! numbers composes the sentence from them (`ClaimResult::headline`);
//! otherwise it is the sentence of the finding ([`established`]). Either is
//! printed only when the check reached the verdict the claims table
//! expects; any other verdict prints a sentence that says what was not
//! reached, so a headline never states a finding the run did not make. The
//! line the report prints beside it is the claim's measured value
//! ([`short_measured`]) and its verdict. Checks of the note's algebra alone
//! ([`algebra_only`]) say so in their headline.

use crate::claim::{ClaimResult, Verdict};
use crate::ClaimId;

/// The claims whose check evaluates the note's equations and runs no
/// model: no wrong model can change their verdict, only wrong algebra in
/// the check itself (issue 32, item 6).
pub const ALGEBRA_ONLY: [ClaimId; 5] = [
    ClaimId::LoneyAccelerationCoefficient,
    ClaimId::FirstTurn58_64_69,
    ClaimId::Eq47_48AngularMomentum,
    ClaimId::Eq54CrossProduct,
    ClaimId::Eq51_55AccretingBody,
];

/// Whether the check of `id` is of the note's algebra alone ([`ALGEBRA_ONLY`]).
pub fn algebra_only(id: ClaimId) -> bool {
    ALGEBRA_ONLY.contains(&id)
}

/// What the report says of an algebra-only check, after its headline.
pub const ALGEBRA_NOTE: &str =
    "an algebra check: it evaluates the note's equations and runs no model";

/// How claim `c` was checked, as the report shows it: the table's method,
/// opened by [`ALGEBRA_NOTE`] for an algebra-only check.
pub(crate) fn method_text(c: &crate::Claim) -> String {
    if algebra_only(c.id) {
        let mut note = ALGEBRA_NOTE.to_string();
        note[..1].make_ascii_uppercase();
        let mut method = c.method.chars();
        let first: String = method
            .next()
            .into_iter()
            .flat_map(char::to_uppercase)
            .collect();
        format!(
            "{note}, so no wrong model can change its verdict. {first}{}",
            method.as_str()
        )
    } else {
        c.method.to_string()
    }
}

/// The headline of a result: the check's own sentence or the table's
/// sentence of the finding (`established`),
/// when the verdict is the one the table expects (with the algebra note
/// where it applies); otherwise a sentence saying which verdict was
/// reached instead.
pub fn headline(r: &ClaimResult) -> String {
    if r.verdict != r.claim.expected {
        return format!(
            "The check of {} did not reach its finding: {} where the claims table expects {}",
            r.claim.paper_ref,
            r.verdict.label(),
            r.claim.expected.label()
        );
    }
    let sentence = r
        .headline
        .clone()
        .unwrap_or_else(|| established(r.claim.id).to_string());
    if algebra_only(r.claim.id) {
        format!("{sentence} ({ALGEBRA_NOTE})")
    } else {
        sentence
    }
}

/// The finding of claim `id` in one sentence, as the check establishes it
/// when it reaches the verdict the table expects. An exhaustive match: a
/// new claim does not compile until it has one.
pub(crate) fn established(id: ClaimId) -> &'static str {
    use ClaimId::*;
    match id {
        CircularAnalysesDiffer => {
            "The four circular analyses of §2 give four different equations of motion (terminal a/G = 1/5, 1/6, 1/3, 2/9)"
        }
        CircularAgreeAsBVanishes => "Every circular model tends to the snowless log, a = (2/3) g sin α, as b → 0",
        LagrangianDiffersFromEnergy => {
            "The Lagrangian eq. (21) differs from eq. (14) only because it omits ∂T/∂x; with it, the two are one equation"
        }
        Eq5ContactTorque => "The torque about the contact line, eq. (5), holds as d(3mrv/2)/dt",
        LoneySolvesEq4 => "Loney's closed form (fn. 4) solves eq. (4)",
        LoneyAccelerationCoefficient => "In Loney's acceleration the decaying term is 7bK/6, not 7bK/3",
        LoneyLimitFifth => "Under eq. (4) the acceleration tends to g sin α / 5",
        TerminalAccelerations => "The terminal acceleration of each circular equation, derived and simulated",
        Eq35TerminalThird => "Under eq. (32) the acceleration tends to g sin α / 3",
        Eq33_35TerminalArgument => "The argument of eqs. (33)–(35) for the terminal value",
        Eq36SlowsApproach => "The lift term (36) slows the approach to G/3 from ∝ r⁻⁴ to ∝ r⁻¹",
        Fn7StallThreshold => "A log too light for its snow never starts: the stall slope of fn. 7, in closed form",
        Fn7StallInFirstTurn => "In the turn model a light log starts and stalls within its first turn",
        SnowlessLimit => "Without snow every derivation gives a = (2/3) g sin α",
        AppAMovingPoints => "Angular momentum and torque about moving points (App. A)",
        FirstTurn58_64_69 => "Torque, energy and Lagrangian agree on the first turn (eqs. (58), (64), (69))",
        Eq47_48AngularMomentum => "An element's velocity and the angular momentum in the first turn (eqs. (47), (48))",
        Eq54CrossProduct => "The cross product of eq. (54) to first order in b",
        Eq51_55AccretingBody => "The torque analysis of the accreting body (eqs. (51)–(55))",
        Eq70MassAfterFirstTurn => "The mass after the first turn is πρl r₁² (eq. (70))",
        MultiTurnNeverSettles => "Turn by turn the acceleration never settles: within every turn a/G swings from about 0 to 2/3",
        MultiTurnMeanFourNinths => {
            "The turn model's long-run mean acceleration is G/4 with the collisions (G/3 within a turn), not the 4G/9 of eq. (79)"
        }
        Eq78SpeedInTurnN => "The speed in turn n: v²/(π g n² b sin α) tends to 1/2, not the 1/3 of eq. (78)",
        Eq89Collision => "The collision at the end of each turn (eq. (89)) keeps the angular momentum about the new contact",
        CollisionPotentialJump => "The rise of the centre at a collision is a small cost that fades turn by turn",
        Eq88EnergyBalance => "The energy balance within a turn (eqs. (80)–(88)) holds with exact mass properties",
        Eq73TruncatesExact => "The turn equation (73) holds to first order in b/r",
        Fn10HopThreshold => "A turn-model log hops in late turns exactly when tan α > 2 (α > 63.43°)",
        SlipMuMin => "The smallest friction coefficient that keeps each model rolling (tan α/3 without snow)",
        SnowballFiveSevenths => "A ball on a bare slope accelerates at (5/7) g sin α",
        SnowballTerminalFractions => {
            "The always-round snowball tends to a/G = 1/6 (torque about the centre), 1/7, 2/7 or 5/28"
        }
        TptLetterClosedForm => "The closed form of the letter in The Physics Teacher 57 (2019) is the ball's eq. (4), from 5/7 to 1/6",
        RegimeMapBorders => "The closed-form stall and hop slopes border the simulated regime map",
        SnowlessDragTerminalVelocity => "With air drag and no snow the log reaches the closed-form terminal velocity",
        EnergyLedgerBalances => "With losses every joule is accounted for in the energy ledger",
        UnwindingTextbookSpeed => {
            "A roll that unwinds on a level floor follows the textbook v² = 4g(R³ − r³)/(3r²) under eq. (15); the torque analyses leave it at rest"
        }
        UnwindingHollowRoll => {
            "A hollow roll on a light tube is not the textbook's roll: eq. (15) with the tube's own mass and moment of inertia"
        }
    }
}

/// Claims the note leaves open (it names the question but not the answer,
/// or does not ask): they open the "found beyond the note" group when they hold.
const BEYOND_THE_NOTE: [ClaimId; 12] = [
    ClaimId::Fn10HopThreshold,
    ClaimId::Fn7StallThreshold,
    ClaimId::Fn7StallInFirstTurn,
    ClaimId::SnowballTerminalFractions,
    ClaimId::TptLetterClosedForm,
    ClaimId::SnowballFiveSevenths,
    ClaimId::SlipMuMin,
    ClaimId::RegimeMapBorders,
    ClaimId::SnowlessDragTerminalVelocity,
    ClaimId::EnergyLedgerBalances,
    ClaimId::UnwindingTextbookSpeed,
    ClaimId::UnwindingHollowRoll,
];

/// The groups of the opening, in the order the report prints them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Group {
    /// Refuted (or undecided): the note is wrong, and what holds instead.
    Refuted,
    /// Holds once an erratum is applied.
    Corrected,
    /// Holds, and answers what the note leaves open.
    Beyond,
    /// Holds as printed.
    Holds,
}

impl Group {
    /// Every group, in order.
    pub const ALL: [Group; 4] = [
        Group::Refuted,
        Group::Corrected,
        Group::Beyond,
        Group::Holds,
    ];

    /// A short name of the group, for the page's markup.
    pub fn key(self) -> &'static str {
        match self {
            Group::Refuted => "refuted",
            Group::Corrected => "corrected",
            Group::Beyond => "beyond",
            Group::Holds => "holds",
        }
    }

    /// The group's heading.
    pub fn title(self) -> &'static str {
        match self {
            Group::Refuted => "Refuted, and what holds instead",
            Group::Corrected => "Holds after a correction (the erratum named)",
            Group::Beyond => "Found beyond the note",
            Group::Holds => "Holds as printed",
        }
    }

    /// The group of a result.
    pub fn of(r: &ClaimResult) -> Group {
        match r.verdict {
            Verdict::Refuted | Verdict::Inconclusive => Group::Refuted,
            Verdict::HoldsAfterCorrection(_) => Group::Corrected,
            Verdict::Holds if BEYOND_THE_NOTE.contains(&r.claim.id) => Group::Beyond,
            Verdict::Holds => Group::Holds,
        }
    }
}

/// Longest measured text a line of the opening shows, in characters.
const SHORT_MEASURED_MAX: usize = 140;

/// The first clause of the measured value (up to its first `; `), cut to
/// [`SHORT_MEASURED_MAX`] characters: the number a reader looks for first.
pub(crate) fn short_measured(measured: &str) -> String {
    let first = measured.split("; ").next().unwrap_or(measured).trim();
    if first.chars().count() <= SHORT_MEASURED_MAX {
        return first.to_string();
    }
    let cut: String = first.chars().take(SHORT_MEASURED_MAX - 1).collect();
    format!("{}…", cut.trim_end())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_claim_has_a_one_line_headline() {
        for id in ClaimId::ALL {
            let h = established(id);
            assert!(
                !h.is_empty() && h.len() < 200 && !h.contains('\n'),
                "{id}: {h}"
            );
        }
    }

    #[test]
    fn short_measured_keeps_the_first_clause() {
        assert_eq!(short_measured("a = 1; b = 2"), "a = 1");
        let long = "x".repeat(300);
        let s = short_measured(&long);
        assert_eq!(s.chars().count(), SHORT_MEASURED_MAX);
        assert!(s.ends_with('…'));
    }
}
