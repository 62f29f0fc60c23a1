//! The parallel runner: rows of a range of grid indices, in order, a chunk
//! at a time.

use std::ops::Range;

use rayon::prelude::*;

use super::grid::Grid;
use super::row::SweepRow;
use crate::error::ParamError;

/// Rows computed (and held in memory) at a time: large enough that the
/// threads rarely wait on one another at a chunk's end, small enough that a
/// chunk costs a few megabytes and, for slow models, seconds of progress.
pub const DEFAULT_CHUNK: usize = 8192;

/// The row of grid point `index`. A point whose run fails is a row with
/// the error in its `error` column.
///
/// # Errors
/// [`ParamError`] when `index` is not a point of the grid.
pub fn run_point(grid: &Grid, index: u64) -> Result<SweepRow, ParamError> {
    let point = grid.point(index)?;
    let traj = point
        .model
        .build()
        .simulate(&point.scenario, &point.options)
        .map_err(|e| e.to_string());
    Ok(SweepRow::new(&point, traj.as_ref().map_err(Clone::clone)))
}

/// The grid indices of shard `shard` (from 0) of `shards`: the grid cut into
/// `shards` contiguous slices whose sizes differ by at most one, so that the
/// shards in order are the whole grid in order.
///
/// # Errors
/// A message when `shards` is 0 or `shard >= shards`.
pub fn shard_range(len: u64, shard: u64, shards: u64) -> Result<Range<u64>, String> {
    if shards == 0 || shard >= shards {
        return Err(format!(
            "shard {shard} of {shards}: expected 0 <= i < N and N >= 1"
        ));
    }
    let cut = |k: u64| (u128::from(len) * u128::from(k) / u128::from(shards)) as u64;
    Ok(cut(shard)..cut(shard + 1))
}

/// Computes the rows of `indices` in parallel on the current rayon pool, and
/// passes them to `emit` in grid order, at most `chunk` at a time. Stops at
/// the first error and returns it.
///
/// # Errors
/// What `emit` returns, and [`ParamError`] for indices outside the grid.
pub fn run_chunks<E: From<ParamError>>(
    grid: &Grid,
    indices: Range<u64>,
    chunk: usize,
    mut emit: impl FnMut(&[SweepRow]) -> Result<(), E>,
) -> Result<(), E> {
    let chunk = chunk.max(1) as u64;
    let mut start = indices.start;
    while start < indices.end {
        let n = chunk.min(indices.end - start);
        let rows: Vec<SweepRow> = (0..n as usize)
            .into_par_iter()
            .map(|k| run_point(grid, start + k as u64))
            .collect::<Result<_, ParamError>>()
            .map_err(E::from)?;
        emit(&rows)?;
        start += n;
    }
    Ok(())
}
