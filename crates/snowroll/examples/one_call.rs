//! One `simulate` call through the Rust API, timed N times: the library's
//! own time per call, the Rust half of `bench/python_overhead.py` (the
//! Python half is `snowroll.simulate` or `snowroll.turns` with the same
//! keywords, timed in the same run).
//!
//! Each call does what the Python call does for the library: the keywords
//! as parameter-table values ([`Given`]) over the defaults, the validated
//! [`Scenario`] and options, the run into a [`Collected`] sink (rows kept
//! in memory), and the model's validity warnings for the scenario
//! ([`validity_warnings`], which the call returns; for a turn model they
//! take about 60 000 instructions, a twentieth of a 100-turn run). For `simulate`: `--model torque-cm`, `t_end = 100 s`,
//! one requested time, 100 s (one row). For `turns`: `--turns N` of the
//! model `turns`, one row per turn.
//!
//! ```text
//! cargo run --release -p snowroll --example one_call -- [simulate | turns [N]] [--n CALLS]
//! ```

use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

use snowroll::models::TURNS_T_END_S;
use snowroll::trajectory::Collected;
use snowroll::{
    run_turns_into, validity_warnings, Given, ModelKind, Param, Sampling, Scenario, Settings,
    TurnRow, TurnSink, Value,
};

/// Untimed calls first, to fault in code and warm caches and the CPU clock.
const WARM_UP_CALLS: usize = 200;

/// What is timed: one `simulate` call, or one `turns` call of N turns.
#[derive(Clone, Copy)]
enum Call {
    Simulate,
    Turns(u64),
}

fn parse_args() -> Result<(Call, usize), Box<dyn Error>> {
    let (mut call, mut n) = (Call::Simulate, 20_000);
    let mut it = std::env::args().skip(1).peekable();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "simulate" => call = Call::Simulate,
            "turns" => {
                let turns = match it.peek().map(|s| s.parse::<u64>()) {
                    Some(Ok(k)) => {
                        it.next();
                        k
                    }
                    _ => 100,
                };
                call = Call::Turns(turns);
            }
            "--n" => {
                n = it.next().ok_or("--n needs a value")?.parse()?;
                if n == 0 {
                    return Err("--n must be at least 1".into());
                }
            }
            "-h" | "--help" => {
                println!("usage: one_call [simulate | turns [N]] [--n CALLS]");
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument {other:?} (try --help)").into()),
        }
    }
    Ok((call, n))
}

fn param(key: &str) -> Result<&'static Param, Box<dyn Error>> {
    Param::of_key(key).ok_or_else(|| format!("no parameter {key}").into())
}

/// The turn rows of a run, kept as `snowroll.turns` keeps them.
#[derive(Default)]
struct Rows(Vec<TurnRow>);

impl TurnSink for Rows {
    fn turn(&mut self, row: &TurnRow) -> Result<(), snowroll::SinkError> {
        self.0.push(*row);
        Ok(())
    }
}

/// One call; returns the last row's speed, m/s (for `black_box` and the
/// printed check).
fn one(call: Call, given: &Given) -> Result<f64, Box<dyn Error>> {
    match call {
        Call::Simulate => {
            let settings = given.apply(Settings::default())?;
            let scenario = Scenario::new(settings.scenario)?;
            settings.options.validate()?;
            let opts = settings.options;
            let mut sink = Collected::default();
            let end = ModelKind::TorqueCm
                .build()
                .simulate_into(&scenario, &opts, &mut sink)?;
            let traj = sink.into_trajectory(ModelKind::TorqueCm, end);
            black_box(validity_warnings(ModelKind::TorqueCm, &scenario));
            Ok(traj.samples.last().ok_or("no rows")?.v_m_s)
        }
        Call::Turns(k) => {
            let mut base = Settings::default();
            base.options.t_end = TURNS_T_END_S;
            base.options.sampling = Sampling::Ends;
            base.options.turns = Some(k);
            let settings = given.apply(base)?;
            let scenario = Scenario::new(settings.scenario)?;
            settings.options.validate()?;
            let mut rows = Rows(Vec::with_capacity(k as usize));
            run_turns_into(ModelKind::Turns, &scenario, &settings.options, &mut rows)?;
            black_box(validity_warnings(ModelKind::Turns, &scenario));
            Ok(rows.0.last().ok_or("no turns")?.v_after_m_s)
        }
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let (call, n) = parse_args()?;
    let mut given = Given::new();
    if let Call::Simulate = call {
        given.insert(param("t_end")?, Value::Real(100.0));
        given.insert(param("times")?, Value::Reals(vec![100.0]));
    }
    for _ in 0..WARM_UP_CALLS {
        black_box(one(call, black_box(&given))?);
    }
    let mut times = Vec::with_capacity(n);
    let mut last = 0.0;
    for _ in 0..n {
        let start = Instant::now();
        last = black_box(one(call, black_box(&given))?);
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let what = match call {
        Call::Simulate => "simulate torque-cm t_end=100 times=[100]".to_string(),
        Call::Turns(k) => format!("turns turns={k}"),
    };
    println!(
        "rust {what}: N = {n}, median {:.3} us, min {:.3} us, last v = {last} m/s",
        times[n / 2] * 1e6,
        times[0] * 1e6
    );
    // For bench/python_overhead.py.
    println!("median_s={:e} min_s={:e}", times[n / 2], times[0]);
    Ok(())
}
