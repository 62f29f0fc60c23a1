//! Helpers shared by the test modules.

use snowroll::{Scenario, ScenarioFile};

/// The default scenario with slope `alpha_deg` (degrees), snow depth `b`,
/// initial radius `r0` (m) and speed `v0` (m/s).
pub fn scenario(alpha_deg: f64, b: f64, r0: f64, v0: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        snow_depth: b,
        r0,
        v0,
        ..ScenarioFile::default()
    })
    .unwrap()
}
