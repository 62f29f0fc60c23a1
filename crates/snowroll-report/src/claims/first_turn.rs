//! Checks of the first turn, §3.1–3.3, and of the errata (`docs/errata.md`) a computation shows there.
//!
//! The note's formulae are typed here as printed (and as corrected), not taken
//! from [`snowroll::models::InTurnCoefficients`]; the body's masses, centres and
//! moments come from integrals over its elements ([`super::quadrature`]).

use std::f64::consts::PI;

use super::quadrature::{integrate, mass_properties, Sector};
use super::{bound, corrected_if, holds_if, pass, symbols, Finding, Lab, Symbols};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// First turn: I_C(θ) of eq. (56) to O(b), per unit m0.
fn ic56(r0: f64, b: f64, th: f64) -> f64 {
    1.5 * r0 * r0 + 2.0 * b * r0 / PI * (th - th.sin())
}

/// First turn: V(θ) of eq. (62), per unit m0.
fn v62(r0: f64, b: f64, gs: f64, gc: f64, th: f64) -> f64 {
    -r0 * th * gs - (b * th * th / (2.0 * PI) - b / PI * (1.0 - th.cos())) * gs
        + (b * th / PI - b / PI * th.sin()) * gc
}

/// The erratum of §3.1–3.3.
pub(super) const ERRATUM_58_69: &str =
    "docs/errata.md (58), (63), (68)–(69): m → m0, θ/π → bθ/π, b/π → bθ/π";

/// `first-turn-58-64-69`: the corrected forms agree.
pub(super) const FIRST_TURN_AGREE: Criterion = Criterion {
    quantity: "largest |Δa|/G between corrected (58), (64), (69)",
    tolerance: Tolerance::Absolute {
        value: 1e-8,
        unit: "g sin α",
    },
    reason:
        "dV/dθ by central difference (h = 1e-5 rad) errs by ~h²V‴/6 ≈ 1e-11 G; rounding ~1e-11 G",
};
/// `first-turn-58-64-69`: each printed form differs.
pub(super) const FIRST_TURN_APART: Criterion = Criterion {
    quantity: "largest |Δa|/G of printed (58), (63), (69) from corrected (58)",
    tolerance: Tolerance::AtLeast {
        value: 1e-4,
        unit: "g sin α",
    },
    reason: "each misprint changes an O(b/r0) ≈ 1e-2 term; 1e-4 is far above the difference quotient's error",
};

/// (58), (64) and (69) are one equation once corrected; (58), (63) and (69)
/// as printed are not.
pub(super) fn first_turn_equivalence(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { r0, b, gs, gc, .. } = symbols(s);
    let mut worst_corr: f64 = 0.0;
    let mut worst_58: f64 = 0.0;
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
            // (58) as printed: m = m0(1 + bθ/(πr0)) on the right.
            let a58p =
                (r0 * torque * (1.0 + b * th / (PI * r0)) - b * v * v * (1.0 - th.cos()) / PI) / ic;
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
            worst_58 = worst_58.max((a58p - a58).abs() / gs);
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
    let corrected_ok = FIRST_TURN_AGREE.accepts_deviation(worst_corr);
    let apart = [worst_58, worst_63, worst_69]
        .iter()
        .all(|d| FIRST_TURN_APART.accepts_deviation(*d));
    Ok(Finding {
        measured: format!(
            "max |Δa|/G over θ ∈ (0, 2π), 3 speeds: corrected (58) vs (64) vs (69): {worst_corr:.1e}; printed (58) vs corrected: {worst_58:.2e}; printed (63): {worst_63:.3}; printed (69): {worst_69:.2e}"
        ),
        verdict: corrected_if(
            [worst_58, worst_63, worst_69]
                .iter()
                .all(|d| FIRST_TURN_AGREE.accepts_deviation(*d)),
            corrected_ok,
            apart,
            ERRATUM_58_69,
            &[worst_corr, worst_58, worst_63, worst_69],
        ),
        evidence: format!(
            "torque (58), energy (64) with dV/dθ differentiated numerically from (62), and the Lagrangian (69) give the same acceleration ({} {:e} G); the printed (58) counts the O(b) mass factor twice, the printed (63) has the wrong units and the printed (69) differs by (b/π)(θ − 1) G",
            pass(corrected_ok),
            FIRST_TURN_AGREE.value()
        ),
    })
}

/// The erratum of eqs. (47), (48).
pub(super) const ERRATUM_47_48: &str =
    "docs/errata.md (47), (48): cos θ′, y′ = r0 − r′ cos θ′; position −r′ sin θ′, integrand r′² − r0r′ cos θ′";

/// `eq47-48-angular-momentum`: kinematics and integrals against the corrected forms.
pub(super) const EQ47_48_MATCH: Criterion = Criterion {
    quantity: "|ẋ′ by difference − (47)|/(r0θ̇) and relative |∫ integrand of (48) − ∫ dm (x′ − x_cm) × v′|",
    tolerance: Tolerance::Relative { value: 1e-8 },
    reason: "central difference with h = 1e-6 rad errs by ~1e-12, rounding by ~1e-10; the integrals are exact quadratures (rounding ~1e-15)",
};
/// `eq47-48-angular-momentum`: the final line of (48) is first order in b.
pub(super) const EQ48_ORDER: Criterion = Criterion {
    quantity: "ratio of |L_cm exact − L_cm of (48)| for b = 1e-2 r0 and 1e-3 r0, against 100",
    tolerance: Tolerance::Relative { value: 0.05 },
    reason: "a second-order remainder shrinks 100-fold; the third-order term changes that by ~1 %",
};
/// `eq47-48-angular-momentum`: the printed forms are visibly off.
pub(super) const EQ47_48_APART: Criterion = Criterion {
    quantity: "relative difference of printed (47) and printed (48) integrand from the element computation",
    tolerance: Tolerance::AtLeast {
        value: 1e-2,
        unit: "(relative)",
    },
    reason: "cos θ for cos θ′ changes ẋ′ by O(1); the printed integrand gives 2πr0⁴/3 for the disk, not πr0⁴/2",
};

/// Eqs. (47), (48): the velocity of a mass element of the rolling log and
/// its angular momentum about the centre of mass, element by element.
pub(super) fn eq47_48_angular_momentum(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { r0, b, rho_l, .. } = symbols(s);
    let theta = 2.3;
    // (47): the element at (r′, θ′₀) is at θ′ = θ′₀ + θ, x′ = r0θ − r′ sin θ′
    // (θ̇ = 1 rad/s); its ẋ′ by central difference against r0 − r′ cos θ′.
    let h = 1e-6;
    let mut worst_47: f64 = 0.0;
    let mut least_47p = f64::INFINITY;
    for (rp, phase) in [(0.3 * r0, 0.4), (r0, 2.0), (r0 + 0.5 * b, 5.0)] {
        let x_of = |th: f64| r0 * th - rp * (phase + th).sin();
        let xdot = (x_of(theta + h) - x_of(theta - h)) / (2.0 * h);
        let corrected = r0 - rp * (phase + theta).cos();
        let printed = r0 - rp * theta.cos();
        worst_47 = worst_47.max((xdot - corrected).abs() / r0);
        least_47p = least_47p.min((xdot - printed).abs() / r0);
    }
    // (48): the body (disk plus the layer over [0, θ]) with the centre of
    // mass of (43) and the element velocity of (47), θ̇ = 1: rotation about
    // the contact line (r0θ, 0), (ẋ′, ẏ′) = (y′, −(x′ − r0θ)).
    let body = |b: f64| {
        [
            Sector::full((r0 * theta, r0), (0.0, r0), rho_l),
            Sector {
                centre: (r0 * theta, r0),
                radii: (r0, r0 + b),
                angles: (0.0, theta),
                rho_l,
            },
        ]
    };
    let velocity = |x: f64, y: f64| (y, r0 * theta - x);
    let cm43 = |b: f64| {
        (
            r0 * theta - b / PI * (1.0 - theta.cos()),
            r0 - b / PI * theta.sin(),
        )
    };
    let about = |b: f64, p: (f64, f64)| {
        integrate(&body(b), |x, y, _, _| {
            let (ux, uy) = velocity(x, y);
            (x - p.0) * uy - (y - p.1) * ux
        })
    };
    // −L_z/(ρl θ̇) against the note's integrand, corrected and printed.
    let integrand = |b: f64, corrected: bool| {
        integrate(&body(b), |_, _, rp, tp| {
            let tail = (b * rp / PI) * (tp.cos() * theta.sin() + tp.sin() * (1.0 - theta.cos()));
            let head = b * r0 / PI * theta.sin();
            if corrected {
                rp * rp - r0 * rp * tp.cos() + head - tail
            } else {
                r0 * rp * (1.0 - tp.cos()) + head + tail
            }
        })
    };
    let direct = -about(b, cm43(b));
    let dev_48 = EQ47_48_MATCH.deviation(integrand(b, true), direct);
    let dev_48p = (integrand(b, false) - direct).abs() / direct.abs();
    let disk_printed = integrand(0.0, false) / rho_l;
    // The final line of (48): L_cm = −(m0r0²/2 + m0 b r0 θ/π) θ̇, against the
    // exact L_cm about the exact centre of mass, for two depths.
    let m0 = PI * rho_l * r0 * r0;
    let residual = |b: f64| {
        let exact_cm = mass_properties(&body(b), (0.0, 0.0)).centre;
        (about(b, exact_cm) + (m0 * r0 * r0 / 2.0 + m0 * b * r0 * theta / PI)).abs()
    };
    let order_ratio = residual(1e-2 * r0) / residual(1e-3 * r0);
    let corrected_ok = EQ47_48_MATCH.accepts_deviation(worst_47)
        && EQ47_48_MATCH.accepts_deviation(dev_48)
        && EQ48_ORDER.accepts(order_ratio, 100.0);
    let apart =
        EQ47_48_APART.accepts_deviation(least_47p) && EQ47_48_APART.accepts_deviation(dev_48p);
    let numbers = [worst_47, least_47p, dev_48, dev_48p, order_ratio];
    Ok(Finding {
        measured: format!(
            "at θ = {theta} rad: |ẋ′ − (47)|/(r0θ̇) ≤ {worst_47:.1e} corrected, ≥ {least_47p:.2} printed; ∫ integrand of (48) against ∫ dm (x′ − x_cm) × v′: {dev_48:.1e} corrected, {dev_48p:.2} printed (disk alone: printed {disk_printed:.3e} m⁴ against πr0⁴/2 = {:.3e} m⁴); |L_cm exact − (48)| shrinks {order_ratio:.1}-fold for a tenfold smaller b",
            PI * r0.powi(4) / 2.0
        ),
        verdict: corrected_if(
            EQ47_48_MATCH.accepts_deviation(least_47p) && EQ47_48_MATCH.accepts_deviation(dev_48p),
            corrected_ok,
            apart,
            ERRATUM_47_48,
            &numbers,
        ),
        evidence: format!(
            "the element velocity is ((r0 − r′ cos θ′)θ̇, r′θ̇ sin θ′) and the corrected integrand of (48) is the cross product term by term ({}); the final L_cm = −(m0r0²/2 + m0br0θ/π)θ̇ of (48) is right to O(b) (remainder second order: {}); the printed ẋ′ and integrand are not",
            bound(&EQ47_48_MATCH, EQ47_48_MATCH.accepts_deviation(worst_47.max(dev_48))),
            bound(&EQ48_ORDER, EQ48_ORDER.accepts(order_ratio, 100.0))
        ),
    })
}

/// The erratum of eq. (54).
pub(super) const ERRATUM_54: &str = "docs/errata.md (54): θ̈ for θ̇, r0 for r";

/// `eq54-cross-product`: the residual of the corrected form is second order.
pub(super) const EQ54_ORDER: Criterion = Criterion {
    quantity: "ratio of residuals for b = 1e-3 r0 and 1e-4 r0, against 100 (corrected) and 10 (printed)",
    tolerance: Tolerance::Relative { value: 0.05 },
    reason: "a second-order residual shrinks 100-fold, a first-order one 10-fold; the next order changes that by ~0.1 %",
};

/// Erratum (54): the z-component of (x_cm − x_C) × m a_cm from (43), (45).
pub(super) fn eq54_erratum(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let r0 = s.initial_radius();
    // θ, θ̇, θ̈: a generic state (rad, rad/s, rad/s²).
    let (th, w, wdot): (f64, f64, f64) = (1.1, 3.0, 2.0);
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
    let corrected_ok = EQ54_ORDER.accepts(c_ratio, 100.0);
    let printed_first_order = EQ54_ORDER.accepts(p_ratio, 10.0);
    Ok(Finding {
        measured: format!(
            "residual vs exact product for b = 1e-3 r0 → 1e-4 r0 shrinks by {c_ratio:.1} (corrected) and by {p_ratio:.1} (printed)"
        ),
        verdict: corrected_if(
            EQ54_ORDER.accepts(p_ratio, 100.0),
            corrected_ok,
            printed_first_order,
            ERRATUM_54,
            &[c_ratio, p_ratio],
        ),
        evidence: format!(
            "the corrected last line of (54) is the O(b) expansion of the cross product (residual second order: {}); the printed one misses an O(b) term (residual first order: {})",
            bound(&EQ54_ORDER, corrected_ok),
            bound(&EQ54_ORDER, printed_first_order)
        ),
    })
}

/// `eq51-55-accreting-body`: the exact torque and energy equations differ by the derived b³ term.
pub(super) const ACCRETING_B3: Criterion = Criterion {
    quantity: "relative |(energy − torque equation) − b³ρl(2C + 3bθ̇² + 4r0θ̇²)/24|",
    tolerance: Tolerance::Relative { value: 1e-5 },
    reason: "I_C′ and V′ by five-point differences (h = 1e-3 rad): error ~h⁴ of terms 1e4 times the b³ term, plus rounding",
};
/// `eq51-55-accreting-body`: both agree with (55) to first order in b.
pub(super) const ACCRETING_ORDER: Criterion = Criterion {
    quantity: "ratio of |θ̈ exact − θ̈ of (55)| for b = 1e-2 r0 and 1e-3 r0, against 100",
    tolerance: Tolerance::Relative { value: 0.05 },
    reason: "a second-order remainder shrinks 100-fold; the third order changes that by ~1 %",
};

/// Derivation error 3 (`docs/errata.md`): (51) is the relation of a body
/// of constant mass, fed with the acceleration of an accreting one. The
/// rigorous balance (angular momentum about the lab-fixed point at the
/// contact line; the snow joins at rest and is jerked to the body's
/// velocity) is typed here from the body's element integrals:
///
/// `I_C θ̈ + r0 θ̇² M(x − x_cm) + θ̇² ρl(b⁴/4 + r0b³/3) = M[G y_cm − C(x − x_cm)]`,
///
/// and the energy equation `I_C θ̈ + ½ I_C′ θ̇² = −V′`. The two differ by
/// `b³ρl(2C + 3bθ̇² + 4r0θ̇²)/24` only, and both reduce to (55) at O(b).
pub(super) fn eq51_55_accreting_body(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols {
        r0, rho_l, gs, gc, ..
    } = symbols(s);
    // The body at θ: disk plus layer over [0, θ], contact line at (r0θ, 0).
    let body = |b: f64, th: f64| {
        [
            Sector::full((r0 * th, r0), (0.0, r0), rho_l),
            Sector {
                centre: (r0 * th, r0),
                radii: (r0, r0 + b),
                angles: (0.0, th),
                rho_l,
            },
        ]
    };
    let props = |b: f64, th: f64| mass_properties(&body(b, th), (r0 * th, 0.0));
    // Potential of body plus removed slope snow (docs/turn-model.md): the
    // layer's snow came from the slope strip [0, r0θ] at height −b/2.
    let potential = |b: f64, th: f64| {
        let p = props(b, th);
        let m0 = PI * rho_l * r0 * r0;
        let m_s = p.mass - m0;
        let x = r0 * th;
        gc * (p.mass * p.centre.1 - m0 * r0 + m_s * b / 2.0)
            - gs * (p.mass * p.centre.0 - m_s * x / 2.0)
    };
    // Five-point derivative in θ.
    let d = |f: &dyn Fn(f64) -> f64, th: f64| {
        let h = 1e-3;
        (f(th - 2.0 * h) - 8.0 * f(th - h) + 8.0 * f(th + h) - f(th + 2.0 * h)) / (12.0 * h)
    };
    // Returns (θ̈ torque, θ̈ energy, difference of the right-hand sides, derived b³ term, θ̈ of (55)).
    let state = |b: f64, th: f64, w: f64| {
        let p = props(b, th);
        let (dx, y_cm) = (p.centre.0 - r0 * th, p.centre.1);
        let jerk = integrate(
            &[Sector {
                centre: (0.0, 0.0),
                radii: (r0, r0 + b),
                angles: (0.0, 1.0),
                rho_l,
            }],
            |_, _, rp, _| (rp - r0).powi(2),
        );
        let torque_rhs =
            p.mass * (gs * y_cm + gc * dx) - r0 * w * w * p.mass * (-dx) - w * w * jerk;
        let dic = d(&|t| props(b, t).inertia, th);
        let dv = d(&|t| potential(b, t), th);
        let energy_rhs = -dv - 0.5 * dic * w * w;
        let derived = b.powi(3) * rho_l * (2.0 * gc + 3.0 * b * w * w + 4.0 * r0 * w * w) / 24.0;
        // (55), per m0: I_C of (56) θ̈ + (b r0/π)(1 − cos θ)θ̇² = g[...].
        let i55 = 1.5 * r0 * r0 + (b * r0 / PI) * (2.0 * th - 2.0 * th.sin());
        let rhs55 = (r0 + b * th / PI - b / PI * th.sin()) * gs
            - b / PI * (1.0 - th.cos()) * gc
            - (b * r0 / PI) * (1.0 - th.cos()) * w * w;
        (
            torque_rhs / p.inertia,
            energy_rhs / p.inertia,
            energy_rhs - torque_rhs,
            derived,
            rhs55 / i55,
        )
    };
    let b = s.snow_depth();
    let states = [(0.7, 5.0), (2.0, 3.0), (4.0, 8.0), (5.5, 1.0)];
    let mut worst_b3: f64 = 0.0;
    let mut order_ratio_worst: f64 = 0.0;
    let mut ratios = Vec::new();
    for &(th, w) in &states {
        let (_, _, diff, derived, _) = state(b, th, w);
        worst_b3 = worst_b3.max(ACCRETING_B3.deviation(diff, derived));
        let remainder = |bb: f64| {
            let (torque, energy, _, _, a55) = state(bb, th, w);
            (torque - a55).abs().max((energy - a55).abs())
        };
        let ratio = remainder(1e-2 * r0) / remainder(1e-3 * r0);
        order_ratio_worst = order_ratio_worst.max(ACCRETING_ORDER.deviation(ratio, 100.0));
        ratios.push(ratio);
    }
    let ok = ACCRETING_B3.accepts_deviation(worst_b3)
        && ACCRETING_ORDER.accepts_deviation(order_ratio_worst);
    let mut numbers = ratios.clone();
    numbers.push(worst_b3);
    Ok(Finding {
        measured: format!(
            "4 states (θ, θ̇): energy − torque against b³ρl(2C + 3bθ̇² + 4r0θ̇²)/24: max relative deviation {worst_b3:.1e}; |θ̈ − θ̈ of (55)| shrinks {} -fold for a tenfold smaller b",
            ratios
                .iter()
                .map(|r| format!("{r:.1}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        verdict: holds_if(ok, &numbers),
        evidence: format!(
            "the rigorous angular-momentum balance of the accreting body and the energy equation differ only by the derived O(b³) term ({}), and both agree with (55) to first order in b ({}): the result of (51)–(55) stands although (51) is the constant-mass relation",
            bound(&ACCRETING_B3, ACCRETING_B3.accepts_deviation(worst_b3)),
            bound(&ACCRETING_ORDER, ACCRETING_ORDER.accepts_deviation(order_ratio_worst))
        ),
    })
}

/// The erratum of eq. (70).
pub(super) const ERRATUM_70: &str = "docs/errata.md (70): m1 = πρl r1²";

/// `eq70-mass-after-first-turn`: masses against the integrated layer.
pub(super) const MASS_EXACT: Criterion = Criterion {
    quantity:
        "relative |mass − (disk + integrated layer)| for πρl r1² and for turns-exact at θ = 2π",
    tolerance: Tolerance::Relative { value: 1e-12 },
    reason:
        "the quadrature of the layer is exact; the model's mass is a closed form; rounding only",
};
/// `eq70-mass-after-first-turn`: the first-order model drops exactly the b² area.
pub(super) const MASS_FIRST_ORDER: Criterion = Criterion {
    quantity: "relative |turns mass at θ = 2π − (integrated mass − ρlπb²)|",
    tolerance: Tolerance::Relative { value: 1e-12 },
    reason: "eq. (38) keeps m0bθ/(πr0) and drops ρlθb²/2, exactly; rounding only",
};
/// `eq70-mass-after-first-turn`: the printed mass is visibly off.
pub(super) const MASS_PRINTED_APART: Criterion = Criterion {
    quantity: "relative |2πρl r1² − integrated mass|",
    tolerance: Tolerance::AtLeast {
        value: 0.5,
        unit: "(relative)",
    },
    reason: "the printed form doubles the mass",
};

/// Eq. (70): the mass after the first turn, from integrating the layer of
/// snow picked up over the turn, against the printed and corrected (70)
/// and against the masses the two turn models report at θ = 2π.
pub(super) fn eq70_mass(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { rho_l, r0, b, .. } = symbols(s);
    let r1 = r0 + b;
    let integrated = mass_properties(
        &[
            Sector::full((0.0, r0), (0.0, r0), rho_l),
            Sector::full((0.0, r0), (r0, r1), rho_l),
        ],
        (0.0, 0.0),
    )
    .mass;
    let one_turn = SimOptions {
        t_end: 1e3,
        turns: Some(1),
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    let at_turn_end = |kind: ModelKind| -> Result<f64, SimError> {
        let traj = lab.run(kind, s, &one_turn)?;
        Ok(if traj.stop.reason == StopReason::Turns {
            traj.samples.last().map_or(f64::NAN, |p| p.mass_kg)
        } else {
            f64::NAN
        })
    };
    let exact_model = at_turn_end(ModelKind::TurnsExact)?;
    let first_order = at_turn_end(ModelKind::Turns)?;
    let printed = 2.0 * PI * rho_l * r1 * r1;
    let corrected = PI * rho_l * r1 * r1;
    let first_order_want = integrated - PI * rho_l * b * b;
    let corrected_ok = MASS_EXACT.accepts(corrected, integrated)
        && MASS_EXACT.accepts(exact_model, integrated)
        && MASS_FIRST_ORDER.accepts(first_order, first_order_want);
    let dev_printed = (printed - integrated).abs() / integrated;
    Ok(Finding {
        measured: format!(
            "mass after one turn: disk + integrated layer {integrated:.6} kg; πρl r1² {corrected:.6} kg; printed 2πρl r1² {printed:.6} kg; turns-exact at θ = 2π {exact_model:.6} kg; turns (eq. (38)) {first_order:.6} kg"
        ),
        verdict: corrected_if(
            MASS_EXACT.accepts(printed, integrated),
            corrected_ok,
            MASS_PRINTED_APART.accepts_deviation(dev_printed),
            ERRATUM_70,
            &[integrated, exact_model, first_order],
        ),
        evidence: format!(
            "the layer of depth b over the full turn brings the log to πρl r1² and turns-exact counts exactly that ({}); turns counts it to first order, m0(1 + 2b/r0), short by ρlπb² ({}); the printed 2πρl r1² is {dev_printed:.2} too large relative",
            bound(&MASS_EXACT, MASS_EXACT.accepts(corrected, integrated) && MASS_EXACT.accepts(exact_model, integrated)),
            bound(&MASS_FIRST_ORDER, MASS_FIRST_ORDER.accepts(first_order, first_order_want))
        ),
    })
}
