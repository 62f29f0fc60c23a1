//! Runs one model N times on the issue-2 speed case and prints the time per
//! trajectory: the Rust half of `bench/compare.sh` (the SciPy half is
//! `bench/peer_scipy.py`, which integrates the same eq. (4)).
//!
//! The case: α = 30°, b = 0.01 m, r0 = 0.1 m, g = 9.81 m/s², from rest, to
//! t = 100 s, rtol 1e-10, atol 1e-12, through the public [`Model::simulate`]
//! recording only the two ends. Each trajectory is timed on its own; the
//! median is robust to other work on a shared machine, and the mean
//! (total / N) is printed beside it.
//!
//! ```text
//! cargo run --release -p snowroll --example batch -- [--model torque-cm] [--n 1000]
//! ```
//!
//! For the drag-only models (eq. (4), eq. (6), eq. (32), `loney`) the final
//! speed is checked against the closed form of fn. 4 (generalised in
//! [`DragOnlyClosedForm`]), so a fast wrong answer cannot pass unnoticed.

use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

use snowroll::integrate::Tolerances;
use snowroll::{DragOnlyClosedForm, ModelKind, Sampling, Scenario, SimOptions};

/// End of every run, s.
const T_END: f64 = 100.0;
/// Relative tolerance of the runs (the issue's case).
const RTOL: f64 = 1e-10;
/// Absolute tolerance of the runs, m and m/s (the issue's case).
const ATOL: f64 = 1e-12;
/// Untimed runs first, to fault in code and warm caches and the CPU clock.
const WARM_UP_RUNS: usize = 20;

/// Command line: `--model ID` (id or alias, default `torque-cm`), `--n N` (default 1000).
struct Args {
    model: ModelKind,
    n: usize,
}

fn parse_args() -> Result<Args, Box<dyn Error>> {
    let mut args = Args {
        model: ModelKind::TorqueCm,
        n: 1000,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--model" => args.model = value()?.parse()?,
            "--n" => {
                args.n = value()?.parse()?;
                if args.n == 0 {
                    return Err("--n must be at least 1".into());
                }
            }
            "-h" | "--help" => {
                println!("usage: batch [--model ID] [--n N]");
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument {other:?} (try --help)").into()),
        }
    }
    Ok(args)
}

fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = parse_args()?;
    let scenario = Scenario::default();
    let opts = SimOptions {
        t_end: T_END,
        tolerances: Tolerances {
            rtol: RTOL,
            atol: ATOL,
            ..Tolerances::default()
        },
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    let model = args.model.build();

    for _ in 0..WARM_UP_RUNS {
        black_box(model.simulate(black_box(&scenario), black_box(&opts))?);
    }
    let mut times = Vec::with_capacity(args.n);
    let mut last = None;
    let total = Instant::now();
    for _ in 0..args.n {
        let start = Instant::now();
        let trajectory = model.simulate(black_box(&scenario), black_box(&opts))?;
        times.push(start.elapsed().as_secs_f64());
        last = Some(black_box(trajectory));
    }
    let total = total.elapsed().as_secs_f64();
    let trajectory = last.ok_or("no run")?;
    times.sort_by(f64::total_cmp);
    let per_trajectory = median(&times);

    let end = trajectory.samples.last().ok_or("no samples")?;
    let stats = trajectory.stats;
    println!(
        "snowroll {} ({}): alpha 30 deg, b 0.01 m, r0 0.1 m, from rest, t = 0..{T_END} s, \
         rtol {RTOL:e}, atol {ATOL:e}, N = {}",
        args.model.id(),
        args.model.equation(),
        args.n
    );
    println!(
        "steps {} accepted, {} rejected, {} RHS evaluations, {} Taylor coefficients (orders \
         summed over the steps) per trajectory",
        stats.accepted, stats.rejected, stats.evaluations, stats.taylor_terms
    );
    println!(
        "final t = {} s, x = {:.15e} m, v = {:.15e} m/s ({})",
        trajectory.stop.t_s,
        end.x_m,
        end.v_m_s,
        trajectory.stop.reason.describe()
    );
    // The closed form applies to the models whose only snow term is the drag.
    let drag_only = match args.model {
        ModelKind::Loney => ModelKind::TorqueCm.derivation(),
        kind => kind.derivation(),
    }
    .map(|d| d.coefficients())
    .filter(|c| c.accretes && c.lift == 0.0 && c.lift_b2 == 0.0 && c.inertia_b2 == 0.0);
    if let Some(c) = drag_only {
        let v_exact = DragOnlyClosedForm::new(&scenario, c.drag)?.speed(end.x_m);
        println!(
            "closed form (fn. 4) at that x: v = {v_exact:.15e} m/s, relative difference {:.2e}",
            (end.v_m_s - v_exact).abs() / v_exact
        );
    }
    println!(
        "per trajectory: median {:.2} us, mean (total/N) {:.2} us, min {:.2} us",
        per_trajectory * 1e6,
        total / args.n as f64 * 1e6,
        times[0] * 1e6
    );
    // For bench/compare.sh.
    println!("per_trajectory_s={per_trajectory:e}");
    Ok(())
}
