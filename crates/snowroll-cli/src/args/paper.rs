//! Flags of `snowroll paper`.

use std::path::PathBuf;

use super::SlopeArgs;

/// Where `snowroll paper` writes when `--out` is not given.
pub const PAPER_OUT_DEFAULT: &str = "snowroll-report";

/// Turns of the long multi-turn runs of `snowroll paper` by default.
pub const PAPER_TURNS_DEFAULT: u64 = 100_000;

/// Flags of `snowroll paper`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct PaperArgs {
    /// Directory for report.html, report.md, claims.json, figures/ and data/ (built beside it, then moved into place whole; an existing report there is replaced, any other existing directory refused)
    #[arg(long, short, value_name = "DIR", default_value = PAPER_OUT_DEFAULT)]
    pub out: PathBuf,

    /// Turns of the long runs behind the multi-turn claims (eqs. (77)-(79)), N >= 10; their tolerances need N >= 10^4
    #[arg(long, value_name = "N", default_value_t = PAPER_TURNS_DEFAULT, value_parser = clap::value_parser!(u64).range(10..))]
    pub turns: u64,

    /// Do not show the progress bar
    #[arg(long)]
    pub quiet: bool,

    /// Exit with an error when any verdict differs from the one the claims table expects (the report is still written)
    #[arg(long)]
    pub strict: bool,

    /// The explorer built by `bash scripts/build-explorer.sh FILE.html`, copied beside the report as explorer.html and linked from it [default: none: the report says how to build or serve it]
    #[arg(long, value_name = "FILE.html")]
    pub explorer: Option<PathBuf>,

    /// Also write the findings as a short journal comment on the note: FILE.pdf, typeset in the program (the `comment` feature), with its typst source FILE.typ and the figures it includes in FILE-figures/ beside it [default: none]
    #[arg(long, value_name = "FILE.pdf")]
    pub comment: Option<PathBuf>,

    /// The scenario every claim is judged on (the flags of `simulate`;
    /// the defaults where none is given). Claims whose check needs the
    /// default scenario say so in their verdict.
    #[command(flatten)]
    pub scenario: SlopeArgs,
}
