//! The one error of writing results.

use thiserror::Error;

use crate::finite::NonFinite;

/// Writing results failed.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum OutputError {
    /// The underlying writer failed.
    #[error("writing the output failed")]
    Io(#[from] std::io::Error),
    /// CSV serialisation failed.
    #[error("writing CSV failed")]
    Csv(#[from] csv::Error),
    /// JSON serialisation failed.
    #[error("writing JSON failed")]
    Json(#[from] serde_json::Error),
    /// A row of a sweep's CSV could not be read back (to be converted).
    #[error("reading back the rows")]
    ReadBack(#[source] csv::Error),
    /// Writing Parquet failed.
    #[cfg(feature = "parquet")]
    #[error(transparent)]
    Parquet(#[from] parquet::errors::ParquetError),
    /// Building an Arrow record batch failed.
    #[cfg(feature = "parquet")]
    #[error(transparent)]
    Arrow(#[from] arrow_schema::ArrowError),
    /// A number about to be written is NaN or infinite; nothing of the
    /// record was written.
    #[error(transparent)]
    NonFinite(#[from] NonFinite),
    /// A run that records the energy ledger sent row `row` without its
    /// ledger (a bug of the model, caught before anything is written).
    #[error("row {row} of a run that records the energy ledger came without its ledger")]
    MissingLedger {
        /// The row, from 1.
        row: u64,
    },
}

/// A writer used as a [`SampleSink`](snowroll::SampleSink) ends the run with
/// its own error, kept whole.
impl From<OutputError> for snowroll::SinkError {
    fn from(e: OutputError) -> Self {
        Self::new(e)
    }
}
