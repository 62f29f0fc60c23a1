//! Writes a SYNTHETIC measured track in the form Tracker exports (a first
//! line naming the mass, a header, tab-separated numbers): one model's x(t)
//! at a video's frame times, with Gaussian noise of a known σ from a fixed
//! seed ([`snowroll::fit::noisy`]). The data of the fit's worked example
//! (`examples/unrolling/`) and of its benchmark; never a measurement, and
//! the first line says so.
//!
//! ```text
//! cargo run --release -p snowroll --example synthetic_track -- \
//!     [--model energy] [--alpha-deg 30] [--snow-depth 0.01] [--r0 0.1] [--core-radius M] \
//!     [--fps 30] [--t-end 3] [--t0 0.2] [--x0 0.05] [--sigma 0.002] [--seed 1]
//! ```
//! Before t0 the body is at rest at x0 (the frames before it is let go).

use std::error::Error;

use snowroll::fit::noisy;
use snowroll::{ModelKind, Sampling, Scenario, ScenarioFile, SimOptions};

struct Args {
    model: ModelKind,
    scenario: ScenarioFile,
    fps: f64,
    t_end: f64,
    t0: f64,
    x0: f64,
    sigma: f64,
    seed: u64,
}

fn parse() -> Result<Args, Box<dyn Error>> {
    let mut a = Args {
        model: ModelKind::Energy,
        scenario: ScenarioFile {
            alpha_deg: 30.0,
            snow_depth: 0.01,
            r0: 0.1,
            ..ScenarioFile::default()
        },
        fps: 30.0,
        t_end: 3.0,
        t0: 0.2,
        x0: 0.05,
        sigma: 0.002,
        seed: 1,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let value = it.next().ok_or(format!("{flag} needs a value"))?;
        let real = || {
            value
                .parse::<f64>()
                .map_err(|e| format!("{flag} {value}: {e}"))
        };
        match flag.as_str() {
            "--model" => a.model = value.parse()?,
            "--alpha-deg" => a.scenario.alpha_deg = real()?,
            "--snow-depth" => a.scenario.snow_depth = real()?,
            "--r0" => a.scenario.r0 = real()?,
            "--core-radius" => a.scenario.core_radius = Some(real()?),
            "--fps" => a.fps = real()?,
            "--t-end" => a.t_end = real()?,
            "--t0" => a.t0 = real()?,
            "--x0" => a.x0 = real()?,
            "--sigma" => a.sigma = real()?,
            "--seed" => a.seed = value.parse()?,
            other => return Err(format!("unknown flag {other}").into()),
        }
    }
    if !(a.fps > 0.0 && a.t_end > a.t0 && a.t0 >= 0.0 && a.sigma >= 0.0) {
        return Err("need fps > 0, 0 <= t0 < t-end, sigma >= 0".into());
    }
    Ok(a)
}

fn main() -> Result<(), Box<dyn Error>> {
    let a = parse()?;
    let frames = (a.t_end * a.fps).floor() as usize;
    let t: Vec<f64> = (0..=frames).map(|k| k as f64 / a.fps).collect();
    let moving: Vec<f64> = t
        .iter()
        .map(|t| t - a.t0)
        .filter(|&tau| tau > 0.0)
        .collect();
    let scenario = Scenario::new(a.scenario)?;
    let opts = SimOptions {
        t_end: *moving.last().ok_or("no frame after t0")?,
        sampling: Sampling::Times(moving.clone()),
        ..SimOptions::default()
    };
    let run = a.model.build().simulate(&scenario, &opts)?;
    if run.samples.len() != moving.len() {
        return Err(format!("the run stopped early: {:?}", run.stop.reason).into());
    }
    let at_rest = t.len() - moving.len();
    let exact: Vec<f64> = std::iter::repeat_n(a.x0, at_rest)
        .chain(run.samples.iter().map(|s| a.x0 + s.x_m))
        .collect();
    let x = noisy(&exact, a.sigma, a.seed);
    println!(
        "roll (SYNTHETIC: snowroll {} {}, alpha_deg {}, snow_depth {}, r0 {}{}, t0 {}, x0 {}, noise sigma {} m, seed {}; not a measurement)",
        a.model.id(),
        a.model.equation(),
        a.scenario.alpha_deg,
        a.scenario.snow_depth,
        a.scenario.r0,
        a.scenario
            .core_radius
            .map_or(String::new(), |c| format!(", core_radius {c}")),
        a.t0,
        a.x0,
        a.sigma,
        a.seed
    );
    println!("t\tx");
    for (t, x) in t.iter().zip(&x) {
        println!("{t:.4}\t{x:.5}");
    }
    Ok(())
}
