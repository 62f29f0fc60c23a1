//! Builds a report from real runs of every circular model and writes it.
//!
//! ```text
//! cargo run -p snowroll --features plot --example report_demo -- OUT_DIR
//! ```
//!
//! The figures are those `snowroll paper` shows for the circular models
//! (a/(g sin α) on a log time axis, v(t), r(t), the approach to each terminal
//! value); the claims table holds three genuine checks, measured from runs.

use std::path::PathBuf;

use snowroll::plot::{Axis, Chart, Legend, Series, Style};
use snowroll::report::{
    params_of, Animation, Claim, ClaimResult, Figure, Metadata, Report, Tolerance, Verdict,
};
use snowroll::{ModelKind, RunParams, Sampling, Scenario, ScenarioFile, SimOptions, Trajectory};

/// End of the long runs, s: long enough for every model to approach its terminal value.
const T_END: f64 = 100.0;
/// First sampled time on the logarithmic time axis, s.
const T_FIRST: f64 = 1e-3;
/// Samples per run on the log time grid.
const N_TIMES: usize = 240;
/// Relative tolerance of "a = (2/3) g sin α with no snow": integrator rtol is 1e-10.
const SNOWLESS_TOL: f64 = 1e-8;
/// Relative tolerance of "Loney's closed form = integrated eq. (4)": both near 1e-10.
const LONEY_TOL: f64 = 1e-7;
/// Relative tolerance of "eq. (14) tends to g sin α / 3" at t = 100 s, where the
/// remaining approach term is still of order 1e-2 (see the approach figure).
const TERMINAL_TOL: f64 = 5e-2;

static SNOWLESS: Claim = Claim {
    id: "appA-snowless-two-thirds",
    paper_ref: "App. A, eq. (95)",
    statement: "With no snow (b = 0) every circular model rolls with a = (2/3) g sin α.",
    method: "Run every circular model with b = 0 for 10 s; compare a/(g sin α) at every sample with 2/3.",
    tolerance: Tolerance::Relative {
        value: SNOWLESS_TOL,
    },
    expected: Verdict::Holds,
};

static LONEY: Claim = Claim {
    id: "fn4-loney-matches-eq4",
    paper_ref: "fn. 4",
    statement: "Loney's closed form solves eq. (4): the two give the same motion.",
    method: "Compare v(t) of the closed form with the integrated eq. (4) at 240 times up to 100 s.",
    tolerance: Tolerance::Relative { value: LONEY_TOL },
    expected: Verdict::Holds,
};

static TERMINAL: Claim = Claim {
    id: "eq35-energy-tends-to-third",
    paper_ref: "eq. (35)",
    statement: "The energy equation (14) tends to a = g sin α / 3.",
    method: "Integrate eq. (14) to t = 100 s; compare a/(g sin α) there with 1/3.",
    tolerance: Tolerance::Relative {
        value: TERMINAL_TOL,
    },
    expected: Verdict::Holds,
};

fn log_times() -> Vec<f64> {
    let (l0, l1) = (T_FIRST.log10(), T_END.log10());
    (0..N_TIMES)
        .map(|i| 10f64.powf(l0 + (l1 - l0) * i as f64 / (N_TIMES - 1) as f64))
        .collect()
}

fn run(kind: ModelKind, s: &Scenario, opts: &SimOptions) -> Trajectory {
    kind.build()
        .simulate(s, opts)
        .unwrap_or_else(|e| panic!("{kind}: {e}"))
}

fn verdict(ok: bool) -> Verdict {
    if ok {
        Verdict::Holds
    } else {
        Verdict::Refuted
    }
}

fn main() {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("snowroll-report-demo"), PathBuf::from);
    let scenario = Scenario::new(ScenarioFile::default()).expect("default scenario");
    let g_along = scenario.g_along();
    let opts = SimOptions {
        t_end: T_END,
        sampling: Sampling::Times(log_times()),
        ..SimOptions::default()
    };
    let runs: Vec<Trajectory> = ModelKind::ALL
        .iter()
        .map(|&k| run(k, &scenario, &opts))
        .collect();

    // Claims measured from runs.
    let snowless = scenario.with_snow_depth(0.0).expect("b = 0 is valid");
    let short = SimOptions {
        t_end: 10.0,
        ..SimOptions::default()
    };
    let worst = ModelKind::ALL
        .iter()
        .filter(|k| k.derivation().is_some())
        .flat_map(|&k| run(k, &snowless, &short).samples)
        .map(|s| (s.a_m_s2 / snowless.g_along() - 2.0 / 3.0).abs() / (2.0 / 3.0))
        .fold(0.0, f64::max);
    let by = |k: ModelKind| &runs[ModelKind::ALL.iter().position(|&m| m == k).unwrap_or(0)];
    let (eq4, loney) = (by(ModelKind::TorqueCm), by(ModelKind::Loney));
    let loney_diff = eq4
        .samples
        .iter()
        .zip(&loney.samples)
        .filter(|(a, _)| a.v_m_s > 0.0)
        .map(|(a, b)| ((a.v_m_s - b.v_m_s) / b.v_m_s).abs())
        .fold(0.0, f64::max);
    let energy_end = by(ModelKind::Energy)
        .samples
        .last()
        .map_or(f64::NAN, |s| s.a_m_s2 / g_along);
    let terminal_diff = (energy_end - 1.0 / 3.0).abs() * 3.0;
    let claims = vec![
        ClaimResult {
            claim: &SNOWLESS,
            measured: format!("largest |a/(g sin α) − 2/3|/(2/3) = {worst:.2e}"),
            verdict: verdict(worst <= SNOWLESS_TOL),
            evidence: format!(
                "{} models, every sample of 10 s runs with b = 0",
                ModelKind::ALL.len() - 1
            ),
        },
        ClaimResult {
            claim: &LONEY,
            measured: format!("largest relative difference in v = {loney_diff:.2e}"),
            verdict: verdict(loney_diff <= LONEY_TOL),
            evidence: format!("{} common sample times", loney.samples.len()),
        },
        ClaimResult {
            claim: &TERMINAL,
            measured: format!("a/(g sin α) at t = {T_END} s: {energy_end:.5}"),
            verdict: verdict(terminal_diff <= TERMINAL_TOL),
            evidence: format!("relative difference from 1/3: {terminal_diff:.2e}"),
        },
    ];

    // Figures: every model on one chart.
    let style = |i: usize| {
        if i % 2 == 1 {
            Style::Dashed
        } else {
            Style::Line
        }
    };
    let label = |t: &Trajectory| format!("{} {}", t.model.id(), t.model.equation());
    let chart = |name: &str, title: &str, x: Axis, y: Axis, f: &dyn Fn(&Trajectory) -> Series| {
        runs.iter()
            .enumerate()
            .fold(Chart::new(name, title, x, y), |c, (i, t)| {
                c.with_series(f(t).style(style(i)))
            })
    };
    let accel = chart(
        "accel-ratio",
        "Acceleration of every circular model",
        Axis::log("time t", "s").column("t_s"),
        Axis::linear("a / (g sin α)", "1").column("a_over_g_sin_alpha"),
        &|t| Series::from_samples(&label(t), &t.samples, |s| s.t_s, |s| s.a_m_s2 / g_along),
    )
    .with_legend(Legend::LowerLeft);
    let speed = chart(
        "speed",
        "Speed down the slope",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("speed v", "m/s").column("v_m_s"),
        &|t| Series::from_samples(&label(t), &t.samples, |s| s.t_s, |s| s.v_m_s),
    )
    .with_legend(Legend::UpperLeft);
    let radius = chart(
        "radius",
        "Radius of the log with its snow",
        Axis::linear("time t", "s").column("t_s"),
        Axis::linear("radius r", "m").column("r_m"),
        &|t| Series::from_samples(&label(t), &t.samples, |s| s.t_s, |s| s.r_m),
    )
    .with_legend(Legend::UpperLeft);
    let mut approach = Chart::new(
        "approach",
        "Approach to the terminal acceleration",
        Axis::log("distance x", "m").column("x_m"),
        Axis::log("|a − a_term| / (g sin α)", "1").column("abs_a_minus_a_term_over_g_sin_alpha"),
    );
    for (i, t) in runs.iter().enumerate() {
        // The snowless model sits exactly on its value: nothing to draw on a log axis.
        let frac = t
            .model
            .terminal_fraction()
            .filter(|_| t.model != ModelKind::Snowless);
        if let Some(frac) = frac {
            approach = approach.with_series(
                Series::from_samples(
                    &format!("{} → {frac:.4}", label(t)),
                    &t.samples,
                    |s| s.x_m,
                    |s| (s.a_m_s2 / g_along - frac).abs(),
                )
                .style(style(i)),
            );
        }
    }
    let approach = approach.with_legend(Legend::LowerLeft);

    let anim_opts = SimOptions {
        t_end: 3.0,
        sampling: Sampling::Every(0.01),
        ..SimOptions::default()
    };
    let anim_run = run(ModelKind::Energy, &scenario, &anim_opts);
    let animation = Animation::from_trajectory(&anim_run, &scenario, 400).expect("animation");

    let meta = Metadata::new("snowroll: the circular models of McDonald's note (demo)")
        .with_run_params(&RunParams::new(&scenario, &opts))
        .expect("params");
    let short_params = params_of(&RunParams::new(&scenario, &opts))
        .expect("params")
        .into_iter()
        .filter(|(k, _)| ["slope_deg", "snow_depth_m", "r0_m", "t_end_s"].contains(&k.as_str()))
        .collect::<Vec<_>>();
    let fig = |c: Chart, caption: &str| Figure {
        params: short_params.clone(),
        ..Figure::new(c, caption)
    };
    let report = Report {
        metadata: meta,
        claims,
        figures: vec![
            fig(accel, "Every model starts at 2/3 g sin α and settles on its own terminal value: 1/5 for eq. (4) and fn. 4, 1/3 for eqs. (14), (15), (32)."),
            fig(speed, "Speed from rest; the models part company once the log has gathered snow."),
            fig(radius, "Radius from eq. (8), π r² = π r0² + b x, along each model's own x(t)."),
            fig(approach, "How fast each model approaches its terminal acceleration, against distance rolled."),
        ],
        animation: Some(animation),
    };
    let written = report.write_to(&out).expect("write report");
    println!("wrote {} files to {}", written.len(), out.display());
}
