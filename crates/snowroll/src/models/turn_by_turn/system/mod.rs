//! The ODE of the turn model: one turn at a time, with the constants of turn
//! k kept up to date as the turns go by, its events (turn end, stall,
//! distance, hop, slip, pivot impact) and its energy ledger.

use crate::portable::Portable as _;
mod access;
mod ahead;
mod closed;
mod doubt;
mod exact_start;
mod stepping;

pub(crate) use closed::run_closed;
pub use doubt::HopDoubt;

use std::f64::consts::PI;

use super::{
    after_collision, kinetic_energy_at_turn_start, turn_radius, CollisionModel, PivotImpact,
    TurnDynamics, TurnExtremes, TurnVariant, TWO_PI,
};

use crate::scenario::Scenario;
use crate::trajectory::{OnHop, SimOptions, StopReason};
use crate::units::{Joules, Meters, Radians};

/// Event indices of [`TurnSystem`].
pub(crate) const EVENT_TURN_END: usize = 0;
const EVENT_STALL: usize = 1;
const EVENT_DISTANCE: usize = 2;
const EVENT_HOP: usize = 3;
const EVENT_SLIP: usize = 4;
const EVENT_IMPACT: usize = 5;

/// The ODE of the current turn, with the constants of turn k kept up to date
/// by [`OdeSystem::commit_event`] (the cost per turn does not grow with k).
///
/// Events: the turn end θ = 2π (the collision, a reset), the stall θ̇ = 0,
/// the end distance, the hop N = 0 (`docs/contact-forces.md` §4), the slip
/// |F| = μN (§5) and, with [`CollisionModel::Pivot`], the impact of the new
/// layer's corner at θ = θ_c (§6.3), after which the state `[θ, θ̇]` follows
/// the pivot about the edge E until θ = 2π. While rolling, the hop and the
/// slip are planned when the turn starts, from N(θ) and F(θ) on the turn's
/// energy integral ([`TurnDynamics::first_hop`], [`TurnDynamics::first_slip`]),
/// and their events are `θ = θ_hop`, `θ = θ_slip`: a window of N < 0 or
/// |F| > μN narrower than a step is not stepped over.
pub(crate) struct TurnSystem {
    variant: TurnVariant,
    r0: Meters,
    b: Meters,
    g_along: f64,
    g_normal: f64,
    rho_l: f64,
    turns_limit: Option<u64>,
    x_end: Option<Meters>,
    mu: Option<f64>,
    stop_on_hop: bool,
    collision: CollisionModel,
    /// Turn number k.
    turn: u64,
    /// Position of the contact line at the start of turn k, `X_k`, m.
    x_start: Meters,
    /// What the pivots so far added to X_k over eq. (74), `Σ (r_j θ_c + d_j − 2π r_j)`, m.
    pivot_shift: Meters,
    /// Mass at the start of turn k, `m_k = πρl r_k²`, kg.
    mass: f64,
    dynamics: TurnDynamics,
    /// The `pivot` impact geometry of turn k.
    impact: PivotImpact,
    /// Whether the log is pivoting about the edge E (after θ_c, `pivot` only).
    pivoting: bool,
    /// A stop decided at an event whose index does not say why (a collision
    /// that leaves the log stuck, or a new turn that starts slipping).
    stop_override: Option<StopReason>,
    /// θ where this turn slips, from the energy integral ([`TurnDynamics::first_slip`]).
    slip_theta: Option<Radians>,
    /// θ where this turn hops while rolling, from the energy integral
    /// ([`TurnDynamics::first_hop`]), when a hop stops the run.
    hop_theta: Option<Radians>,
    /// The extremes of this turn from the plan of its hop, with the `θ̇(0)`
    /// they were computed for, for the turn table to reuse ([`Self::turn_extremes`]).
    planned: Option<(f64, TurnExtremes)>,
    /// The energy ledger, when the run records one.
    ledger: Option<TurnLedger>,
    /// The speed at the start of this turn as its row reports it, m/s.
    v_start: f64,
    /// Turns of the closed-form path computed ahead ([`ahead`]), in order,
    /// those not yet reached.
    ahead: std::collections::VecDeque<ahead::Prepared>,
    /// This turn as computed ahead, when it was for its `θ̇(0)`.
    current: Option<ahead::Prepared>,
    /// On the integrator's path, `θ̇(0)` of this turn as the closed form
    /// has it (the energy integral at θ = 2π and the collision from the
    /// run's start, exact but for rounding), where the closed form covers
    /// the run ([`Self::track_exact_starts`]): the hop of a turn whose
    /// least N is within the integrator's error of 0 is planned from it.
    exact_omega0: Option<f64>,
    /// Where no exact `θ̇(0)` is carried, the integrator's error estimate ([`doubt`]).
    doubt: doubt::DoubtTracker,
}

/// The energy bookkeeping of a turn run (`docs/snowball-and-losses.md`
/// §3.2), in the model's own terms: within turn k, `K = m_k I(θ) θ̇²/2` and
/// `V = V_k + m_k W(θ)` (during a pivot `K = m_k I_E θ̇²/2` and
/// `V = V_c + m_k U(φ)`, [`PivotImpact::pivot_potential`]); each collision
/// adds to `collision_j` the kinetic energy its rule removes and, for the
/// note's rule, to `created_j` the free lift `m_{k+1} g b cos α`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct TurnLedger {
    /// E0 = K(0) (V(0) = 0), J.
    initial_j: Joules,
    /// V_k, the potential energy at the start of turn k, J.
    base_j: Joules,
    /// V_c, the potential energy at the impact (`pivot`), J.
    impact_j: Joules,
    /// Kinetic energy removed by the collisions so far, J.
    collision_j: Joules,
    /// Energy created by the collisions so far (the note's free lift), J.
    created_j: Joules,
}

impl TurnSystem {
    pub(crate) fn new(variant: TurnVariant, s: &Scenario, opts: &SimOptions) -> Self {
        let mut system = Self {
            variant,
            r0: s.initial_radius(),
            b: s.snow_depth(),
            g_along: s.g_along(),
            g_normal: s.g_normal(),
            rho_l: s.density() * s.length(),
            turns_limit: opts.turns,
            x_end: opts.x_end,
            mu: opts.mu,
            stop_on_hop: opts.on_hop == OnHop::Stop,
            collision: opts.collision,
            turn: 0,
            x_start: 0.0,
            pivot_shift: 0.0,
            mass: 0.0,
            dynamics: TurnDynamics::new(variant, s.initial_radius(), 0.0, 0.0, 0.0),
            impact: PivotImpact::new(s.initial_radius(), s.snow_depth()),
            pivoting: false,
            stop_override: None,
            slip_theta: None,
            hop_theta: None,
            planned: None,
            ledger: None,
            v_start: 0.0,
            ahead: std::collections::VecDeque::new(),
            exact_omega0: None,
            current: None,
            doubt: doubt::DoubtTracker::default(),
        };
        system.enter_turn(0);
        if opts.losses.records_ledger() {
            let y0 = [0.0, s.initial_speed() / s.initial_radius()];
            system.ledger = Some(TurnLedger {
                initial_j: system.kinetic(&y0),
                base_j: 0.0,
                impact_j: 0.0,
                collision_j: 0.0,
                created_j: 0.0,
            });
        }
        system
    }

    /// The kinetic energy at `[θ, θ̇]` in the model's own terms, J:
    /// `m_k I(θ) θ̇²/2` rolling, `m_k I_E θ̇²/2` pivoting.
    fn kinetic(&self, y: &[f64; 2]) -> Joules {
        let inertia = if self.pivoting {
            self.impact.inertia_e
        } else {
            self.dynamics.inertia(y[0]).0
        };
        0.5 * self.mass * inertia * y[1] * y[1]
    }

    /// The potential energy at θ relative to the start of the run, J
    /// ([`TurnLedger`]); 0 without a ledger.
    fn potential(&self, theta: Radians) -> Joules {
        let Some(l) = &self.ledger else {
            return 0.0;
        };
        if self.pivoting {
            let phi = theta - self.impact.theta_c;
            l.impact_j
                + self.mass
                    * self
                        .impact
                        .pivot_potential(phi, self.g_along, self.g_normal)
        } else {
            l.base_j + self.mass * self.dynamics.potential(theta).0
        }
    }

    /// Books the impact of the `pivot` collision: `y_before` rolling about
    /// C, `y_after` pivoting about E (`self.pivoting` not yet set). The
    /// kinetic energy the impact removes, `K⁻ − m_k I_E θ̇₊²/2`, is a collision loss.
    fn book_impact(&mut self, y_before: &[f64; 2], y_after: &[f64; 2]) {
        if self.ledger.is_none() {
            return;
        }
        let k_before = self.kinetic(y_before);
        let v_impact = self.potential(y_before[0]);
        let k_after = 0.5 * self.mass * self.impact.inertia_e * y_after[1] * y_after[1];
        if let Some(l) = &mut self.ledger {
            l.impact_j = v_impact;
            l.collision_j += k_before - k_after;
        }
    }

    /// What the collision at the end of turn k does to the ledger, from the
    /// state just before it (in turn k): `(V_{k+1}, collision loss, created)`
    /// with `θ̇′ = omega_next` the speed the rule gives turn k + 1
    /// (`docs/snowball-and-losses.md` §3.2):
    /// * `note`: the kinetic energy `K_end − (3/2) m_{k+1} r_{k+1}² θ̇′²/2` is
    ///   lost, the lift `m_{k+1} C b` is created;
    /// * `charged`: the lift is paid from the kinetic energy, so the loss is
    ///   `K_end − K′ − m_{k+1} C b`;
    /// * `pivot`: the notch's plastic accretion loses `K_end − m_k I_{k+1} θ̇_fill²/2`
    ///   and its lift `m_k ΔV` ([`PivotImpact::notch_lift`]) raises V.
    fn turn_end_booking(&self, y_before: &[f64; 2], omega_next: f64) -> (Joules, Joules, Joules) {
        let k_end = self.kinetic(y_before);
        let v_end = self.potential(y_before[0]);
        let r = self.dynamics.radius();
        let r_next = r + self.b;
        let m_next = PI * self.rho_l * r_next * r_next;
        // The round log of the next turn rolling at r_{k+1} θ̇′, eq. (82).
        let k_next = kinetic_energy_at_turn_start(self.rho_l, r_next, r_next * omega_next);
        let lift = m_next * self.g_normal * self.b;
        match self.collision {
            CollisionModel::Note => (v_end + lift, k_end - k_next, lift),
            CollisionModel::Charged => (v_end + lift, k_end - k_next - lift, 0.0),
            CollisionModel::Pivot => {
                let p = &self.impact;
                let omega_fill = p.omega_fill(r, self.b, y_before[1]);
                let k_fill = 0.5
                    * self.mass
                    * PivotImpact::inertia_next(r, self.b)
                    * omega_fill
                    * omega_fill;
                let notch = self.mass * p.notch_lift(r, self.b, self.g_along, self.g_normal);
                (v_end + notch, k_end - k_fill, 0.0)
            }
        }
    }

    /// Sets the constants of turn `k`: r_k, m_k, X_k (eq. (74), plus the
    /// shift of the pivots) and the in-turn coefficients, in O(1).
    fn enter_turn(&mut self, k: u64) {
        let kf = k as f64;
        let r = turn_radius(self.r0, self.b, k);
        self.turn = k;
        self.x_start = 2.0 * PI * kf * self.r0 + kf * (kf - 1.0) * PI * self.b + self.pivot_shift;
        self.mass = PI * self.rho_l * r * r;
        self.dynamics = TurnDynamics::new(self.variant, r, self.b, self.g_along, self.g_normal);
        // The impact geometry (two inverse trigonometric functions) only
        // where the collision uses it.
        if self.collision == CollisionModel::Pivot {
            self.impact = PivotImpact::new(r, self.b);
        }
        self.pivoting = false;
    }

    /// Whether the turn now ending is the last one asked for.
    fn last_turn(&self) -> bool {
        self.turns_limit == Some(self.turn + 1)
    }

    /// θ̇ that starts turn k + 1 after the collision at the end of turn k,
    /// from `θ̇` at θ = 2π, by [`CollisionModel`]; `None` when the log is
    /// stuck at the step.
    pub(crate) fn omega_next(&self, omega_end: f64) -> Option<f64> {
        let r = self.dynamics.radius();
        match self.collision {
            CollisionModel::Pivot => {
                self.impact
                    .omega_next(r, self.b, omega_end, self.g_along, self.g_normal)
            }
            rule => after_collision(rule, r, self.b, self.g_normal, omega_end).map(|(w, _)| w),
        }
    }

    /// What the end of turn k leads to: the state `[0, θ̇′]` of turn k + 1,
    /// or why the run stops there.
    fn turn_end_outcome(&self, omega_end: f64) -> Result<[f64; 2], StopReason> {
        if self.last_turn() {
            return Err(StopReason::Turns);
        }
        let omega = self.omega_next(omega_end).ok_or(StopReason::Stuck)?;
        let next = TurnDynamics::new(
            self.variant,
            self.dynamics.radius() + self.b,
            self.b,
            self.g_along,
            self.g_normal,
        );
        let (n, f) = next.contact_per_mass(0.0, omega);
        self.check_contact(n, f)?;
        Ok([0.0, omega])
    }

    /// What the impact at θ_c leads to: the pivot's state `[θ_c, θ̇₊]`, or a
    /// hop or slip at the edge right away.
    fn impact_outcome(&self, omega_before: f64) -> Result<[f64; 2], StopReason> {
        let omega = self.impact.omega_after(omega_before);
        let (n, f) = self
            .impact
            .contact_per_mass(0.0, omega, self.g_along, self.g_normal);
        self.check_contact(n, f)?;
        Ok([self.impact.theta_c, omega])
    }

    /// A state entered by a reset must not already be past the hop or the
    /// slip (the events see crossings only).
    fn check_contact(&self, n: f64, f: f64) -> Result<(), StopReason> {
        if self.stop_on_hop && n <= 0.0 {
            return Err(StopReason::Hop);
        }
        match self.mu {
            Some(mu) if f.abs() - mu * n >= 0.0 => Err(StopReason::Slip),
            _ => Ok(()),
        }
    }

    /// `(N, F)` per unit m_k at `(θ, θ̇)`, rolling or pivoting, m/s².
    fn contact_per_mass(&self, theta: f64, omega: f64) -> (f64, f64) {
        if self.pivoting {
            self.impact.contact_per_mass(
                theta - self.impact.theta_c,
                omega,
                self.g_along,
                self.g_normal,
            )
        } else {
            self.dynamics.contact_per_mass(theta, omega)
        }
    }

    /// Why a run that starts at `y0` stops at once, if it does (hop or slip
    /// at the start); otherwise plans the hop and the slip of turn 0.
    pub(crate) fn start(&mut self, y0: &[f64; 2]) -> Option<StopReason> {
        let (n, f) = self.contact_per_mass(y0[0], y0[1]);
        if let Err(reason) = self.check_contact(n, f) {
            return Some(reason);
        }
        let r = self.dynamics.radius();
        self.plan_turn(y0[1], r * y0[1]);
        None
    }

    /// Where the turn just entered with `θ̇(0) = omega0` slips while
    /// rolling, and where it hops when a hop stops the run. `v_start` is the
    /// turn's starting speed as the turn table computes it (`v_after` of
    /// the collision before, [`Self::speed_after`]); the hop is planned from
    /// `v_start/r_k`, equal to `omega0` but for rounding, so that the table
    /// can reuse the extremes found on the way ([`Self::turn_extremes`]).
    fn plan_turn(&mut self, omega0: f64, v_start: f64) {
        self.v_start = v_start;
        self.current = self.take_prepared(omega0, v_start);
        if let Some(p) = self.current {
            // Computed ahead by the same functions as below, for this θ̇(0).
            self.slip_theta = p.slip;
            self.planned = Some((v_start / self.dynamics.radius(), p.extremes));
            self.hop_theta = if self.stop_on_hop {
                p.extremes.contact.first_zero_normal
            } else {
                None
            };
            return;
        }
        let theta_max = match self.collision {
            CollisionModel::Pivot => self.impact.theta_c,
            _ => TWO_PI,
        };
        // On the integrator's path, from the closed form's θ̇(0) where it
        // is carried along: the slip is then the closed form's whatever the
        // tolerance, as the hop is (below).
        let omega_plan = self.exact_omega0.unwrap_or(omega0);
        self.slip_theta = self
            .mu
            .and_then(|mu| self.dynamics.first_slip(omega_plan, mu, theta_max));
        self.planned = None;
        self.hop_theta = None;
        if self.stop_on_hop {
            let omega_table = v_start / self.dynamics.radius();
            let extremes = self.rolling_extremes(omega_table);
            self.hop_theta = extremes.contact.first_zero_normal;
            self.planned = Some((omega_table, extremes));
            if let Some(exact) = self.exact_omega0 {
                // The integrator's θ̇(0) is off by its error: where that
                // could decide whether (or where) the turn hops, the hop is
                // the closed form's, from the exact θ̇(0).
                let margin = self.hop_margin(omega_table, exact);
                let c = extremes.contact;
                if c.first_zero_normal.is_some() || c.min_normal_per_mk <= margin {
                    self.hop_theta = self.dynamics.first_hop(exact, theta_max);
                }
            }
        }
        self.doubt_turn_start(omega0);
    }

    /// The speed at the start of this turn as its row reports it, m/s.
    pub(super) fn speed_at_start(&self) -> f64 {
        self.v_start
    }

    /// The extremes of a turn started with `θ̇(0) = omega0` while rolling:
    /// over the whole turn, or with `--collision pivot` the contact forces up
    /// to θ_c only (the range of a is then left NaN).
    fn rolling_extremes(&self, omega0: f64) -> TurnExtremes {
        match self.collision {
            CollisionModel::Pivot => TurnExtremes {
                a_min: f64::NAN,
                a_max: f64::NAN,
                contact: self.dynamics.contact_range(omega0, self.impact.theta_c),
            },
            _ => self.dynamics.turn_extremes(omega0),
        }
    }

    /// What a row of the turn table reports for the current turn started
    /// with `θ̇(0) = omega0`: the range of a over the whole turn and the
    /// contact forces while rolling. Reuses the extremes of the turn's plan
    /// when they were computed for this very `omega0`.
    pub(crate) fn turn_extremes(&self, omega0: f64) -> TurnExtremes {
        let planned = self
            .planned
            .filter(|(w, _)| w.to_bits() == omega0.to_bits())
            .map(|(_, e)| e);
        let extremes = planned.unwrap_or_else(|| self.rolling_extremes(omega0));
        match self.collision {
            CollisionModel::Pivot => {
                let (a_min, a_max) = self.dynamics.acceleration_range(omega0);
                TurnExtremes {
                    a_min,
                    a_max,
                    ..extremes
                }
            }
            _ => extremes,
        }
    }

    /// The speed just after the collision at the end of turn k, from `θ̇` at
    /// θ = 2π, as the turn table reports it: eq. (89) for `note`, else the
    /// rule's `θ̇′ r_{k+1}` (0 when the log is stuck), m/s.
    pub(crate) fn speed_after(&self, omega_end: f64) -> f64 {
        let r = self.dynamics.radius();
        match self.collision {
            CollisionModel::Pivot => self.omega_next(omega_end).unwrap_or(0.0) * (r + self.b),
            rule => {
                after_collision(rule, r, self.b, self.g_normal, omega_end).map_or(0.0, |(_, v)| v)
            }
        }
    }

    /// Position of the nominal centre along the slope: `X_k + r_k θ` while
    /// rolling; during the pivot `x_E − (r + b) sin(δ − φ)`, φ = θ − θ_c,
    /// continuous from x_C to x_E, m.
    fn position(&self, theta: f64) -> Meters {
        let r = self.dynamics.radius();
        if self.pivoting {
            let p = &self.impact;
            let x_e = self.x_start + r * p.theta_c + p.d;
            x_e - (r + self.b) * (p.delta - (theta - p.theta_c)).sin_p()
        } else {
            self.x_start + r * theta
        }
    }
}
