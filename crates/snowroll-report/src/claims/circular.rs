//! Checks of §2 (the circular log): the four analyses, the Lagrangian's
//! omission, eq. (5), Loney's closed form (fn. 4), and the threshold slope
//! of fn. 7.
//!
//! Each equation the checks compare with is typed here from the note (as
//! printed, and as corrected in `docs/errata.md`); the models are observed
//! only through their runs ([`Lab::run`], [`Lab::acceleration_at`]).

use std::f64::consts::PI;

use super::{
    corrected_if, edited, finite, holds_if, pass, refuted_if, symbols, Edit, Finding, Lab, Symbols,
};
use crate::{Criterion, Tolerance, Verdict};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// The four analyses of §2.1–2.3 as the note prints them.
const FOUR: [ModelKind; 4] = [
    ModelKind::TorqueCm,
    ModelKind::TorqueContact,
    ModelKind::Energy,
    ModelKind::LagrangianPrinted,
];

/// `circular-analyses-differ`: the smallest difference of a/G between two analyses.
pub(super) const DIFFER: Criterion = Criterion {
    quantity: "smallest pairwise |Δa|/G at t = 10 s",
    tolerance: Tolerance::AtLeast {
        value: 1e-3,
        unit: "g sin α",
    },
    reason: "far above the integration error (~1e-9 G at rtol 1e-10) and below the gap any two distinct drag coefficients leave",
};

/// The four analyses give four different equations of motion.
pub(super) fn circular_differ(lab: &Lab) -> Result<Finding, SimError> {
    let opts = SimOptions {
        sampling: Sampling::Times(vec![10.0]),
        t_end: 10.0,
        ..SimOptions::default()
    };
    let mut values = Vec::new();
    for kind in FOUR {
        values.push((
            kind,
            super::last_a_over_g(lab, kind, lab.scenario(), &opts)?,
        ));
    }
    let mut min_gap = f64::INFINITY;
    for (i, a) in values.iter().enumerate() {
        for b in &values[i + 1..] {
            min_gap = min_gap.min((a.1 - b.1).abs());
        }
    }
    let ok = DIFFER.accepts_deviation(min_gap);
    let measured = values
        .iter()
        .map(|(k, v)| format!("{} a/G = {v:.4}", k.equation()))
        .collect::<Vec<_>>()
        .join("; ");
    Ok(Finding {
        measured: format!("at t = 10 s: {measured}"),
        verdict: holds_if(ok, &[min_gap]),
        evidence: format!(
            "smallest pairwise difference of a/(g sin α) = {min_gap:.3e}, {} the bound of at least {:e}",
            pass(ok),
            DIFFER.value()
        ),
    })
}

/// `circular-agree-as-b-vanishes`: the spread must fall like b.
pub(super) const SPREAD_LINEAR: Criterion = Criterion {
    quantity: "ratio of spreads for a hundredfold smaller b, against 100",
    tolerance: Tolerance::Relative { value: 0.1 },
    reason: "the O(b²) remainder is < 1e-4 of the O(b) spread at b ≤ 1e-6 m; 10 % leaves room for integration noise at b = 1e-10 m",
};
/// `circular-agree-as-b-vanishes`: the spread at the smallest b.
pub(super) const SPREAD_SMALL: Criterion = Criterion {
    quantity: "largest |a/G − 2/3| at b = 1e-10 m",
    tolerance: Tolerance::Absolute {
        value: 1e-6,
        unit: "g sin α",
    },
    reason: "the snow terms are O(b/r0) = 1e-9 there; 1e-6 fails any analysis whose snowless part is not 2G/3",
};

/// All four agree on (2/3) g sin α as b → 0, the deviation shrinking like b.
pub(super) fn circular_agree_as_b_vanishes(lab: &Lab) -> Result<Finding, SimError> {
    let opts = SimOptions {
        t_end: 5.0,
        ..SimOptions::default()
    };
    let mut spreads = Vec::new();
    for b in [1e-6, 1e-8, 1e-10] {
        let s = edited(
            lab.scenario(),
            Edit {
                snow_depth: Some(b),
                ..Edit::default()
            },
        )?;
        let mut worst: f64 = 0.0;
        for kind in FOUR {
            for p in lab.run(kind, &s, &opts)?.samples {
                worst = worst.max((p.a_m_s2 / s.g_along() - 2.0 / 3.0).abs());
            }
        }
        spreads.push((b, worst));
    }
    let ratios: Vec<f64> = spreads.windows(2).map(|w| w[0].1 / w[1].1).collect();
    let linear = ratios.iter().all(|r| SPREAD_LINEAR.accepts(*r, 100.0));
    let small = SPREAD_SMALL.accepts(spreads[2].1, 0.0);
    let mut numbers = ratios.clone();
    numbers.push(spreads[2].1);
    Ok(Finding {
        measured: spreads
            .iter()
            .map(|(b, w)| format!("b = {b:e} m: max |a/G − 2/3| = {w:.2e}"))
            .collect::<Vec<_>>()
            .join("; "),
        verdict: holds_if(linear && small, &numbers),
        evidence: format!(
            "each hundredfold reduction of b reduces the spread by {:.1} and {:.1} ({} {:.0} % of 100: first order in b); at b = 1e-10 m the spread {:.1e} is {} {:e}",
            ratios[0],
            ratios[1],
            pass(linear),
            100.0 * SPREAD_LINEAR.value(),
            spreads[2].1,
            pass(small),
            SPREAD_SMALL.value()
        ),
    })
}

/// `lagrangian-differs-from-energy`: corrected (21) against the measured (14).
pub(super) const LAGRANGE_CORRECTED: Criterion = Criterion {
    quantity: "|a of (21) with ∂T/∂x restored − a of the energy model|/G",
    tolerance: Tolerance::Absolute {
        value: 1e-12,
        unit: "g sin α",
    },
    reason: "the two are one formula term by term; only the rounding of a few operations (~1e-15) remains",
};
/// `lagrangian-differs-from-energy`: the printed difference against its derived form.
pub(super) const LAGRANGE_DIFFERENCE: Criterion = Criterion {
    quantity: "|(a₂₁ − a₁₄) measured − its derived form|/G",
    tolerance: Tolerance::Absolute {
        value: 1e-12,
        unit: "g sin α",
    },
    reason: "an identity of the two printed equations; rounding only",
};
/// `lagrangian-differs-from-energy`: the printed (21) is visibly not (14).
pub(super) const LAGRANGE_APART: Criterion = Criterion {
    quantity: "largest |a₂₁ − a₁₄|/G over the grid",
    tolerance: Tolerance::AtLeast {
        value: 1e-3,
        unit: "g sin α",
    },
    reason: "far above rounding, far below the omitted bv²/(2πr²) at the grid's faster states (up to tens of G)",
};

/// Positions of the grid of states on which (21) and (14) are compared, m.
const LAGRANGE_XS: [f64; 5] = [0.0, 0.3, 3.0, 30.0, 300.0];
/// Speeds of that grid, m/s.
const LAGRANGE_VS: [f64; 4] = [0.5, 2.0, 8.0, 30.0];

/// `{a, b, c}` for a grid axis.
fn grid_set(values: &[f64]) -> String {
    let list: Vec<String> = values.iter().map(f64::to_string).collect();
    format!("{{{}}}", list.join(", "))
}

/// The Lagrangian result (21) "differs slightly" from (14): an artefact of
/// the missing ∂T/∂x (`docs/errata.md`, derivation error 1). What holds
/// instead, and is measured: (21) with ∂T/∂x restored is (14), and the
/// printed (21) differs from (14) by exactly `−(b v²/(2πr²))/(1 + b²/(6π²r²))`.
pub(super) fn lagrangian_vs_energy(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { b, gs, gc, r0, .. } = symbols(s);
    let mut worst_corrected: f64 = 0.0;
    let mut worst_difference: f64 = 0.0;
    let mut largest_gap: f64 = 0.0;
    for x in LAGRANGE_XS {
        let r2 = r0 * r0 + b * x / PI;
        let r = r2.sqrt();
        for v in LAGRANGE_VS {
            let a14 = lab.acceleration_at(ModelKind::Energy, r, v)?;
            let a21 = lab.acceleration_at(ModelKind::LagrangianPrinted, r, v)?;
            // (17), (18) and (19) with ∂T/∂x = (3/4)ρ l b v² restored (per ρl):
            // (3πr²/2) a (1 + b²/6π²r²) = π r² G − 3bv²/4 − (C/2)(3rb + b²).
            let inertia = 1.0 + b * b / (6.0 * PI * PI * r2);
            let a_corrected = (PI * r2 * gs - 0.75 * b * v * v - 0.5 * gc * (3.0 * r * b + b * b))
                / (1.5 * PI * r2 * inertia);
            worst_corrected = worst_corrected.max((a_corrected - a14).abs() / gs);
            // (21) − (14) as printed: drag b v²/(πr²) against b v²/(2πr²).
            let derived = -(b * v * v / (2.0 * PI * r2)) / inertia;
            worst_difference = worst_difference.max(((a21 - a14) - derived).abs() / gs);
            largest_gap = largest_gap.max((a21 - a14).abs() / gs);
        }
    }
    let corrected_ok = LAGRANGE_CORRECTED.accepts_deviation(worst_corrected);
    let difference_ok = LAGRANGE_DIFFERENCE.accepts_deviation(worst_difference);
    let apart = LAGRANGE_APART.accepts_deviation(largest_gap);
    let numbers = [worst_corrected, worst_difference, largest_gap];
    Ok(Finding {
        measured: format!(
            "on the {}-state grid x ∈ {} m × v ∈ {} m/s: max |a(21 corrected) − a(14)|/G = {worst_corrected:.1e}; max |(a₂₁ − a₁₄) − derived|/G = {worst_difference:.1e}; max |a₂₁ − a₁₄|/G = {largest_gap:.4}",
            LAGRANGE_XS.len() * LAGRANGE_VS.len(),
            grid_set(&LAGRANGE_XS),
            grid_set(&LAGRANGE_VS)
        ),
        verdict: if finite(&numbers) {
            refuted_if(apart, corrected_ok && difference_ok)
        } else {
            Verdict::Inconclusive
        },
        evidence: format!(
            "restoring ∂T/∂x = (3/4)ρlbv² in eq. (19) turns (21) into (14) ({} {:e}); the printed (21) differs from (14) by −(bv²/2πr²)/(1 + b²/6π²r²) ({} {:e}), up to {largest_gap:.4} G on that grid (at its fastest, smallest-radius state): the difference is the omission, not a second equation of motion",
            pass(corrected_ok),
            LAGRANGE_CORRECTED.value(),
            pass(difference_ok),
            LAGRANGE_DIFFERENCE.value()
        ),
    })
}

/// Loney's closed form, fn. 4: `u = v² = 2G s/(5b) + K s^(−7/3)`,
/// `s = π r0² + b x`, with K from `u(0) = v0²`, i.e.
/// `K = (v0² − 2G s0/(5b)) s0^(7/3)`. Written as
/// `u = (2G s/(5b)) (1 − (s0/s)^(10/3)) + v0² (s0/s)^(7/3)` and evaluated
/// through `ln(1 + b x/s0)` so that nothing cancels near x = 0. Returns
/// `(u(x), K)`.
fn loney_u(g_along: f64, b: f64, r0: f64, v0: f64, x: f64) -> (f64, f64) {
    let s0 = PI * r0 * r0;
    let k = (v0 * v0 - 2.0 * g_along * s0 / (5.0 * b)) * s0.powf(7.0 / 3.0);
    let s = s0 + b * x;
    let ln_ratio = (b * x / s0).ln_1p();
    let u = 2.0 * g_along * s / (5.0 * b) * -(-(10.0 / 3.0) * ln_ratio).exp_m1()
        + v0 * v0 * (-(7.0 / 3.0) * ln_ratio).exp();
    (u, k)
}

/// `loney-solves-eq4`: the integrated eq. (4) against fn. 4's u(x).
pub(super) const LONEY_SPEED: Criterion = Criterion {
    quantity: "relative |v of eq. (4) − v of fn. 4| over 0 ≤ x ≤ 10 km",
    tolerance: Tolerance::Relative { value: 1e-9 },
    reason: "DOP853 at rtol 1e-10 accumulates ≲ 1e-9 relative error in v over 10 km",
};

/// Loney's closed form solves eq. (4).
pub(super) fn loney_closed_form(lab: &Lab) -> Result<Finding, SimError> {
    let mut worst: f64 = 0.0;
    let base = *lab.scenario();
    let scenarios = [
        base,
        edited(
            &base,
            Edit {
                alpha_deg: Some(10.0),
                snow_depth: Some(0.001),
                ..Edit::default()
            },
        )?,
        edited(
            &base,
            Edit {
                snow_depth: Some(0.05),
                v0: Some(5.0),
                ..Edit::default()
            },
        )?,
    ];
    for s in &scenarios {
        let opts = SimOptions {
            t_end: 1e6,
            x_end: Some(1e4),
            ..SimOptions::default()
        };
        let traj = lab.run(ModelKind::TorqueCm, s, &opts)?;
        for p in traj.samples.iter().filter(|p| p.v_m_s > 0.0) {
            let (u, _) = loney_u(
                s.g_along(),
                s.snow_depth(),
                s.initial_radius(),
                s.initial_speed(),
                p.x_m,
            );
            worst = worst.max((p.v_m_s / u.sqrt() - 1.0).abs());
        }
    }
    let ok = LONEY_SPEED.accepts_deviation(worst);
    Ok(Finding {
        measured: format!(
            "max relative |v_ODE − v_Loney| over 0 ≤ x ≤ 10 km, 3 scenarios: {worst:.2e}"
        ),
        verdict: holds_if(ok, &[worst]),
        evidence: format!(
            "v² = 2G s/(5b) + K s^(−7/3), s = π r0² + b x, typed from fn. 4, matches the integrated eq. (4): {worst:.1e} {} {:e}",
            pass(ok),
            LONEY_SPEED.value()
        ),
    })
}

/// The erratum of fn. 4's acceleration.
pub(super) const ERRATUM_FN4: &str = "docs/errata.md fn. 4: 7bK/6, not 7bK/3";

/// `loney-acceleration-coefficient`: a against ½ du/dx.
pub(super) const LONEY_DERIVATIVE: Criterion = Criterion {
    quantity: "relative |a of fn. 4 − ½ du/dx| (central difference, h = 1e-6 m)",
    tolerance: Tolerance::Relative { value: 1e-6 },
    reason: "the difference quotient errs by ~u‴h²/6 ≈ 1e-12 and ~ε u/h ≈ 1e-10 relative; 1e-6 leaves a wide margin",
};
/// `loney-acceleration-coefficient`: the printed coefficient is visibly off.
pub(super) const LONEY_PRINTED_APART: Criterion = Criterion {
    quantity: "relative |a with 7bK/3 − ½ du/dx|",
    tolerance: Tolerance::AtLeast {
        value: 1e-2,
        unit: "(relative)",
    },
    reason: "doubling the decaying term moves a by a sizeable fraction near the start; 1e-2 is far above the difference quotient's error",
};

/// fn. 4's decaying term: 7bK/6, not 7bK/3.
pub(super) fn loney_coefficient(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { gs: g, b, r0, .. } = symbols(s);
    let v0 = s.initial_speed();
    let x = 0.05;
    let h = 1e-6;
    let u = |x| loney_u(g, b, r0, v0, x).0;
    let half_du = 0.5 * (u(x + h) - u(x - h)) / (2.0 * h);
    let (_, k) = loney_u(g, b, r0, v0, x);
    let s_x = PI * r0 * r0 + b * x;
    let decay = b * k * s_x.powf(-10.0 / 3.0);
    let corrected = g / 5.0 - 7.0 * decay / 6.0;
    let printed = g / 5.0 - 7.0 * decay / 3.0;
    let dev_corrected = LONEY_DERIVATIVE.deviation(corrected, half_du);
    let dev_printed = (printed - half_du).abs() / half_du.abs();
    let verdict = corrected_if(
        LONEY_DERIVATIVE.accepts(printed, half_du),
        LONEY_DERIVATIVE.accepts_deviation(dev_corrected),
        LONEY_PRINTED_APART.accepts_deviation(dev_printed),
        ERRATUM_FN4,
        &[dev_corrected, dev_printed],
    );
    Ok(Finding {
        measured: format!(
            "at x = {x} m: ½ du/dx = {half_du:.6} m/s², 7bK/6 form {corrected:.6}, printed 7bK/3 form {printed:.6}"
        ),
        verdict,
        evidence: format!(
            "relative deviation from ½ du/dx: corrected {dev_corrected:.1e} (bound {:e}), printed {dev_printed:.2} (must be at least {:e})",
            LONEY_DERIVATIVE.value(),
            LONEY_PRINTED_APART.value()
        ),
    })
}

/// `loney-limit-fifth`: the late-time a/G of eq. (4).
pub(super) const LONEY_LIMIT: Criterion = Criterion {
    quantity: "|a/G − 1/5| at x = 10⁷ r0, closed form and integrated",
    tolerance: Tolerance::Absolute {
        value: 1e-6,
        unit: "g sin α",
    },
    reason: "a − G/5 ∝ s^(−10/3) is ~1e-30 G there; 1e-6 allows the integration error",
};

/// fn. 4's limit g sin α / 5 for eq. (4).
pub(super) fn loney_limit(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let Symbols { gs: g, b, r0, .. } = symbols(s);
    let v0 = s.initial_speed();
    let x = 1e7 * r0;
    let h = 1e-3 * x;
    let u = |x| loney_u(g, b, r0, v0, x).0;
    let closed = 0.5 * (u(x + h) - u(x - h)) / (2.0 * h) / g;
    let sim = super::last_a_over_g(
        lab,
        ModelKind::TorqueCm,
        s,
        &SimOptions {
            t_end: 1e8,
            x_end: Some(x),
            sampling: Sampling::Ends,
            ..SimOptions::default()
        },
    )?;
    let ok = LONEY_LIMIT.accepts(closed, 0.2) && LONEY_LIMIT.accepts(sim, 0.2);
    Ok(Finding {
        measured: format!(
            "a/G at x = {x:e} m: ½ du/dx of fn. 4 {closed:.10}, integrated eq. (4) {sim:.10}"
        ),
        verdict: holds_if(ok, &[closed, sim]),
        evidence: format!(
            "both {} {:e} of 1/5: a − G/5 ∝ s^(−10/3) → 0",
            pass(ok),
            LONEY_LIMIT.value()
        ),
    })
}

/// The erratum of eq. (5).
pub(super) const ERRATUM_5: &str = "docs/errata.md (5): dL_C/dt = d(3mrv/2)/dt";

/// `eq5-contact-torque`: d(3mrv/2)/dt along eq. (6) against the torque.
pub(super) const EQ5_TORQUE: Criterion = Criterion {
    quantity: "relative |d(3mrv/2)/dt − r m g sin α| along the integrated eq. (6)",
    tolerance: Tolerance::Relative { value: 1e-5 },
    reason: "central differences of dense output with h = 1e-3 s: truncation ~L‴h²/6 ≈ 1e-8; the dense output's ~1e-10 relative error divided by h gives ~1e-7",
};
/// `eq5-contact-torque`: the printed d(3mr²/2)/dt is visibly not the torque.
pub(super) const EQ5_PRINTED_APART: Criterion = Criterion {
    quantity: "relative |d(3mr²/2)/dt − r m g sin α|",
    tolerance: Tolerance::AtLeast {
        value: 0.5,
        unit: "(relative)",
    },
    reason: "dI_C/dt is O(b v/r) of the torque, not equal to it; 0.5 is a plain separation",
};

/// Eq. (5): the torque about the contact line equals d(3mrv/2)/dt (the
/// printed d(3mr²/2)/dt is dI_C/dt); checked along the integrated eq. (6),
/// which (5) yields.
pub(super) fn eq5_contact_torque(lab: &Lab) -> Result<Finding, SimError> {
    let s = lab.scenario();
    let h = 1e-3;
    let centres = [0.5, 2.0, 8.0];
    let times: Vec<f64> = centres.iter().flat_map(|&t| [t - h, t, t + h]).collect();
    let traj = lab.run(
        ModelKind::TorqueContact,
        s,
        &SimOptions {
            t_end: 10.0,
            sampling: Sampling::Times(times),
            ..SimOptions::default()
        },
    )?;
    let p = &traj.samples;
    let mut worst_corrected: f64 = 0.0;
    let mut least_printed = f64::INFINITY;
    if p.len() != 3 * centres.len() {
        worst_corrected = f64::NAN;
    }
    for w in p.chunks_exact(3) {
        let l_c = |q: &snowroll::trajectory::Sample| 1.5 * q.mass_kg * q.r_m * q.v_m_s;
        let i_c = |q: &snowroll::trajectory::Sample| 1.5 * q.mass_kg * q.r_m * q.r_m;
        let torque = w[1].r_m * w[1].mass_kg * s.g_along();
        let dl = (l_c(&w[2]) - l_c(&w[0])) / (2.0 * h);
        let di = (i_c(&w[2]) - i_c(&w[0])) / (2.0 * h);
        worst_corrected = worst_corrected.max(EQ5_TORQUE.deviation(dl, torque));
        least_printed = least_printed.min((di - torque).abs() / torque);
    }
    let verdict = corrected_if(
        EQ5_TORQUE.accepts_deviation(least_printed),
        EQ5_TORQUE.accepts_deviation(worst_corrected),
        EQ5_PRINTED_APART.accepts_deviation(least_printed),
        ERRATUM_5,
        &[worst_corrected, least_printed],
    );
    Ok(Finding {
        measured: format!(
            "eq. (6) at t = 0.5, 2, 8 s: max relative |d(3mrv/2)/dt − r m G| = {worst_corrected:.1e}; smallest relative |d(3mr²/2)/dt − r m G| = {least_printed:.3}"
        ),
        verdict,
        evidence: format!(
            "the angular momentum about the contact line is L_C = I_C ω = 3mrv/2 and its rate equals the gravity torque ({} {:e}); the printed d(3mr²/2)/dt is the rate of I_C, in kg m²/s, at least {least_printed:.2} of the torque away",
            pass(EQ5_TORQUE.accepts_deviation(worst_corrected)),
            EQ5_TORQUE.value()
        ),
    })
}

/// `fn7-stall-threshold`: the simulated threshold against the closed form.
pub(super) const STALL_BISECTION: Criterion = Criterion {
    quantity: "|α* by bisection on the simulated model − α* of the closed form|",
    tolerance: Tolerance::Absolute {
        value: 1e-9,
        unit: "degree",
    },
    reason: "bisection to 1e-12 degree; rounding of a(0) near its zero moves the sign change by ~1e-14 rad",
};
/// `fn7-stall-threshold`: how far above and below the threshold the runs start.
pub(super) const STALL_MARGIN: Criterion = Criterion {
    quantity: "offset of the runs above and below α*",
    tolerance: Tolerance::Absolute {
        value: 0.01,
        unit: "degree",
    },
    reason: "0.35 % of α* at the defaults: a lift coefficient off by more than that moves the model's threshold past one of the runs",
};

/// Bisection on `starts(α°)` (false below the threshold, true above) over
/// `[lo, hi]` degrees, to `STALL_TOL_DEG`.
pub(super) fn bisect(
    mut lo: f64,
    mut hi: f64,
    mut starts: impl FnMut(f64) -> Result<bool, SimError>,
) -> Result<f64, SimError> {
    /// Resolution of the bisection, degrees.
    const STALL_TOL_DEG: f64 = 1e-12;
    while hi - lo > STALL_TOL_DEG {
        let mid = 0.5 * (lo + hi);
        if starts(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// fn. 7: below a critical slope the log cannot lift the snow. The closed
/// forms, from a(0) = 0 at x = 0, v = 0 in the printed equations:
/// eq. (14) `tan α* = (3 b r0 + b²)/(2π r0²)`, eq. (15) `tan α* = 3b/(2π r0)`.
pub(super) fn stall_threshold(lab: &Lab) -> Result<Finding, SimError> {
    let base = edited(
        lab.scenario(),
        Edit {
            v0: Some(0.0),
            ..Edit::default()
        },
    )?;
    let (b, r0) = (base.snow_depth(), base.initial_radius());
    let closed = [
        (
            ModelKind::Energy,
            ((3.0 * b * r0 + b * b) / (2.0 * PI * r0 * r0))
                .atan()
                .to_degrees(),
        ),
        (
            ModelKind::EnergyThin,
            (3.0 * b / (2.0 * PI * r0)).atan().to_degrees(),
        ),
    ];
    let at = |deg: f64| {
        edited(
            &base,
            Edit {
                alpha_deg: Some(deg),
                ..Edit::default()
            },
        )
    };
    let quick = SimOptions {
        t_end: 1e-3,
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    let long = SimOptions {
        t_end: 20.0,
        ..SimOptions::default()
    };
    let mut ok = true;
    let mut numbers = Vec::new();
    let mut parts = Vec::new();
    let margin = STALL_MARGIN.value();
    for (kind, crit) in closed {
        let sim = bisect(0.0, 45.0, |deg| {
            Ok(lab.run(kind, &at(deg)?, &quick)?.stop.reason != StopReason::DoesNotStart)
        })?;
        let below = lab.run(kind, &at(crit - margin)?, &long)?;
        let above = lab.run(kind, &at(crit + margin)?, &long)?;
        let keeps_rolling = above.stop.reason == StopReason::EndTime
            && above.samples.iter().skip(1).all(|p| p.v_m_s > 0.0);
        let bisection_ok = STALL_BISECTION.accepts(sim, crit);
        ok &= bisection_ok && below.stop.reason == StopReason::DoesNotStart && keeps_rolling;
        numbers.extend([sim, crit]);
        parts.push(format!(
            "{}: closed form {crit:.6}°, bisection on the model {sim:.6}° (difference {:.1e}°); at α* − {margin}°: {}; at α* + {margin}°: {}{}",
            kind.equation(),
            (sim - crit).abs(),
            below.stop.reason.describe(),
            above.stop.reason.describe(),
            if keeps_rolling { ", rolling throughout" } else { ", NOT rolling throughout" }
        ));
    }
    Ok(Finding {
        measured: format!("b = {b} m, r0 = {r0} m: {}", parts.join("; ")),
        verdict: holds_if(ok, &numbers),
        evidence: format!(
            "a(0) = 0 in the printed eqs. (14) and (15) gives tan α* = (3br0 + b²)/(2πr0²) and 3b/(2πr0); the simulated threshold {} {:e}° of it, the log does not start {margin}° below and rolls on {margin}° above",
            pass(ok),
            STALL_BISECTION.value()
        ),
    })
}
