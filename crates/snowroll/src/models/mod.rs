//! Every model of the note behind one interface.
//!
//! [`ModelKind`] (generated from the one table [`MODEL_TABLE`]) is the only
//! list of model names; [`ModelKind::build`] is the only place that maps a
//! name to an implementation.

mod circular;
mod closed_form;
mod coefficients;
mod contact;
pub mod exact_geometry;
mod in_turn;
mod ledger;
mod ode;
mod tolerance;
mod turn_by_turn;
mod validity;
mod warning_code;
mod warnings;

pub use circular::{Balance, CircularModel, Coefficients, Derivation};
pub use closed_form::{
    circular_end, ContactCheck, DragOnlyClosedForm, FastEnd, LoneyModel, SpeedSquared,
};
pub use contact::{circular_forces, ContactForces};
pub use exact_geometry::SectorBody;
pub use tolerance::{
    atol_bound, check_tolerances, default_atol, state_scale, tolerance_warning, ATOL_MAX_FRACTION,
    CLAIMS_ACCURACY,
};
pub use turn_by_turn::{
    charged_collision_speed, check_turn_scale, collision_speed, first_turn_stall_slope,
    kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, run_turns, run_turns_into,
    CollisionModel, ContactRange, HopDoubt, InTurnCoefficients, PivotImpact, TurnCheckpoint,
    TurnDynamics, TurnExtremes, TurnMethod, TurnModel, TurnRow, TurnRunEnd, TurnSink, TurnSummary,
    TurnTable, TurnVariant,
};
pub use validity::{
    validity_warnings, StallKind, StallThreshold, Validity, ValidityWarning,
    THIN_SNOW_MAX_B_OVER_R0,
};
pub use warnings::{run_warnings, warning_codes, RunWarning, WarningCode};

use crate::error::{ParamError, SimError};
use crate::scenario::{Scenario, Shape};
use crate::trajectory::{Collected, RunEnd, SampleSink, SimOptions, Trajectory};
#[cfg(doc)]
use crate::trajectory::{Stop, StopReason};

/// Turns of a turn-model run when the caller does not say (`snowroll turns`,
/// Python's `snowroll.turns`).
pub const TURNS_DEFAULT: u64 = 100;

/// End time of a turn-model run when the caller does not say, s: about 30
/// years, so that the turn count, not the clock, ends any realistic run
/// (10^5 turns of the default scenario take about 6 hours).
pub const TURNS_T_END_S: f64 = 1e9;

/// Largest denominator [`as_fraction`] tries.
const MAX_DENOMINATOR: u32 = 100;

/// How close `p/q` must be to the value, absolutely: the terminal fractions
/// come from a few divisions of small rationals, exact to a few ulps.
const FRACTION_TOL: f64 = 1e-12;

/// `f >= 0` as `p/q` with the smallest `q <= 100`, if there is one (to print
/// a terminal fraction as 1/5 rather than 0.2000, or a coefficient as 7/6).
pub fn as_fraction(f: f64) -> Option<(u64, u32)> {
    if !(f.is_finite() && f >= 0.0) {
        return None;
    }
    (1..=MAX_DENOMINATOR).find_map(|q| {
        let p = (f * f64::from(q)).round();
        ((p / f64::from(q) - f).abs() <= FRACTION_TOL).then_some((p as u64, q))
    })
}

/// A model of the rolling log: from a scenario and options to a trajectory.
pub trait Model {
    /// Which model this is.
    fn kind(&self) -> ModelKind;

    /// Everything that makes the model refuse a run, checked before any
    /// output: the options ([`SimOptions::validate`]), the shape
    /// ([`ModelKind::check_shape`]) and the tolerances
    /// ([`check_tolerances`]); models with more to refuse (the turn models:
    /// the scale of a turn, the losses they do not take) add theirs.
    /// [`simulate_into`](Self::simulate_into) calls it first; a caller that
    /// writes a header before the run (the CLI) calls it before the header,
    /// so that a refused run writes nothing.
    ///
    /// ```
    /// use snowroll::{Model, ModelKind, Scenario, ScenarioFile, Shape, SimOptions};
    /// let ball = Scenario::new(ScenarioFile { shape: Shape::Sphere, ..ScenarioFile::default() })?;
    /// let opts = SimOptions::default();
    /// assert!(ModelKind::TorqueCm.build().check(&ball, &opts).is_ok());
    /// let err = ModelKind::Turns.build().check(&ball, &opts).unwrap_err();
    /// assert!(err.to_string().contains("turns does not support shape = sphere"));
    /// # Ok::<(), snowroll::ParamError>(())
    /// ```
    ///
    /// # Errors
    /// [`SimError::Param`] naming the model and the reason.
    fn check(&self, scenario: &Scenario, opts: &SimOptions) -> Result<(), SimError> {
        opts.validate()?;
        self.kind().check_shape(scenario)?;
        check_tolerances(self.kind(), scenario, opts)?;
        check_unwinding_losses(scenario, opts)?;
        Ok(())
    }

    /// Runs the model and sends each sample to `sink` as soon as it is
    /// computed, so memory does not grow with the number of samples. The
    /// samples are those of [`simulate`](Self::simulate), bit for bit.
    ///
    /// ```
    /// use snowroll::{Collected, Model, ModelKind, Scenario, SimOptions};
    /// let model = ModelKind::TorqueCm.build();
    /// let mut sink = Collected::default();
    /// let end = model.simulate_into(&Scenario::default(), &SimOptions::default(), &mut sink)?;
    /// assert_eq!(end.stop.t_s, sink.samples.last().unwrap().t_s);
    /// # Ok::<(), snowroll::SimError>(())
    /// ```
    ///
    /// # Errors
    /// [`SimError`] when the options are invalid or the integration fails;
    /// [`SimError::Sink`] when the sink fails (the run stops at once). An
    /// early stop on a limit ([`StopReason::StepLimit`], [`StopReason::RowLimit`])
    /// is not an error: it is the [`Stop`] of the [`RunEnd`].
    fn simulate_into(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError>;

    /// Runs the model and gathers its samples in a [`Trajectory`]
    /// ([`simulate_into`](Self::simulate_into) with a [`Collected`] sink).
    ///
    /// # Errors
    /// [`SimError`] when the options are invalid or the integration fails.
    fn simulate(&self, scenario: &Scenario, opts: &SimOptions) -> Result<Trajectory, SimError> {
        let mut collected = Collected::default();
        let end = self.simulate_into(scenario, opts, &mut collected)?;
        Ok(collected.into_trajectory(self.kind(), end))
    }
}

pub use crate::model_kind::{ModelInfo, ModelKind, MODEL_TABLE};

/// What each model computes (the names are in [`MODEL_TABLE`]).
/// The losses an unwinding roll (b < 0) takes: air drag and rolling
/// resistance, not the work of compacting snow, since it lays its layer down
/// and picks nothing up (`docs/unwinding.md`); with b < 0 the term
/// e_c dM/dx would push the roll instead of braking it.
fn check_unwinding_losses(scenario: &Scenario, opts: &SimOptions) -> Result<(), ParamError> {
    let e = opts.losses.compaction_energy;
    if scenario.unwinds() && e > 0.0 {
        return Err(ParamError::InvalidParameter {
            name: "compaction_energy (J/kg)",
            value: e,
            expected: "compaction_energy = 0 for an unwinding roll (snow_depth < 0): it lays its \
                       layer down and compacts nothing; drop {compaction_energy}",
        });
    }
    Ok(())
}

impl ModelKind {
    /// Late-time acceleration as a fraction of g sin α, where the model has
    /// one (with snow, b > 0), computed from the model's coefficients. `None`
    /// for the turn models, whose long-run mean is measured ([`run_turns`]).
    pub fn terminal_fraction(self) -> Option<f64> {
        match self {
            ModelKind::Loney => Derivation::TorqueAboutCentre
                .coefficients()
                .terminal_fraction(),
            _ => self
                .derivation()
                .and_then(|d| d.coefficients().terminal_fraction()),
        }
    }

    /// The shapes the model supports (`docs/snowball-and-losses.md` §1.2):
    /// every circular model and Loney's closed form take the ball too; the
    /// turn models of §3 know only the log.
    pub fn shapes(self) -> &'static [Shape] {
        if self.is_circular() {
            &Shape::ALL
        } else {
            &[Shape::Cylinder]
        }
    }

    /// Refuses a scenario whose shape the model's derivation does not cover.
    ///
    /// # Errors
    /// [`ParamError::ShapeNotSupported`] naming the model and why: a turn
    /// model with a ball; Loney's closed form with a ball of fixed swath
    /// width or on the chord (it needs the area law π r² = π r0² + b x).
    pub fn check_shape(self, s: &Scenario) -> Result<(), ParamError> {
        let reason = match (self, s.shape()) {
            (_, Shape::Cylinder) => return Ok(()),
            (ModelKind::Turns | ModelKind::TurnsExact, Shape::Sphere) => {
                "the turn-by-turn geometry of §3 is the log's: a ball that picks up a swath in \
                 one turn gains a band round its equator, not a shell, and stops being a ball \
                 (docs/snowball-and-losses.md §1.2); use a circular model such as torque-cm"
            }
            (ModelKind::Loney, Shape::Sphere) if s.swath_width().is_some() => {
                "the closed form needs the area law pi r^2 = pi r0^2 + b x of the natural swath \
                 2r; with a fixed {swath_width} integrate torque-cm instead"
            }
            (ModelKind::Loney, Shape::Sphere) if !s.follows_area_law() => {
                "the closed form needs the area law pi r^2 = pi r0^2 + b x of the natural swath \
                 2r; with {swath_width chord} integrate torque-cm instead"
            }
            _ => return Ok(()),
        };
        Err(ParamError::ShapeNotSupported {
            model: self.id(),
            shape: s.shape().id(),
            reason,
        })
    }

    /// Late-time acceleration over g sin α on `scenario`'s shape and swath
    /// (`docs/snowball-and-losses.md` §1.3); `None` for the turn models.
    /// On the log it is [`ModelKind::terminal_fraction`].
    pub fn terminal_fraction_on(self, scenario: &Scenario) -> Option<f64> {
        let derivation = match self {
            ModelKind::Loney => Derivation::TorqueAboutCentre,
            kind => kind.derivation()?,
        };
        let c = derivation.coefficients_for(scenario.shape());
        if scenario.follows_area_law() || !c.accretes {
            c.terminal_fraction()
        } else {
            Some(
                derivation
                    .balance()
                    .terminal_fraction(scenario.shape(), scenario.swath().power()),
            )
        }
    }

    /// The coefficient set of a circular model; `None` for closed forms.
    pub fn derivation(self) -> Option<Derivation> {
        Some(match self {
            ModelKind::Snowless => Derivation::Snowless,
            ModelKind::TorqueCm => Derivation::TorqueAboutCentre,
            ModelKind::TorqueContact => Derivation::TorqueAboutContact,
            ModelKind::Energy => Derivation::Energy,
            ModelKind::EnergyThin => Derivation::EnergyLinearised,
            ModelKind::LagrangianPrinted => Derivation::LagrangianPrinted,
            ModelKind::QuasiCircular => Derivation::QuasiCircular,
            ModelKind::QuasiCircularLift => Derivation::QuasiCircularLift,
            ModelKind::Loney | ModelKind::Turns | ModelKind::TurnsExact => return None,
        })
    }

    /// The implementation.
    pub fn build(self) -> Box<dyn Model> {
        match (self.derivation(), TurnVariant::of(self)) {
            (Some(derivation), _) => Box::new(CircularModel::new(derivation)),
            (None, Some(variant)) => Box::new(TurnModel::new(variant)),
            (None, None) => Box::new(LoneyModel),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_has_exactly_one_implementation_kind_matching_the_table() {
        // Turn models have a turn variant and no coefficients; circular
        // models have coefficients or are Loney's closed form.
        for kind in ModelKind::ALL {
            let variant = TurnVariant::of(kind);
            assert_eq!(variant.is_some(), kind.is_turn_model(), "{kind}");
            if kind.is_circular() {
                assert!(
                    kind.derivation().is_some() || kind == ModelKind::Loney,
                    "{kind}"
                );
            } else {
                assert!(kind.derivation().is_none(), "{kind}");
            }
            assert_eq!(kind.build().kind(), kind);
        }
    }
}
