//! The closed-form path's work done ahead, in parallel
//! (`docs/turn-model.md`, "The closed-form path"): the speed at the start of
//! each turn follows from the previous one by the energy integral at θ = 2π
//! and the collision rule alone, so the starts of the next few thousand
//! turns are found first (cheap, in order), then each turn's costly parts,
//! its stall check, its time (eq. (T3)) and the extremes its row reports,
//! on all cores at once, while the turns already prepared go through the
//! run in order ([`super::closed::run_closed`]).
//!
//! Nothing here decides anything: a prepared turn is used only when the run
//! reaches that turn with the very `θ̇(0)` (to the bit) it was prepared for,
//! and the values are those the run would compute itself, by the same
//! functions. A run that leaves the prediction (a hop, a slip, an end
//! distance or time, a stall) stops there, or computes its turns itself.

use rayon::prelude::*;

use super::{TurnSystem, TWO_PI};
use crate::models::turn_by_turn::orbit::Orbit;
use crate::models::turn_by_turn::{
    charged_collision_speed, collision_speed, CollisionModel, Hints, TurnDynamics, TurnExtremes,
    TurnVariant,
};
use crate::units::Radians;

/// Turns prepared per block: enough to share out over the cores (each
/// takes a few microseconds), few enough to keep memory small (~100 bytes each).
pub(super) const BLOCK: u64 = 8192;
/// Turns per parallel task.
const TASK: usize = 256;

/// What a turn's closed form needs besides `θ̇(0)`: the run's constants.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ahead {
    variant: TurnVariant,
    r0: f64,
    b: f64,
    g_along: f64,
    g_normal: f64,
    collision: CollisionModel,
    mu: Option<f64>,
}

/// Where a turn starts: its number, `θ̇(0)` and the speed its row reports.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct TurnStart {
    pub(super) turn: u64,
    pub(super) omega0: f64,
    pub(super) v_start: f64,
}

/// One turn computed ahead.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Prepared {
    pub(super) start: TurnStart,
    /// The first stall in the turn ([`Orbit::first_stall`]).
    pub(super) stall: Option<Radians>,
    /// Time of the whole turn (eq. (T3)), when it does not stall, s.
    pub(super) time: f64,
    /// The turn's extremes at `θ̇(0) = v_start/r_k`, as its row asks for them.
    pub(super) extremes: TurnExtremes,
    /// Where it slips, with μ given ([`TurnDynamics::first_slip`]).
    pub(super) slip: Option<Radians>,
}

impl Ahead {
    /// The constants of `system`'s run; `None` where the closed form does
    /// not run the turns ([`CollisionModel::Pivot`]).
    pub(super) fn of(system: &TurnSystem) -> Option<Self> {
        (system.collision != CollisionModel::Pivot).then_some(Self {
            variant: system.variant,
            r0: system.r0,
            b: system.b,
            g_along: system.g_along,
            g_normal: system.g_normal,
            collision: system.collision,
            mu: system.mu,
        })
    }

    fn dynamics(&self, turn: u64) -> TurnDynamics {
        // r_k as `TurnSystem::enter_turn` computes it.
        let r = self.r0 + turn as f64 * self.b;
        TurnDynamics::new(self.variant, r, self.b, self.g_along, self.g_normal)
    }

    /// The start of the turn after `start`, as the run computes it when the
    /// turn ends at θ = 2π: `θ̇(2π)` from the energy integral, then the
    /// collision (`TurnSystem::omega_next`, `TurnSystem::speed_after`);
    /// `None` when the log is stuck at the step.
    pub(super) fn next_after(&self, start: &TurnStart) -> Option<TurnStart> {
        let dynamics = self.dynamics(start.turn);
        let r = dynamics.radius();
        let r_next = r + self.b;
        let omega_end = Orbit::new(&dynamics, start.omega0).omega(TWO_PI);
        let (omega0, v_start) = match self.collision {
            CollisionModel::Note => {
                let v = collision_speed(r, self.b, r * omega_end);
                (v / r_next, v)
            }
            _ => {
                let v = charged_collision_speed(r, self.b, self.g_normal, r * omega_end)?;
                let omega = v / r_next;
                (omega, omega * r_next)
            }
        };
        Some(TurnStart {
            turn: start.turn + 1,
            omega0,
            v_start,
        })
    }

    /// The starts of up to `count` turns from `first` on, in order (fewer
    /// where the log gets stuck or the speed stops being finite).
    pub(super) fn starts(&self, first: TurnStart, count: u64) -> Vec<TurnStart> {
        let mut out = Vec::with_capacity(count as usize);
        let mut start = Some(first);
        while let Some(s) = start.filter(|s| s.omega0.is_finite() && out.len() < count as usize) {
            out.push(s);
            start = self.next_after(&s);
        }
        out
    }

    /// Each of `starts` prepared, in parallel: in fixed runs of [`TASK`]
    /// turns, each run in order with Newton's method for a turn's extremes
    /// started where the turn before had them ([`Hints`]), so that the
    /// result does not depend on how the runs are shared out.
    pub(super) fn prepare(&self, starts: &[TurnStart]) -> Vec<Prepared> {
        starts
            .par_chunks(TASK)
            .flat_map_iter(|run| {
                let mut hints = Hints::default();
                run.iter()
                    .map(move |s| self.prepare_one(s, &mut hints))
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    fn prepare_one(&self, start: &TurnStart, hints: &mut Hints) -> Prepared {
        let dynamics = self.dynamics(start.turn);
        let orbit = Orbit::new(&dynamics, start.omega0);
        let stall = orbit.first_stall(TWO_PI);
        let time = match stall {
            None => orbit.time_to(TWO_PI, false),
            Some(_) => f64::NAN,
        };
        Prepared {
            start: *start,
            stall,
            time,
            extremes: dynamics.turn_extremes_hinted(start.v_start / dynamics.radius(), hints),
            slip: self
                .mu
                .and_then(|mu| dynamics.first_slip(start.omega0, mu, TWO_PI)),
        }
    }
}
