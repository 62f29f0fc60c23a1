//! Checks of the losses of fn. 5 (issue 11, `docs/snowball-and-losses.md` §2).

use super::{bound, edited, holds_if, Edit, Finding, Lab};
use crate::notation;
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::losses::Losses;
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, Shape};
use snowroll::trajectory::{Sampling, SimOptions, StopReason, Trajectory};
use std::f64::consts::PI;

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

/// `energy-ledger-balances`: the energy account of a run with losses,
/// recomputed by the check, against the initial energy.
pub(super) const LEDGER_BALANCE: Criterion = Criterion {
    quantity: "|K + D_drag + D_rr + D_comp + W_model − (E_released + K0)| at every sample, relative to the largest term, K and E_released recomputed from eqs. (7), (10) and D_comp = e_c (M − M0)",
    tolerance: Tolerance::Relative { value: 1e-8 },
    reason: "the works are quadratures integrated with the run at rtol 1e-10 over up to ~10³ time scales; the random-scenario test of the library (2700 runs) finds at most 1.7e-9",
};

/// Scenarios per circular model of `energy-ledger-balances`.
const LEDGER_CASES: u64 = 12;

/// Uniform numbers in [0, 1) from a fixed seed (SplitMix64): the same
/// scenarios on every run of the report.
struct Draws(u64);

impl Draws {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// Kinetic energy, eq. (7) for any body with I = k M r² on the area law:
/// `½ M (1 + k + r′²) v²` with r′ = b/(2πr) (the log: k = ½, M = π ρ l r²;
/// the ball: k = 2/5, M = (4/3) π ρ r³, `docs/snowball-and-losses.md` §1.2).
fn kinetic(s: &Scenario, b: f64, r: f64, v: f64) -> f64 {
    let r_prime = b / (2.0 * PI * r);
    let (mass, k) = body(s, r);
    0.5 * mass * (1.0 + k + r_prime * r_prime) * v * v
}

/// Mass at radius r, kg, and the inertia factor k of I = k M r².
fn body(s: &Scenario, r: f64) -> (f64, f64) {
    match s.shape() {
        Shape::Cylinder => (PI * s.density() * s.length() * r * r, 0.5),
        Shape::Sphere => (4.0 / 3.0 * PI * s.density() * r.powi(3), 0.4),
    }
}

/// Potential energy released since the start, −V of eq. (10) for the body
/// and the snow it will collect (zero at the start, the layer's snow at
/// −b/2; b = 0 for the snowless body), §1.2:
/// `G ∫₀ˣ M dx − C [M r − M0 r0 + (b/2)(M − M0)]`, with
/// `∫M dx = ρl (π r0² x + b x²/2)` for the log and `8π²ρ (r⁵ − r0⁵)/(15 b)`
/// for the ball (`M0 x` without snow).
fn released(s: &Scenario, b: f64, x: f64, r: f64) -> f64 {
    let r0 = s.initial_radius();
    let (m, _) = body(s, r);
    let (m0, _) = body(s, r0);
    let gathered = match s.shape() {
        _ if b == 0.0 => m0 * x,
        Shape::Cylinder => s.density() * s.length() * (PI * r0 * r0 * x + 0.5 * b * x * x),
        Shape::Sphere => 8.0 * PI * PI * s.density() * (r.powi(5) - r0.powi(5)) / (15.0 * b),
    };
    s.g_along() * gathered - s.g_normal() * (m * r - m0 * r0 + 0.5 * b * (m - m0))
}

/// Scenario `case` of `energy-ledger-balances`, drawn from `draws`: the
/// scenario, its drawn r0, its losses and the run's options.
fn draw_case(
    lab: &Lab,
    draws: &mut Draws,
    case: u64,
) -> Result<(Scenario, f64, Losses, SimOptions), SimError> {
    let r0 = 10f64.powf(draws.between(-1.5, 0.0));
    // Every other scenario a ball (swath 2r, the area law).
    let shape = if case.is_multiple_of(2) {
        Shape::Cylinder
    } else {
        Shape::Sphere
    };
    let s = edited(
        lab.scenario(),
        Edit {
            alpha_deg: Some(draws.between(10.0, 70.0)),
            r0: Some(r0),
            snow_depth: Some(r0 * 10f64.powf(draws.between(-3.0, -0.7))),
            v0: Some(draws.between(0.0, 3.0)),
            shape: Some(shape),
            ..Edit::default()
        },
    )?;
    let losses = Losses {
        drag_coefficient: draws.between(0.0, 2.0),
        rolling_resistance: draws.between(0.0, 0.1),
        compaction_energy: draws.between(0.0, 3.0),
        terminal_tol: 0.0,
        ..Losses::default()
    };
    let t_end = 10f64.powf(draws.between(0.0, 2.0));
    let opts = SimOptions {
        t_end,
        sampling: Sampling::Every(t_end / 16.0),
        losses,
        ..SimOptions::default()
    };
    Ok((s, r0, losses, opts))
}

/// The largest imbalance of the ledger found so far, where, and over how
/// many samples.
struct Imbalance {
    /// The largest imbalance, relative to the largest term.
    worst: f64,
    /// Where it was found: model and time, or a ledger of the wrong length.
    worst_at: String,
    /// Samples checked.
    samples: usize,
}

impl Imbalance {
    /// Checks every sample of the run `traj` of `kind` on `s` (initial radius
    /// `r0`, `losses`): the ledger's works against the energies recomputed
    /// here, keeping the largest imbalance (a NaN one wins).
    fn check_run(
        &mut self,
        kind: ModelKind,
        s: &Scenario,
        r0: f64,
        losses: &Losses,
        traj: &Trajectory,
    ) {
        // The snowless model picks up nothing: b = 0 in its energies.
        let b = if kind == ModelKind::Snowless {
            0.0
        } else {
            s.snow_depth()
        };
        let m0 = s.initial_mass();
        let k0 = kinetic(s, b, r0, s.initial_speed());
        for (p, l) in traj.samples.iter().zip(&traj.ledger) {
            self.samples += 1;
            let kinetic = kinetic(s, b, p.r_m, p.v_m_s);
            let released = released(s, b, p.x_m, p.r_m);
            let compaction = losses.compaction_energy * (p.mass_kg - m0);
            let terms = [kinetic, l.drag_j, l.rolling_j, compaction, l.model_j];
            let scale = terms
                .iter()
                .chain([released, k0].iter())
                .fold(f64::MIN_POSITIVE, |m, t| m.max(t.abs()));
            let dev = (terms.iter().sum::<f64>() - released - k0).abs() / scale;
            if dev.is_nan() || dev > self.worst {
                self.worst = dev;
                self.worst_at = format!("{kind} at t = {:.3} s", p.t_s);
            }
        }
        if traj.ledger.len() != traj.samples.len() {
            self.worst = f64::INFINITY;
            self.worst_at = format!(
                "{kind}: {} ledger rows for {} samples",
                traj.ledger.len(),
                traj.samples.len()
            );
        }
    }
}

/// fn. 5 sets the losses aside; with them the energy must still be
/// accounted for: every circular model on [`LEDGER_CASES`] scenarios drawn
/// from a fixed seed (shape, slope, depth, radius, initial speed, the three
/// losses), the ledger's works against the energies the check computes.
pub(super) fn ledger_balances(lab: &Lab) -> Result<Finding, SimError> {
    let mut draws = Draws(0x5EED_0011);
    let mut imbalance = Imbalance {
        worst: 0.0,
        worst_at: String::new(),
        samples: 0,
    };
    let mut runs = 0;
    for kind in ModelKind::ALL.into_iter().filter(|k| k.is_circular()) {
        for case in 0..LEDGER_CASES {
            let (s, r0, losses, opts) = draw_case(lab, &mut draws, case)?;
            let traj = lab.run(kind, &s, &opts)?;
            runs += 1;
            imbalance.check_run(kind, &s, r0, &losses, &traj);
        }
    }
    let Imbalance {
        worst,
        worst_at,
        samples,
    } = imbalance;
    let ok = LEDGER_BALANCE.accepts_deviation(worst);
    Ok(Finding {
        measured: format!(
            "largest imbalance {} of the largest term ({worst_at}), over {samples} samples of {runs} runs",
            notation::number(worst, 2)
        ),
        verdict: holds_if(ok, &[worst]),
        evidence: format!(
            "{} ({}); each circular model on {LEDGER_CASES} scenarios, logs and balls alternately: α 10°–70°, r0 0.03–1 m, b/r0 10⁻³–0.2, v0 0–3 m/s, C_d 0–2, c_rr 0–0.1, e_c 0–3 J/kg, 1–100 s",
            notation::number(worst, 2),
            bound(&LEDGER_BALANCE, ok)
        ),
    })
}
