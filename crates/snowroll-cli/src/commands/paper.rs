//! `snowroll paper`: every claim of the note judged, and the report written.
//! The physics, the claims and the report are the library's
//! ([`snowroll::report`]); this command shows progress and says where the
//! report is. With `--strict` it fails when any verdict differs from the one
//! the claims table expects (after writing the report, so it can be read).

use std::io::Write;
use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use snowroll::params::Settings;
use snowroll::{Scenario, Shape};
use snowroll_report::{build_paper_report, paper_steps, ClaimResult, Lab, ReportError, Tally};

use crate::args::PaperArgs;
use crate::clash::{refuse_clashes, RunFile};
use crate::console;
use crate::outdir::StagedDir;

/// Runs the claims and figures, writes the report, prints the claims table.
pub fn run(args: &PaperArgs) -> Result<()> {
    // `paper` reads no file, so its one output cannot clash today; it goes
    // through the check every command does, which an input added later needs.
    let mut outputs = vec![RunFile::output(&args.out, "--out report directory")];
    if let Some(pdf) = &args.comment {
        check_comment_path(pdf)?;
        outputs.push(RunFile::output(pdf, "--comment PDF"));
    }
    refuse_clashes(&outputs)?;
    // Check --out and stdout (where the claims table goes) before the long
    // computation, so that a bad path or a closed stdout fails at once.
    console::check_stdout().context("writing the claims table to stdout")?;
    let explorer = args.explorer.as_deref().map(read_explorer).transpose()?;
    let staged = StagedDir::open(&args.out)?;
    let scenario = scenario_of(args)?;
    let lab = Lab::new(scenario, args.turns);
    let bar = progress_bar(args.quiet)?;
    let mut report = build_paper_report(&lab, &mut |p| {
        bar.set_position(p.done as u64);
        bar.set_message(p.label.to_string());
    })
    .context("building the report")?;
    report.explorer = explorer.is_some();
    bar.set_message("writing files");
    let written = report
        .write_to(staged.path())
        .map_err(|e| match e {
            // Name the file as it will be once in place, not the temporary one.
            ReportError::Io { path, source } => {
                anyhow!("{}: {source}", staged.shown(&path).display())
            }
            other => other.into(),
        })
        .with_context(|| format!("writing the report to {}", args.out.display()))?;
    if let Some(page) = &explorer {
        let path = staged.path().join(EXPLORER);
        std::fs::write(&path, page)
            .with_context(|| format!("writing {}", args.out.join(EXPLORER).display()))?;
    }
    staged.commit()?;
    if let Some(pdf) = &args.comment {
        bar.set_message("typesetting the comment");
        write_comment(&report, pdf)?;
    }
    bar.finish_and_clear();
    let tally = print_claims(&report.claims)?;
    writeln!(
        console::Stdout,
        "Report: {} ({} files in {})",
        args.out.join("report.html").display(),
        written.len(),
        args.out.display()
    )?;
    if let Some(pdf) = &args.comment {
        writeln!(console::Stdout, "Comment: {}", pdf.display())?;
    }
    if args.strict && tally.unexpected > 0 {
        bail!(
            "--strict: {} verdict(s) differ from the claims table's expectation: {}",
            tally.unexpected,
            unexpected(&report.claims)
        );
    }
    Ok(())
}

/// Refuses a `--comment` path before the long computation: a build
/// without the `comment` feature, a name that does not end in `.pdf`, a
/// folder that does not exist.
fn check_comment_path(pdf: &Path) -> Result<()> {
    if !cfg!(feature = "comment") {
        bail!(
            "--comment {}: this snowroll was built without the `comment` feature, which typesets the comment; \
             build it with `cargo build --release -p snowroll-cli --features comment`",
            pdf.display()
        );
    }
    let is_pdf = pdf
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("pdf"));
    if !is_pdf || pdf.file_stem().is_none() {
        bail!(
            "--comment {}: the comment is a PDF: give a file name ending in .pdf (its source is written beside it as .typ)",
            pdf.display()
        );
    }
    let dir = pdf
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !dir.is_dir() {
        bail!(
            "--comment {}: the folder {} does not exist",
            pdf.display(),
            dir.display()
        );
    }
    Ok(())
}

/// Typesets the comment on `report` and writes it as `pdf`, its source
/// and its figures beside it.
#[cfg(feature = "comment")]
fn write_comment(report: &snowroll_report::Report, pdf: &Path) -> Result<()> {
    snowroll_report::write_comment(report, pdf)
        .with_context(|| format!("writing the comment {}", pdf.display()))?;
    Ok(())
}

/// Never called: [`check_comment_path`] refuses `--comment` first in a
/// build without the `comment` feature.
#[cfg(not(feature = "comment"))]
fn write_comment(_report: &snowroll_report::Report, pdf: &Path) -> Result<()> {
    check_comment_path(pdf)
}

/// The explorer's name in the report directory.
const EXPLORER: &str = "explorer.html";

/// The page of `--explorer`, read before the long computation: an explorer
/// built by scripts/build-explorer.sh (it holds the library in WebAssembly),
/// else an error naming the file and how to build one.
fn read_explorer(path: &Path) -> Result<Vec<u8>> {
    let page = std::fs::read(path).with_context(|| format!("--explorer {}", path.display()))?;
    let marker: &[u8] = b"const SNOWROLL_WASM = '";
    if !page.starts_with(b"<!DOCTYPE html>") || !page.windows(marker.len()).any(|w| w == marker) {
        bail!(
            "--explorer {}: not an explorer page built by `bash scripts/build-explorer.sh FILE.html` \
             (no WebAssembly module inlined)",
            path.display()
        );
    }
    Ok(page)
}

/// The scenario of the flags given (the defaults for the others). The
/// note's claims are about the log: a ball is refused.
fn scenario_of(args: &PaperArgs) -> Result<Scenario> {
    let settings = args.scenario.given.apply(Settings::default())?;
    let scenario = Scenario::new(settings.scenario)?;
    if scenario.snow_depth() == 0.0 {
        bail!("paper judges the note's claims about snow: give --snow-depth > 0 m (the snowless log is every model's b → 0 limit, which the report checks)");
    }
    if scenario.shape() != Shape::Cylinder {
        bail!(
            "paper judges the note's claims about the log: give no --shape (or --shape cylinder); \
             the report's snowball claims and figures roll their own ball"
        );
    }
    Ok(scenario)
}

/// The progress bar on stderr: hidden with `--quiet` or off a terminal.
fn progress_bar(quiet: bool) -> Result<ProgressBar> {
    let bar = if quiet || !console::stderr_is_terminal() {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(paper_steps() as u64)
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:32} {pos}/{len} {elapsed:>4} {msg}")
            .context("progress bar template")?,
    );
    Ok(bar)
}

/// Prints one line per claim (symbol, id, verdict, reference to the note)
/// and the tally, which it returns.
fn print_claims(claims: &[ClaimResult]) -> Result<Tally> {
    let mut out = console::Stdout;
    let id_width = claims
        .iter()
        .map(|c| c.claim.id.as_str().chars().count())
        .max()
        .unwrap_or(0);
    writeln!(out, "Claims of the note ({} checked):", claims.len())?;
    for c in claims {
        let flag = if c.as_expected() {
            ""
        } else {
            "  (NOT the expected verdict)"
        };
        writeln!(
            out,
            "  {} {:<id_width$}  {:<9}  {}{flag}",
            c.verdict.symbol(),
            c.claim.id,
            c.verdict.class(),
            c.claim.paper_ref,
        )?;
    }
    let tally = Tally::of(claims);
    writeln!(out, "{}", tally.sentence())?;
    Ok(tally)
}

/// The claims whose verdict is not the expected one, with both verdicts.
fn unexpected(claims: &[ClaimResult]) -> String {
    claims
        .iter()
        .filter(|c| !c.as_expected())
        .map(|c| {
            format!(
                "{} ({}, expected {})",
                c.claim.id, c.verdict, c.claim.expected
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}
