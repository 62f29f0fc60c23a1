//! The report of `snowroll paper`: claims of the note with verdicts, figures,
//! and animations of the rolling log and snowball.
//!
//! A [`Report`] (metadata, claim results, [`Figure`]s, [`Animation`]s, one
//! per shape) renders to a directory with [`Report::write_to`]:
//!
//! ```text
//! report.html        self-contained: inline CSS, SVG, JS and data; no network
//! report.md          the claims table, figures linked as figures/NAME.svg
//! claims.json        the claim results
//! figures/NAME.svg   one per figure, and NAME.png
//! data/NAME.csv      the plotted series of each figure
//! data/claims.csv    every claim: measured values, verdict, evidence
//! data/animation.csv the log animation's frames (data/ball-animation.csv the snowball's)
//! ```
//!
//! Every file records the program version and the parameters. Each file is
//! written to a temporary name in its folder and then renamed into place, so
//! a reader never sees half a file.

#![deny(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::print_stdout
)]

mod claim;
mod claim_id;
mod claims;
mod part_ways;
mod turn_digest;

pub use claim::{Claim, ClaimResult, Criterion, Tally, Tolerance, Verdict, EXPECTATION_NOTE};
pub use claim_id::{ClaimId, UnknownClaimId};
pub use claims::{tuned_to_default, ClaimCheck, Finding, Lab, Runner, CLAIMS};
pub use findings::{algebra_only, headline, ALGEBRA_ONLY};
pub use part_ways::{where_turn_models_part_ways, FirstTurn, PartingRow};
pub use story::{
    abstract_sentences, abstract_text, scenario_text, ABSTRACT_CLAIMS, ABSTRACT_MAX_WORDS,
};
pub use turn_digest::{LedgerPoint, TurnDigest, HEAD_ROWS, LEDGER_POINTS};

mod animation;
#[cfg(feature = "comment")]
mod comment;
mod contact;
mod document;
mod errata;
mod error;
mod files;
mod findings;
mod findings_table;
pub mod fit_plot;
mod html;
mod intro;
mod loss_figures;
mod losses_section;
mod markdown;
mod markup;
pub mod notation;
mod paper;
pub mod plot;
pub mod run_plot;
mod snowball;
mod story;

pub use animation::{Animation, Frame};
#[cfg(feature = "comment")]
pub use comment::{write_comment, Comment, CommentError};
pub use document::{params_of, Figure, Metadata, RenderedFigure, Report, Table};
pub use error::ReportError;
pub use files::figure_csv;
/// The file in `data/` with every claim's row (linked from the pages).
const CLAIMS_CSV: &str = "claims.csv";

pub use paper::{build_paper_report, paper_steps, Progress};

/// `n ≥ 2` times from `first` to `last` (both > 0), evenly spaced in log t;
/// the last is `last` exactly (exp(ln t) may round above it, past the end of
/// the run).
fn log_grid(first: f64, last: f64, n: usize) -> Vec<f64> {
    let (a, b) = (first.ln(), last.ln());
    let mut times: Vec<f64> = (0..n)
        .map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp())
        .collect();
    if let Some(t) = times.last_mut() {
        *t = last;
    }
    times
}

/// About `n` indices of `0..len` spread evenly in log(k + 1), in order,
/// without repeats (the first is 0).
fn log_spread(len: u64, n: usize) -> Vec<u64> {
    let mut out: Vec<u64> = (0..n)
        .map(|i| ((len as f64).powf(i as f64 / (n - 1) as f64) - 1.0).round() as u64)
        .filter(|&k| k < len)
        .collect();
    out.dedup();
    out
}
