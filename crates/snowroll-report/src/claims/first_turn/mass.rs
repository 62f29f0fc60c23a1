//! Eq. (70): the mass after the first turn, against the integrated layer
//! and the masses both turn models report.

use std::f64::consts::PI;

use crate::claims::quadrature::{mass_properties, Sector};
use crate::claims::{bound, corrected_if, symbols, Finding, Lab, Symbols};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// The erratum of eq. (70).
pub(in crate::claims) const ERRATUM_70: &str = "docs/errata.md (70): m1 = πρl r1²";

/// `eq70-mass-after-first-turn`: masses against the integrated layer.
pub(in crate::claims) const MASS_EXACT: Criterion = Criterion {
    quantity:
        "relative |mass − (disk + integrated layer)| for πρl r1² and for turns-exact at θ = 2π",
    tolerance: Tolerance::Relative { value: 1e-12 },
    reason:
        "the quadrature of the layer is exact; the model's mass is a closed form; rounding only",
};
/// `eq70-mass-after-first-turn`: the first-order model drops exactly the b² area.
pub(in crate::claims) const MASS_FIRST_ORDER: Criterion = Criterion {
    quantity: "relative |turns mass at θ = 2π − (integrated mass − ρlπb²)|",
    tolerance: Tolerance::Relative { value: 1e-12 },
    reason: "eq. (38) keeps m0bθ/(πr0) and drops ρlθb²/2, exactly; rounding only",
};
/// `eq70-mass-after-first-turn`: the printed mass is visibly off.
pub(in crate::claims) const MASS_PRINTED_APART: Criterion = Criterion {
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
pub(in crate::claims) fn eq70_mass(lab: &Lab) -> Result<Finding, SimError> {
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
        headline: None,
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
