//! [`CircularModel`]: a circular model of §2 and its run on the one
//! integrator loop (`models/ode.rs`).

use super::system::CircularSystem;
use super::{Coefficients, Derivation};
use crate::error::SimError;
use crate::models::ode::{run_ode, stopped_at_start};
use crate::models::{Model, ModelKind};
use crate::scenario::Scenario;
use crate::trajectory::{RunEnd, SampleSink, SimOptions, StopReason};

/// A circular model of §2, one right-hand side for all derivations.
///
/// ```
/// use snowroll::{CircularModel, Derivation, Model, Scenario, SimOptions};
/// let model = CircularModel::new(Derivation::TorqueAboutCentre);
/// let traj = model.simulate(&Scenario::default(), &SimOptions::default())?;
/// assert!(traj.samples.last().unwrap().v_m_s > 0.0);
/// # Ok::<(), snowroll::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularModel {
    derivation: Derivation,
    coefficients: Coefficients,
    /// Whether `coefficients` were given ([`CircularModel::with_coefficients`])
    /// rather than taken from the scenario's shape.
    given: bool,
}

impl CircularModel {
    /// The model of `derivation`.
    pub fn new(derivation: Derivation) -> Self {
        Self {
            derivation,
            coefficients: derivation.coefficients(),
            given: false,
        }
    }

    /// The model of `derivation` run with other coefficients: a deliberately
    /// wrong model, for the tests that check a claim's verdict changes when
    /// its model is wrong. It still reports itself as `derivation`'s model.
    pub fn with_coefficients(derivation: Derivation, coefficients: Coefficients) -> Self {
        Self {
            derivation,
            coefficients,
            given: true,
        }
    }

    /// Its derivation.
    pub fn derivation(&self) -> Derivation {
        self.derivation
    }

    /// The coefficients it runs with on a log (on a ball:
    /// [`Derivation::coefficients_for`]).
    pub fn coefficients(&self) -> Coefficients {
        self.coefficients
    }

    /// The coefficients it runs with on `scenario`.
    pub fn coefficients_on(&self, scenario: &Scenario) -> Coefficients {
        if self.given {
            self.coefficients
        } else {
            self.derivation.coefficients_for(scenario.shape())
        }
    }
}

impl CircularModel {
    /// Runs the system with `N` states (2, or 6 with the ledger).
    fn run<const N: usize>(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError> {
        let mut system = CircularSystem::<N>::new(
            self.derivation,
            self.coefficients_on(scenario),
            scenario,
            opts,
        );
        let mut y0 = [0.0; N];
        y0[1] = scenario.initial_speed();
        // fn. 7: from rest the log moves only if a(0) > 0 (with losses: if
        // the drive exceeds the static couples, §2.2).
        if y0[1] == 0.0 && system.accel.at(0.0, 0.0) <= 0.0 {
            return stopped_at_start(&system, y0, StopReason::DoesNotStart, sink);
        }
        if let Some(reason) = system.stops_at(&y0) {
            return stopped_at_start(&system, y0, reason, sink);
        }
        run_ode(&mut system, y0, opts, sink)
    }
}

impl Model for CircularModel {
    fn kind(&self) -> ModelKind {
        self.derivation.kind()
    }

    fn simulate_into(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError> {
        self.check(scenario, opts)?;
        if opts.losses.records_ledger() {
            self.run::<6>(scenario, opts, sink)
        } else {
            self.run::<2>(scenario, opts, sink)
        }
    }
}
