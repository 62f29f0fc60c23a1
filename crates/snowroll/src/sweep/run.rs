//! The parallel runner: rows of a range of grid indices, in order, a chunk
//! at a time.

use std::ops::Range;

use rayon::prelude::*;

use super::grid::{Grid, Point};
use super::row::SweepRow;
use super::row::{circular_turns, point_warnings};
use crate::error::ParamError;
use crate::models::{circular_end, circular_forces, ContactCheck, Derivation, ModelKind};
use crate::physics;
use crate::trajectory::Sample;

/// Rows computed (and held in memory) at a time: large enough that the
/// threads rarely wait on one another at a chunk's end, small enough that a
/// chunk costs a few megabytes and, for slow models, seconds of progress.
pub const DEFAULT_CHUNK: usize = 8192;

/// How the rows of the circular models are computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Method {
    /// The closed form of [`circular_end`] where it applies (a circular
    /// model that does not come near a stall, rtol ≥ [`FAST_MIN_RTOL`]),
    /// the ODE elsewhere.
    #[default]
    #[cfg_attr(
        feature = "clap",
        value(
            help = "The closed form of the circular models where it applies (a run that does not come near a stall, --rtol at least 1e-12), the ODE elsewhere"
        )
    )]
    Auto,
    /// The model's own `simulate` for every row (the ODE for the circular
    /// models): for comparisons and benchmarks.
    Ode,
}

/// Smallest rtol for which the fast path stands in for the ODE: its own
/// accuracy is about 1e-12 (the quadrature's 1e-13 per panel, summed).
pub const FAST_MIN_RTOL: f64 = 1e-12;

/// The row of grid point `index`. A point whose run fails is a row with
/// the error in its `error` column.
///
/// # Errors
/// [`ParamError`] when `index` is not a point of the grid.
pub fn run_point(grid: &Grid, index: u64, method: Method) -> Result<SweepRow, ParamError> {
    let point = grid.point(index)?;
    let fast = (method == Method::Auto).then(|| fast_row(&point)).flatten();
    let row = fast.unwrap_or_else(|| {
        let traj = point
            .model
            .build()
            .simulate(&point.scenario, &point.options)
            .map_err(|e| e.to_string());
        SweepRow::new(&point, traj.as_ref().map_err(Clone::clone))
    });
    Ok(row.finite_or_error())
}

/// The row of a circular model from the closed form, or `None` where it
/// does not apply.
fn fast_row(point: &Point) -> Option<SweepRow> {
    let o = &point.options;
    let s = &point.scenario;
    // The closed form knows no losses (`docs/snowball-and-losses.md` §2).
    // Loney's closed form is eq. (4) on the scenario's body (the ball too,
    // on its natural swath: [`crate::LoneyModel`] runs the same solver);
    // the ball's circular models take the ODE path.
    let c = match point.model {
        ModelKind::Loney => Derivation::TorqueAboutCentre.coefficients_for(s.shape()),
        _ if s.shape() != crate::scenario::Shape::Cylinder => return None,
        kind => kind.derivation()?.coefficients(),
    };
    if o.tolerances.rtol < FAST_MIN_RTOL || o.losses.records_ledger() {
        return None;
    }
    let contact = ContactCheck {
        stop_on_hop: o.on_hop == crate::trajectory::OnHop::Stop,
        mu: o.mu,
    };
    let end = circular_end(&c, s, o.t_end, o.x_end, contact)?;
    let (r, mass_kg) = if c.accretes {
        (physics::radius_at(s, end.x), physics::mass_at(s, end.x))
    } else {
        (s.initial_radius(), s.initial_mass())
    };
    let a = c.acceleration(s, end.x, end.v);
    let forces = circular_forces(&c, s, end.x, end.v, a);
    let sample = Sample {
        t_s: end.t,
        x_m: end.x,
        v_m_s: end.v,
        a_m_s2: a,
        r_m: r,
        mass_kg,
        normal_n: forces.normal_n,
        friction_n: forces.friction_n,
        friction_ratio: forces.friction_ratio(),
    };
    let mut row = SweepRow::parameters(point);
    row.set_results(
        point,
        end.reason,
        &sample,
        circular_turns(end.x, r, s.initial_radius()),
    );
    Some(row)
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

/// How many of the points of `indices` have warnings ([`point_warnings`]):
/// the count a sweep's header records, known before any point is run since
/// the warnings depend on the point only.
///
/// # Errors
/// [`ParamError`] for indices outside the grid.
pub fn count_warnings(grid: &Grid, indices: Range<u64>) -> Result<u64, ParamError> {
    indices
        .into_par_iter()
        .map(|i| Ok(u64::from(point_warnings(&grid.point(i)?).is_some())))
        .sum()
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
    method: Method,
    mut emit: impl FnMut(&[SweepRow]) -> Result<(), E>,
) -> Result<(), E> {
    let chunk = chunk.max(1) as u64;
    let mut start = indices.start;
    while start < indices.end {
        let n = chunk.min(indices.end - start);
        let rows: Vec<SweepRow> = (0..n as usize)
            .into_par_iter()
            .map(|k| run_point(grid, start + k as u64, method))
            .collect::<Result<_, ParamError>>()
            .map_err(E::from)?;
        emit(&rows)?;
        start += n;
    }
    Ok(())
}

/// Rows of one task of [`run_folded`]: enough to make a task's overhead
/// small, few enough that both threads stay busy to a chunk's end.
pub const PART_ROWS: usize = 512;

/// Computes the rows of `indices` in parallel on the current rayon pool and
/// folds them in grid order, `part` rows to a task: each task starts from
/// `init()` and hands each row, as it is computed, to `fold` (the row is
/// not kept). The tasks' results go to `emit` in grid order, a chunk of at
/// most `chunk` rows at a time, with the chunk's number of rows; while
/// `emit` takes one chunk, the pool computes the next. Stops at the first
/// error and returns it (the chunks before it emitted, as with
/// [`run_chunks`]).
///
/// A sweep's writer folds each row into its text: no chunk of rows is held
/// in memory, and the pool does not wait while a chunk is written.
///
/// # Errors
/// What `fold` or `emit` returns, and [`ParamError`] for indices outside
/// the grid.
#[allow(clippy::too_many_arguments)]
pub fn run_folded<T, E>(
    grid: &Grid,
    indices: Range<u64>,
    (chunk, part): (usize, usize),
    method: Method,
    init: impl Fn() -> T + Sync,
    fold: impl Fn(&mut T, &SweepRow) -> Result<(), E> + Sync,
    mut emit: impl FnMut(Vec<T>, u64) -> Result<(), E> + Send,
) -> Result<(), E>
where
    T: Send,
    E: From<ParamError> + Send,
{
    let (chunk, part) = (chunk.max(1) as u64, part.max(1) as u64);
    let compute = |range: Range<u64>| -> Result<Vec<T>, E> {
        let parts = (range.end - range.start).div_ceil(part);
        (0..parts)
            .into_par_iter()
            .map(|k| {
                let lo = range.start + k * part;
                let mut acc = init();
                for i in lo..(lo + part).min(range.end) {
                    fold(&mut acc, &run_point(grid, i, method)?)?;
                }
                Ok(acc)
            })
            .collect()
    };
    let mut start = indices.start;
    let mut pending: Option<(Vec<T>, u64)> = None;
    loop {
        let next = (start < indices.end).then(|| {
            let n = chunk.min(indices.end - start);
            start += n;
            start - n..start
        });
        if next.is_none() && pending.is_none() {
            return Ok(());
        }
        let (written, computed) = rayon::join(
            || pending.take().map_or(Ok(()), |(parts, n)| emit(parts, n)),
            || {
                next.map(|r| compute(r.clone()).map(|p| (p, r.end - r.start)))
                    .transpose()
            },
        );
        written?;
        pending = computed?;
    }
}

#[cfg(all(test, feature = "clap"))]
mod help_tests {
    use super::*;
    use clap::ValueEnum;

    /// The `--method auto` help quotes the fast path's smallest rtol: it must
    /// be the constant the runner uses.
    #[test]
    fn auto_help_quotes_the_fast_paths_smallest_rtol() {
        let help = Method::Auto
            .to_possible_value()
            .and_then(|v| v.get_help().map(ToString::to_string))
            .unwrap_or_default();
        assert!(help.contains(&format!("{FAST_MIN_RTOL:e}")), "{help}");
    }
}
