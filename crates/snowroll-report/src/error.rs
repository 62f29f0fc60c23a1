//! The error of building or writing a report ([`ReportError`]), below
//! every module that builds or writes one.

use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::plot::PlotError;

/// A report that could not be built or written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ReportError {
    /// Reading or writing a file failed. The message names the file; the
    /// cause is the error's `source`, so that a chain of messages names it once.
    #[error("{}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// A figure could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A simulation behind the report failed.
    #[error(transparent)]
    Simulation(#[from] snowroll::error::SimError),
    /// JSON serialisation failed.
    #[error("JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// Writing a CSV or JSON data file failed.
    #[error(transparent)]
    Output(#[from] snowroll_io::OutputError),
    /// A data file would carry NaN or infinity.
    #[error("{figure}: {source}")]
    NonFinite {
        /// The figure or data file.
        figure: String,
        /// The number and where it is.
        source: snowroll_io::NonFinite,
    },
    /// Two figures share a name, so their files would collide.
    #[error("two figures are named {name:?}")]
    DuplicateFigure {
        /// The shared name.
        name: String,
    },
    /// The animation data cannot be played.
    #[error("animation: {reason}")]
    InvalidAnimation {
        /// What is wrong.
        reason: &'static str,
    },
}

pub(super) fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> ReportError + '_ {
    move |source| ReportError::Io {
        path: path.to_path_buf(),
        source,
    }
}
