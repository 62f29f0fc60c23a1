//! `snowroll paper --comment FILE.pdf`: the comment is written with its
//! typst source and figures beside it, the same bytes from two runs (two
//! processes, two folders), no source text in the PDF's text; a bad name is
//! refused before the long computation; a build without the `comment`
//! feature names the feature.

#[cfg(feature = "comment")]
use std::fs;
#[cfg(feature = "comment")]
use std::path::Path;

use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;

/// `snowroll paper --turns 10 --quiet --out DIR/report --comment DIR/NAME`
/// in `dir` (10 turns: quick; the comment states what the run found,
/// whatever the verdicts).
#[cfg(feature = "comment")]
fn paper_with_comment(dir: &Path, name: &str) -> assert_cmd::assert::Assert {
    cargo_bin_cmd!("snowroll")
        .args(["paper", "--quiet", "--turns", "10", "--out"])
        .arg(dir.join("report"))
        .arg("--comment")
        .arg(dir.join(name))
        .assert()
}

#[cfg(feature = "comment")]
#[test]
fn paper_comment_is_the_same_bytes_in_two_runs() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    for dir in [&a, &b] {
        paper_with_comment(dir.path(), "comment.pdf")
            .success()
            .stdout(predicate::str::contains("Comment: "));
    }
    let read = |dir: &Path, file: &str| fs::read(dir.join(file)).unwrap();
    let pdf = read(a.path(), "comment.pdf");
    assert!(pdf.starts_with(b"%PDF-"));
    assert_eq!(pdf, read(b.path(), "comment.pdf"), "the PDFs differ");
    let typ = read(a.path(), "comment.typ");
    assert_eq!(typ, read(b.path(), "comment.typ"), "the sources differ");
    let figures: Vec<_> = fs::read_dir(a.path().join("comment-figures"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(figures.len(), 4, "{figures:?}");
    for f in &figures {
        let name = Path::new("comment-figures").join(f);
        let name = name.to_str().unwrap();
        assert_eq!(read(a.path(), name), read(b.path(), name), "{name} differs");
        // The source includes each figure from the folder beside it.
        assert!(String::from_utf8_lossy(&typ).contains(&format!("\"{name}\"")));
    }
    // What a reader of the PDF sees has no source text (item 4's scan).
    let text = std::process::Command::new("pdftotext")
        .args(["-enc", "UTF-8"])
        .arg(a.path().join("comment.pdf"))
        .arg("-")
        .output()
        .expect("pdftotext (poppler-utils, bash .ci/install-poppler.sh)");
    let text = String::from_utf8(text.stdout).unwrap();
    assert!(text.contains("Abstract."), "{text}");
    let found = crate::source_text::findings(&text);
    assert!(found.is_empty(), "source text in the comment: {found:?}");
}

#[cfg(feature = "comment")]
#[test]
fn paper_comment_refuses_a_bad_name_before_running() {
    let dir = tempfile::tempdir().unwrap();
    paper_with_comment(dir.path(), "comment.txt")
        .failure()
        .stderr(predicate::str::contains("--comment"))
        .stderr(predicate::str::contains("ending in .pdf"));
    paper_with_comment(dir.path(), "no/such/folder/comment.pdf")
        .failure()
        .stderr(predicate::str::contains("does not exist"));
    // Refused before the report was computed or written.
    assert!(!dir.path().join("report").exists());
}

/// In a build without the `comment` feature, `--comment` names the feature
/// to enable, before the long computation.
#[cfg(not(feature = "comment"))]
#[test]
fn paper_comment_without_its_feature_names_the_feature() {
    let dir = tempfile::tempdir().unwrap();
    cargo_bin_cmd!("snowroll")
        .args(["paper", "--quiet", "--out"])
        .arg(dir.path().join("report"))
        .arg("--comment")
        .arg(dir.path().join("comment.pdf"))
        .assert()
        .failure()
        .code(1)
        .stderr(predicate::str::contains("the `comment` feature"));
    assert!(!dir.path().join("report").exists());
}
