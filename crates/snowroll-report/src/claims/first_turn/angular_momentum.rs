//! Eqs. (47), (48) and (54): the velocity of a mass element of the log in
//! its first turn, its angular momentum about the centre of mass, and the
//! cross product of (54), each against element integrals
//! ([`crate::claims::quadrature`]).

use std::f64::consts::PI;

use crate::claims::quadrature::{integrate, mass_properties, Sector};
use crate::claims::{bound, corrected_if, symbols, Finding, Lab, Symbols};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;

/// The erratum of eqs. (47), (48).
pub(in crate::claims) const ERRATUM_47_48: &str =
    "docs/errata.md (47), (48): cos θ′, y′ = r0 − r′ cos θ′; position −r′ sin θ′, integrand r′² − r0r′ cos θ′";

/// `eq47-48-angular-momentum`: kinematics and integrals against the corrected forms.
pub(in crate::claims) const EQ47_48_MATCH: Criterion = Criterion {
    quantity: "|ẋ′ by difference − (47)|/(r0θ̇) and relative |∫ integrand of (48) − ∫ dm (x′ − x_cm) × v′|",
    tolerance: Tolerance::Relative { value: 1e-8 },
    reason: "central difference with h = 1e-6 rad errs by ~1e-12, rounding by ~1e-10; the integrals are exact quadratures (rounding ~1e-15)",
};
/// `eq47-48-angular-momentum`: the final line of (48) is first order in b.
pub(in crate::claims) const EQ48_ORDER: Criterion = Criterion {
    quantity: "ratio of |L_cm exact − L_cm of (48)| for b = 1e-2 r0 and 1e-3 r0, against 100",
    tolerance: Tolerance::Relative { value: 0.05 },
    reason: "a second-order remainder shrinks 100-fold; the third-order term changes that by ~1 %",
};
/// `eq47-48-angular-momentum`: the printed forms are visibly off.
pub(in crate::claims) const EQ47_48_APART: Criterion = Criterion {
    quantity: "relative difference of printed (47) and printed (48) integrand from the element computation",
    tolerance: Tolerance::AtLeast {
        value: 1e-2,
        unit: "(relative)",
    },
    reason: "cos θ for cos θ′ changes ẋ′ by O(1); the printed integrand gives 2πr0⁴/3 for the disk, not πr0⁴/2",
};

/// (47) at θ for three mass elements: the largest miss of the corrected
/// ẋ′ = r0 − r′ cos θ′ from the difference quotient of x′, and the smallest
/// miss of the printed r0 − r′ cos θ, both over r0θ̇.
fn eq47_misses(r0: f64, b: f64, theta: f64) -> (f64, f64) {
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
    (worst_47, least_47p)
}

/// The log at θ for (48): the disk plus the layer over [0, θ], with the
/// centre of mass of (43) and the element velocity of (47) at θ̇ = 1, a
/// rotation about the contact line (r0θ, 0): (ẋ′, ẏ′) = (y′, −(x′ − r0θ)).
#[derive(Debug, Clone, Copy)]
struct RollingBody {
    /// Initial radius r0, m.
    r0: f64,
    /// Angle rolled θ, rad.
    theta: f64,
    /// ρl, kg/m.
    rho_l: f64,
}

impl RollingBody {
    /// The disk and the layer of depth `b`.
    fn sectors(&self, b: f64) -> [Sector; 2] {
        let Self { r0, theta, rho_l } = *self;
        [
            Sector::full((r0 * theta, r0), (0.0, r0), rho_l),
            Sector {
                centre: (r0 * theta, r0),
                radii: (r0, r0 + b),
                angles: (0.0, theta),
                rho_l,
            },
        ]
    }

    /// The velocity of the element at (x, y).
    fn velocity(&self, x: f64, y: f64) -> (f64, f64) {
        (y, self.r0 * self.theta - x)
    }

    /// The centre of mass of (43) for depth `b`.
    fn cm43(&self, b: f64) -> (f64, f64) {
        let Self { r0, theta, .. } = *self;
        (
            r0 * theta - b / PI * (1.0 - theta.cos()),
            r0 - b / PI * theta.sin(),
        )
    }

    /// L_z about the point `p`, ∫ dm (x′ − p) × v′, for depth `b`.
    fn about(&self, b: f64, p: (f64, f64)) -> f64 {
        integrate(&self.sectors(b), |x, y, _, _| {
            let (ux, uy) = self.velocity(x, y);
            (x - p.0) * uy - (y - p.1) * ux
        })
    }

    /// The note's integrand of (48), corrected or printed, integrated over
    /// the body of depth `b`: to be compared with −L_z/(ρl θ̇).
    fn integrand(&self, b: f64, corrected: bool) -> f64 {
        let Self { r0, theta, .. } = *self;
        integrate(&self.sectors(b), |_, _, rp, tp| {
            let tail = (b * rp / PI) * (tp.cos() * theta.sin() + tp.sin() * (1.0 - theta.cos()));
            let head = b * r0 / PI * theta.sin();
            if corrected {
                rp * rp - r0 * rp * tp.cos() + head - tail
            } else {
                r0 * rp * (1.0 - tp.cos()) + head + tail
            }
        })
    }

    /// |L_cm exact − L_cm of the final line of (48)| for depth `b`: the
    /// exact L_cm about the exact centre of mass against
    /// −(m0r0²/2 + m0 b r0 θ/π) θ̇.
    fn l_cm_residual(&self, b: f64) -> f64 {
        let Self { r0, theta, rho_l } = *self;
        let m0 = PI * rho_l * r0 * r0;
        let exact_cm = mass_properties(&self.sectors(b), (0.0, 0.0)).centre;
        (self.about(b, exact_cm) + (m0 * r0 * r0 / 2.0 + m0 * b * r0 * theta / PI)).abs()
    }
}

/// Eqs. (47), (48): the velocity of a mass element of the rolling log and
/// its angular momentum about the centre of mass, element by element.
pub(in crate::claims) fn eq47_48_angular_momentum(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { r0, b, rho_l, .. } = symbols(s);
    let theta = 2.3;
    let (worst_47, least_47p) = eq47_misses(r0, b, theta);
    let body = RollingBody { r0, theta, rho_l };
    // −L_z/(ρl θ̇) against the note's integrand, corrected and printed.
    let direct = -body.about(b, body.cm43(b));
    let dev_48 = EQ47_48_MATCH.deviation(body.integrand(b, true), direct);
    let dev_48p = (body.integrand(b, false) - direct).abs() / direct.abs();
    let disk_printed = body.integrand(0.0, false) / rho_l;
    // The final line of (48), for two depths.
    let order_ratio = body.l_cm_residual(1e-2 * r0) / body.l_cm_residual(1e-3 * r0);
    let corrected_ok = EQ47_48_MATCH.accepts_deviation(worst_47)
        && EQ47_48_MATCH.accepts_deviation(dev_48)
        && EQ48_ORDER.accepts(order_ratio, 100.0);
    let apart =
        EQ47_48_APART.accepts_deviation(least_47p) && EQ47_48_APART.accepts_deviation(dev_48p);
    let numbers = [worst_47, least_47p, dev_48, dev_48p, order_ratio];
    Ok(Finding {
        headline: None,
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
pub(in crate::claims) const ERRATUM_54: &str = "docs/errata.md (54): θ̈ for θ̇, r0 for r";

/// `eq54-cross-product`: the residual of the corrected form is second order.
pub(in crate::claims) const EQ54_ORDER: Criterion = Criterion {
    quantity: "ratio of residuals for b = 1e-3 r0 and 1e-4 r0, against 100 (corrected) and 10 (printed)",
    tolerance: Tolerance::Relative { value: 0.05 },
    reason: "a second-order residual shrinks 100-fold, a first-order one 10-fold; the next order changes that by ~0.1 %",
};

/// Erratum (54): the z-component of (x_cm − x_C) × m a_cm from (43), (45).
pub(in crate::claims) fn eq54_erratum(lab: &Lab) -> Result<Finding, SimError> {
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
        headline: None,
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
