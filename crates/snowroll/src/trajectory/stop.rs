//! How a run ends: why ([`StopReason`]), where ([`Stop`]) and at what cost
//! ([`RunEnd`]).

use serde::{Deserialize, Serialize};

use super::TurnState;
use crate::integrate::Stats;
#[cfg(doc)]
use crate::integrate::Tolerances;
use crate::units::{Meters, MetersPerSecond, Seconds};

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum StopReason {
    /// Reached `t_end`.
    EndTime,
    /// Reached `x_end`.
    Distance,
    /// Completed the requested number of turns.
    Turns,
    /// The speed returned to zero (the log would have to shed snow to roll back, `docs/turn-model.md`, Conventions).
    Stalled,
    /// The acceleration at the start is not positive: the log cannot lift the snow (fn. 7),
    /// or an unwinding roll on a level floor has nothing in its equation to drive it
    /// (the torque balances, `docs/unwinding.md`).
    DoesNotStart,
    /// The normal force reached zero: the log leaves the ground (fn. 10,
    /// `docs/contact-forces.md` §4; with `--collision pivot` also at the edge of
    /// the new layer, §6.3).
    Hop,
    /// |F| reached μ N: rolling without slipping needs more friction than
    /// `mu` (`docs/contact-forces.md` §5).
    Slip,
    /// With `--collision charged|pivot`, the kinetic energy after the impact
    /// cannot lift the log onto the new layer (`docs/contact-forces.md` §6.2, §6.3).
    Stuck,
    /// The integrator used up its step budget ([`Tolerances::max_steps`]);
    /// the samples up to there are kept.
    StepLimit,
    /// The run recorded [`SimOptions::max_rows`](super::SimOptions::max_rows)
    /// samples, the most allowed; the samples up to there are kept.
    RowLimit,
    /// The snowless log with drag reached its terminal velocity: |a| fell to
    /// [`Losses::terminal_tol`](crate::Losses::terminal_tol) of the initial
    /// drive (`docs/snowball-and-losses.md` §2.2).
    Terminal,
    /// An unwinding roll (b < 0) laid its layer down to its core: r reached
    /// [`core_radius`](crate::ScenarioFile::core_radius) (`docs/unwinding.md`).
    Unwound,
}

impl StopReason {
    /// A sentence for people.
    pub fn describe(self) -> &'static str {
        match self {
            StopReason::EndTime => "reached the end time",
            StopReason::Distance => "reached the end distance",
            StopReason::Turns => "completed the requested number of turns",
            StopReason::Stalled => "the speed returned to zero (stall)",
            StopReason::DoesNotStart => {
                "the body does not start: a(0) <= 0 (a log or ball that cannot lift the snow, \
                 fn. 7, or an unwinding roll on a level floor that nothing in its equation drives)"
            }
            StopReason::Hop => "the normal force reached zero: the body hops (fn. 10)",
            StopReason::Slip => {
                "the friction needed reached mu times the normal force: the body slips"
            }
            StopReason::Stuck => "the log cannot climb the step onto the new layer of snow (stuck)",
            StopReason::StepLimit => {
                "the integrator used up its step budget (max_steps); the rows computed so far are kept"
            }
            StopReason::RowLimit => {
                "the run recorded max_rows rows, the most allowed; the rows computed so far are kept"
            }
            StopReason::Terminal => {
                "the acceleration fell below the terminal tolerance: terminal velocity reached"
            }
            StopReason::Unwound => "the roll unwound down to its core (core_radius)",
        }
    }

    /// Whether the run ended on a limit of the program rather than on its
    /// physics or its requested end.
    pub fn is_limit(self) -> bool {
        matches!(self, StopReason::StepLimit | StopReason::RowLimit)
    }
}

/// Where and why the run ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Stop {
    /// Why.
    pub reason: StopReason,
    /// Time, s.
    pub t_s: Seconds,
    /// Position, m.
    pub x_m: Meters,
    /// Speed, m/s.
    pub v_m_s: MetersPerSecond,
    /// For the turn models, turn, θ and θ̇ at the stop.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub turn: Option<TurnState>,
}

impl Stop {
    /// Where, for people: `t = … s, x = … m, v = … m/s` and, for the turn
    /// models, `, turn k, theta = … rad, omega = … rad/s`.
    pub fn place(&self) -> String {
        // Numbers as the outputs write them: exponent form outside
        // 1e-4..1e9 (`v = -5.551115123125783e-18`, not eighteen zeros).
        let n = crate::number::format_number;
        let mut s = format!(
            "t = {} s, x = {} m, v = {} m/s",
            n(self.t_s),
            n(self.x_m),
            n(self.v_m_s)
        );
        if let Some(k) = self.turn {
            s.push_str(&format!(
                ", turn {} (0-based), theta = {} rad, omega = {} rad/s",
                k.turn,
                n(k.theta_rad),
                n(k.omega_rad_s)
            ));
        }
        s
    }
}

/// How a run ended: where and why, and what it cost. What
/// [`Model::simulate_into`](crate::Model::simulate_into) returns once its
/// samples have gone to the sink.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunEnd {
    /// How the run ended.
    pub stop: Stop,
    /// Integrator counts (zero for closed forms).
    pub stats: Stats,
    /// A turn model's run on the integrator's path whose first hop the
    /// integrator's error could decide (`None` for every other run).
    pub hop_doubt: Option<HopDoubt>,
}

/// A turn whose least normal force is within the integrator's error of 0,
/// on a run the closed form does not cover: whether (and where) the first
/// hop happens may depend on the tolerance. Rerun at a tighter `rtol`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HopDoubt {
    /// The turn (0-based).
    pub turn: u64,
    /// Its least N over `m_k g` (`m_k` the log's mass at the turn's start),
    /// as the integrator's run has it.
    pub least_normal_over_mkg: f64,
    /// The estimated error of that value, from the integrator's error
    /// carried along the run.
    pub error_over_mkg: f64,
}
