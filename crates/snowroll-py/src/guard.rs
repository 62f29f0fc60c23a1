//! What a call may hold in memory, and Ctrl-C while it runs (issue 20,
//! item 6): a call whose result cannot fit in `max_memory` is refused before
//! it starts where its row count is known, stopped with `MemoryError` where
//! it is not, and a pending signal (`KeyboardInterrupt`) ends the run within
//! [`SIGNAL_CHECK`] of the next row instead of when the call returns.
//!
//! The rows are counted by sinks that wrap the library's own collectors
//! ([`GuardedSamples`], [`GuardedTurns`]); the sweep counts its chunks.
//!
//! A `max_memory` raised past what the machine has must still end in
//! `MemoryError`, never in an aborted interpreter (issue 33, item 3: Rust's
//! infallible allocation aborts the process, rc 134, a dead Jupyter kernel).
//! So every buffer of a result is allocated fallibly ([`grow`],
//! [`try_vec`]), and each growth, and each count known up front, is first
//! compared with the memory the machine has available ([`available_memory`]):
//! with the kernel's overcommit a reservation larger than what is free may
//! succeed and the process be killed later when it touches the pages.

use std::mem::size_of;
use std::time::{Duration, Instant};

use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use snowroll::error::SinkError;
use snowroll::trajectory::{Collected, Sample, SampleSink, TurnState};
use snowroll::LedgerRow;
use snowroll::{TurnRow, TurnSink};
use std::collections::TryReserveError;

/// The default of the `max_memory` keyword, bytes: 2 GiB, a tenth of a
/// common workstation's memory and more than any run of the defaults needs
/// (10^6 turns hold about 0.3 GB).
pub(crate) const MAX_MEMORY_DEFAULT: u64 = 2 << 30;

/// How often a running call looks for a signal: a tenth of a second keeps
/// Ctrl-C prompt, and re-taking the interpreter's lock that rarely costs
/// nothing measurable.
const SIGNAL_CHECK: Duration = Duration::from_millis(100);

/// Rows of a turn table between two reads of the clock for
/// [`SIGNAL_CHECK`] (a read cost about as much as keeping the row, a third
/// of a `turns(100)` call's overhead). A turn is one integration of
/// eq. (64) over 2π, microseconds, so 64 of them stay far below a tenth of
/// a second. A trajectory's rows read it every row: one requested time may
/// be far from the last.
pub(crate) const TURN_ROWS_PER_CLOCK: u64 = 64;

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
    /// Bytes held besides the rows' `per_row` each.
    extra: u64,
    last_check: Instant,
    /// Rows counted since the clock was last read.
    unclocked: u64,
    /// Rows between two reads of the clock (1: every row).
    clock_every: u64,
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
            extra: 0,
            last_check: Instant::now(),
            unclocked: 0,
            clock_every: 1,
            stop: None,
        }
    }

    /// The guard reading the clock only every `rows` rows.
    pub(crate) fn with_clock_every(mut self, rows: u64) -> Self {
        self.clock_every = rows.max(1);
        self
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

    /// Refuses, before the run, a result of `rows` rows that cannot fit in
    /// `max_memory`, or in the memory the machine has available.
    pub(crate) fn check_up_front(&self, rows: f64, what: &str) -> PyResult<()> {
        let bytes = rows * self.per_row as f64;
        if bytes > self.limit as f64 {
            return Err(self.too_big(rows, what));
        }
        if let Some(free) = (bytes > CHECK_FROM as f64).then(available_memory).flatten() {
            if bytes > free as f64 {
                return Err(PyMemoryError::new_err(format!(
                    "{what} would hold about {rows:.3e} rows of {} bytes, {:.2} GB, more than this machine has \
                     available ({:.2} GB); ask for fewer rows (a coarser dt, fewer turns, a shard of the grid)",
                    self.per_row,
                    bytes / 1e9,
                    free as f64 / 1e9,
                )));
            }
        }
        Ok(())
    }

    /// Records `e` as the reason the run stopped, for [`Guard::outcome`],
    /// and returns the sink error that ends the library's run.
    pub(crate) fn stop_with(&mut self, e: PyErr) -> SinkError {
        self.stop = Some(e);
        SinkError::new(Stopped("memory"))
    }

    /// Counts `bytes` more held besides the rows' own (a failed sweep row's
    /// message): an error ends the run when the whole does not fit.
    pub(crate) fn bytes(&mut self, bytes: u64, what: &str) -> Result<(), SinkError> {
        self.extra = self.extra.saturating_add(bytes);
        self.rows(0, what)
    }

    /// Counts `n` more rows: an error ends the run when they do not fit or
    /// a signal is pending.
    pub(crate) fn rows(&mut self, n: u64, what: &str) -> Result<(), SinkError> {
        self.rows += n;
        if self
            .rows
            .saturating_mul(self.per_row)
            .saturating_add(self.extra)
            > self.limit
        {
            self.stop = Some(self.too_big(self.rows as f64, what));
            return Err(SinkError::new(Stopped("max_memory")));
        }
        // The clock is read every `clock_every` rows.
        self.unclocked += n;
        if self.unclocked < self.clock_every {
            return Ok(());
        }
        self.unclocked = 0;
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
        let room = grow(&mut self.collected.samples, "simulate()").and_then(|()| match turn {
            Some(_) => grow(&mut self.collected.turn_states, "simulate()"),
            None => Ok(()),
        });
        room.map_err(|e| self.guard.stop_with(e))?;
        self.collected.sample(sample, turn)
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        grow(&mut self.collected.ledger, "simulate()").map_err(|e| self.guard.stop_with(e))?;
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
        grow(&mut self.rows, "turns()").map_err(|e| self.guard.stop_with(e))?;
        self.rows.push(*row);
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        grow(&mut self.ledger, "turns()").map_err(|e| self.guard.stop_with(e))?;
        self.ledger.push(*row);
        Ok(())
    }
}

/// Below this many bytes an allocation is not compared with the memory
/// available (reading it costs a few file reads, too much for every small
/// call; an allocation this small cannot be what exhausts a machine).
const CHECK_FROM: u64 = 64 << 20;

/// Bytes this process may still take: the kernel's `MemAvailable`
/// (`/proc/meminfo`), or less when a cgroup (v2) limit leaves less
/// (`memory.max` less `memory.current`); `None` where neither can be read
/// (not Linux), and then only the allocations themselves can fail.
pub(crate) fn available_memory() -> Option<u64> {
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok();
    let free = meminfo.as_deref().and_then(|text| {
        let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
        let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
        kib.checked_mul(1024)
    });
    let read = |name: &str| -> Option<u64> {
        std::fs::read_to_string(format!("/sys/fs/cgroup/{name}"))
            .ok()?
            .trim()
            .parse()
            .ok()
    };
    let cgroup =
        read("memory.max").map(|max| max.saturating_sub(read("memory.current").unwrap_or(0)));
    match (free, cgroup) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// The `MemoryError` of an allocation of `bytes` that failed.
pub(crate) fn alloc_failed(what: &str, bytes: u64, why: &dyn std::fmt::Display) -> PyErr {
    PyMemoryError::new_err(format!(
        "{what} could not allocate {:.2} GB for its result ({why}); ask for fewer rows \
         (a coarser dt, fewer turns, a shard of the grid)",
        bytes as f64 / 1e9
    ))
}

/// Makes room for one more item in `v` without aborting: where `v` is full
/// it doubles (at least 64 items), after checking that the machine has the
/// bytes available, with a fallible reservation.
pub(crate) fn grow<T>(v: &mut Vec<T>, what: &str) -> PyResult<()> {
    if v.len() < v.capacity() {
        return Ok(());
    }
    let more = v.capacity().max(64);
    let bytes = (more as u64).saturating_mul(size_of::<T>() as u64);
    if let Some(free) = (bytes > CHECK_FROM).then(available_memory).flatten() {
        if bytes > free {
            return Err(alloc_failed(
                what,
                bytes,
                &format_args!("{:.2} GB available on this machine", free as f64 / 1e9),
            ));
        }
    }
    v.try_reserve(more)
        .map_err(|e: TryReserveError| alloc_failed(what, bytes, &e))
}

/// An empty vector with room for exactly `n` items, allocated fallibly.
pub(crate) fn try_vec<T>(n: usize, what: &str) -> PyResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|e| alloc_failed(what, (n as u64).saturating_mul(size_of::<T>() as u64), &e))?;
    Ok(v)
}
