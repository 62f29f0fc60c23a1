//! The turn table without the integrator (`docs/turn-model.md`, "The
//! closed-form path"): the same [`TurnSystem`] (its events, collision
//! outcomes, plans of hop and slip, ledger and stop reasons) driven turn by
//! turn by the closed form of each turn ([`Orbit`]) instead of DOP853. The
//! observer sees the same calls as from the integrator (`start`, one
//! `event` per turn end or stop, `stop_requested` before each turn), so the
//! rows are made by the same code; only t and θ̇ at the events differ, by
//! the integrator's error.

use super::ahead::{Ahead, Pipeline, TurnStart};
use super::*;

use crate::error::SimError;
use crate::integrate::{EventAction, EventRecord, OdeSystem, Outcome, Stats, Termination};
use crate::models::ode::{end_observed, RunObserver};
use crate::models::turn_by_turn::orbit::Orbit;
use crate::trajectory::RunEnd;

/// What a turn computed in closed form ends with.
#[derive(Debug, Clone, Copy, PartialEq)]
enum TurnEnd {
    /// The event `index` at time `t`, with the state `y` there (before any reset).
    Event { index: usize, t: f64, y: [f64; 2] },
    /// The run's end time falls inside the turn, at state `y`.
    EndTime { y: [f64; 2] },
}

impl TurnSystem {
    /// Whether the closed form covers this run: every collision but
    /// `pivot` (whose pivot phase has its own energy integral, not done in
    /// closed form yet), and a start from rest only where the log surely
    /// starts (`E′(0) > 0`; the integrator decides the borderline case).
    pub(crate) fn closed_form_covers(&self, y0: &[f64; 2]) -> bool {
        let starts = y0[1] > 0.0 || self.dynamics.potential_slope_sc(0.0, 0.0, 1.0) < 0.0;
        self.collision != CollisionModel::Pivot && starts && y0[0] == 0.0
    }

    /// The turn now current, started at time `t0` with `θ̇(0) = omega0`,
    /// in closed form: the first of its events (θ = 2π, the stall, the end
    /// distance, the planned hop and slip; on a tie the lower event index,
    /// as the integrator offers them), and when it happens, unless the run's
    /// end time `t_end` comes first.
    fn closed_turn(&self, t0: f64, omega0: f64, t_end: f64) -> TurnEnd {
        let orbit = Orbit::new(&self.dynamics, omega0);
        let r = self.dynamics.radius();
        // This turn as computed ahead, if it was, for this very θ̇(0).
        let prepared = self
            .current
            .filter(|p| p.start.turn == self.turn && p.start.omega0.to_bits() == omega0.to_bits());
        let mut end = (TWO_PI, EVENT_TURN_END);
        let mut candidates = [
            prepared
                .map_or_else(|| orbit.first_stall(TWO_PI), |p| p.stall)
                .map(|th| (th, EVENT_STALL)),
            self.x_end
                .map(|x| ((x - self.x_start) / r, EVENT_DISTANCE))
                .filter(|&(th, _)| th >= 0.0),
            self.hop_theta
                .filter(|_| self.stop_on_hop)
                .map(|th| (th, EVENT_HOP)),
            self.slip_theta.map(|th| (th, EVENT_SLIP)),
        ];
        for (theta, index) in candidates.iter_mut().flatten() {
            if *theta < end.0 {
                end = (*theta, *index);
            }
        }
        let (theta, index) = end;
        let stalls = index == EVENT_STALL;
        let dt = match prepared {
            Some(p) if index == EVENT_TURN_END => p.time,
            _ => orbit.time_to(theta, stalls),
        };
        if t0 + dt > t_end {
            let theta_e = orbit.angle_at_time(t_end - t0, theta, stalls);
            return TurnEnd::EndTime {
                y: [theta_e, orbit.omega(theta_e)],
            };
        }
        let omega = if stalls { 0.0 } else { orbit.omega(theta) };
        TurnEnd::Event {
            index,
            t: t0 + dt,
            y: [theta, omega],
        }
    }
}

/// Runs `system` from `y0` at t = 0 turn by turn in closed form, reporting
/// the events to `observer` as [`run_observed`](crate::models::ode::run_observed)
/// does from the integrator; the run's `stats` are zero (no steps). The
/// caller has checked [`TurnSystem::closed_form_covers`].
///
/// # Errors
/// [`SimError::Sink`] when the observer's sink failed.
pub(crate) fn run_closed<O: RunObserver<TurnSystem, 2>>(
    system: &mut TurnSystem,
    y0: [f64; 2],
    t_end: f64,
    observer: &mut O,
) -> Result<RunEnd, SimError> {
    observer.start(system, 0.0, &y0);
    let (mut t, mut y) = (0.0, y0);
    let ahead = Ahead::of(system).filter(|_| system.turns_limit.is_none_or(|n| n > ahead::BLOCK));
    let termination = match ahead {
        Some(ahead) => run_ahead(system, &ahead, (&mut t, &mut y), t_end, observer),
        None => loop {
            if let Some(end) = closed_step(system, (&mut t, &mut y), t_end, observer) {
                break end;
            }
        },
    };
    let outcome = Outcome {
        t,
        y,
        termination,
        stats: Stats::default(),
    };
    end_observed(system, observer, outcome)
}

/// [`run_closed`]'s turns in blocks of [`ahead::BLOCK`]: while the turns of
/// one block go through the run in order on this thread, the next blocks
/// (up to three) are predicted and prepared by the thread pool
/// ([`Pipeline`]), each from where the prediction says the one before ends;
/// this thread helps with a block not yet done when it gets to it.
fn run_ahead<O: RunObserver<TurnSystem, 2>>(
    system: &mut TurnSystem,
    ahead: &Ahead,
    (t, y): (&mut f64, &mut [f64; 2]),
    t_end: f64,
    observer: &mut O,
) -> Termination {
    // Turn 0 was planned by `start`, at its own θ̇(0); the blocks start at turn 1.
    if let Some(end) = closed_step(system, (t, y), t_end, observer) {
        return end;
    }
    let limit = system.turns_limit.unwrap_or(u64::MAX);
    let first = TurnStart {
        turn: system.turn,
        omega0: y[1],
        v_start: system.speed_at_start(),
    };
    // This thread runs the turns in order, block after block, and helps
    // with a block not yet prepared when it gets to it ([`Pipeline`]); the
    // pool has the other cores (a pool of every core would put one more
    // thread than cores at work, its spinning taking time from this one).
    let pool = pipeline_pool();
    let workers = pool.map_or(1, rayon::ThreadPool::current_num_threads);
    let pipeline = Pipeline::new(ahead, first, limit);
    in_place_scope(pool, |scope| {
        for _ in 0..workers {
            scope.spawn(|_| pipeline.work());
        }
        let _stop = pipeline.stopped_on_drop();
        loop {
            let Some(ready) = pipeline.take() else {
                // The prediction stopped (a stuck log): the run finds out itself.
                break loop {
                    if let Some(end) = closed_step(system, (t, y), t_end, observer) {
                        break end;
                    }
                };
            };
            let block_end = system.turn + ready.len() as u64;
            system.load_prepared(ready);
            let end = loop {
                if let Some(end) = closed_step(system, (t, y), t_end, observer) {
                    break Some(end);
                }
                if system.turn >= block_end {
                    break None;
                }
            };
            if let Some(end) = end {
                break end;
            }
        }
    })
}

/// The pool of the turns computed ahead: one less thread than rayon's global
/// pool has, made once per process and kept. Made anew for every run, its
/// threads would start while the run's tables take memory; under an
/// address-space limit a new thread's first use of the Python module's
/// thread-local data then failed in the C library, which ends the process
/// rather than report it (seen once in four runs of the Python package's
/// memory-limit test), and each run paid for the threads' start.
fn pipeline_pool() -> Option<&'static rayon::ThreadPool> {
    static POOL: std::sync::OnceLock<Option<rayon::ThreadPool>> = std::sync::OnceLock::new();
    POOL.get_or_init(|| {
        let workers = rayon::current_num_threads().saturating_sub(1).max(1);
        rayon::ThreadPoolBuilder::new()
            .num_threads(workers)
            .thread_name(|i| format!("snowroll-turns-{i}"))
            .build()
            .ok()
    })
    .as_ref()
}

/// `op` in a scope of `pool` (of rayon's global pool without one) that
/// this thread takes part in.
fn in_place_scope<'scope, R>(
    pool: Option<&rayon::ThreadPool>,
    op: impl FnOnce(&rayon::Scope<'scope>) -> R,
) -> R {
    match pool {
        Some(pool) => pool.in_place_scope(op),
        None => rayon::in_place_scope(op),
    }
}

/// One turn of [`run_closed`] from time `t` and state `y`: the event it
/// ends with goes to the system and the observer, and `(t, y)` move on;
/// `Some` with why the run ends there, if it does.
fn closed_step<O: RunObserver<TurnSystem, 2>>(
    system: &mut TurnSystem,
    (t, y): (&mut f64, &mut [f64; 2]),
    t_end: f64,
    observer: &mut O,
) -> Option<Termination> {
    if observer.stop_requested() {
        return Some(Termination::Stopped);
    }
    let (index, te, ye) = match system.closed_turn(*t, y[1], t_end) {
        TurnEnd::EndTime { y: ye } => {
            (*t, *y) = (t_end, ye);
            return Some(Termination::EndTime);
        }
        TurnEnd::Event { index, t, y } => (index, t, y),
    };
    let action = system.on_event(index, te, &ye);
    let y_after = match action {
        EventAction::Reset(r) => r,
        EventAction::Stop | EventAction::Continue => ye,
    };
    let record = EventRecord {
        index,
        t: te,
        y_before: ye,
        y_after,
        action,
    };
    observer.event(system, &record);
    system.commit_event(&record);
    *t = te;
    match action {
        EventAction::Reset(_) => {
            *y = y_after;
            None
        }
        // The turn models stop at every event but the turn end's reset.
        EventAction::Stop | EventAction::Continue => {
            *y = ye;
            Some(Termination::Event { index })
        }
    }
}
