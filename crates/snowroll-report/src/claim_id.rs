//! The names of the claims: [`ClaimId`], one variant per row of
//! [`crate::CLAIMS`], in the table's order.
//!
//! The table, the figures that are evidence for a claim, the report's
//! sections and the tests all name a claim by its variant, so a misspelt
//! name is a compile error instead of a lookup that silently finds nothing.
//! The text of an id ([`ClaimId::as_str`]) is what every output shows:
//! `claims.json`, `data/claims.csv`, the anchors of the pages.
//!
//! This module depends on nothing else in the crate; a unit test of
//! `claims/table.rs` checks that [`ClaimId::ALL`] and the table agree row by
//! row.

use std::fmt;
use std::str::FromStr;

use serde::{Serialize, Serializer};

macro_rules! claim_ids {
    ($(
        $(#[$doc:meta])*
        $variant:ident: $id:literal;
    )*) => {
        /// A claim of the note, by its stable kebab-case id. The variants are
        /// in the order of the rows of [`crate::CLAIMS`].
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum ClaimId {
            $(
                $(#[$doc])*
                $variant,
            )*
        }

        impl ClaimId {
            /// Every claim, in the order of the table.
            pub const ALL: [ClaimId; [$($id),*].len()] = [$(ClaimId::$variant),*];

            /// The id as the outputs spell it, e.g. `eq35-terminal-third`.
            pub fn as_str(self) -> &'static str {
                match self {
                    $(ClaimId::$variant => $id,)*
                }
            }
        }
    };
}

claim_ids! {
    /// §2.1–2.3: the four analyses of the circular log give four equations.
    CircularAnalysesDiffer: "circular-analyses-differ";
    /// §2.1.3, §2.3, App. A: the four agree with the snowless log as b → 0.
    CircularAgreeAsBVanishes: "circular-agree-as-b-vanishes";
    /// §2.3, eqs. (19)–(21): the Lagrangian result differs from eq. (14).
    LagrangianDiffersFromEnergy: "lagrangian-differs-from-energy";
    /// §2.1.2, eq. (5): the torque about the contact line.
    Eq5ContactTorque: "eq5-contact-torque";
    /// fn. 4: Loney's closed form solves eq. (4).
    LoneySolvesEq4: "loney-solves-eq4";
    /// fn. 4: the coefficient of Loney's acceleration.
    LoneyAccelerationCoefficient: "loney-acceleration-coefficient";
    /// fn. 4: under eq. (4) the acceleration tends to (g/5) sin α.
    LoneyLimitFifth: "loney-limit-fifth";
    /// §2.4: the terminal acceleration of each circular equation.
    TerminalAccelerations: "terminal-accelerations";
    /// eq. (35): under eq. (32) the acceleration tends to g sin α / 3.
    Eq35TerminalThird: "eq35-terminal-third";
    /// §2.4, eqs. (33)–(35): the argument for the terminal value.
    Eq33_35TerminalArgument: "eq33-35-terminal-argument";
    /// §2.4, term (36): the lift term slows the approach to the limit.
    Eq36SlowsApproach: "eq36-slows-approach";
    /// fn. 7: a log too light for the snow does not start.
    Fn7StallThreshold: "fn7-stall-threshold";
    /// fn. 7 in §3: a light log starts but stalls inside its first turn.
    Fn7StallInFirstTurn: "fn7-stall-in-first-turn";
    /// App. A: without snow every derivation gives (2/3) g sin α.
    SnowlessLimit: "snowless-limit";
    /// App. A.3–A.5: angular momentum and torque about moving points.
    AppAMovingPoints: "app-a-moving-points";
    /// §3.1–3.3: torque, energy and Lagrangian agree on the first turn.
    FirstTurn58_64_69: "first-turn-58-64-69";
    /// §3, eqs. (47), (48): an element's velocity and the angular momentum.
    Eq47_48AngularMomentum: "eq47-48-angular-momentum";
    /// eq. (54): the cross product to first order in b.
    Eq54CrossProduct: "eq54-cross-product";
    /// §3.1, eqs. (51)–(55): the torque analysis of the accreting body.
    Eq51_55AccretingBody: "eq51-55-accreting-body";
    /// eq. (70): the mass after the first turn.
    Eq70MassAfterFirstTurn: "eq70-mass-after-first-turn";
    /// §3.4: the acceleration turn by turn never settles.
    MultiTurnNeverSettles: "multi-turn-never-settles";
    /// eq. (79): the mean acceleration over many turns.
    MultiTurnMeanFourNinths: "multi-turn-mean-four-ninths";
    /// eq. (78): the speed in the n-th turn.
    Eq78SpeedInTurnN: "eq78-speed-in-turn-n";
    /// eq. (89): the collision at the end of a turn.
    Eq89Collision: "eq89-collision";
    /// §3.4: the rise of the centre at a collision is a small cost.
    CollisionPotentialJump: "collision-potential-jump";
    /// eqs. (80)–(88): the energy balance within a turn.
    Eq88EnergyBalance: "eq88-energy-balance";
    /// §3.4, eq. (73): the turn equation holds to first order in b/r.
    Eq73TruncatesExact: "eq73-truncates-exact";
    /// fn. 10: when the turn-by-turn log hops.
    Fn10HopThreshold: "fn10-hop-threshold";
    /// Issue 10: the smallest coefficient of friction that keeps rolling.
    SlipMuMin: "slip-mu-min";
    /// Issue 11: a ball on a bare slope accelerates at (5/7) g sin α.
    SnowballFiveSevenths: "snowball-five-sevenths";
    /// Issue 11: the terminal fractions of the always-round snowball.
    SnowballTerminalFractions: "snowball-terminal-fractions";
    /// The Physics Teacher 57 (2019): the letter's closed form.
    TptLetterClosedForm: "tpt-letter-closed-form";
    /// fn. 7, fn. 10: the closed forms border the regime map.
    RegimeMapBorders: "regime-map-borders";
    /// fn. 5: with air drag and no snow there is a terminal velocity.
    SnowlessDragTerminalVelocity: "snowless-drag-terminal-velocity";
    /// fn. 5: with the losses the energy is still accounted for.
    EnergyLedgerBalances: "energy-ledger-balances";
    /// Issue 35, eq. (15) with b < 0: the unwinding roll on a level floor.
    UnwindingTextbookSpeed: "unwinding-textbook-speed";
    /// Issue 35, eq. (15) with b < 0 on a hollow roll: the tube's own mass.
    UnwindingHollowRoll: "unwinding-hollow-roll";
}

impl fmt::Display for ClaimId {
    /// The id's text; width and alignment apply as they would to the text.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.as_str())
    }
}

impl Serialize for ClaimId {
    /// As the id's text.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

/// A text that is no claim's id.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("no claim has the id `{given}`")]
pub struct UnknownClaimId {
    /// The text given.
    pub given: String,
}

impl FromStr for ClaimId {
    type Err = UnknownClaimId;

    /// Accepts exactly the text [`ClaimId::as_str`] gives.
    fn from_str(s: &str) -> Result<Self, UnknownClaimId> {
        ClaimId::ALL
            .into_iter()
            .find(|id| id.as_str() == s)
            .ok_or_else(|| UnknownClaimId {
                given: s.to_string(),
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `eq33-35-terminal-argument` → `Eq33_35TerminalArgument`: each word
    /// capitalised, an underscore kept only between two digits.
    fn variant_name(id: &str) -> String {
        let mut out = String::new();
        for word in id.split('-') {
            if out.ends_with(|c: char| c.is_ascii_digit())
                && word.starts_with(|c: char| c.is_ascii_digit())
            {
                out.push('_');
            }
            let mut chars = word.chars();
            if let Some(first) = chars.next() {
                out.push(first.to_ascii_uppercase());
                out.extend(chars);
            }
        }
        out
    }

    #[test]
    fn ids_are_unique_kebab_case_and_match_their_variant_names() {
        let mut ids: Vec<&str> = ClaimId::ALL.iter().map(|id| id.as_str()).collect();
        for (i, id) in ClaimId::ALL.iter().enumerate() {
            assert_eq!(*id as usize, i, "{id}: ALL is not in declaration order");
            let text = id.as_str();
            assert!(
                !text.is_empty()
                    && !text.starts_with('-')
                    && !text.ends_with('-')
                    && !text.contains("--")
                    && text
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'),
                "{text} is not kebab-case"
            );
            assert_eq!(format!("{id:?}"), variant_name(text), "{text}");
        }
        ids.sort_unstable();
        let n = ids.len();
        ids.dedup();
        assert_eq!(ids.len(), n, "an id is used twice");
    }

    #[test]
    fn display_serde_and_from_str_spell_the_id() {
        for id in ClaimId::ALL {
            assert_eq!(id.to_string(), id.as_str());
            assert_eq!(
                serde_json::to_string(&id).unwrap(),
                format!("\"{}\"", id.as_str())
            );
            assert_eq!(id.as_str().parse::<ClaimId>(), Ok(id));
        }
        assert_eq!(format!("[{:<8}]", ClaimId::SlipMuMin), "[slip-mu-min]");
        assert_eq!(format!("[{:<13}]", ClaimId::SlipMuMin), "[slip-mu-min  ]");
        assert!("eq89-colision".parse::<ClaimId>().is_err());
        assert!(" eq89-collision".parse::<ClaimId>().is_err());
    }
}
