//! How loose the integrator's tolerances may be for a given scenario.
//!
//! The step-size controller accepts a step when each component's error is
//! below `atol + rtol |y|`. `rtol` is relative already and is bounded in
//! [`SimOptions::validate`]; `atol` is in the units of the state, so its
//! meaning depends on the scenario: `atol = 1e6` is nothing for a log
//! rolling at 1e9 m/s and everything for one rolling at 1 m/s (the defect
//! of issue 7: `--atol 1e308` let eq. (4) run away). Here `atol` is measured
//! against the **state scale** of the model's variables:
//!
//! - circular models (state `[x, v]`): `x` changes on the scale `r0` (the
//!   radius law eq. (8) and the drag `b v²/r²` of eq. (4) vary on it), and a
//!   log that has rolled a distance `r0` from rest moves at `~ √(g r0)`; so
//!   the scale is `min(r0 [m], √(g r0) [m/s])`;
//! - turn models (state `[θ, θ̇]`): `θ` runs over one turn, `2π`, so its
//!   scale is 1 rad, and `θ̇ ~ v/r0 ~ √(g/r0)`; the scale is
//!   `min(1 rad, √(g/r0) [rad/s])`.
//!
//! `atol` may be at most [`ATOL_MAX_FRACTION`] of that scale (above it the
//! controller accepts errors comparable to the state itself, and the
//! result is noise), and a run is warned about when it is looser than
//! [`CLAIMS_ACCURACY`], the accuracy the note's claims are judged at.

use super::ModelKind;
use crate::error::ParamError;
use crate::scenario::Scenario;
use crate::trajectory::SimOptions;

/// The largest `atol` as a fraction of the state scale: errors of a tenth
/// of a percent of the scale per step are the most a result can carry and
/// still be a trajectory rather than noise.
pub const ATOL_MAX_FRACTION: f64 = 1e-3;

/// The accuracy the claims of the note need: several are judged at a
/// relative 1e-6 (for instance the terminal acceleration of fn. 4 against
/// a difference quotient, the stall slopes); a run whose `rtol`, or whose
/// `atol` relative to the state scale, is looser than this cannot tell a
/// claim that holds from one that fails.
pub const CLAIMS_ACCURACY: f64 = 1e-6;

/// The state scale of `kind` for `s` (see the module docs), in the units
/// of the state; `None` for the closed forms, which do not integrate.
pub fn state_scale(kind: ModelKind, s: &Scenario) -> Option<f64> {
    let (r0, g) = (s.initial_radius(), s.gravity());
    if kind.derivation().is_some() {
        Some(r0.min((g * r0).sqrt()))
    } else if kind.is_turn_model() {
        Some((g / r0).sqrt().min(1.0))
    } else {
        None
    }
}

/// The largest `atol` allowed for `kind` and `s`: [`ATOL_MAX_FRACTION`] of
/// the state scale; `None` when the model does not integrate.
pub fn atol_bound(kind: ModelKind, s: &Scenario) -> Option<f64> {
    state_scale(kind, s).map(|scale| ATOL_MAX_FRACTION * scale)
}

/// The `atol` to use when none is given: the library default (1e-12),
/// or 1e-10 of the state scale when that is smaller, so that a scenario
/// of tiny scale (a log of 1 mm, a turn model with a huge radius) is
/// integrated as accurately as the default one; never below
/// [`MIN_ATOL`](crate::integrate::MIN_ATOL).
pub fn default_atol(kind: ModelKind, s: &Scenario) -> f64 {
    let d = SimOptions::default().tolerances.atol;
    state_scale(kind, s).map_or(d, |scale| {
        d.min(1e-10 * scale).max(crate::integrate::MIN_ATOL)
    })
}

/// Checks `opts.tolerances.atol` against [`atol_bound`].
///
/// # Errors
/// [`ParamError::OutOfScale`] with the bound.
pub fn check_tolerances(
    kind: ModelKind,
    s: &Scenario,
    opts: &SimOptions,
) -> Result<(), ParamError> {
    let atol = opts.tolerances.atol;
    match atol_bound(kind, s) {
        Some(bound) if atol > bound => Err(ParamError::OutOfScale {
            quantity: "atol",
            value: atol,
            allowed: format!(
                "atol <= {} for this scenario, {ATOL_MAX_FRACTION:e} of the scale of the state \
                 (min(r0, sqrt(g r0)) for x, v; min(1, sqrt(g/r0)) for the turn models' theta, omega)",
                crate::number::format_number(bound)
            ),
            hint: "lower {atol}",
        }),
        _ => Ok(()),
    }
}

/// A warning when the tolerances are looser than [`CLAIMS_ACCURACY`]
/// (`rtol`, or `atol` relative to the state scale); `None` otherwise.
pub fn tolerance_warning(kind: ModelKind, s: &Scenario, opts: &SimOptions) -> Option<String> {
    let t = &opts.tolerances;
    let scale = state_scale(kind, s)?;
    let atol_relative = t.atol / scale;
    (t.rtol > CLAIMS_ACCURACY || atol_relative > CLAIMS_ACCURACY).then(|| {
        format!(
            "tolerances looser than the accuracy the note's claims are judged at \
             ({CLAIMS_ACCURACY:e} relative): rtol = {:e}, atol = {:e} = {:e} of the state scale; \
             expect errors of that order",
            t.rtol,
            t.atol,
            // Three significant digits are enough to compare.
            format!("{atol_relative:.2e}")
                .parse::<f64>()
                .unwrap_or(atol_relative)
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::ScenarioFile;

    #[test]
    fn the_bound_follows_the_state_scale() {
        let s = Scenario::default();
        // r0 = 0.1 m, sqrt(g r0) = 0.99 m/s: the scale is r0.
        let bound = atol_bound(ModelKind::TorqueCm, &s).unwrap();
        assert!((bound - 1e-4).abs() < 1e-18, "{bound}");
        // Turn models: sqrt(g/r0) = 9.9 rad/s > 1 rad: the scale is 1.
        assert_eq!(atol_bound(ModelKind::Turns, &s), Some(1e-3));
        assert_eq!(atol_bound(ModelKind::Loney, &s), None);
        let big = Scenario::new(ScenarioFile {
            r0: 1e20,
            ..ScenarioFile::default()
        })
        .unwrap();
        let turn = atol_bound(ModelKind::Turns, &big).unwrap();
        assert!((turn / (1e-3 * (9.81f64 / 1e20).sqrt()) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_default_is_kept_for_ordinary_scenarios_and_shrinks_for_tiny_scales() {
        let s = Scenario::default();
        let d = SimOptions::default().tolerances.atol;
        assert_eq!(default_atol(ModelKind::TorqueCm, &s).to_bits(), d.to_bits());
        assert_eq!(default_atol(ModelKind::Turns, &s).to_bits(), d.to_bits());
        let tiny = Scenario::new(ScenarioFile {
            r0: 1e-6,
            ..ScenarioFile::default()
        })
        .unwrap();
        let a = default_atol(ModelKind::Energy, &tiny);
        assert!((a - 1e-16).abs() < 1e-30, "{a}");
        assert!(a <= atol_bound(ModelKind::Energy, &tiny).unwrap());
    }
}
