//! One row per completed turn of §3.4 ([`TurnRow`]), and the sink that
//! receives the rows as the turns end ([`TurnSink`]).
//!
//! The rows come from the integrator's events (v before and after each
//! collision, eq. (89)) and, for the range of a within a turn, from the
//! energy integral of the turn (no dense output is needed): see
//! `observer.rs`.

use serde::{Deserialize, Serialize};

use crate::error::SinkError;
use crate::trajectory::LedgerRow;
use crate::units::{Joules, Meters, MetersPerSecond, MetersPerSecondSquared, Seconds};

/// One completed turn k. Column names carry their units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnRow {
    /// Turn number k, 0-based.
    pub turn: u64,
    /// Time the turn starts, s.
    pub t_start_s: Seconds,
    /// Position of the contact line at the start, `X_k` (eq. (74)), m.
    pub x_start_m: Meters,
    /// Speed of the nominal centre at the start (after the previous collision), m/s.
    pub v_start_m_s: MetersPerSecond,
    /// Time the turn ends (θ = 2π), s.
    pub t_end_s: Seconds,
    /// Speed just before the collision, `r_k θ̇(2π)`, m/s.
    pub v_end_m_s: MetersPerSecond,
    /// Speed just after the collision, eq. (89) (also for the last turn of a
    /// run stopped by a turn count, as if the run went on), m/s.
    pub v_after_m_s: MetersPerSecond,
    /// Kinetic energy the collision removes, `T_end [1 − (r_{k+1}² + 2r_k²)/(3r_{k+1}²)]`
    /// with `T_end = m_{k+1}(r_{k+1}²/2 + r_k²) θ̇²/2` (eqs. (85), (86)), J.
    pub collision_loss_j: Joules,
    /// Mean acceleration within the turn, `(v_end − v_start)/(t_end − t_start)`, m/s².
    pub mean_a_turn_m_s2: MetersPerSecondSquared,
    /// Smallest acceleration within the turn, m/s².
    pub min_a_m_s2: MetersPerSecondSquared,
    /// Largest acceleration within the turn, m/s².
    pub max_a_m_s2: MetersPerSecondSquared,
    /// Mean acceleration including the collision's jump,
    /// `(v_after − v_start)/(t_end − t_start)`, m/s².
    pub mean_a_with_collision_m_s2: MetersPerSecondSquared,
    /// Smallest normal force within the turn (while rolling; up to θ_c with
    /// `--collision pivot`), from the energy integral (`docs/contact-forces.md` §3, §4), N.
    pub min_normal_n: f64,
    /// The same minimum as a fraction of M g, M the mass at that point, 1.
    pub min_normal_over_mg: f64,
    /// Largest |F|/N within the turn (the smallest μ that keeps it rolling, §5), 1;
    /// `None` (undefined: an empty CSV cell, a JSON `null`) when N ≤ 0 somewhere in the turn.
    pub max_friction_ratio: Option<f64>,
}

/// Receives the rows of a turn run one at a time, as each turn ends
/// ([`TurnModel::run_table_into`](super::TurnModel::run_table_into)), so a
/// run of any length needs memory for one row.
pub trait TurnSink {
    /// One completed turn.
    ///
    /// # Errors
    /// A [`SinkError`] ends the run at once; it comes back as
    /// [`SimError::Sink`](crate::SimError::Sink).
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError>;

    /// The energy ledger at the end of the turn whose row comes next, just
    /// before its collision (`docs/snowball-and-losses.md` §3.2), for a run
    /// that records one ([`Losses::records_ledger`](crate::Losses::records_ledger)).
    /// Ignored unless overridden.
    ///
    /// # Errors
    /// As [`turn`](Self::turn).
    fn ledger(&mut self, _row: &LedgerRow) -> Result<(), SinkError> {
        Ok(())
    }
}

/// Gathers every row in memory (without the ledger).
impl TurnSink for Vec<TurnRow> {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.push(*row);
        Ok(())
    }
}
