//! Checks of the first turn, §3.1–3.3, and of the errata a computation shows there.
//!
//! The note's formulae are typed here as printed (and as corrected), not taken
//! from [`crate::models::InTurnCoefficients`]: the checks compare the note's
//! analyses with each other, independently of the model the program runs.

use std::f64::consts::PI;

use super::{Finding, Lab};
use crate::error::SimError;
use crate::report::Verdict;

/// First turn: I_C(θ) of eq. (56) to O(b), per unit m0.
fn ic56(r0: f64, b: f64, th: f64) -> f64 {
    1.5 * r0 * r0 + 2.0 * b * r0 / PI * (th - th.sin())
}

/// First turn: V(θ) of eq. (62), per unit m0.
fn v62(r0: f64, b: f64, gs: f64, gc: f64, th: f64) -> f64 {
    -r0 * th * gs - (b * th * th / (2.0 * PI) - b / PI * (1.0 - th.cos())) * gs
        + (b * th / PI - b / PI * th.sin()) * gc
}

/// (58), (64) and (69) are one equation once corrected; (63) and (69) as
/// printed are not.
pub(super) fn first_turn_equivalence(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let (r0, b, gs, gc) = (
        s.initial_radius(),
        s.snow_depth(),
        s.g_along(),
        s.g_normal(),
    );
    let mut worst_corr: f64 = 0.0;
    let mut worst_63: f64 = 0.0;
    let mut worst_69: f64 = 0.0;
    let h = 1e-5;
    for i in 1..24 {
        let th = 2.0 * PI * f64::from(i) / 24.0;
        for v in [0.3, 1.0, 2.5] {
            let ic = ic56(r0, b, th);
            // (58), torque (per unit m0, m → m0 corrected):
            let torque =
                gs * (r0 + b * th / PI - b / PI * th.sin()) - b / PI * (1.0 - th.cos()) * gc;
            let a58 = (r0 * torque - b * v * v * (1.0 - th.cos()) / PI) / ic;
            // (64), energy: dT/dt = −dV/dt with dV/dθ by central difference of (62)
            // and dT/dt = I_C v a/r0² + m0 b v³ (1 − cos θ)/(π r0²) (eq. (59)).
            let dv_dth = (v62(r0, b, gs, gc, th + h) - v62(r0, b, gs, gc, th - h)) / (2.0 * h);
            let a64 =
                (-dv_dth * v / r0 - b * v.powi(3) * (1.0 - th.cos()) / (PI * r0 * r0)) * r0 * r0
                    / (ic * v);
            // (69), Lagrangian with θ: d/dt(I_C θ̇) = ∂T/∂θ − ∂V/∂θ,
            // I_C' = (2 b r0/π)(1 − cos θ) (eq. (56)).
            let dic = 2.0 * b * r0 / PI * (1.0 - th.cos());
            let w = v / r0;
            let a69 = r0 * (-0.5 * dic * w * w - dv_dth) / ic;
            worst_corr = worst_corr.max(((a58 - a64).abs()).max((a58 - a69).abs()) / gs);
            // (63) as printed: θ/π in place of bθ/π in −dV/dt.
            let minus_dv_63 = (v / r0)
                * (gs * r0 + (th / PI - b / PI * th.sin()) * gs - gc * b / PI * (1.0 - th.cos()));
            let a63 = (minus_dv_63 - b * v.powi(3) * (1.0 - th.cos()) / (PI * r0 * r0)) * r0 * r0
                / (ic * v);
            worst_63 = worst_63.max((a63 - a58).abs() / gs);
            // (69) as printed: b/π in place of bθ/π.
            let torque_69 = gs * (r0 + b / PI - b / PI * th.sin()) - b / PI * (1.0 - th.cos()) * gc;
            let a69p = (r0 * torque_69 - b * v * v * (1.0 - th.cos()) / PI) / ic;
            worst_69 = worst_69.max((a69p - a58).abs() / gs);
        }
    }
    let ok = worst_corr < 1e-8 && worst_63 > 1e-3 && worst_69 > 1e-4;
    Ok(Finding {
        measured: format!(
            "max |Δa|/G over θ ∈ (0, 2π), 3 speeds: corrected (58) vs (64) vs (69): {worst_corr:.1e}; printed (63) vs (58): {worst_63:.3}; printed (69) vs (58): {worst_69:.2e}"
        ),
        verdict: if ok {
            Verdict::HoldsAfterCorrection("errata (58) m→m0, (63) θ/π→bθ/π, (68)–(69) b/π→bθ/π")
        } else {
            Verdict::Refuted
        },
        evidence: "torque (58), energy (64) with dV/dθ differentiated numerically from (62), and the Lagrangian (69) give the same acceleration to the finite-difference error; the printed (63) is dimensionally inconsistent and the printed (69) differs by (b/π)(θ − 1) G".to_string(),
    })
}

/// Erratum (54): the z-component of (x_cm − x_C) × m a_cm from (43), (45).
pub(super) fn eq54_erratum(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let r0 = s.initial_radius();
    let (th, w, wdot): (f64, f64, f64) = (1.1, 3.0, 2.0); // θ, θ̇, θ̈: a generic state (rad, rad/s, rad/s²)
                                                          // Exact cross product of the O(b) kinematics (43), (45) with m = m0(1 + bθ/πr0), per m0.
    let exact = |b: f64| {
        let dx = -b / PI * (1.0 - th.cos());
        let ycm = r0 - b / PI * th.sin();
        let ax = r0 * wdot - b / PI * (wdot * th.sin() + w * w * th.cos());
        let ay = -b / PI * (wdot * th.cos() - w * w * th.sin());
        (1.0 + b * th / (PI * r0)) * (dx * ay - ycm * ax)
    };
    let corrected = |b: f64| {
        -(r0 * r0 * wdot + b * r0 / PI * (th * wdot - 2.0 * wdot * th.sin() - w * w * th.cos()))
    };
    let printed = |b: f64| {
        -(r0 * r0 * wdot + b * r0 / PI * (th * wdot - 2.0 * w * th.sin() - w * w * th.cos()))
    };
    let (b1, b2) = (1e-3 * r0, 1e-4 * r0);
    let c_ratio = (exact(b1) - corrected(b1)).abs() / (exact(b2) - corrected(b2)).abs();
    let p_ratio = (exact(b1) - printed(b1)).abs() / (exact(b2) - printed(b2)).abs();
    let ok = (c_ratio / 100.0 - 1.0).abs() < 0.05 && (p_ratio / 10.0 - 1.0).abs() < 0.05;
    Ok(Finding {
        measured: format!(
            "residual vs exact product for b = 1e-3 r0 → 1e-4 r0 shrinks by {c_ratio:.1} (corrected, O(b²)) and by {p_ratio:.1} (printed, O(b))"
        ),
        verdict: if ok {
            Verdict::HoldsAfterCorrection("errata (54): θ̈ for θ̇, r0 for r")
        } else {
            Verdict::Refuted
        },
        evidence: "the corrected last line of (54) is the O(b) expansion of the cross product; the printed one misses an O(b) term".to_string(),
    })
}

/// Erratum (70): the mass after one turn is π ρ l r1², not 2π ρ l r1².
pub(super) fn eq70_mass(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let (rho, l, r0, b) = (s.density(), s.length(), s.initial_radius(), s.snow_depth());
    let r1 = r0 + b;
    // Disk plus the full annulus r0 < r < r0 + b (turn-model.md, θ = 2π).
    let exact = PI * rho * l * r0 * r0 + rho * l * 2.0 * PI * ((r0 + b).powi(2) - r0 * r0) / 2.0;
    let printed = 2.0 * PI * rho * l * r1 * r1;
    let corrected = PI * rho * l * r1 * r1;
    let ok = ((corrected - exact) / exact).abs() < 1e-14 && ((printed - exact) / exact).abs() > 0.5;
    Ok(Finding {
        measured: format!(
            "mass after one turn: exact {exact:.6} kg, corrected πρl r1² {corrected:.6} kg, printed 2πρl r1² {printed:.6} kg"
        ),
        verdict: if ok {
            Verdict::HoldsAfterCorrection("errata (70): m1 = πρl r1²")
        } else {
            Verdict::Refuted
        },
        evidence: "the printed form doubles the mass and contradicts its own next two forms and eq. (75)".to_string(),
    })
}
