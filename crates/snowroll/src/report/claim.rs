//! Claims of the note and what the program found about them.
//!
//! A [`Claim`] is a static table entry: where in the note, what it says, how
//! the program checks it, with which tolerance, and the verdict we expect. A
//! [`ClaimResult`] pairs a claim with the measured numbers, the verdict the
//! check reached and the evidence for it.

use std::fmt;

use serde::Serialize;

/// What the program concluded about a claim of the note.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "verdict", content = "erratum", rename_all = "kebab-case")]
pub enum Verdict {
    /// The claim holds as printed.
    Holds,
    /// The claim holds once the named erratum is applied (e.g. `errata §2.1`).
    HoldsAfterCorrection(&'static str),
    /// The claim does not hold; the evidence says why.
    Refuted,
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
        }
    }

    /// A short machine-friendly class name: `holds`, `corrected`, `refuted`.
    pub fn class(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::HoldsAfterCorrection(_) => "corrected",
            Verdict::Refuted => "refuted",
        }
    }

    /// A symbol that tells the verdicts apart without colour.
    pub fn symbol(self) -> &'static str {
        match self {
            Verdict::Holds => "✓",
            Verdict::HoldsAfterCorrection(_) => "✎",
            Verdict::Refuted => "✗",
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
    /// The check is exact or qualitative (a sign, an ordering, an identity of formulae).
    Exact,
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tolerance::Relative { value } => write!(f, "relative {value:e}"),
            Tolerance::Absolute { value, unit } => write!(f, "absolute {value:e} {unit}"),
            Tolerance::Exact => f.write_str("exact"),
        }
    }
}

/// A claim of the note, as a static table entry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Claim {
    /// Stable identifier, kebab-case (e.g. `eq35-terminal-third`).
    pub id: &'static str,
    /// Where in the note: `eq. (35)`, `§2.4`, `fn. 7`.
    pub paper_ref: &'static str,
    /// What the note says, in our words.
    pub statement: &'static str,
    /// How the program checks it: models, scenarios, quantity compared.
    pub method: &'static str,
    /// The tolerance of the check.
    pub tolerance: Tolerance,
    /// The verdict we expect the check to reach.
    pub expected: Verdict,
}

/// What a check found about one claim.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClaimResult {
    /// The claim.
    pub claim: &'static Claim,
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
            }
            if !r.as_expected() {
                t.unexpected += 1;
            }
        }
        t
    }

    /// One sentence: `5 claims: 3 hold, 1 holds after correction, 1 refuted; all as expected.`
    pub fn sentence(&self) -> String {
        let total = self.holds + self.holds_after_correction + self.refuted;
        let expectation = if self.unexpected == 0 {
            "every verdict as expected".to_string()
        } else {
            format!(
                "{} verdict(s) differ from the expected one",
                self.unexpected
            )
        };
        format!(
            "{total} claims: {} hold, {} hold after correction, {} refuted; {expectation}.",
            self.holds, self.holds_after_correction, self.refuted
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    static CLAIM: Claim = Claim {
        id: "demo",
        paper_ref: "eq. (35)",
        statement: "s",
        method: "m",
        tolerance: Tolerance::Relative { value: 1e-6 },
        expected: Verdict::HoldsAfterCorrection("errata §2.1"),
    };

    #[test]
    fn verdict_json_names_the_erratum() {
        let v = serde_json::to_value(Verdict::HoldsAfterCorrection("errata §2.1")).unwrap();
        assert_eq!(v["verdict"], "holds-after-correction");
        assert_eq!(v["erratum"], "errata §2.1");
        let v = serde_json::to_value(Verdict::Refuted).unwrap();
        assert_eq!(v["verdict"], "refuted");
    }

    #[test]
    fn tally_counts_each_verdict_and_the_unexpected_ones() {
        let r = |verdict| ClaimResult {
            claim: &CLAIM,
            measured: String::new(),
            verdict,
            evidence: String::new(),
        };
        let results = [
            r(Verdict::Holds),
            r(Verdict::HoldsAfterCorrection("errata §2.1")),
            r(Verdict::Refuted),
            r(Verdict::HoldsAfterCorrection("errata §2.1")),
        ];
        let t = Tally::of(&results);
        assert_eq!(
            (t.holds, t.holds_after_correction, t.refuted, t.unexpected),
            (1, 2, 1, 2)
        );
    }
}
