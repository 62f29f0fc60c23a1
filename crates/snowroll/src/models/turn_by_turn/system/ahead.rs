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

use std::collections::VecDeque;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, OnceLock};

use super::{TurnSystem, TWO_PI};
use crate::models::turn_by_turn::orbit::Orbit;
use crate::models::turn_by_turn::{
    after_collision, turn_radius, CollisionModel, Hints, TurnDynamics, TurnExtremes, TurnVariant,
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
        let r = turn_radius(self.r0, self.b, turn);
        TurnDynamics::new(self.variant, r, self.b, self.g_along, self.g_normal)
    }

    /// The start of the turn after `start`, as the run computes it when the
    /// turn ends at θ = 2π: `θ̇(2π)` from the energy integral, then the
    /// collision (`TurnSystem::omega_next`, `TurnSystem::speed_after`);
    /// `None` when the log is stuck at the step.
    pub(super) fn next_after(&self, start: &TurnStart) -> Option<TurnStart> {
        let dynamics = self.dynamics(start.turn);
        let omega_end = Orbit::new(&dynamics, start.omega0).omega(TWO_PI);
        let (omega0, v_start) = after_collision(
            self.collision,
            dynamics.radius(),
            self.b,
            self.g_normal,
            omega_end,
        )?;
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

    /// The turns of one run of a [`Block`], in order, with Newton's method
    /// for a turn's extremes started where the turn before had them
    /// ([`Hints`]): runs of fixed length, each from no hints, so that the
    /// result does not depend on which thread prepares which run.
    fn prepare_run(&self, run: &[TurnStart]) -> Vec<Prepared> {
        let mut hints = Hints::default();
        run.iter()
            .map(|s| self.prepare_one(s, &mut hints))
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

/// A block of turns being prepared: its runs of [`TASK`] turns are claimed
/// one at a time by whichever thread asks next ([`Block::work`]), so that
/// the thread that runs the turns in order, once through its own block,
/// takes runs of the next one instead of waiting for the other threads.
/// Claimed by hand (an atomic counter) rather than by rayon's scheduler:
/// that thread is not one of the pool's, and a pool's scope would have it
/// sleep until the pool is done.
pub(super) struct Block<'a> {
    ahead: &'a Ahead,
    starts: Vec<TurnStart>,
    /// The next run not yet claimed.
    next: AtomicUsize,
    /// Each run's turns, once prepared.
    runs: Vec<OnceLock<Vec<Prepared>>>,
}

impl<'a> Block<'a> {
    fn new(ahead: &'a Ahead, starts: Vec<TurnStart>) -> Self {
        let runs = starts.len().div_ceil(TASK);
        Self {
            ahead,
            starts,
            next: AtomicUsize::new(0),
            runs: (0..runs).map(|_| OnceLock::new()).collect(),
        }
    }

    /// Prepares runs not yet claimed, one at a time, until none is left.
    fn work(&self) {
        loop {
            let i = self.next.fetch_add(1, Ordering::Relaxed);
            let Some(run) = self.starts.chunks(TASK).nth(i) else {
                return;
            };
            let cell = &self.runs[i];
            let unfinished = Unfinished(cell);
            // Each run is claimed once, so the cell is empty.
            let _ = cell.set(self.ahead.prepare_run(run));
            drop(unfinished);
        }
    }

    /// Leaves the runs not yet claimed unprepared (the run stopped).
    fn abandon(&self) {
        self.next.store(self.runs.len(), Ordering::Relaxed);
    }

    /// Whether a run is left to claim.
    fn has_unclaimed(&self) -> bool {
        self.next.load(Ordering::Relaxed) < self.runs.len()
    }

    /// The start of the turn after this block's last, by the prediction.
    fn next_start(&self) -> Option<TurnStart> {
        self.starts.last().and_then(|s| self.ahead.next_after(s))
    }

    /// Every prepared turn in order, once the runs other threads claimed
    /// are done (this thread takes those left, then waits for the others).
    fn prepared(&self) -> Vec<Prepared> {
        self.work();
        let mut prepared = Vec::with_capacity(self.starts.len());
        for run in &self.runs {
            prepared.extend_from_slice(run.wait());
        }
        prepared
    }
}

/// A claimed run's cell, filled with no turns should its preparation not
/// finish (a panic on another thread): the waiting thread then goes on,
/// and the run computes those turns itself.
struct Unfinished<'b>(&'b OnceLock<Vec<Prepared>>);

impl Drop for Unfinished<'_> {
    fn drop(&mut self) {
        let _ = self.0.set(Vec::new());
    }
}

/// Blocks prepared ahead of the run, at most [`DEPTH`] of them at a time:
/// the threads of the pool ([`Pipeline::work`]) extend the prediction by
/// a block when there is room and prepare the runs of the blocks queued;
/// the thread that runs the turns takes the blocks in order
/// ([`Pipeline::take`]), helping with the runs of a block not yet done.
/// Deeper than one block, so that the pool goes on while the run is held
/// up (by a slow write, say), and the run does not wait for the pool's
/// last run of a block.
pub(super) struct Pipeline<'a> {
    ahead: &'a Ahead,
    /// Turns of the run, `u64::MAX` without a limit.
    limit: u64,
    state: Mutex<PipelineState<'a>>,
    changed: Condvar,
}

/// What [`Pipeline`] shares between its threads.
struct PipelineState<'a> {
    /// Blocks made and not yet taken by the run, in order.
    queue: VecDeque<Arc<Block<'a>>>,
    /// Where the next block starts; `None` where the prediction ends
    /// (a stuck log, the turn limit) or a thread is making the block.
    next: Option<TurnStart>,
    /// A thread is making the next block (its starts, in order).
    extending: bool,
    /// The run has ended, or taken every block there will be.
    stopped: bool,
}

/// Blocks made ahead of the run, at most.
const DEPTH: usize = 3;

impl<'a> Pipeline<'a> {
    /// A pipeline whose first block starts at `first`.
    pub(super) fn new(ahead: &'a Ahead, first: TurnStart, limit: u64) -> Self {
        Self {
            ahead,
            limit,
            state: Mutex::new(PipelineState {
                queue: VecDeque::new(),
                next: Some(first).filter(|s| s.turn < limit),
                extending: false,
                stopped: false,
            }),
            changed: Condvar::new(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, PipelineState<'a>> {
        // A panic elsewhere leaves the state as consistent as before it.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The starts of up to a block of turns from `from` on.
    fn make_block(&self, from: TurnStart) -> Arc<Block<'a>> {
        let count = BLOCK.min(self.limit.saturating_sub(from.turn));
        Arc::new(Block::new(self.ahead, self.ahead.starts(from, count)))
    }

    /// Makes the block from `from` on (`extending` set by the caller) and
    /// queues it. Should that fail half-way (a panic), the prediction ends
    /// there ([`Extending`]) rather than leave the run waiting for it.
    fn extend(&self, from: TurnStart) -> Arc<Block<'a>> {
        let guard = Extending(self);
        let b = self.make_block(from);
        std::mem::forget(guard);
        let mut state = self.lock();
        state.next = b.next_start().filter(|s| s.turn < self.limit);
        state.extending = false;
        state.queue.push_back(Arc::clone(&b));
        self.changed.notify_all();
        b
    }

    /// A pool thread's part, until the run stops: prepares runs of queued
    /// blocks, and makes the next block when there is room for it.
    pub(super) fn work(&self) {
        enum Task<'a> {
            Prepare(Arc<Block<'a>>),
            Extend(TurnStart),
        }
        loop {
            let task = {
                let mut state = self.lock();
                loop {
                    if state.stopped {
                        return;
                    }
                    if let Some(b) = state.queue.iter().find(|b| b.has_unclaimed()) {
                        break Task::Prepare(Arc::clone(b));
                    }
                    if state.queue.len() < DEPTH && !state.extending {
                        if let Some(from) = state.next.take() {
                            state.extending = true;
                            break Task::Extend(from);
                        }
                    }
                    state = self.changed.wait(state).unwrap_or_else(|e| e.into_inner());
                }
            };
            match task {
                Task::Prepare(b) => b.work(),
                Task::Extend(from) => {
                    self.extend(from);
                }
            }
        }
    }

    /// The next block's prepared turns, in order; `None` where the
    /// prediction ends. Makes the block itself when no thread has, and
    /// helps with its runs.
    pub(super) fn take(&self) -> Option<Vec<Prepared>> {
        let b = {
            let mut state = self.lock();
            loop {
                // Left in the queue while it is being prepared, for the
                // pool's threads to help with.
                if let Some(b) = state.queue.front() {
                    break Arc::clone(b);
                }
                if !state.extending {
                    match state.next.take() {
                        Some(from) => {
                            // No thread has started it: this one makes it.
                            state.extending = true;
                            drop(state);
                            break self.extend(from);
                        }
                        None => return None,
                    }
                }
                state = self.changed.wait(state).unwrap_or_else(|e| e.into_inner());
            }
        };
        let prepared = b.prepared();
        let mut state = self.lock();
        state.queue.pop_front();
        self.changed.notify_all();
        drop(state);
        Some(prepared)
    }

    /// Ends the pool's part: the blocks queued are left as they are. Called
    /// when the returned guard is dropped, however the run ends (a panic
    /// included: the pool's threads would otherwise wait for the run, and
    /// the run's scope for them).
    pub(super) fn stopped_on_drop(&self) -> StopOnDrop<'_, 'a> {
        StopOnDrop(self)
    }

    fn stop(&self) {
        let mut state = self.lock();
        state.stopped = true;
        for b in &state.queue {
            b.abandon();
        }
        self.changed.notify_all();
    }
}

/// A block being made, until it is queued: dropped before (a panic while
/// making it), it ends the prediction (`next` stays `None`) and wakes the
/// threads waiting for the block, so that the run computes its turns itself.
struct Extending<'p, 'a>(&'p Pipeline<'a>);

impl Drop for Extending<'_, '_> {
    fn drop(&mut self) {
        let mut state = self.0.lock();
        state.extending = false;
        self.0.changed.notify_all();
    }
}

/// Stops a [`Pipeline`] when dropped ([`Pipeline::stopped_on_drop`]).
pub(super) struct StopOnDrop<'p, 'a>(&'p Pipeline<'a>);

impl Drop for StopOnDrop<'_, '_> {
    fn drop(&mut self) {
        self.0.stop();
    }
}

/// The run's side of the turns computed ahead: handed over, and taken
/// turn by turn.
impl TurnSystem {
    /// The turns computed ahead of the run, in order, from the current one on.
    pub(in crate::models::turn_by_turn) fn load_prepared(&mut self, prepared: Vec<Prepared>) {
        self.ahead = prepared.into();
    }

    /// The current turn's entry among those computed ahead, if it was
    /// computed for this very start (`θ̇(0)` and `v_start` to the bit).
    pub(super) fn take_prepared(&mut self, omega0: f64, v_start: f64) -> Option<Prepared> {
        while self.ahead.front().is_some_and(|p| p.start.turn < self.turn) {
            self.ahead.pop_front();
        }
        let p = self.ahead.front().copied()?;
        (p.start.turn == self.turn
            && p.start.omega0.to_bits() == omega0.to_bits()
            && p.start.v_start.to_bits() == v_start.to_bits()
            && self.collision != CollisionModel::Pivot)
            .then_some(p)
    }
}
