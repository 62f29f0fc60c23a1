//! The unwinding roll (issue 35, `docs/unwinding.md`): a negative snow
//! depth lays a layer down; on a level floor the energy balance of eq. (15)
//! is the textbook unrolling carpet, and the torque analyses do not start.

use std::f64::consts::PI;

use super::{holds_if, Finding, Lab};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// `unwinding-textbook-speed`: eq. (15) with b < 0 against the textbook.
pub(super) const UNWINDING_SPEED: Criterion = Criterion {
    quantity: "|v²/(4g(R³ − r³)/(3r²)) − 1| of energy-thin at r = 0.09, 0.07, 0.05 (R/2, where the textbook gives 14gR/3) and 0.03 m",
    tolerance: Tolerance::Relative { value: 1e-9 },
    reason: "the runs are integrated at rtol 1e-12 on a smooth right-hand side (DOP853 keeps a few times rtol); the issue asks 1e-9",
};

/// The roll of the check: R = 10 cm, a layer of 0.1 mm, core 2 cm, level floor.
const R: f64 = 0.1;
const B: f64 = -1e-4;
const CORE: f64 = 0.02;

/// The radii at which the speed is compared.
const RADII: [f64; 4] = [0.09, 0.07, 0.05, 0.03];

/// The check: energy-thin's speed on its way to the core against the
/// textbook energy balance (typed here: M0 g R = M g r + (3/4) M v², M ∝ r²),
/// and eqs. (4), (6) stopped at the start (`does-not-start`).
pub(super) fn unwinding_textbook_speed(lab: &Lab) -> Result<Finding, SimError> {
    let g = lab.scenario().gravity();
    let s = Scenario::new(ScenarioFile {
        alpha_deg: 0.0,
        snow_depth: B,
        r0: R,
        g,
        core_radius: Some(CORE),
        ..ScenarioFile::default()
    })?;
    let textbook = |r: f64| 4.0 * g * (R.powi(3) - r.powi(3)) / (3.0 * r * r);
    let (worst, numbers, speeds) = speeds_against(lab, &s, R, &RADII, textbook)?;
    // The third radius is R/2.
    let at_half = speeds[2];
    let opts = SimOptions {
        t_end: 10.0,
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    let mut still = Vec::new();
    for kind in [ModelKind::TorqueCm, ModelKind::TorqueContact] {
        let traj = lab.run(kind, &s, &opts)?;
        still.push((kind, traj.stop.reason == StopReason::DoesNotStart));
    }
    let torque_still = still.iter().all(|(_, s)| *s);
    let ok = worst.is_finite() && UNWINDING_SPEED.accepts_deviation(worst) && torque_still;
    Ok(Finding {
        headline: None,
        measured: format!(
            "energy-thin at r = R/2: v = {at_half:.12} m/s, √(14gR/3) = {:.12} m/s; torque-cm and torque-contact {}",
            (14.0 * g * R / 3.0).sqrt(),
            if torque_still {
                "do not start"
            } else {
                "START (a wrong torque balance)"
            }
        ),
        verdict: holds_if(ok, &numbers),
        evidence: format!(
            "largest |v²/v²_textbook − 1| = {worst:.2e} ({}) over r = 0.09 … 0.03 m; R = {R} m, b = {B} m, core {CORE} m, α = 0 (synthetic runs of the program)",
            UNWINDING_SPEED.tolerance
        ),
    })
}

/// `unwinding-hollow-roll`: eq. (15) with a tube of its own mass
/// (`docs/unwinding.md`, "The core").
pub(super) const HOLLOW_ROLL: Criterion = Criterion {
    quantity: "|v²/v²_E − 1| of energy-thin on a 5 g tube at r = 0.055, 0.045, 0.03 (R/2) and 0.025 m, v²_E = 2g (M(R) R − M(r) r)/(M(r) + I(r)/r²) with M and I of the paper and the tube",
    tolerance: Tolerance::Relative { value: 1e-9 },
    reason: "the runs are integrated at rtol 1e-12 on a smooth right-hand side (DOP853 keeps a few times rtol), as for the uniform roll",
};

/// The hollow roll of the check: R = 6 cm, 0.1 mm paper of 700 kg/m³, 10 cm
/// wide, on a 2 cm tube of 5 g, level floor.
const HOLLOW: (f64, f64, f64) = (0.06, 700.0, 0.1);
const TUBE: f64 = 0.005;

/// The check: energy-thin on a hollow roll against its energy integral with
/// the tube, typed here (thin tube I = m r_c², paper between r_c and r), and
/// how far the hollow roll is from the textbook's uniform one at R/2.
pub(super) fn unwinding_hollow_roll(lab: &Lab) -> Result<Finding, SimError> {
    let g = lab.scenario().gravity();
    let (r0, rho, l) = HOLLOW;
    let s = Scenario::new(ScenarioFile {
        alpha_deg: 0.0,
        snow_depth: B,
        r0,
        g,
        density: rho,
        length: l,
        core_radius: Some(CORE),
        core_mass: Some(TUBE),
        ..ScenarioFile::default()
    })?;
    let mass = |r: f64| TUBE + PI * rho * l * (r * r - CORE * CORE);
    let inertia = |r: f64| TUBE * CORE * CORE + PI * rho * l * (r.powi(4) - CORE.powi(4)) / 2.0;
    let closed =
        |r: f64| 2.0 * g * (mass(r0) * r0 - mass(r) * r) / (mass(r) + inertia(r) / (r * r));
    let radii = [0.055, 0.045, r0 / 2.0, 0.025];
    let (worst, numbers, speeds) = speeds_against(lab, &s, r0, &radii, closed)?;
    // The third radius is R/2.
    let at_half = speeds[2];
    let textbook = (14.0 * g * r0 / 3.0).sqrt();
    let ok = worst.is_finite() && HOLLOW_ROLL.accepts_deviation(worst);
    Ok(Finding {
        headline: None,
        measured: format!(
            "energy-thin at r = R/2 on a 5 g tube: v = {at_half:.6} m/s, {:.1} % above the uniform roll's √(14gR/3) = {textbook:.6} m/s",
            100.0 * (at_half / textbook - 1.0)
        ),
        verdict: holds_if(ok, &numbers),
        evidence: format!(
            "largest |v²/v²_E − 1| = {worst:.2e} ({}) over r = 0.055 … 0.025 m; R = {r0} m, b = {B} m, paper {rho} kg/m³, {l} m wide (0.70 kg), tube {TUBE} kg at {CORE} m, α = 0 (synthetic runs of the program)",
            HOLLOW_ROLL.tolerance
        ),
    })
}

/// energy-thin on `s` (a roll of radius `r0` unwinding from rest) stopped at
/// each of `radii` (x_end = π(r² − r0²)/b, rtol 1e-12) against v² = `want(r)`:
/// the largest |v²/want − 1| (infinite for a run that stopped before its
/// radius), every (v, want) in turn, and each v.
fn speeds_against(
    lab: &Lab,
    s: &Scenario,
    r0: f64,
    radii: &[f64],
    want: impl Fn(f64) -> f64,
) -> Result<(f64, Vec<f64>, Vec<f64>), SimError> {
    let (mut worst, mut numbers, mut speeds) = (0.0_f64, Vec::new(), Vec::new());
    for &r in radii {
        let mut opts = SimOptions {
            t_end: 1e6,
            x_end: Some(PI * (r * r - r0 * r0) / s.snow_depth()),
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        opts.tolerances.rtol = 1e-12;
        opts.tolerances.atol = 1e-14;
        let traj = lab.run(ModelKind::EnergyThin, s, &opts)?;
        let (v, want) = (traj.stop.v_m_s, want(r));
        let dev = if traj.stop.reason == StopReason::Distance {
            (v * v / want - 1.0).abs()
        } else {
            f64::INFINITY
        };
        worst = worst.max(dev);
        numbers.extend([v, want]);
        speeds.push(v);
    }
    Ok((worst, numbers, speeds))
}
