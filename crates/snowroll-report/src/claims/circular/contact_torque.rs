//! Eq. (5): the torque about the contact line against the rate of the
//! angular momentum about it, along the integrated eq. (6).

use crate::claims::{corrected_if, pass, Finding, Lab};
use crate::{Criterion, Tolerance};
use snowroll::error::SimError;
use snowroll::models::ModelKind;
use snowroll::trajectory::{Sampling, SimOptions};

/// The erratum of eq. (5).
pub(in crate::claims) const ERRATUM_5: &str = "docs/errata.md (5): dL_C/dt = d(3mrv/2)/dt";

/// `eq5-contact-torque`: d(3mrv/2)/dt along eq. (6) against the torque.
pub(in crate::claims) const EQ5_TORQUE: Criterion = Criterion {
    quantity: "relative |d(3mrv/2)/dt − r m g sin α| along the integrated eq. (6)",
    tolerance: Tolerance::Relative { value: 1e-5 },
    reason: "central differences of dense output with h = 1e-3 s: truncation ~L‴h²/6 ≈ 1e-8; the dense output's ~1e-10 relative error divided by h gives ~1e-7",
};
/// `eq5-contact-torque`: the printed d(3mr²/2)/dt is visibly not the torque.
pub(in crate::claims) const EQ5_PRINTED_APART: Criterion = Criterion {
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
pub(in crate::claims) fn eq5_contact_torque(lab: &Lab) -> Result<Finding, SimError> {
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
        headline: None,
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
