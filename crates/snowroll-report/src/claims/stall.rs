//! fn. 7 in the setting the note gives it, §3: on the turn models the log
//! always starts (a(0) = 2G/3, no snow lifted yet) but may stall inside its
//! first turn. The threshold slope is found by bisection on the simulated
//! models and compared with the closed form typed here from eqs. (62),
//! (73) and with its leading orders in ε = b/(πr0)
//! (`docs/turn-model.md`, "Stall in the first turn").

use std::f64::consts::PI;

use super::circular::bisect;
use super::quadrature::{mass_properties, Sector};
use super::{alpha_deg, edited, holds_if, pass, symbols, Edit, Finding, Lab, Symbols};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::scenario::Scenario;
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// `fn7-stall-in-first-turn`: a(0)/G of `turns`.
pub(super) const TURN_START: Criterion = Criterion {
    quantity: "|a(0)/G − 2/3| of turns from rest",
    tolerance: Tolerance::Absolute {
        value: 1e-12,
        unit: "g sin α",
    },
    reason: "nothing is lifted yet at θ = 0, so eq. (73) gives a(0) = 2G/3 exactly; rounding only",
};
/// `fn7-stall-in-first-turn`: a(0)/G of `turns-exact`.
pub(super) const TURN_START_EXACT: Criterion = Criterion {
    quantity: "|a(0)/G − 2/3| of turns-exact from rest",
    tolerance: Tolerance::Absolute {
        value: 1e-3,
        unit: "g sin α",
    },
    reason: "the exact layer is a wedge whose centroid lies below the slab it came from: an extra push (C/G) b³/(18π r0³) ≈ 3e-5 G at the defaults",
};
/// `fn7-stall-in-first-turn`: the simulated threshold against the closed form.
pub(super) const TURN_STALL_FORMULA: Criterion = Criterion {
    quantity: "relative |tan α* by bisection on turns − tan α* of the closed form|",
    tolerance: Tolerance::Relative { value: 1e-6 },
    reason: "bisection to 1e-12 degree; near the threshold θ̇ touches 0, which the stall event locates to the integrator's tolerance",
};
/// `fn7-stall-in-first-turn`: the simulated threshold of `turns-exact`
/// against the one integrated here over the exact body.
pub(super) const TURN_STALL_EXACT: Criterion = Criterion {
    quantity: "relative |tan α* by bisection on turns-exact − max Q/P of the exact disk and layer, integrated element by element|",
    tolerance: Tolerance::Relative { value: 1e-6 },
    reason: "as above, plus the 4-point Gauss panels of π/4 over sin and cos (relative error ~1e-10)",
};
/// `fn7-stall-in-first-turn`: the simulated thresholds against the library's (shown by `snowroll models`).
pub(super) const TURN_STALL_LIBRARY: Criterion = Criterion {
    quantity:
        "relative |tan α* by bisection − tan α* of the library's closed-form stall slope| for both turn models",
    tolerance: Tolerance::Relative { value: 1e-6 },
    reason: "as above: bisection and stall-event resolution",
};
/// `fn7-stall-in-first-turn`: the orders of the leading-order forms.
pub(super) const TURN_STALL_ORDER: Criterion = Criterion {
    quantity: "error ratios of the leading and first-corrected forms from ε/10 to ε/100, against 10 and 100",
    tolerance: Tolerance::Relative { value: 0.05 },
    reason: "the ratios are 10 and 100 up to a relative O(ε/10) ≈ 1 % at the defaults",
};

/// `fn7-stall-in-first-turn`: how far above and below the threshold the runs start.
pub(super) const TURN_STALL_MARGIN: Criterion = Criterion {
    quantity: "offset of the runs above and below α* (turn models)",
    tolerance: Tolerance::Absolute {
        value: 0.01,
        unit: "degree",
    },
    reason: "0.5 % of α* at the defaults: a model whose threshold is off by more stalls above it or rolls on below it",
};

/// Golden-section fraction `(3 − √5)/2`.
const GOLDEN: f64 = 0.381_966_011_250_105_1;
/// Grid points over (0, 2π] that bracket the maximum of the ratio.
const GRID: usize = 4096;
/// The same for the exact body, whose ratio costs three quadratures (it
/// has one maximum, near θ₁ ≈ 4.49, so a coarser grid brackets it).
const EXACT_GRID: usize = 256;

/// tan α* typed from eqs. (62), (73) (first-order in b, turn 0, from rest):
/// θ̇² = −2W/I with `W/(m0 r0) = −G[θ + ε(θ²/2 − 1 + cos θ)] + C ε (θ − sin θ)`,
/// so the log completes the turn iff
/// `tan α > max ε(θ − sin θ)/(θ + ε(θ²/2 − 1 + cos θ))` over 0 < θ ≤ 2π.
pub(super) fn closed_form_tan(eps: f64) -> f64 {
    max_over_turn(GRID, |t| {
        eps * (t - t.sin()) / (t + eps * (t * t / 2.0 - 1.0 + t.cos()))
    })
}

/// tan α* of the exact first turn (`docs/turn-model.md`, "The first turn
/// with exact geometry"), integrated here element by element: the disk r0
/// plus the layer r0 < r′ < r0 + b over θ′ ∈ [0, θ], the contact line at
/// x = r0 θ; V = C Q − G P with `Q = M y_cm − m r0 + m_s b/2` and
/// `P = M x_cm − m_s x/2` (the layer's snow from the strip [0, x] at depth
/// b/2), so the log completes the turn from rest iff tan α > max Q/P.
fn exact_body_tan(b: f64, r0: f64, rho_l: f64) -> f64 {
    let m = PI * rho_l * r0 * r0;
    max_over_turn(EXACT_GRID, |theta| {
        let x = r0 * theta;
        let layer = Sector {
            centre: (x, r0),
            radii: (r0, r0 + b),
            angles: (0.0, theta),
            rho_l,
        };
        let body = [Sector::full((x, r0), (0.0, r0), rho_l), layer];
        let p = mass_properties(&body, (x, 0.0));
        let m_s = p.mass - m;
        let q = p.mass * p.centre.1 - m * r0 + m_s * b / 2.0;
        let pp = p.mass * p.centre.0 - m_s * x / 2.0;
        q / pp
    })
}

/// The maximum of `f` over (0, 2π]: the best of `grid` points, refined by
/// golden-section search between its neighbours.
fn max_over_turn(grid: usize, f: impl Fn(f64) -> f64) -> f64 {
    let step = 2.0 * PI / grid as f64;
    let best = (1..=grid)
        .max_by(|&i, &j| f(i as f64 * step).total_cmp(&f(j as f64 * step)))
        .unwrap_or(grid);
    let (mut lo, mut hi) = (
        (best as f64 - 1.0) * step,
        ((best + 1) as f64 * step).min(2.0 * PI),
    );
    for _ in 0..100 {
        let (a, b) = (lo + GOLDEN * (hi - lo), hi - GOLDEN * (hi - lo));
        if f(a) > f(b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    f(0.5 * (lo + hi)).max(f(2.0 * PI))
}

/// θ₁, the first positive root of tan θ = θ (in (π, 3π/2)), by Newton's method.
fn theta_1() -> f64 {
    let mut t: f64 = 4.5;
    for _ in 0..50 {
        let tan = t.tan();
        t -= (tan - t) / (tan * tan);
    }
    t
}

/// The leading-order form `tan α* ≈ ε(1 − cos θ₁)` and the first-corrected
/// one `ε(1 − cos θ₁)/(1 + ε(θ₁²/2 − 1 + cos θ₁)/θ₁)` (relative errors O(ε)
/// and O(ε²): the maximiser moves by O(ε), which changes the maximum only
/// at second order).
fn leading_forms(eps: f64) -> (f64, f64) {
    let t1 = theta_1();
    let lead = eps * (1.0 - t1.cos());
    (
        lead,
        lead / (1.0 + eps * (t1 * t1 / 2.0 - 1.0 + t1.cos()) / t1),
    )
}

/// The relative errors of the leading and the first-corrected forms
/// against the closed form at ε, and how much each error shrinks from ε/10
/// to ε/100 (tenfold for an O(ε) error, a hundredfold for an O(ε²) one).
fn leading_form_errors(eps: f64) -> ((f64, f64), (f64, f64)) {
    let err = |e: f64| {
        let (l, c) = leading_forms(e);
        let exact = closed_form_tan(e);
        ((l / exact - 1.0).abs(), (c / exact - 1.0).abs())
    };
    let (e1, e2) = err(eps);
    let (d1, d2) = err(eps / 10.0);
    let (f1, f2) = err(eps / 100.0);
    ((e1, e2), (d1 / f1, d2 / f2))
}

/// Whether `kind` started from rest at `deg` degrees stalls inside its
/// first turn (and the run that says so).
pub(super) fn stalls_in_first_turn(
    lab: &Lab,
    kind: ModelKind,
    base: &Scenario,
    deg: f64,
    turns: u64,
) -> Result<(bool, StopReason, f64), SimError> {
    let s = edited(
        base,
        Edit {
            alpha_deg: Some(deg),
            ..Edit::default()
        },
    )?;
    let traj = lab.run(
        kind,
        &s,
        &SimOptions {
            t_end: 1e4,
            turns: Some(turns),
            sampling: Sampling::Ends,
            ..SimOptions::default()
        },
    )?;
    let first_turn = 2.0 * PI * s.initial_radius();
    let a0 = traj
        .samples
        .first()
        .map_or(f64::NAN, |p| p.a_m_s2 / s.g_along());
    Ok((
        traj.stop.reason == StopReason::Stalled && traj.stop.x_m < first_turn,
        traj.stop.reason,
        a0,
    ))
}

/// One turn model of `fn7-stall-in-first-turn` on `base`: its threshold by
/// bisection against `independent` (tan α*, the closed form for `turns`,
/// the exact body integrated here for `turns-exact`) and the library's,
/// and runs [`TURN_STALL_MARGIN`] below and above `independent` (must
/// start, then stall in turn 0; must roll on). Returns (whether all hold,
/// the numbers behind them, the measured text).
fn judge_turn_model(
    lab: &Lab,
    kind: ModelKind,
    base: &Scenario,
    independent: f64,
) -> Result<(bool, [f64; 4], String), SimError> {
    let (b, r0) = (base.snow_depth(), base.initial_radius());
    let margin = TURN_STALL_MARGIN.value();
    let sim = bisect(1e-3, 60.0, |deg| {
        Ok(!stalls_in_first_turn(lab, kind, base, deg, 1)?.0)
    })?;
    let library = kind
        .stall_threshold(b, r0)
        .map_or(f64::NAN, |t| t.slope.tan());
    let (criterion, start, name) = if kind == ModelKind::Turns {
        (TURN_STALL_FORMULA, TURN_START, "closed form")
    } else {
        (TURN_STALL_EXACT, TURN_START_EXACT, "exact body integrated")
    };
    // The runs bracket the independent threshold, not the bisected one.
    let at = independent.atan().to_degrees();
    let (stalls_below, _, a0_below) = stalls_in_first_turn(lab, kind, base, at - margin, 1)?;
    let (stalls_above, reason_above, a0_above) =
        stalls_in_first_turn(lab, kind, base, at + margin, 3)?;
    let rolls_on = !stalls_above && reason_above == StopReason::Turns;
    let sim_tan = sim.to_radians().tan();
    let start_ok = start.accepts(a0_below, 2.0 / 3.0) && start.accepts(a0_above, 2.0 / 3.0);
    let ok = start_ok
        && stalls_below
        && rolls_on
        && TURN_STALL_LIBRARY.accepts(sim_tan, library)
        && criterion.accepts(sim_tan, independent);
    let part = format!(
        "{}: α* = {sim:.6}° by bisection (library {:.6}°, {name} {at:.6}°), a(0)/G = {a0_below:.12}; {margin}° below that the log stalls in turn 0: {stalls_below}; {margin}° above it rolls on for 3 turns: {rolls_on}",
        kind.id(),
        library.atan().to_degrees(),
    );
    Ok((ok, [sim, library, a0_below, a0_above], part))
}

/// fn. 7 in §3: the turn models start at a = 2G/3 and stall inside turn 0
/// below the threshold slope.
pub(super) fn stall_in_first_turn(lab: &Lab) -> Result<Finding, SimError> {
    let base = edited(
        lab.scenario(),
        Edit {
            v0: Some(0.0),
            ..Edit::default()
        },
    )?;
    let Symbols { b, r0, rho_l, .. } = symbols(&base);
    let eps = b / (PI * r0);
    let closed = closed_form_tan(eps);
    let exact = exact_body_tan(b, r0, rho_l);
    let (lead, corrected) = leading_forms(eps);
    let mut ok = true;
    let mut numbers = vec![closed, exact, lead, corrected];
    let mut parts = Vec::new();
    let margin = TURN_STALL_MARGIN.value();
    for (kind, independent) in [(ModelKind::Turns, closed), (ModelKind::TurnsExact, exact)] {
        let (kind_ok, kind_numbers, part) = judge_turn_model(lab, kind, &base, independent)?;
        ok &= kind_ok;
        numbers.extend(kind_numbers);
        parts.push(part);
    }
    // The orders of the leading forms, on the closed form at ε and ε/10.
    let ((e1, e2), (ratio_lead, ratio_corr)) = leading_form_errors(eps);
    let orders_ok =
        TURN_STALL_ORDER.accepts(ratio_lead, 10.0) && TURN_STALL_ORDER.accepts(ratio_corr, 100.0);
    ok &= orders_ok;
    numbers.extend([ratio_lead, ratio_corr]);
    let deg = |t: f64| t.atan().to_degrees();
    Ok(Finding {
        headline: Some(format!(
            "In the turn model a light log starts and stalls within its first turn below {:.4}° (turns) or {:.4}° (turns-exact) at b/r0 = {}",
            deg(closed),
            deg(exact),
            snowroll::format_readable(b / r0)
        )),
        measured: format!(
            "b = {b} m, r0 = {r0} m (ε = b/(πr0) = {eps:.5}): {}; closed form {:.6}°, leading order ε(1 − cos θ₁) {:.4}° (error {:.2} %), first-corrected {:.5}° (error {:.3} %); error ratios from ε/10 to ε/100: {ratio_lead:.2} and {ratio_corr:.1}",
            parts.join("; "),
            deg(closed),
            deg(lead),
            100.0 * e1,
            deg(corrected),
            100.0 * e2
        ),
        verdict: holds_if(ok, &numbers),
        evidence: format!(
            "from rest θ̇² = −2W(θ)/I(θ) in turn 0, so the log stalls there iff tan α ≤ max over θ of ε(θ − sin θ)/(θ + ε(θ²/2 − 1 + cos θ)) for eq. (73), of Q/P for the exact disk and layer (V = CQ − GP integrated element by element); the bisections on the simulated turns and turns-exact are {} {:e} of these, and runs {margin}° below and above these independent thresholds stall and roll on; θ₁ = {:.6} rad; the slope used ({:.2}°) is far above the threshold",
            pass(ok),
            TURN_STALL_FORMULA.value(),
            theta_1(),
            alpha_deg(lab.scenario())
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::circular::STALL_TOL_DEG;

    #[test]
    fn the_tolerance_quotes_the_bisections_resolution() {
        let quoted = format!("bisection to {STALL_TOL_DEG:e} degree");
        assert!(TURN_STALL_FORMULA.reason.contains(&quoted), "{quoted}");
    }

    /// The exact body's threshold tends to the first-order one as b → 0,
    /// their relative difference falling like ε (tenfold per tenfold b).
    #[test]
    fn the_exact_first_turn_threshold_tends_to_the_first_order_one() {
        let (r0, rho_l) = (0.1, 1.0);
        let diff =
            |b: f64| (exact_body_tan(b, r0, rho_l) / closed_form_tan(b / (PI * r0)) - 1.0).abs();
        let (d1, d2) = (diff(1e-3), diff(1e-4));
        assert!(d1 < 0.02 && (d1 / d2 - 10.0).abs() < 1.0, "{d1:e} {d2:e}");
    }
}
