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
        headline: None,
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
    reason: "the works are quadratures integrated with the run at rtol 1e-10; the error of a DOP853 run grows about linearly with the time scales it spans, ≲ 10² for these runs (1–100 s, r/v ≳ 0.1 s), so ≲ 1e-8 of the largest term",
};

/// `energy-ledger-balances`: W_model of the models that conserve energy.
pub(super) const LEDGER_CONSERVED: Criterion = Criterion {
    quantity: "|W_model| of `energy` and `snowless` at every sample of their runs above, relative to the largest term of the ledger",
    tolerance: Tolerance::Relative { value: 1e-12 },
    reason: "their rate P is zero term by term (docs/snowball-and-losses.md §3.1); what is integrated is the rounding of its O(1) terms, ~1e-16 of the largest per unit time, over at most 100 s",
};
/// `energy-ledger-balances`: W_model of eq. (4) against its closed form.
pub(super) const LEDGER_W4: Criterion = Criterion {
    quantity: "|W_model of torque-cm − W_4(x)| at every sample of a lossless run from rest (lab scenario, 100 s), relative to the largest of K and the energy released",
    tolerance: Tolerance::Relative { value: 1e-9 },
    reason: "W_model is a quadrature integrated with the run at rtol 1e-10 over ~10³ time scales; W_4 is exact (both of its integrals elementary)",
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
    /// The largest |W_model| of the models that conserve energy, relative
    /// to the largest term of their ledger.
    conserved: f64,
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
            if matches!(kind, ModelKind::Energy | ModelKind::Snowless) {
                let w = l.model_j.abs() / scale;
                if w.is_nan() || w > self.conserved {
                    self.conserved = w;
                }
            }
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

/// The energy eq. (4) destroys from rest without losses, §3.1 of
/// `docs/snowball-and-losses.md`, by Loney's u(s) = v² (fn. 4):
/// `W_4(s) = ρl ∫u ds − ρl C [π(r³ − r0³) + b²x/2] − (ρl b²/4π)[(2G/3) x − (7/6) ∫(u/s) ds]`,
/// u = (2G/5b) s [1 − (s0/s)^{10/3}], s = π r² = s0 + b x: both integrals
/// elementary. Returns (the largest deviation of the run's W_model from
/// W_4 relative to the largest of K and the energy released, W_4 at the
/// last sample, the run's W_model there).
fn torque_cm_defect(lab: &Lab) -> Result<(f64, f64, f64), SimError> {
    let s = edited(
        lab.scenario(),
        Edit {
            v0: Some(0.0),
            shape: Some(Shape::Cylinder),
            ..Edit::default()
        },
    )?;
    let t_end = 100.0;
    let opts = SimOptions {
        t_end,
        sampling: Sampling::Every(t_end / 32.0),
        losses: Losses {
            ledger: true,
            ..Losses::default()
        },
        ..SimOptions::default()
    };
    let traj = lab.run(ModelKind::TorqueCm, &s, &opts)?;
    let (b, r0, rho_l) = (s.snow_depth(), s.initial_radius(), s.density() * s.length());
    let (gs, gc) = (s.g_along(), s.g_normal());
    let s0 = PI * r0 * r0;
    let c = 2.0 * gs / (5.0 * b);
    let p = 10.0 / 3.0;
    // ∫u ds = c [s²/2 − s0^p s^(2−p)/(2−p)]; ∫u/s ds = c [s − s0^p s^(1−p)/(1−p)].
    let int_u = |x: f64| c * (x * x / 2.0 - s0.powf(p) * x.powf(2.0 - p) / (2.0 - p));
    let int_u_s = |x: f64| c * (x - s0.powf(p) * x.powf(1.0 - p) / (1.0 - p));
    let (mut worst, mut last) = (0.0_f64, (f64::NAN, f64::NAN));
    for (q, row) in traj.samples.iter().zip(&traj.ledger) {
        let area = s0 + b * q.x_m;
        let r = (area / PI).sqrt();
        let w4 = rho_l * (int_u(area) - int_u(s0))
            - rho_l * gc * (PI * (r.powi(3) - r0.powi(3)) + b * b * q.x_m / 2.0)
            - rho_l * b * b / (4.0 * PI)
                * (2.0 * gs / 3.0 * q.x_m - 7.0 / 6.0 * (int_u_s(area) - int_u_s(s0)));
        let scale = row.kinetic_j.max(row.released_j).max(f64::MIN_POSITIVE);
        let dev = (row.model_j - w4).abs() / scale;
        worst = if dev.is_nan() { dev } else { worst.max(dev) };
        last = (w4, row.model_j);
    }
    if traj.ledger.len() != traj.samples.len() || traj.samples.len() < 2 {
        worst = f64::INFINITY;
    }
    Ok((worst, last.0, last.1))
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
        conserved: 0.0,
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
        conserved,
    } = imbalance;
    let (w4_dev, w4, w_model) = torque_cm_defect(lab)?;
    let balance_ok = LEDGER_BALANCE.accepts_deviation(worst);
    let conserved_ok = LEDGER_CONSERVED.accepts_deviation(conserved);
    // Eq. (4) destroys energy: the snow's inelastic pick-up outweighs the
    // lift it does not pay (§3.1), so W_4 > 0, and the run's W_model with it.
    let w4_ok = LEDGER_W4.accepts_deviation(w4_dev) && w4 > 0.0 && w_model > 0.0;
    let ok = balance_ok && conserved_ok && w4_ok;
    Ok(Finding {
        headline: None,
        measured: format!(
            "largest imbalance {} of the largest term ({worst_at}), over {samples} samples of {runs} runs; largest |W_model| of energy and snowless {} of the largest term; torque-cm from rest without losses, 100 s: W_model = {w_model:.6e} J against W_4 = {w4:.6e} J, largest deviation {} of max(K, E_released)",
            notation::number(worst, 2),
            notation::number(conserved, 2),
            notation::number(w4_dev, 2)
        ),
        verdict: holds_if(ok, &[worst, conserved, w4_dev, w4, w_model]),
        evidence: format!(
            "{} ({}); each circular model on {LEDGER_CASES} scenarios, logs and balls alternately: α 10°–70°, r0 0.03–1 m, b/r0 10⁻³–0.2, v0 0–3 m/s, C_d 0–2, c_rr 0–0.1, e_c 0–3 J/kg, 1–100 s. The balance holds for any equation (W_model is −∫P with P from the model's own a), so the models' W_model is checked too: energy and snowless destroy nothing ({} {}), eq. (4) destroys the W_4 of Loney's closed form ({} {}), a positive amount",
            notation::number(worst, 2),
            bound(&LEDGER_BALANCE, balance_ok),
            notation::number(conserved, 2),
            bound(&LEDGER_CONSERVED, conserved_ok),
            notation::number(w4_dev, 2),
            bound(&LEDGER_W4, w4_ok)
        ),
    })
}
