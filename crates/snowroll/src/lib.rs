//! # snowroll
//!
//! A log (or snowball) rolling without slipping down a slope of angle α
//! covered by snow of depth b, picking up all the snow it meets: every
//! analysis of K. T. McDonald, "Snowball/Log Rolling down a Snowy Slope",
//! with the corrections of `docs/errata.md`.
//!
//! ## The physics on one page
//! * §2 takes the log as circular at all times, radius `π r² = π r0² + b x`
//!   (eq. (8)). Torque about the centre (eq. (4)), torque about the contact
//!   line (eq. (6)), energy conservation (eqs. (14), (15)) and the Lagrangian
//!   (eq. (21) as printed) give different equations of motion that agree as
//!   b → 0 on `a = (2/3) g sin α` (App. A). The corrected Lagrangian is eq. (14).
//!   Each tends to its own terminal acceleration: g sin α/5 for eq. (4)
//!   (Loney's closed form, fn. 4), g sin α/3 for eqs. (14), (15), (32) (eq. (35)).
//! * §2.4 treats the log as only approximately circular (eq. (32), with the
//!   optional lift term (36)).
//! * §3 follows the log turn by turn without assuming it is circular, with a
//!   collision at each full turn (eq. (89)). Its acceleration never settles;
//!   over many turns its mean tends to g sin α/3 within the turns and to
//!   g sin α/4 including the collisions (measured by [`run_turns`]; the note's
//!   4 g sin α/9 of eq. (79) does not hold).
//! * Every model states its range of validity, the order in b/r it keeps
//!   ([`ModelKind::validity`]); [`validity_warnings`] says when a scenario
//!   leaves it (e.g. `turns` on thick snow, where `turns-exact` stalls in
//!   its first turn while `turns` rolls on).
//! * `snowroll_report::CLAIMS` (crate `snowroll-report`) is the table of the
//!   note's claims with the computation that judges each; `snowroll paper`
//!   renders it with plots. The checks type
//!   the note's equations themselves and observe the models only through
//!   their runs, so a wrong model changes a verdict (the report crate's tests).
//!   The errata are `docs/errata.md`, the turn model's conventions
//!   `docs/turn-model.md`.
//!
//! All models implement [`Model`]; [`ModelKind`] lists them. ODE models run on
//! one integrator ([`integrate`]): DOP853, or Taylor-series steps where the
//! model gives its Taylor coefficients, with dense output and events.
//! [`Model::simulate_into`] sends each sample to a [`SampleSink`] as it is
//! computed (`snowroll_io::TrajectoryWriter` writes CSV or JSON that way), and
//! [`TurnModel::run_table_into`] each turn's row to a [`TurnSink`]
//! (`snowroll_io::TurnTableWriter`), so memory does not grow with the length of a run;
//! [`Model::simulate`] and [`run_turns`] gather the same values in memory.
//! A run stops early, keeping what it computed, at its step budget
//! ([`StopReason::StepLimit`]) or its row limit ([`StopReason::RowLimit`]).
//!
//! ## Quick start
//! Build a [`Scenario`] from a [`ScenarioFile`] (its fields are the command
//! line's flags in snake_case, SI units, angles in degrees), pick a model
//! by id or equation alias, and read the samples:
//!
//! ```
//! use snowroll::{ModelKind, Sampling, Scenario, ScenarioFile, SimOptions};
//!
//! let scenario = Scenario::new(ScenarioFile { alpha_deg: 20.0, snow_depth: 0.02, ..Default::default() })?;
//! let model: ModelKind = "eq4".parse()?; // torque about the centre, eq. (4)
//! let opts = SimOptions { t_end: 50.0, sampling: Sampling::Times(vec![0.0, 50.0]), ..Default::default() };
//! let run = model.build().simulate(&scenario, &opts)?;
//! let (start, end) = (run.samples[0], run.samples[1]);
//! // From rest the snow costs nothing yet: a(0) = (2/3) g sin α (eq. (4) at v = 0).
//! assert!((start.a_m_s2 - 2.0 / 3.0 * scenario.g_along()).abs() < 1e-12);
//! // Late on, eq. (4) approaches g sin α / 5 (fn. 4).
//! assert!((end.a_m_s2 / scenario.g_along() - 0.2).abs() < 1e-3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! `examples/quickstart.rs` runs every model on one scenario and prints a
//! table; [`integrate`] shows the integrator on a system of your own.
//!
//! ## Symbols
//! | symbol | meaning | Rust name | unit |
//! |---|---|---|---|
//! | α | slope angle | [`Scenario::slope_angle`] | rad (degrees on the command line) |
//! | b | snow depth normal to the slope | [`Scenario::snow_depth`] | m |
//! | r0 | initial radius | [`Scenario::initial_radius`] | m |
//! | r | radius (nominal radius in §3) | [`Sample::r_m`] | m |
//! | g | gravitational acceleration | [`Scenario::gravity`] | m/s² |
//! | G, C | g sin α, g cos α | [`Scenario::g_along`], [`Scenario::g_normal`] | m/s² |
//! | ρ | density of log and snow | [`Scenario::density`] | kg/m³ |
//! | l | length of the log | [`Scenario::length`] | m |
//! | x | distance rolled down the slope | [`Sample::x_m`] | m |
//! | v, a | speed and acceleration down the slope | [`Sample::v_m_s`], [`Sample::a_m_s2`] | m/s, m/s² |
//! | m | mass of log plus snow | [`Sample::mass_kg`] | kg |
//! | k | turn number, 0-based (§3.4) | [`TurnState::turn`] | 1 |
//! | θ, θ̇ | angle rolled in the turn, its rate | [`TurnState::theta_rad`], [`TurnState::omega_rad_s`] | rad, rad/s |
//! | r_k, m_k, X_k | radius, mass, position at the start of turn k (eq. (74)) | [`TurnDynamics::radius`], [`TurnRow::x_start_m`] | m, kg, m |
//! | N, F | normal force of the slope; friction, positive up the slope (`docs/contact-forces.md` §1) | [`Sample::normal_n`], [`Sample::friction_n`], [`ContactForces`] | N |
//! | \|F\|/N | friction needed to roll without slipping | [`Sample::friction_ratio`], [`TurnRow::max_friction_ratio`] | 1 |
//! | μ | coefficient of static friction (`--mu`) | [`SimOptions::mu`] | 1 |
//! | θ_c | angle where the new layer's edge meets the snow (`--collision pivot`) | [`PivotImpact`] | rad |
//!
//! ## Equation → item
//! | note | item |
//! |---|---|
//! | eq. (4) | [`Derivation::TorqueAboutCentre`] |
//! | eq. (6) | [`Derivation::TorqueAboutContact`] |
//! | eqs. (7), (10), (11) | [`physics::kinetic_energy`], [`physics::potential_energy`], [`physics::mechanical_energy`] |
//! | eq. (8) | [`body::Body::radius_at`], [`body::Body::mass_at`], [`body::Body::swath`] (wrapped by [`physics::radius_at`], [`physics::mass_at`]) |
//! | eq. (14) | [`Derivation::Energy`] |
//! | eq. (15) | [`Derivation::EnergyLinearised`] |
//! | eq. (21) | [`Derivation::LagrangianPrinted`] |
//! | eq. (32), (36) | [`Derivation::QuasiCircular`], [`Derivation::QuasiCircularLift`] |
//! | eq. (35) and every terminal value | [`Coefficients::terminal_fraction`] |
//! | fn. 4 (and its form (F1) for every circular model) | [`sweep::SpeedSquared`] (the one closed-form solver), as [`LoneyModel`], [`DragOnlyClosedForm`] and the sweep's [`sweep::circular_end`] |
//! | fn. 7 | [`Coefficients::stall_slope`] (§2: does not start), [`first_turn_stall_slope`] (§3: stalls in turn 0), [`ModelKind::stall_threshold`] |
//! | range of validity (order in b/r) | [`ModelKind::validity`], [`validity_warnings`] |
//! | eq. (95) | [`Derivation::Snowless`] |
//! | eqs. (37)–(43), (48), (56), (60)–(62), exact | [`SectorBody`] |
//! | eqs. (58), (64), (69), (71)–(76) | [`TurnDynamics`], [`InTurnCoefficients::paper`] |
//! | exact in-turn equation (57), (88) | [`TurnVariant::Exact`], [`models::exact_geometry::exact_turn_coefficients`] |
//! | eq. (74) (0-based), §3.4 | [`TurnModel`] |
//! | eqs. (81)–(89), the collision | [`collision_speed`], [`kinetic_energy_at_turn_start`], [`kinetic_energy_at_turn_end`], [`TurnRow::collision_loss_j`] |
//! | eqs. (77)–(79), measured | [`run_turns`], [`TurnSummary`] |
//! | fn. 10, contact forces and the hop (§1–§4 of `docs/contact-forces.md`) | [`circular_forces`], [`TurnDynamics::contact_per_mass`], [`TurnDynamics::turn_extremes`], [`StopReason::Hop`], [`OnHop`] |
//! | slip, the smallest μ (`docs/contact-forces.md` §5) | [`SimOptions::mu`], [`StopReason::Slip`], [`TurnRow::max_friction_ratio`] |
//! | the step of each new layer (`docs/contact-forces.md` §6) | [`CollisionModel`], [`charged_collision_speed`], [`PivotImpact`], [`StopReason::Stuck`] |
//! | every claim of the note, with its verdict | `snowroll_report::CLAIMS` |
#![deny(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::print_stdout
)]

pub mod body;
pub mod error;
pub mod fit;
pub mod integrate;
pub mod losses;
pub mod model_kind;
pub mod models;
pub mod number;
pub mod params;
pub mod physics;
mod portable;
mod quadrature;
pub mod scenario;
pub mod sweep;
pub mod trajectory;
pub mod units;

pub use error::{ParamError, SimError, SinkError};
pub use losses::Losses;
pub use models::{
    as_fraction, atol_bound, charged_collision_speed, check_tolerances, check_turn_scale,
    circular_forces, collision_speed, default_atol, first_turn_stall_slope,
    kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, run_turns, run_turns_into,
    run_warnings, state_scale, tolerance_warning, validity_warnings, warning_codes, Balance,
    CircularModel, Coefficients, CollisionModel, ContactForces, ContactRange, Derivation,
    DragOnlyClosedForm, HopDoubt, InTurnCoefficients, LoneyModel, Model, ModelKind, PivotImpact,
    RunWarning, SectorBody, TurnCheckpoint, TurnDynamics, TurnExtremes, TurnMethod, TurnModel,
    TurnRow, TurnRunEnd, TurnSink, TurnSummary, TurnTable, TurnVariant, Validity, ValidityWarning,
    WarningCode,
};
pub use number::{format_number, format_readable};
pub use params::{Given, Param, RecordedSampling, Settings, Value, PARAMS};
pub use scenario::{ChordWord, Scenario, ScenarioFile, Shape, Swath, SwathWidth};
pub use trajectory::{
    Collected, LedgerRow, OnHop, RunEnd, Sample, SampleSink, Sampling, SimOptions, Stop,
    StopReason, Trajectory, TurnState, DEFAULT_MAX_ROWS,
};
