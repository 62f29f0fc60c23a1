//! Checks of the losses of fn. 5 (issue 11, `docs/snowball-and-losses.md` §2).

use super::{holds_if, Finding, Lab};
use crate::error::SimError;
use crate::losses::Losses;
use crate::models::ModelKind;
use crate::report::{Criterion, Tolerance};
use crate::trajectory::{Sampling, SimOptions, StopReason};

/// `snowless-drag-terminal-velocity`: the measured terminal velocity
/// against `v_t² = M g sin α/(½ ρ_a C_d A)`.
pub(super) const DRAG_TERMINAL: Criterion = Criterion {
    quantity: "|v_stop/v_t − 1| at the `terminal` stop, the run stopping where |a| ≤ 1e-10 of g sin α/(1 + k)",
    tolerance: Tolerance::Relative { value: 1e-9 },
    reason: "there |1 − v²/v_t²| ≤ 1e-10, so |1 − v/v_t| ≤ 5e-11, plus the integration error at rtol 1e-10 (~1e-10)",
};

/// Drag coefficient of the check (a bluff cylinder), and the air density, kg/m³.
const CD: f64 = 1.0;
const RHO_AIR: f64 = 1.2;

/// fn. 5 sets dissipation aside; with air drag and no snow the log has a
/// terminal velocity, `v_t² = M g sin α/(½ ρ_a C_d A)`, M = π ρ l r0², A = 2 r0 l
/// (§2.2): the snowless model run with drag until its acceleration vanishes.
pub(super) fn drag_terminal_velocity(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let opts = SimOptions {
        t_end: 1e5,
        sampling: Sampling::Ends,
        losses: Losses {
            drag_coefficient: CD,
            air_density: RHO_AIR,
            terminal_tol: 1e-10,
            ..Losses::default()
        },
        ..SimOptions::default()
    };
    let traj = lab.run(ModelKind::Snowless, s, &opts)?;
    let (r0, l, rho) = (s.initial_radius(), s.length(), s.density());
    let mass = std::f64::consts::PI * rho * l * r0 * r0;
    let area = 2.0 * r0 * l;
    let vt = (mass * s.g_along() / (0.5 * RHO_AIR * CD * area)).sqrt();
    let v = traj.stop.v_m_s;
    let dev = (v / vt - 1.0).abs();
    let reached = traj.stop.reason == StopReason::Terminal;
    Ok(Finding {
        measured: format!(
            "stop `{}` at t = {:.3} s with v = {v:.12} m/s; closed form v_t = {vt:.12} m/s",
            serde_json::to_value(traj.stop.reason)
                .ok()
                .and_then(|x| x.as_str().map(str::to_string))
                .unwrap_or_default(),
            traj.stop.t_s
        ),
        verdict: holds_if(reached && DRAG_TERMINAL.accepts_deviation(dev), &[v, vt]),
        evidence: format!(
            "|v/v_t − 1| = {dev:.2e} ({}), C_d = {CD}, rho_a = {RHO_AIR} kg/m^3",
            DRAG_TERMINAL.tolerance
        ),
    })
}
