//! Quick start: every model of the note on one scenario, side by side.
//!
//! ```text
//! cargo run --release -p snowroll --example quickstart
//! ```
//!
//! Builds the scenario from the one parameter vocabulary ([`ScenarioFile`]:
//! the command line's flags in snake_case), runs each model to t = 20 s,
//! reading its samples at a few times, and prints the acceleration as a
//! fraction of G = g sin α beside the terminal fraction the model tends to
//! (eq. (35) and fn. 4 for the circular models; none for the turn models,
//! whose acceleration swings within every turn).

use std::error::Error;

use snowroll::{ModelKind, Sampling, Scenario, ScenarioFile, SimOptions};

fn main() -> Result<(), Box<dyn Error>> {
    let scenario = Scenario::new(ScenarioFile {
        alpha_deg: 30.0,
        snow_depth: 0.01,
        r0: 0.1,
        ..ScenarioFile::default()
    })?;
    let times = vec![0.0, 1.0, 5.0, 20.0];
    let opts = SimOptions {
        t_end: 20.0,
        sampling: Sampling::Times(times.clone()),
        ..SimOptions::default()
    };
    let g_along = scenario.g_along();
    println!("a / (g sin alpha) at t = {times:?} s, and the model's terminal fraction");
    for kind in ModelKind::ALL {
        let run = kind.build().simulate(&scenario, &opts)?;
        let fractions: Vec<String> = run
            .samples
            .iter()
            .map(|s| format!("{:.4}", s.a_m_s2 / g_along))
            .collect();
        let terminal = kind
            .terminal_fraction()
            .map_or("-".to_string(), |f| format!("{f:.4}"));
        println!(
            "{:<22} {:<12} {}  -> {terminal}",
            kind.id(),
            kind.alias(),
            fractions.join("  ")
        );
    }
    Ok(())
}
