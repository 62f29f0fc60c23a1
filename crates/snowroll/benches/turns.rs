//! 10^5 turns of the turn-by-turn model (§3.4): the cost per turn must not
//! grow with k, and 10^5 turns of `turns` must take under 1 s on one core.
//!
//! `simulate` records only the ends (the integrator with its collision
//! resets); `table` also builds the per-turn rows with the range of a in
//! every turn (the energy integral, no dense output).

use std::hint::black_box;

use criterion::Criterion;
use snowroll::{run_turns, ModelKind, Sampling, Scenario, SimOptions};

/// Turns per run.
const TURNS: u64 = 100_000;

fn options() -> SimOptions {
    SimOptions {
        turns: Some(TURNS),
        // 10^5 turns take ~2.3e4 s of simulated time with the default scenario.
        t_end: 1e9,
        sampling: Sampling::Ends,
        ..SimOptions::default()
    }
}

fn turns(c: &mut Criterion) {
    let scenario = Scenario::default();
    let opts = options();
    let mut group = c.benchmark_group("turns_1e5");
    group.sample_size(10);
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let model = kind.build();
        group.bench_function(format!("{kind}/simulate"), |b| {
            b.iter(|| black_box(model.simulate(black_box(&scenario), &opts)))
        });
        group.bench_function(format!("{kind}/table"), |b| {
            b.iter(|| black_box(run_turns(kind, black_box(&scenario), &opts)))
        });
    }
    group.finish();
}

// What `criterion_group!`/`criterion_main!` expand to, written out so that
// the generated items do not need `allow(missing_docs)`.
fn main() {
    let mut c = Criterion::default().configure_from_args();
    turns(&mut c);
    c.final_summary();
}
