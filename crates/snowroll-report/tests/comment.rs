//! The comment on the note (`snowroll paper --comment`, feature `comment`):
//! the PDF opens and has 4 to 8 pages; its text, as poppler's `pdftotext`
//! extracts it, holds the abstract, every refuted claim's measured number
//! and every erratum of `docs/errata.md`, and no source text; the same
//! report gives the same bytes; a compiler warning fails the typesetting;
//! a deliberately wrong model changes the verdict sentence.
//!
//! Needs `pdftotext` and `pdfinfo` (Debian's poppler-utils, installed by
//! `.ci/install-poppler.sh`, which `scripts/test.sh` runs).

use std::path::Path;
use std::process::Command;
use std::sync::OnceLock;

use snowroll::{Coefficients, Derivation, Scenario};
use snowroll_report::{
    build_paper_report, write_comment, ClaimId, Comment, CommentError, Lab, Report, Verdict, CLAIMS,
};

/// Turns of the long runs: as tests/claims.rs, enough for every expected
/// verdict (the report runs 10^5).
const TURNS: u64 = 10_000;

/// The report every test reads, built once.
fn report() -> &'static Report {
    static REPORT: OnceLock<Report> = OnceLock::new();
    REPORT.get_or_init(|| {
        let lab = Lab::new(Scenario::default(), TURNS);
        build_paper_report(&lab, &mut |_| {}).unwrap()
    })
}

/// Runs a poppler tool with `args` and returns its standard output.
fn poppler(tool: &str, args: &[&std::ffi::OsStr]) -> String {
    let out = Command::new(tool).args(args).output().unwrap_or_else(|e| {
        panic!("{tool} not found ({e}): install poppler-utils (bash .ci/install-poppler.sh)")
    });
    assert!(
        out.status.success(),
        "{tool} failed on the comment: {out:?}"
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The PDF's text with every run of white space one space, and words
/// hyphenated at a line's end joined again.
fn pdf_text(pdf: &Path) -> String {
    let raw = poppler(
        "pdftotext",
        &[
            "-enc".as_ref(),
            "UTF-8".as_ref(),
            pdf.as_os_str(),
            "-".as_ref(),
        ],
    );
    raw.replace("-\n", "")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The number printed after `label` in `measured`, as printed (the test's
/// own reading of a claim's measured text, not the comment's).
fn number_after(measured: &str, label: &str) -> String {
    let start = measured
        .find(label)
        .unwrap_or_else(|| panic!("{label:?} not in {measured}"));
    measured[start + label.len()..]
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect()
}

/// Where each refuted claim's headline number is in its measured text: a
/// claim refuted in a later version fails here until it is added.
fn refuted_label(id: ClaimId) -> &'static str {
    match id {
        ClaimId::LagrangianDiffersFromEnergy => "max |a₂₁ − a₁₄|/G =",
        ClaimId::MultiTurnMeanFourNinths => "with collisions",
        ClaimId::Eq78SpeedInTurnN => "v²/(π g n² b sin α) =",
        other => panic!("claim {other} is refuted: name the number the comment must quote"),
    }
}

/// The "Where" cells of both errata tables of `docs/errata.md`.
fn errata_places() -> Vec<String> {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/errata.md"))
            .unwrap();
    text.lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| Where"))
        .map(|l| l[2..].split(" | ").next().unwrap().trim().to_string())
        .collect()
}

#[test]
fn comment_pdf_holds_the_abstract_the_refuted_numbers_and_the_errata() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = dir.path().join("comment.pdf");
    let written = write_comment(report(), &pdf).unwrap();
    // The PDF, its source and its four figures (vector: SVG).
    assert_eq!(written.len(), 6, "{written:?}");
    assert!(dir.path().join("comment.typ").is_file());
    let svgs = std::fs::read_dir(dir.path().join("comment-figures"))
        .unwrap()
        .count();
    assert!((3..=5).contains(&svgs), "{svgs} figures");

    let info = poppler("pdfinfo", &[pdf.as_os_str()]);
    let pages: usize = info
        .lines()
        .find_map(|l| l.strip_prefix("Pages:"))
        .and_then(|n| n.trim().parse().ok())
        .unwrap_or_else(|| panic!("no page count in {info}"));
    assert!((4..=8).contains(&pages), "{pages} pages");

    let text = pdf_text(&pdf);
    assert!(text.contains("Comment on K. T. McDonald"), "{text}");
    // The abstract, with the run's tally in it.
    let tally = snowroll_report::Tally::of(&report().claims);
    assert!(
        text.contains("Abstract. We have implemented every analysis"),
        "{text}"
    );
    let total = tally.holds + tally.holds_after_correction + tally.refuted + tally.inconclusive;
    assert!(text.contains(&format!("checked {total} claims")), "{text}");
    assert!(
        text.contains(&format!(
            "integration: {} hold as printed, {} hold once a misprint is corrected, and {} are refuted",
            tally.holds, tally.holds_after_correction, tally.refuted
        )),
        "{text}"
    );
    // Every refuted claim's number, as its check printed it.
    let refuted: Vec<_> = report()
        .claims
        .iter()
        .filter(|r| r.verdict == Verdict::Refuted)
        .collect();
    assert_eq!(refuted.len(), tally.refuted);
    assert!(!refuted.is_empty());
    for r in refuted {
        let number = number_after(&r.measured, refuted_label(r.claim.id));
        assert!(number.len() >= 3, "{}: {number:?}", r.claim.id);
        assert!(
            text.contains(&number),
            "{}: {number} not in the comment",
            r.claim.id
        );
    }
    // Every erratum, by where it is in the note, under its table's caption.
    assert!(text.contains("Table 1: Misprints of the note"), "{text}");
    assert!(text.contains("Table 2: Errors of derivation"), "{text}");
    for place in errata_places() {
        assert!(
            text.contains(&place),
            "erratum at {place} not in the comment"
        );
    }
    // No source text: code paths, Rust paths, ASCII subscripts, claim ids.
    for bad in ["::", "docs/", ".rs", ".md", "tests/", "`", "_", "r0", "m0"] {
        assert!(!text.contains(bad), "{bad:?} in the comment's text");
    }
    for c in CLAIMS {
        assert!(
            !text.contains(c.claim.id.as_str()),
            "claim id {} in the text",
            c.claim.id
        );
    }
}

#[test]
fn the_same_report_gives_the_same_bytes() {
    let a = Comment::new(report(), "figures").unwrap();
    let b = Comment::new(report(), "figures").unwrap();
    assert_eq!(a, b);
    let (pa, pb) = (a.pdf().unwrap(), b.pdf().unwrap());
    assert!(pa.starts_with(b"%PDF-"));
    assert_eq!(pa, pb);
    // No date: the bytes cannot depend on the day.
    assert!(!pa.windows(13).any(|w| w == b"/CreationDate"));
}

#[test]
fn a_compiler_warning_fails_the_typesetting() {
    // The same comment with one line that typst compiles with a warning
    // (an unknown font family): the check that the source compiles without
    // warnings is not vacuous.
    let mut comment = Comment::new(report(), "figures").unwrap();
    comment
        .source
        .push_str("\n#text(font: \"No Such Family\")[x]\n");
    match comment.pdf() {
        Err(CommentError::Typeset { messages }) => {
            assert!(
                messages.iter().any(|m| m.starts_with("warning")),
                "{messages:?}"
            );
        }
        other => panic!(
            "expected a typesetting error, got {:?}",
            other.map(|p| p.len())
        ),
    }
}

#[test]
fn a_wrong_model_changes_the_lagrangian_sentence() {
    // The printed (21) with a wrong drag coefficient: the check no longer
    // finds that (21) differs from (14) by the omitted term alone
    // (tests/claims.rs), and the comment must not say that it does.
    let refuted = "is refuted: the difference is the omitted term";
    let right = Comment::new(report(), "figures").unwrap();
    assert!(right.source.contains(refuted));

    let check = CLAIMS
        .iter()
        .find(|c| c.claim.id == ClaimId::LagrangianDiffersFromEnergy)
        .unwrap();
    let mut wrong: Coefficients = Derivation::LagrangianPrinted.coefficients();
    wrong.drag = 1.01;
    let lab =
        Lab::new(Scenario::default(), 10).with_coefficients(Derivation::LagrangianPrinted, wrong);
    let result = check.run(&lab).unwrap();
    assert_ne!(result.verdict, Verdict::Refuted);
    let mut report = report().clone();
    for r in &mut report.claims {
        if r.claim.id == ClaimId::LagrangianDiffersFromEnergy {
            *r = result.clone();
        }
    }
    let changed = Comment::new(&report, "figures").unwrap();
    assert!(!changed.source.contains(refuted));
    let said = match result.verdict {
        Verdict::Holds => "the printed eq. (21) agreed with eq. (14)",
        Verdict::Inconclusive => "the comparison is inconclusive and no finding is stated",
        _ => "reached the verdict",
    };
    assert!(changed.source.contains(said), "{said:?} not in the source");
    // The abstract's sentence on (21) goes too, and the source still
    // typesets cleanly.
    assert!(!changed
        .source
        .contains("with the term it is the same equation"));
    changed.pdf().unwrap();
}
