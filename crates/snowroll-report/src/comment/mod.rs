//! `snowroll paper --comment FILE.pdf`: the findings as a short journal
//! comment on McDonald's note, typeset in the program by typst (feature
//! `comment`; no TeX, no network, no system font).
//!
//! [`Comment::new`] composes the typst source from a [`Report`]: its words
//! are this module's, its numbers are read from the claims' outcomes and the
//! report's parameters ([`numbers`]), and each sentence that states a
//! verdict is chosen by a `match` on that verdict, so a run whose check
//! reaches another verdict says something else. Four of the report's
//! figures are included as SVG (vector in the PDF), drawn with their
//! parameters in the note's symbols. [`Comment::pdf`] compiles the source
//! ([`world`]): a warning of the compiler is an error, and the PDF has a
//! fixed identifier and no date, so the same run gives the same bytes.
//! [`Comment::write`] writes the PDF, its source (`NAME.typ`) and the
//! figures the source includes (`NAME-figures/`) beside each other.

mod errata;
mod markup;
mod numbers;
mod sections;
mod text;
mod world;

use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::plot::Provenance;
use crate::{ClaimId, Report, ReportError};

/// A comment that could not be composed, typeset or written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum CommentError {
    /// The report has no result for a claim the comment discusses.
    #[error("the report has no result for the claim {claim}")]
    MissingClaim {
        /// The claim.
        claim: ClaimId,
    },
    /// A claim's measured text has no number where the comment reads one.
    #[error("the measured text of claim {claim} has no number after {label:?}")]
    MissingNumber {
        /// The claim.
        claim: ClaimId,
        /// The text the number should follow.
        label: String,
    },
    /// The report's metadata lacks a parameter the comment states.
    #[error("the report records no parameter {key}")]
    MissingParam {
        /// The parameter's key.
        key: String,
    },
    /// The report lacks a figure the comment includes.
    #[error("the report has no figure {name}")]
    MissingFigure {
        /// The figure's name.
        name: &'static str,
    },
    /// The typst compiler reported errors or warnings.
    #[error("typesetting the comment: {}", messages.join("; "))]
    Typeset {
        /// One message per diagnostic, with its line in the source.
        messages: Vec<String>,
    },
    /// A figure could not be drawn or a file not written.
    #[error(transparent)]
    Report(#[from] ReportError),
}

/// A figure as the text refers to it and as the source includes it.
#[derive(Debug, Clone)]
struct FigureRef {
    /// The label the text cites (`@fig-…`).
    label: String,
    /// The `#figure(…)` markup.
    markup: String,
}

/// The report's figures the comment shows, in order, each with its caption
/// (our words; the numbers are on the figure's axes and in the text).
const FIGURES: [(&str, &str); 4] = [
    (
        "acceleration-all-models",
        "Acceleration of the log in units of $G$ against time, for every model of the program on the run's slope: the four circular analyses of §2 (and their variants) level off at four different values; the turn-by-turn models are shown by their mean per turn.",
    ),
    (
        "turns-long-run-means",
        "Mean acceleration of the turn-by-turn log over its late turns, within the turns and with the collisions counted, against the number of turns completed; the horizontal lines mark the note's $4G\\/9$ of eq. (79) and the two limits derived for the model.",
    ),
    (
        "regime-map-turns",
        "What the turn-by-turn log started from rest does over slope and snow depth: it stalls in its first turn, rolls on, or hops; the lines are the closed-form stall slope of footnote 7 and the late-turn hop slope of footnote 10.",
    ),
    (
        "snowball-acceleration",
        "Acceleration of an always-round snowball in units of $G$ against time, for each circular analysis applied to a ball on the same slope.",
    ),
];

/// The comment on the note, as typst source and the figures it includes.
#[derive(Debug, Clone, PartialEq)]
pub struct Comment {
    /// The typst source.
    pub source: String,
    /// The figures the source includes: `(name, SVG)`, included from the
    /// folder [`Comment::figures_dir`] names.
    pub figures: Vec<(String, String)>,
    /// The folder of the figures, relative to the source.
    figures_dir: String,
}

/// A figure's parameters in the note's symbols, for the line under it.
fn symbol_params(params: &[(String, String)]) -> Vec<(String, String)> {
    params
        .iter()
        .map(|(k, v)| {
            let (key, unit) = match k.as_str() {
                "alpha_deg" => ("α", "°"),
                "snow_depth" => ("b", " m"),
                "r0" => ("r₀", " m"),
                "v0" => ("v₀", " m/s"),
                "g" => ("g", " m/s²"),
                "density" => ("ρ", " kg/m³"),
                "length" => ("l", " m"),
                "rtol" => ("relative tolerance", ""),
                other => (other, ""),
            };
            (key.replace('_', " "), format!("{v}{unit}"))
        })
        .collect()
}

impl Comment {
    /// The comment on `report`, whose figures are included from the
    /// folder `figures_dir` (relative to the source).
    ///
    /// # Errors
    /// [`CommentError`] when the report lacks a claim, a number, a
    /// parameter or a figure the comment needs, or a figure cannot be drawn.
    pub fn new(report: &Report, figures_dir: &str) -> Result<Self, CommentError> {
        let version = report
            .metadata
            .software
            .strip_prefix("snowroll ")
            .unwrap_or(&report.metadata.software)
            .to_string();
        let mut figures = Vec::new();
        let mut refs = Vec::new();
        for (name, caption) in FIGURES {
            let figure = report
                .figures
                .iter()
                .find(|f| f.chart.name == name)
                .ok_or(CommentError::MissingFigure { name })?;
            let prov = figure.provenance(&report.metadata);
            let prov = Provenance {
                software: prov.software,
                params: symbol_params(&prov.params),
            };
            let mut chart = figure.chart.clone();
            for series in &mut chart.series {
                series.name = markup::legend(&series.name);
            }
            let svg = chart.render_svg(&prov).map_err(ReportError::from)?;
            let file = format!("{name}.svg");
            refs.push(FigureRef {
                label: format!("fig-{name}"),
                markup: format!(
                    "#figure(\n  placement: auto,\n  {{\n    set text(font: \"DejaVu Sans\")\n    image(\"{figures_dir}/{file}\", width: 100%)\n  }},\n  caption: [{caption}],\n) <fig-{name}>"
                ),
            });
            figures.push((file, svg));
        }
        let mut source = String::new();
        text::preamble(&mut source, &version);
        text::abstract_(&mut source, report)?;
        text::introduction(&mut source, report)?;
        text::circular(&mut source, report, &refs[0])?;
        sections::turn_model(&mut source, report, &refs[1])?;
        sections::open_questions(&mut source, report, &refs[2], &refs[3])?;
        sections::all_claims(&mut source, report);
        errata::errata_section(&mut source);
        sections::references(&mut source, &version);
        Ok(Self {
            source,
            figures,
            figures_dir: figures_dir.to_string(),
        })
    }

    /// The folder the source includes its figures from.
    pub fn figures_dir(&self) -> &str {
        &self.figures_dir
    }

    /// The PDF, typeset in the program.
    ///
    /// # Errors
    /// [`CommentError::Typeset`] for any error or warning of the compiler.
    pub fn pdf(&self) -> Result<Vec<u8>, CommentError> {
        let files = self
            .figures
            .iter()
            .map(|(file, svg)| {
                (
                    format!("{}/{file}", self.figures_dir),
                    svg.clone().into_bytes(),
                )
            })
            .collect();
        world::CommentWorld::new(self.source.clone(), files).pdf()
    }
}

/// Writes the comment on `report` as `pdf` (a path ending in `.pdf`), its
/// typst source beside it (same name, `.typ`) and the figures the source
/// includes in the folder `NAME-figures/` beside them; returns the paths
/// written. Each file is written whole under a temporary name and renamed
/// into place.
///
/// # Errors
/// [`CommentError`] when the comment cannot be composed or typeset, or a
/// file cannot be written.
pub fn write_comment(report: &Report, pdf: &Path) -> Result<Vec<PathBuf>, CommentError> {
    let stem = pdf
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "comment".to_string());
    let figures_dir = format!("{stem}-figures");
    let comment = Comment::new(report, &figures_dir)?;
    let bytes = comment.pdf()?;
    let dir = pdf.parent().unwrap_or(Path::new(""));
    let fig_dir = dir.join(&figures_dir);
    std::fs::create_dir_all(&fig_dir).map_err(|source| ReportError::Io {
        path: fig_dir.clone(),
        source,
    })?;
    let mut written = Vec::new();
    for (file, svg) in &comment.figures {
        let path = fig_dir.join(file);
        crate::files::write_atomic(&path, svg.as_bytes())?;
        written.push(path);
    }
    let typ = pdf.with_extension("typ");
    crate::files::write_atomic(&typ, comment.source.as_bytes())?;
    written.push(typ);
    crate::files::write_atomic(pdf, &bytes)?;
    written.push(pdf.to_path_buf());
    Ok(written)
}
