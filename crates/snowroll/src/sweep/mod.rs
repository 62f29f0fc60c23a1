//! Sweeps: many trajectories over a grid of parameters and models, one
//! summary row each ([`SweepRow`]), in grid order whatever the number of
//! threads.
//!
//! - [`Grid`] holds the models and one [`Axis`] per swept [`AxisParam`], each a
//!   list or a range that is never expanded into memory.
//! - [`run_chunks`] computes the rows of a range of grid indices in parallel
//!   (rayon), a chunk at a time, and hands each chunk over in order: memory
//!   stays bounded by one chunk whatever the grid's size. [`run_folded`]
//!   folds each row as it is computed (a writer into its text) and
//!   computes the next chunk while the last one is handed over.
//! - The circular models take a fast path ([`circular_end`]): their speed is
//!   a closed form in x and their time one quadrature, with no ODE solver.
//! - [`Outcome`] names what the log did in a row, and [`boundaries`] gives
//!   the closed-form borders between those regimes (stall, hop, slip), for
//!   regime maps.
//! - Each row is a pure function of its grid point, so the rows are
//!   bit-identical for any thread count, chunk size and shard split.

mod axis;
mod grid;
mod regime;
mod row;
mod row_serde;
mod run;

pub use crate::models::{circular_end, ContactCheck, FastEnd, SpeedSquared};
pub use axis::{Axis, AxisParam, DecimalRange, GridError, Values};
pub use grid::{Choices, Grid, Point, MAX_GRID_POINTS};
pub use regime::{boundaries, hop_slope_within, slip_mu, Boundary, Outcome};
pub use row::{point_warnings, AxisValues, SweepRow};
pub use run::{
    count_warnings, run_chunks, run_folded, run_point, shard_range, Method, DEFAULT_CHUNK,
    FAST_MIN_RTOL, PART_ROWS,
};
