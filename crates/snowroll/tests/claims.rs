//! Every claim of the note reaches the verdict the table expects (issue 4).
//! The checks are the same functions the `paper` report runs: one table,
//! `report::CLAIMS`, so the report and these tests cannot disagree.

use snowroll::report::{Lab, CLAIMS};
use snowroll::Scenario;

/// 10^4 turns are enough for the long-run claims' verdicts (the last-decade
/// means are within 1e-3 G of their limits there); the report runs 10^5.
const TURNS: u64 = 10_000;

#[test]
fn every_claim_reaches_its_expected_verdict() {
    let lab = Lab::new(Scenario::default(), TURNS);
    let mut failures = Vec::new();
    for check in CLAIMS {
        let result = check.run(&lab).unwrap();
        if result.verdict != check.claim.expected {
            failures.push(format!(
                "{} ({}): expected {}, got {}\n  measured: {}\n  evidence: {}",
                check.claim.id,
                check.claim.paper_ref,
                check.claim.expected,
                result.verdict,
                result.measured,
                result.evidence
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn claim_ids_are_unique_and_every_claim_cites_the_note() {
    let mut ids: Vec<&str> = CLAIMS.iter().map(|c| c.claim.id).collect();
    ids.sort_unstable();
    let n = ids.len();
    ids.dedup();
    assert_eq!(ids.len(), n, "duplicate claim id");
    for c in CLAIMS {
        let r = c.claim.paper_ref;
        assert!(
            r.contains("eq.")
                || r.contains("eqs.")
                || r.contains('§')
                || r.contains("fn.")
                || r.contains("App."),
            "{}: {r}",
            c.claim.id
        );
    }
}
