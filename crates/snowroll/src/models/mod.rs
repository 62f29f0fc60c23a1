//! Every model of the note behind one interface.
//!
//! [`ModelKind`] is the only list of model names; [`ModelKind::build`] is the
//! only place that maps a name to an implementation.

mod circular;
mod closed_form;
mod contact;
pub mod exact_geometry;
mod ode;
mod tolerance;
mod turn_by_turn;
mod validity;

pub use circular::{Balance, CircularModel, Coefficients, Derivation};
pub use closed_form::{DragOnlyClosedForm, LoneyModel};
pub use contact::{circular_forces, ContactForces};
pub use exact_geometry::SectorBody;
pub use tolerance::{
    atol_bound, check_tolerances, default_atol, state_scale, tolerance_warning, ATOL_MAX_FRACTION,
    CLAIMS_ACCURACY,
};
pub use turn_by_turn::{
    charged_collision_speed, check_turn_scale, collision_speed, first_turn_stall_slope,
    kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, run_turns, CollisionModel,
    ContactRange, InTurnCoefficients, PivotImpact, TurnCheckpoint, TurnDynamics, TurnExtremes,
    TurnModel, TurnRow, TurnSummary, TurnTable, TurnVariant,
};
pub use validity::{
    validity_warnings, StallKind, StallThreshold, Validity, ValidityWarning,
    THIN_SNOW_MAX_B_OVER_R0,
};

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use crate::error::{ParamError, SimError};
use crate::scenario::{Scenario, Shape};
use crate::trajectory::{SimOptions, Trajectory};

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

    /// Runs the model.
    ///
    /// # Errors
    /// [`SimError`] when the options are invalid or the integration fails.
    fn simulate(&self, scenario: &Scenario, opts: &SimOptions) -> Result<Trajectory, SimError>;
}

/// The models of the note, by kebab-case id; each also answers to the
/// equation alias in the second column.
///
/// | id | alias | equation |
/// |---|---|---|
/// | `snowless` | `eq95` | App. A, a = (2/3) g sin α |
/// | `torque-cm` | `eq4` | §2.1.1, eq. (4) |
/// | `torque-contact` | `eq6` | §2.1.2, eq. (6) |
/// | `energy` | `eq14` | §2.2, eq. (14) |
/// | `energy-thin` | `eq15` | eq. (15) |
/// | `lagrangian-printed` | `eq21` | eq. (21) as printed |
/// | `quasi-circular` | `eq32` | §2.4, eq. (32) |
/// | `quasi-circular-lift` | `eq32+36` | eqs. (32) + (36) |
/// | `loney` | `fn4` | fn. 4, closed form of eq. (4) |
/// | `turns` | `eq73` | §3.4, eqs. (73), (76), collision eq. (89) |
/// | `turns-exact` | `eq88` | §3.4, exact geometry, eq. (88) with (87) corrected |
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum ModelKind {
    /// App. A: no snow, a = (2/3) g sin α, eq. (95).
    #[serde(alias = "eq95")]
    #[cfg_attr(feature = "clap", value(alias = "eq95"))]
    Snowless,
    /// §2.1.1: torque about the centre of mass, eq. (4).
    #[serde(alias = "eq4")]
    #[cfg_attr(feature = "clap", value(alias = "eq4"))]
    TorqueCm,
    /// §2.1.2: torque about the contact line, eq. (6).
    #[serde(alias = "eq6")]
    #[cfg_attr(feature = "clap", value(alias = "eq6"))]
    TorqueContact,
    /// §2.2: energy conservation with the b² terms, eq. (14).
    #[serde(alias = "eq14")]
    #[cfg_attr(feature = "clap", value(alias = "eq14"))]
    Energy,
    /// §2.2: eq. (14) without the b² terms, eq. (15).
    #[serde(alias = "eq15")]
    #[cfg_attr(feature = "clap", value(alias = "eq15"))]
    EnergyThin,
    /// §2.3: the Lagrangian result exactly as printed, eq. (21) (omits ∂T/∂x, `docs/errata.md` (19)–(21)).
    #[serde(alias = "eq21")]
    #[cfg_attr(feature = "clap", value(alias = "eq21"))]
    LagrangianPrinted,
    /// §2.4: the approximately circular log, eq. (32).
    #[serde(alias = "eq32")]
    #[cfg_attr(feature = "clap", value(alias = "eq32"))]
    QuasiCircular,
    /// §2.4: eq. (32) plus the lift term (36).
    #[serde(alias = "eq32+36")]
    #[cfg_attr(feature = "clap", value(alias = "eq32+36"))]
    QuasiCircularLift,
    /// fn. 4: Loney's closed-form solution of eq. (4), no ODE solver.
    #[serde(alias = "fn4")]
    #[cfg_attr(feature = "clap", value(alias = "fn4"))]
    Loney,
    /// §3.4: turn by turn, eqs. (73), (76) to first order in b/r, collision eq. (89).
    #[serde(alias = "eq73")]
    #[cfg_attr(feature = "clap", value(alias = "eq73"))]
    Turns,
    /// §3.4: turn by turn with the exact mass properties, so that eq. (88) holds.
    #[serde(alias = "eq88")]
    #[cfg_attr(feature = "clap", value(alias = "eq88"))]
    TurnsExact,
}

impl ModelKind {
    /// Every model, in the order of the note.
    pub const ALL: [ModelKind; 11] = [
        ModelKind::Snowless,
        ModelKind::TorqueCm,
        ModelKind::TorqueContact,
        ModelKind::Energy,
        ModelKind::EnergyThin,
        ModelKind::LagrangianPrinted,
        ModelKind::QuasiCircular,
        ModelKind::QuasiCircularLift,
        ModelKind::Loney,
        ModelKind::Turns,
        ModelKind::TurnsExact,
    ];

    /// The kebab-case id.
    pub fn id(self) -> &'static str {
        match self {
            ModelKind::Snowless => "snowless",
            ModelKind::TorqueCm => "torque-cm",
            ModelKind::TorqueContact => "torque-contact",
            ModelKind::Energy => "energy",
            ModelKind::EnergyThin => "energy-thin",
            ModelKind::LagrangianPrinted => "lagrangian-printed",
            ModelKind::QuasiCircular => "quasi-circular",
            ModelKind::QuasiCircularLift => "quasi-circular-lift",
            ModelKind::Loney => "loney",
            ModelKind::Turns => "turns",
            ModelKind::TurnsExact => "turns-exact",
        }
    }

    /// The equation alias (`eq4`, `fn4`, …).
    pub fn alias(self) -> &'static str {
        match self {
            ModelKind::Snowless => "eq95",
            ModelKind::TorqueCm => "eq4",
            ModelKind::TorqueContact => "eq6",
            ModelKind::Energy => "eq14",
            ModelKind::EnergyThin => "eq15",
            ModelKind::LagrangianPrinted => "eq21",
            ModelKind::QuasiCircular => "eq32",
            ModelKind::QuasiCircularLift => "eq32+36",
            ModelKind::Loney => "fn4",
            ModelKind::Turns => "eq73",
            ModelKind::TurnsExact => "eq88",
        }
    }

    /// Where in the note, in the citation form `eq. (N)` / `fn. N`.
    pub fn equation(self) -> &'static str {
        match self {
            ModelKind::Snowless => "eq. (95)",
            ModelKind::TorqueCm => "eq. (4)",
            ModelKind::TorqueContact => "eq. (6)",
            ModelKind::Energy => "eq. (14)",
            ModelKind::EnergyThin => "eq. (15)",
            ModelKind::LagrangianPrinted => "eq. (21) as printed",
            ModelKind::QuasiCircular => "eq. (32)",
            ModelKind::QuasiCircularLift => "eqs. (32)+(36)",
            ModelKind::Loney => "fn. 4",
            ModelKind::Turns => "eqs. (73), (76), (89)",
            ModelKind::TurnsExact => "eqs. (88), (89), exact geometry",
        }
    }

    /// One line for people.
    pub fn description(self) -> &'static str {
        match self {
            ModelKind::Snowless => "cylinder on a bare slope (App. A)",
            ModelKind::TorqueCm => "circular log, torque about the centre of mass (§2.1.1)",
            ModelKind::TorqueContact => "circular log, torque about the contact line (§2.1.2)",
            ModelKind::Energy => "circular log, energy conservation with b^2 terms (§2.2)",
            ModelKind::EnergyThin => "circular log, energy conservation to first order in b (§2.2)",
            ModelKind::LagrangianPrinted => {
                "circular log, Lagrangian as printed: omits dT/dx (docs/errata.md (19)-(21); corrected = eq. 14)"
            }
            ModelKind::QuasiCircular => "approximately circular log, energy rate (§2.4)",
            ModelKind::QuasiCircularLift => "eq. (32) plus the snow-lifting term (36) (§2.4)",
            ModelKind::Loney => "Loney's closed form of eq. (4), no ODE solver (fn. 4)",
            ModelKind::Turns => {
                "turn by turn, first order in b/r, collision at every full turn (§3.4)"
            }
            ModelKind::TurnsExact => {
                "turn by turn, exact disk + sector mass properties, eq. (88) holds (§3.4)"
            }
        }
    }

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
    /// width (it needs the area law π r² = π r0² + b x).
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
                 2r; with a fixed --swath-width integrate torque-cm instead"
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
                    .terminal_fraction(scenario.shape(), 0.0),
            )
        }
    }

    /// Whether the model takes the log as circular at all times (§2, App. A
    /// and Loney's fn. 4), as opposed to following it turn by turn (§3).
    pub fn is_circular(self) -> bool {
        TurnVariant::of(self).is_none()
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

impl fmt::Display for ModelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}

impl FromStr for ModelKind {
    type Err = ParamError;

    /// Accepts the id or the equation alias, case-insensitively.
    fn from_str(s: &str) -> Result<Self, ParamError> {
        let wanted = s.trim().to_ascii_lowercase();
        ModelKind::ALL
            .into_iter()
            .find(|k| k.id() == wanted || k.alias() == wanted)
            .ok_or_else(|| ParamError::UnknownModel {
                given: s.to_string(),
                expected: ModelKind::ALL
                    .iter()
                    .map(|k| format!("{} ({})", k.id(), k.alias()))
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }
}
