//! What a call may hold in memory, and Ctrl-C while it runs (issue 20,
//! item 6): a call whose result cannot fit in `max_memory` is refused before
//! it starts where its row count is known, stopped with `MemoryError` where
//! it is not, and a pending signal (`KeyboardInterrupt`) ends the run within
//! [`SIGNAL_CHECK`] of the next row instead of when the call returns.
//!
//! The rows are counted by sinks that wrap the library's own collectors
//! ([`GuardedSamples`], [`GuardedTurns`]); the sweep counts its chunks.

use std::mem::size_of;
use std::time::{Duration, Instant};

use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use snowroll::error::SinkError;
use snowroll::trajectory::{Collected, Sample, SampleSink, TurnState};
use snowroll::LedgerRow;
use snowroll::{TurnRow, TurnSink};

/// The default of the `max_memory` keyword, bytes: 2 GiB, a tenth of a
/// common workstation's memory and more than any run of the defaults needs
/// (10^6 turns hold about 0.3 GB).
pub(crate) const MAX_MEMORY_DEFAULT: u64 = 2 << 30;

/// How often a running call looks for a signal: a tenth of a second keeps
/// Ctrl-C prompt, and re-taking the interpreter's lock that rarely costs
/// nothing measurable.
const SIGNAL_CHECK: Duration = Duration::from_millis(100);

/// Bytes a row of each result holds until the call returns: the library's
/// row, the ledger row, and one float per numpy column made from them.
pub(crate) fn sample_bytes() -> u64 {
    (size_of::<Sample>() + size_of::<TurnState>() + size_of::<LedgerRow>() + 8 * 21) as u64
}

/// As [`sample_bytes`], for a row of a turn table.
pub(crate) fn turn_bytes() -> u64 {
    (size_of::<TurnRow>() + size_of::<LedgerRow>() + 8 * 24) as u64
}

/// The guard of one call.
pub(crate) struct Guard {
    limit: u64,
    per_row: u64,
    rows: u64,
    last_check: Instant,
    /// Why the run was stopped, raised when the call returns.
    stop: Option<PyErr>,
}

/// The error a guarded sink hands the library to end the run; the Python
/// error behind it is kept in the guard.
#[derive(Debug)]
struct Stopped(&'static str);

impl std::fmt::Display for Stopped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "stopped by the Python call's guard: {}", self.0)
    }
}

impl std::error::Error for Stopped {}

impl Guard {
    /// A guard of `limit` bytes for rows of `per_row` bytes each.
    pub(crate) fn new(limit: u64, per_row: u64) -> Self {
        Self {
            limit,
            per_row,
            rows: 0,
            last_check: Instant::now(),
            stop: None,
        }
    }

    /// The `MemoryError` for `rows` rows.
    fn too_big(&self, rows: f64, what: &str) -> PyErr {
        PyMemoryError::new_err(format!(
            "{what} would hold about {rows:.3e} rows of {} bytes, {:.2} GB, more than max_memory = {} bytes ({:.2} GB); \
             raise max_memory, or ask for fewer rows (a coarser dt, fewer turns, a shard of the grid)",
            self.per_row,
            rows * self.per_row as f64 / 1e9,
            self.limit,
            self.limit as f64 / 1e9,
        ))
    }

    /// Refuses, before the run, a result of `rows` rows that cannot fit.
    pub(crate) fn check_up_front(&self, rows: f64, what: &str) -> PyResult<()> {
        if rows * self.per_row as f64 > self.limit as f64 {
            return Err(self.too_big(rows, what));
        }
        Ok(())
    }

    /// Counts `n` more rows: an error ends the run when they do not fit or
    /// a signal is pending.
    pub(crate) fn rows(&mut self, n: u64, what: &str) -> Result<(), SinkError> {
        self.rows += n;
        if self.rows.saturating_mul(self.per_row) > self.limit {
            self.stop = Some(self.too_big(self.rows as f64, what));
            return Err(SinkError::new(Stopped("max_memory")));
        }
        if self.last_check.elapsed() >= SIGNAL_CHECK {
            self.last_check = Instant::now();
            if let Err(e) = Python::attach(|py| py.check_signals()) {
                self.stop = Some(e);
                return Err(SinkError::new(Stopped("signal")));
            }
        }
        Ok(())
    }

    /// The result of the call: the guard's own error first (the library's
    /// is then only the sink error it caused), else `r` mapped by `err`.
    pub(crate) fn outcome<T, E>(
        self,
        r: Result<T, E>,
        err: impl FnOnce(E) -> PyErr,
    ) -> PyResult<T> {
        match self.stop {
            Some(e) => Err(e),
            None => r.map_err(err),
        }
    }
}

/// The samples of a run, gathered as the library's [`Collected`] does,
/// under a [`Guard`].
pub(crate) struct GuardedSamples {
    pub(crate) collected: Collected,
    pub(crate) guard: Guard,
}

impl SampleSink for GuardedSamples {
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError> {
        self.guard.rows(1, "simulate()")?;
        self.collected.sample(sample, turn)
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.collected.ledger(row)
    }
}

/// The rows of a turn table and their ledger, under a [`Guard`].
pub(crate) struct GuardedTurns {
    pub(crate) rows: Vec<TurnRow>,
    pub(crate) ledger: Vec<LedgerRow>,
    pub(crate) guard: Guard,
}

impl TurnSink for GuardedTurns {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.guard.rows(1, "turns()")?;
        self.rows.push(*row);
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.ledger.push(*row);
        Ok(())
    }
}
