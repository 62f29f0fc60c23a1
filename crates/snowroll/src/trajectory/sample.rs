//! What a run records at each sample: the state of the log, the turn
//! state of the turn models (§3), and the energy ledger.

use serde::{Deserialize, Serialize};

use crate::units::{
    Kilograms, Meters, MetersPerSecond, MetersPerSecondSquared, Newtons, Radians, Seconds,
};

/// The state of the log at one time. Column names carry their units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// Time since the start, s.
    pub t_s: Seconds,
    /// Distance rolled down the slope (of the contact line / nominal centre), m.
    pub x_m: Meters,
    /// Speed down the slope, m/s.
    pub v_m_s: MetersPerSecond,
    /// Acceleration dv/dt, m/s².
    pub a_m_s2: MetersPerSecondSquared,
    /// Radius (nominal radius for the turn models), m.
    pub r_m: Meters,
    /// Mass of log plus snow as the model counts it, kg.
    pub mass_kg: Kilograms,
    /// Normal force N of the slope on the log, from the momentum balance of
    /// the accreting body (`docs/contact-forces.md` §1–§3), N.
    pub normal_n: Newtons,
    /// Friction force F that rolling without slipping needs, positive up the
    /// slope (`docs/contact-forces.md` §1–§3), N.
    pub friction_n: Newtons,
    /// |F|/N: the smallest coefficient of static friction that keeps this
    /// sample rolling; `None` (undefined) when N ≤ 0, the log having left
    /// the ground: an empty CSV cell, a JSON `null`.
    pub friction_ratio: Option<f64>,
}

/// Extra state of the turn-by-turn models (§3), one per sample.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnState {
    /// Turn number k, 0-based (`docs/turn-model.md`, Conventions).
    pub turn: u64,
    /// Angle rolled in this turn, rad, in [0, 2π].
    pub theta_rad: Radians,
    /// Rotation rate dθ/dt, rad/s.
    pub omega_rad_s: f64,
}

/// The energy ledger at one sample, J (`docs/snowball-and-losses.md` §3):
/// `kinetic + drag + rolling + compaction + model + collision − created
/// = initial + released`, the zero of potential energy being the note's
/// (eqs. (9)–(10)): body plus all the snow it will collect, at the start.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LedgerRow {
    /// Kinetic energy K, eq. (7), J.
    pub kinetic_j: f64,
    /// Potential energy released since the start, −V (eq. (10)), J.
    pub released_j: f64,
    /// Work done against air drag, ∫ F_d v dt, J.
    pub drag_j: f64,
    /// Work done against rolling resistance, ∫ c_rr N v dt, J.
    pub rolling_j: f64,
    /// Work of compacting the snow picked up, ∫ e_c dM, J.
    pub compaction_j: f64,
    /// Energy the model's own equation destroys (negative: creates), W_model
    /// of §3.1: 0 for `energy` and `snowless`, the inelastic pick-up for the
    /// torque models, J.
    pub model_j: f64,
    /// Kinetic energy lost in the collisions of the turn models, J.
    pub collision_j: f64,
    /// Energy created by the note's collision (eq. (89): the free jump onto
    /// the new layer), J.
    pub created_j: f64,
    /// `kinetic + drag + rolling + compaction + model + collision − created
    /// − released − initial`: zero but for the integration error, J.
    pub residual_j: f64,
}
