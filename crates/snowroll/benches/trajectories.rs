//! Cost of one trajectory of every model (issue 2, "speed").
//!
//! The problem is the default scenario (α = 30°, b = 1 cm, r0 = 10 cm, from
//! rest) run to t = 100 s at rtol 1e-10, atol 1e-12 through the public
//! [`Model::simulate`], recording only the two ends ([`Sampling::Ends`]), so
//! that the figure is the cost of the integration itself. One more case
//! records every accepted step of eq. (4) ([`Sampling::Steps`]) to show what
//! recording costs.
//!
//! Run with `cargo bench -p snowroll --bench trajectories`; for a quick look,
//! append `-- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::Criterion;
use snowroll::integrate::Tolerances;
use snowroll::{Model, ModelKind, Sampling, Scenario, SimOptions};

/// End of every benchmarked run, s (the case).
const T_END: f64 = 100.0;

/// Relative tolerance of every benchmarked run (the case).
const RTOL: f64 = 1e-10;
/// Absolute tolerance of every benchmarked run, m and m/s (the case).
const ATOL: f64 = 1e-12;

/// The options of the benchmarked runs: to [`T_END`] at [`RTOL`], [`ATOL`],
/// recording as `sampling` asks.
fn options(sampling: Sampling) -> SimOptions {
    SimOptions {
        t_end: T_END,
        tolerances: Tolerances {
            rtol: RTOL,
            atol: ATOL,
            ..Tolerances::default()
        },
        sampling,
        ..SimOptions::default()
    }
}

/// One run of `model`, kept opaque to the optimiser.
fn run(model: &dyn Model, scenario: &Scenario, opts: &SimOptions) {
    let trajectory = model.simulate(black_box(scenario), black_box(opts));
    black_box(trajectory).ok();
}

fn every_model_to_100_s(c: &mut Criterion) {
    let scenario = Scenario::default();
    let ends = options(Sampling::Ends);
    let mut group = c.benchmark_group("trajectory_100s_ends");
    for kind in ModelKind::ALL {
        let model = kind.build();
        group.bench_function(kind.id(), |b| {
            b.iter(|| run(model.as_ref(), &scenario, &ends))
        });
    }
    group.finish();

    let steps = options(Sampling::Steps);
    let model = ModelKind::TorqueCm.build();
    let mut group = c.benchmark_group("trajectory_100s_steps");
    group.bench_function(ModelKind::TorqueCm.id(), |b| {
        b.iter(|| run(model.as_ref(), &scenario, &steps))
    });
    group.finish();
}

// What `criterion_group!`/`criterion_main!` expand to, written out so that
// the entry point is documented like every other item.
fn main() {
    // No plotting backend: the figures are the text report.
    let mut criterion = Criterion::default().without_plots().configure_from_args();
    every_model_to_100_s(&mut criterion);
    criterion.final_summary();
}
