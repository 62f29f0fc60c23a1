//! Claims of the note and what the program found about them.
//!
//! A [`Claim`] is a static table entry: where in the note, what it says, how
//! the program checks it, with which tolerances, and the verdict we expect. A
//! [`ClaimResult`] pairs a claim with the measured numbers, the verdict the
//! check reached and the evidence for it.
//!
//! The tolerances a claim shows are the ones its check uses: each is a
//! [`Criterion`] constant that the table lists and the check calls
//! ([`Criterion::accepts`]), so the two cannot drift apart.

use std::fmt;

use serde::Serialize;

use super::claim_id::ClaimId;
use super::notation::compact;

/// What the program concluded about a claim of the note.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "verdict", content = "erratum", rename_all = "kebab-case")]
pub enum Verdict {
    /// The claim holds as printed.
    Holds,
    /// The claim holds once the named erratum of `docs/errata.md` is applied.
    HoldsAfterCorrection(&'static str),
    /// The claim does not hold, and the check established what holds instead.
    Refuted,
    /// The check could establish neither the claim nor what holds instead
    /// (a wrong model, a non-finite number): never an expected verdict.
    Inconclusive,
}

impl Verdict {
    /// The verdict in words, with the erratum where there is one.
    pub fn label(self) -> String {
        match self {
            Verdict::Holds => "holds".to_string(),
            Verdict::HoldsAfterCorrection(erratum) => {
                format!("holds after correction ({erratum})")
            }
            Verdict::Refuted => "refuted".to_string(),
            Verdict::Inconclusive => "inconclusive".to_string(),
        }
    }

    /// A short machine-friendly class name: `holds`, `corrected`, `refuted`,
    /// `inconclusive`.
    pub fn class(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::HoldsAfterCorrection(_) => "corrected",
            Verdict::Refuted => "refuted",
            Verdict::Inconclusive => "inconclusive",
        }
    }

    /// A symbol that tells the verdicts apart without colour.
    pub fn symbol(self) -> &'static str {
        match self {
            Verdict::Holds => "✓",
            Verdict::HoldsAfterCorrection(_) => "✎",
            Verdict::Refuted => "✗",
            Verdict::Inconclusive => "?",
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

/// The tolerance a check allows.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Tolerance {
    /// `|measured − expected| ≤ value · |expected|`.
    Relative {
        /// The allowed relative difference.
        value: f64,
    },
    /// `|measured − expected| ≤ value`, in `unit`.
    Absolute {
        /// The allowed difference.
        value: f64,
        /// Its unit, e.g. `m/s²`; `1` for a ratio.
        unit: &'static str,
    },
    /// `|measured − expected| ≥ value`, in `unit`: a separation that shows
    /// two things differ (a printed form from the corrected one).
    AtLeast {
        /// The smallest difference that counts as different.
        value: f64,
        /// Its unit.
        unit: &'static str,
    },
    /// The check is exact or qualitative (a sign, an ordering, a stop reason).
    Exact,
}

impl Tolerance {
    /// The deviation this tolerance bounds: relative for [`Tolerance::Relative`],
    /// absolute otherwise (0 or ∞ for [`Tolerance::Exact`]).
    pub fn deviation(self, measured: f64, expected: f64) -> f64 {
        let diff = (measured - expected).abs();
        match self {
            Tolerance::Relative { .. } => diff / expected.abs(),
            Tolerance::Absolute { .. } | Tolerance::AtLeast { .. } => diff,
            Tolerance::Exact if diff <= 0.0 => 0.0,
            Tolerance::Exact => f64::INFINITY,
        }
    }

    /// Whether a deviation (as [`Tolerance::deviation`] measures it) passes.
    /// A NaN deviation never passes.
    pub fn accepts_deviation(self, deviation: f64) -> bool {
        match self {
            Tolerance::Relative { value } | Tolerance::Absolute { value, .. } => deviation <= value,
            Tolerance::AtLeast { value, .. } => deviation >= value,
            Tolerance::Exact => deviation <= 0.0,
        }
    }

    /// Whether `measured` passes against `expected`.
    pub fn accepts(self, measured: f64, expected: f64) -> bool {
        self.accepts_deviation(self.deviation(measured, expected))
    }
}

/// ` m/s` after a number, or ` (dimensionless)` for the unit `1`.
fn unit_suffix(unit: &str) -> String {
    match unit.trim() {
        "" | "1" => " (dimensionless)".to_string(),
        u => format!(" {u}"),
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tolerance::Relative { value } => write!(f, "relative {}", compact(*value)),
            Tolerance::Absolute { value, unit } => {
                write!(f, "absolute {}{}", compact(*value), unit_suffix(unit))
            }
            Tolerance::AtLeast { value, unit } => {
                write!(f, "at least {}{} apart", compact(*value), unit_suffix(unit))
            }
            Tolerance::Exact => f.write_str("exact"),
        }
    }
}

/// One tolerance of a check: what it bounds, how much, and why that much.
/// The claims table lists these constants and the checks call them, so the
/// tolerance shown is the tolerance used.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Criterion {
    /// The quantity compared, e.g. `a/G against the derived limit`.
    pub quantity: &'static str,
    /// The tolerance.
    pub tolerance: Tolerance,
    /// Why this tolerance, one line.
    pub reason: &'static str,
}

impl Criterion {
    /// [`Tolerance::deviation`].
    pub fn deviation(&self, measured: f64, expected: f64) -> f64 {
        self.tolerance.deviation(measured, expected)
    }

    /// [`Tolerance::accepts_deviation`].
    pub fn accepts_deviation(&self, deviation: f64) -> bool {
        self.tolerance.accepts_deviation(deviation)
    }

    /// [`Tolerance::accepts`].
    pub fn accepts(&self, measured: f64, expected: f64) -> bool {
        self.tolerance.accepts(measured, expected)
    }

    /// The bound's value (0 for [`Tolerance::Exact`]), for evidence text.
    pub fn value(&self) -> f64 {
        match self.tolerance {
            Tolerance::Relative { value }
            | Tolerance::Absolute { value, .. }
            | Tolerance::AtLeast { value, .. } => value,
            Tolerance::Exact => 0.0,
        }
    }
}

impl fmt::Display for Criterion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {} ({})", self.quantity, self.tolerance, self.reason)
    }
}

/// A claim of the note, as a static table entry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Claim {
    /// Stable identifier; its text is kebab-case (e.g. `eq35-terminal-third`).
    pub id: ClaimId,
    /// Where in the note: `eq. (35)`, `§2.4`, `fn. 7`.
    pub paper_ref: &'static str,
    /// What the note says, in our words.
    pub statement: &'static str,
    /// How the program checks it: models, scenarios, quantity compared.
    pub method: &'static str,
    /// The tolerances of the check: the constants it compares with.
    pub tolerances: &'static [Criterion],
    /// The verdict we expect the check to reach (recorded here, checked by
    /// `tests/claims.rs` and by `snowroll paper --strict`).
    pub expected: Verdict,
}

impl Claim {
    /// The tolerances in one line, `; `-separated.
    pub fn tolerances_text(&self) -> String {
        self.tolerances
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// What a check found about one claim.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClaimResult {
    /// The claim.
    pub claim: &'static Claim,
    /// The finding in one sentence as its check composed it from what it
    /// measured, if it did; the report's headline is
    /// [`crate::headline`] of the whole result (`claims.json` records that).
    #[serde(skip)]
    pub headline: Option<String>,
    /// The measured numbers, with units.
    pub measured: String,
    /// The verdict reached.
    pub verdict: Verdict,
    /// Why: the comparison behind the verdict.
    pub evidence: String,
}

impl ClaimResult {
    /// Whether the verdict is the one the table expects.
    pub fn as_expected(&self) -> bool {
        self.verdict == self.claim.expected
    }
}

/// Counts of verdicts over a set of results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct Tally {
    /// Claims that hold as printed.
    pub holds: usize,
    /// Claims that hold after an erratum.
    pub holds_after_correction: usize,
    /// Claims refuted.
    pub refuted: usize,
    /// Checks that established neither the claim nor its refutation.
    pub inconclusive: usize,
    /// Results whose verdict differs from the expected one.
    pub unexpected: usize,
}

impl Tally {
    /// Counts `results`.
    pub fn of(results: &[ClaimResult]) -> Self {
        let mut t = Tally::default();
        for r in results {
            match r.verdict {
                Verdict::Holds => t.holds += 1,
                Verdict::HoldsAfterCorrection(_) => t.holds_after_correction += 1,
                Verdict::Refuted => t.refuted += 1,
                Verdict::Inconclusive => t.inconclusive += 1,
            }
            if !r.as_expected() {
                t.unexpected += 1;
            }
        }
        t
    }

    /// One sentence: `5 claims: 3 hold, 1 holds after correction, 1 refuted; every verdict as expected.`
    pub fn sentence(&self) -> String {
        let total = self.holds + self.holds_after_correction + self.refuted + self.inconclusive;
        let inconclusive = if self.inconclusive > 0 {
            format!(", {} inconclusive", self.inconclusive)
        } else {
            String::new()
        };
        let expectation = if self.unexpected == 0 {
            "every verdict as expected".to_string()
        } else {
            format!(
                "{} verdict(s) differ from the expected one",
                self.unexpected
            )
        };
        format!(
            "{total} claims: {} hold, {} hold after correction, {} refuted{inconclusive}; {expectation}.",
            self.holds, self.holds_after_correction, self.refuted
        )
    }
}

/// What "every verdict as expected" means, one sentence for the report.
pub const EXPECTATION_NOTE: &str = "“As expected” means that each verdict equals the one recorded for its claim in the program's table of claims; the program's tests and `snowroll paper --strict` fail when any verdict differs, and a claim is marked refuted only when its check also measured what holds instead.";

#[cfg(test)]
mod tests {
    use super::*;

    static CLAIM: Claim = Claim {
        id: ClaimId::Eq35TerminalThird,
        paper_ref: "eq. (35)",
        statement: "s",
        method: "m",
        tolerances: &[Criterion {
            quantity: "q",
            tolerance: Tolerance::Relative { value: 1e-6 },
            reason: "r",
        }],
        expected: Verdict::HoldsAfterCorrection("docs/errata.md (21)"),
    };

    #[test]
    fn verdict_json_names_the_erratum() {
        let v = serde_json::to_value(Verdict::HoldsAfterCorrection("docs/errata.md (21)")).unwrap();
        assert_eq!(v["verdict"], "holds-after-correction");
        assert_eq!(v["erratum"], "docs/errata.md (21)");
        let v = serde_json::to_value(Verdict::Refuted).unwrap();
        assert_eq!(v["verdict"], "refuted");
    }

    #[test]
    fn tally_counts_each_verdict_and_the_unexpected_ones() {
        let r = |verdict| ClaimResult {
            claim: &CLAIM,
            headline: None,
            measured: String::new(),
            verdict,
            evidence: String::new(),
        };
        let results = [
            r(Verdict::Holds),
            r(Verdict::HoldsAfterCorrection("docs/errata.md (21)")),
            r(Verdict::Refuted),
            r(Verdict::HoldsAfterCorrection("docs/errata.md (21)")),
        ];
        let t = Tally::of(&results);
        assert_eq!(
            (t.holds, t.holds_after_correction, t.refuted, t.unexpected),
            (1, 2, 1, 2)
        );
        let t = Tally::of(&[r(Verdict::Inconclusive)]);
        assert_eq!((t.inconclusive, t.unexpected), (1, 1));
        assert!(t.sentence().contains("1 inconclusive"));
    }

    #[test]
    fn tolerances_fail_on_nan_and_at_least_means_apart() {
        let rel = Tolerance::Relative { value: 1e-3 };
        assert!(rel.accepts(1.0005, 1.0));
        assert!(!rel.accepts(1.002, 1.0));
        assert!(!rel.accepts(f64::NAN, 1.0));
        let apart = Tolerance::AtLeast {
            value: 0.1,
            unit: "1",
        };
        assert!(apart.accepts(1.2, 1.0));
        assert!(!apart.accepts(1.05, 1.0));
        assert!(!apart.accepts(f64::NAN, 1.0));
        assert!(Tolerance::Exact.accepts(2.0, 2.0));
        assert!(!Tolerance::Exact.accepts(2.0, 2.5));
    }
}
