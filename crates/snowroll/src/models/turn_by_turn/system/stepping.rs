//! The turn model's [`OdeSystem`] (right-hand side, events, the collision
//! as a reset) and [`OdeModel`] (its samples, ledger and stop reasons).

use super::*;

use crate::integrate::{Direction, EventAction, EventRecord, OdeSystem};
use crate::models::contact::ContactForces;
use crate::models::ode::OdeModel;
use crate::trajectory::{LedgerRow, Sample, StopReason, TurnState};

impl OdeSystem<2> for TurnSystem {
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = if self.pivoting {
            self.impact.angular_acceleration(
                y[0] - self.impact.theta_c,
                self.g_along,
                self.g_normal,
            )
        } else {
            self.dynamics.angular_acceleration(y[0], y[1])
        };
    }

    fn event_count(&self) -> usize {
        6
    }

    fn event(&self, index: usize, _t: f64, y: &[f64; 2]) -> f64 {
        match index {
            EVENT_TURN_END => y[0] - TWO_PI,
            EVENT_STALL => y[1],
            EVENT_DISTANCE => match self.x_end {
                Some(x_end) => self.position(y[0]) - x_end,
                None => -1.0,
            },
            EVENT_HOP if self.stop_on_hop && self.pivoting => self.contact_per_mass(y[0], y[1]).0,
            EVENT_HOP if self.stop_on_hop => match self.hop_theta {
                Some(theta) => theta - y[0],
                None => 1.0,
            },
            EVENT_SLIP => match (self.mu, self.pivoting, self.slip_theta) {
                (Some(mu), true, _) => {
                    let (n, f) = self.contact_per_mass(y[0], y[1]);
                    f.abs() - mu * n
                }
                (Some(_), false, Some(theta)) => y[0] - theta,
                _ => -1.0,
            },
            EVENT_IMPACT if self.collision == CollisionModel::Pivot && !self.pivoting => {
                y[0] - self.impact.theta_c
            }
            // Switched off: a constant that never crosses in its direction.
            EVENT_HOP => 1.0,
            _ => -1.0,
        }
    }

    fn event_direction(&self, index: usize) -> Direction {
        match index {
            EVENT_STALL | EVENT_HOP => Direction::Falling,
            _ => Direction::Rising,
        }
    }

    fn on_event(&self, index: usize, _t: f64, y: &[f64; 2]) -> EventAction<2> {
        let outcome = match index {
            EVENT_TURN_END => self.turn_end_outcome(y[1]),
            EVENT_IMPACT => self.impact_outcome(y[1]),
            _ => return EventAction::Stop,
        };
        outcome.map_or(EventAction::Stop, EventAction::Reset)
    }

    fn commit_event(&mut self, event: &EventRecord<2>) {
        let (index, y_before, y_after) = (event.index, &event.y_before, &event.y_after);
        if index == EVENT_IMPACT {
            self.doubt_impact(y_before[1]);
        }
        // `on_event` resets exactly where the outcome is a new state: that
        // state is taken from its action, the outcome found again only for
        // the reason of a stop.
        let outcome = match (index, event.action) {
            (EVENT_TURN_END | EVENT_IMPACT, EventAction::Reset(y)) => Ok(y),
            (EVENT_TURN_END, _) => self.turn_end_outcome(y_before[1]),
            (EVENT_IMPACT, _) => self.impact_outcome(y_before[1]),
            _ => return,
        };
        match (index, outcome) {
            (_, Err(reason)) => self.stop_override = Some(reason),
            (EVENT_TURN_END, Ok(_)) => {
                if self.ledger.is_some() {
                    let (base, lost, created) = self.turn_end_booking(y_before, y_after[1]);
                    if let Some(l) = &mut self.ledger {
                        l.base_j = base;
                        l.collision_j += lost;
                        l.created_j += created;
                    }
                }
                if self.pivoting {
                    let p = self.impact;
                    let r = self.dynamics.radius();
                    self.pivot_shift += r * p.theta_c + p.d - TWO_PI * r;
                }
                self.doubt_turn_end(y_before[1]);
                let v_start = self.speed_after(y_before[1]);
                self.exact_omega0 = self.exact_omega0.and_then(|w| self.exact_next(w));
                self.enter_turn(self.turn + 1);
                self.plan_turn(y_after[1], v_start);
            }
            (_, Ok(_)) => {
                self.book_impact(y_before, y_after);
                self.pivoting = true;
            }
        }
    }
}

impl OdeModel<2> for TurnSystem {
    fn sample(&self, t: f64, y: &[f64; 2]) -> Sample {
        let (theta, omega) = (y[0], y[1]);
        let r = self.dynamics.radius();
        let (n, f) = self.contact_per_mass(theta, omega);
        let forces = ContactForces {
            normal_n: self.mass * n,
            friction_n: self.mass * f,
        };
        let (v, a, mass) = if self.pivoting {
            // The centre circles E at radius R = r + b: its speed along the
            // slope is R cos(δ − φ) φ̇.
            let p = &self.impact;
            let big_r = r + self.b;
            let phi = theta - p.theta_c;
            let (s, c) = (p.delta - phi).sin_cos_p();
            let alpha = p.angular_acceleration(phi, self.g_along, self.g_normal);
            (
                big_r * c * omega,
                big_r * (c * alpha + s * omega * omega),
                self.mass * p.mass,
            )
        } else {
            (
                r * omega,
                self.dynamics.acceleration(theta, omega),
                self.mass * (1.0 + self.dynamics.coeffs.accretion * theta),
            )
        };
        Sample {
            t_s: t,
            x_m: self.position(theta),
            v_m_s: v,
            a_m_s2: a,
            r_m: r,
            mass_kg: mass,
            normal_n: forces.normal_n,
            friction_n: forces.friction_n,
            friction_ratio: forces.friction_ratio(),
        }
    }

    /// The ledger row (`docs/snowball-and-losses.md` §3.2): no losses act
    /// within a turn, so `K + collision − created − released = E0` but for
    /// the integration error.
    fn ledger(&self, _t: f64, y: &[f64; 2]) -> Option<LedgerRow> {
        let l = self.ledger.as_ref()?;
        let kinetic = self.kinetic(y);
        // `0.0 - V`, not `-V`: at the start the released energy is +0, not −0.
        let released = 0.0 - self.potential(y[0]);
        Some(LedgerRow {
            kinetic_j: kinetic,
            released_j: released,
            drag_j: 0.0,
            rolling_j: 0.0,
            compaction_j: 0.0,
            model_j: 0.0,
            collision_j: l.collision_j,
            created_j: l.created_j,
            residual_j: kinetic + l.collision_j - l.created_j - released - l.initial_j,
        })
    }

    fn turn_state(&self, _t: f64, y: &[f64; 2]) -> Option<TurnState> {
        Some(TurnState {
            turn: self.turn,
            theta_rad: y[0],
            omega_rad_s: y[1],
        })
    }

    fn stop_reason(&self, event: usize) -> StopReason {
        if let Some(reason) = self.stop_override {
            return reason;
        }
        match event {
            EVENT_TURN_END => StopReason::Turns,
            EVENT_DISTANCE => StopReason::Distance,
            EVENT_HOP => StopReason::Hop,
            EVENT_SLIP => StopReason::Slip,
            _ if self.pivoting => StopReason::Stuck,
            _ => StopReason::Stalled,
        }
    }
}
