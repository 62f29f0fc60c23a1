//! The turn table's observer of the integrator: one [`TurnRow`] per
//! turn-end event, sent to a [`TurnSink`].
//!
//! The table runs through the same run of the integrator as every ODE model,
//! [`run_observed`] (the row budget and the sink's failure, [`RowBudget`];
//! the integrator's end mapped to a [`StopReason`](crate::StopReason) and a
//! [`Stop`](crate::Stop)), but not through [`run_ode`]'s [`Recorder`], which
//! would change what is recorded:
//! * a row is made at the event θ = 2π, from the state just before the
//!   collision and from the turn that ends (its radius, mass, collision rule,
//!   range of a and contact forces), before [`OdeSystem::commit_event`] moves
//!   the system to turn k + 1. The [`Recorder`] records at the times
//!   [`Sampling`](crate::Sampling) asks for, not at events, and its sink sees
//!   a [`Sample`](crate::Sample) and a turn state, not the system;
//! * its row limit counts samples, the table's counts turns; it sends a
//!   ledger row with every sample, the table one per turn; and a run stopped
//!   at its start sends one sample, where the table sends nothing;
//! * sampling at given times asks for the dense output, three more
//!   evaluations per step, which would change the table's `stats`.
//!
//! [`Recorder`]: crate::models::ode::Recorder
//! [`run_ode`]: crate::models::ode::run_ode
//! [`run_observed`]: crate::models::ode::run_observed
//! [`OdeSystem::commit_event`]: crate::integrate::OdeSystem::commit_event

use super::{
    kinetic_energy_at_turn_end, kinetic_energy_at_turn_start, CollisionModel, SummaryBuilder,
    TurnRow, TurnSink, TurnSummary, TurnSystem, EVENT_TURN_END,
};
use crate::integrate::{EventRecord, Observer};
use crate::models::ode::{OdeModel, RowBudget, RunObserver};

/// Makes one [`TurnRow`] per turn-end event and sends it on, with the
/// ledger just before its collision when the run records one.
pub(super) struct TableObserver<'a> {
    sink: &'a mut dyn TurnSink,
    summary: SummaryBuilder,
    /// Rows sent, against [`SimOptions::max_rows`](crate::SimOptions::max_rows),
    /// and the sink's failure.
    budget: RowBudget,
    /// Time the current turn started, s.
    t_start: f64,
    /// Speed at the start of the current turn, m/s.
    v_start: f64,
}

impl<'a> TableObserver<'a> {
    /// An observer that sends rows to `sink`, at most `max_rows` of them,
    /// and sums them up in `summary`.
    pub(super) fn new(sink: &'a mut dyn TurnSink, summary: SummaryBuilder, max_rows: u64) -> Self {
        Self {
            sink,
            summary,
            budget: RowBudget::new(max_rows),
            t_start: 0.0,
            v_start: 0.0,
        }
    }

    /// The long-run statistics of the rows sent.
    pub(super) fn into_summary(self) -> TurnSummary {
        self.summary.finish()
    }
}

impl Observer<TurnSystem, 2> for TableObserver<'_> {
    fn start(&mut self, system: &TurnSystem, t0: f64, y0: &[f64; 2]) {
        self.t_start = t0;
        self.v_start = system.dynamics().radius() * y0[1];
    }

    fn event(&mut self, system: &TurnSystem, event: &EventRecord<2>) {
        if event.index != EVENT_TURN_END || self.stop_requested() {
            return;
        }
        let dynamics = system.dynamics();
        let (r, b) = (dynamics.radius(), system.snow_depth());
        let r_next = r + b;
        let omega_end = event.y_before[1];
        let v_end = r * omega_end;
        let v_after = system.speed_after(omega_end);
        let collision_loss = match system.collision() {
            CollisionModel::Note => {
                // The collision keeps (r_{k+1}² + 2r_k²)/(3r_{k+1}²) of T_end (eqs. (85), (86), (89)).
                let t_end_kinetic = kinetic_energy_at_turn_end(system.rho_l(), r, b, v_end);
                t_end_kinetic * 2.0 * b * (2.0 * r + b) / (3.0 * r_next * r_next)
            }
            collision => {
                // Kinetic energy before (rolling about C, or pivoting about E)
                // minus after (eq. (82) for turn k + 1); 0 speed when stuck.
                let before = if collision == CollisionModel::Pivot {
                    0.5 * system.start_mass()
                        * system.pivot_impact().inertia_e
                        * omega_end
                        * omega_end
                } else {
                    kinetic_energy_at_turn_end(system.rho_l(), r, b, v_end)
                };
                let after = kinetic_energy_at_turn_start(system.rho_l(), r_next, v_after);
                before - after
            }
        };
        // The range of a, and the contact forces while rolling (up to θ_c
        // with `--collision pivot`).
        let extremes = system.turn_extremes(self.v_start / r);
        let (a_min, a_max, contact) = (extremes.a_min, extremes.a_max, extremes.contact);
        let m_k = system.start_mass();
        let dt = event.t - self.t_start;
        let row = TurnRow {
            turn: system.turn(),
            t_start_s: self.t_start,
            x_start_m: system.turn_start_x(),
            v_start_m_s: self.v_start,
            t_end_s: event.t,
            v_end_m_s: v_end,
            v_after_m_s: v_after,
            collision_loss_j: collision_loss,
            mean_a_turn_m_s2: (v_end - self.v_start) / dt,
            min_a_m_s2: a_min,
            max_a_m_s2: a_max,
            mean_a_with_collision_m_s2: (v_after - self.v_start) / dt,
            min_normal_n: m_k * contact.min_normal_per_mk,
            min_normal_over_mg: contact.min_normal_over_mg,
            max_friction_ratio: contact.max_friction_ratio,
        };
        let sent = match system.ledger(event.t, &event.y_before) {
            Some(ledger) => self.sink.ledger(&ledger),
            None => Ok(()),
        }
        .and_then(|()| self.sink.turn(&row));
        if self.budget.book(sent) {
            self.summary.push(&row);
        }
        self.t_start = event.t;
        self.v_start = v_after;
    }

    fn stop_requested(&self) -> bool {
        self.budget.full()
    }
}

impl RunObserver<TurnSystem, 2> for TableObserver<'_> {
    fn budget(&mut self) -> &mut RowBudget {
        &mut self.budget
    }
}
