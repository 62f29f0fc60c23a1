//! One output schema for every model: samples, the stop, the options.
//!
//! One file per part: `sample.rs` what each sample records, `stop.rs` how a
//! run ends, `sink.rs` where the samples go, `sampling.rs` which samples are
//! recorded, `options.rs` the options of a run and their checks, and
//! `choices.rs` the collision and hop choices. Every item is re-exported
//! here, so `crate::trajectory::X` names it whatever file holds it.

mod choices;
mod options;
mod sample;
mod sampling;
mod sink;
mod stop;

pub use choices::{CollisionModel, OnHop};
pub use options::{SimOptions, DEFAULT_MAX_ROWS};
pub use sample::{LedgerRow, Sample, TurnState};
pub use sampling::Sampling;
pub use sink::{Collected, SampleSink, Trajectory};
pub use stop::{HopDoubt, RunEnd, Stop, StopReason};
