//! §3 and §3.4: the log followed turn by turn, not assumed circular, with a
//! collision at the end of every full turn (eq. (89)).
//!
//! Conventions (`docs/turn-model.md`): turn k = 0, 1, 2, … starts with a
//! circular log of radius `r_k = r0 + k b` and mass `m_k = πρl r_k²` at
//! `X_k = 2πk r0 + k(k − 1)πb` (eq. (74), 0-based). During the turn the log
//! is the disk plus an annular sector of the snow it has picked up; the
//! state is `[θ (rad), θ̇ (rad/s)]`, θ ∈ [0, 2π] the angle rolled in this
//! turn, and `x = X_k + r_k θ`, `v = r_k θ̇` (the nominal centre). Per unit
//! `m_k` the equation of motion is that of energy conservation,
//!
//! `I(θ) θ̈ + ½ I′(θ) θ̇² = −W′(θ)`, `a = r_k θ̈`,
//!
//! with two sets of mass properties ([`TurnVariant`]):
//! * `Paper`: eqs. (73), (76), first order in b/r_k (the note's own);
//! * `Exact`: the disk plus annular sector without truncation
//!   ([`super::exact_geometry`]), for which eq. (88) with the corrected (87)
//!   holds exactly.
//!
//! Both are one form, `I = 3r²/2 + c₁θ − c₂ sin θ`,
//! `W = −G(rθ + e₁θ²/2 − e₂(1 − cos θ)) + C(e₃θ − e₂ sin θ)`
//! (G = g sin α, C = g cos α), with coefficients per turn
//! ([`TurnDynamics`]). A turn ends at the event θ = 2π, where the collision
//! (eq. (89): angular momentum about the contact line conserved) resets the
//! state to `[0, θ̇′]` of turn k + 1; the integrator applies the reset. If θ̇
//! reaches 0 first the log stalls and the run stops (rolling back would
//! un-accrete snow, `docs/turn-model.md`). Valid to O(b/r_k) (`Paper`); the
//! collision model itself is the note's idealisation (§3.4).
//!
//! Samples report `r_m = r_k` (nominal) and `mass_kg = m_k + m_s(θ)` in the
//! variant's own bookkeeping (`m_s = m_k bθ/(πr_k)`, eq. (38), for `Paper`;
//! the exact sector mass for `Exact`), so the mass may jump by O(b²) at a
//! collision for `Paper`. The per-turn table is [`run_turns`].

mod collision;
mod contact;
mod extremes;
mod stall;
mod table;

pub use collision::CollisionModel;
pub use stall::first_turn_stall_slope;
pub use table::{run_turns, TurnCheckpoint, TurnRow, TurnSummary, TurnTable};

use std::f64::consts::PI;

use super::exact_geometry::exact_turn_coefficients;
use super::ode::{run_ode, OdeModel};
use super::{Model, ModelKind};
use crate::error::SimError;
use crate::integrate::{Direction, EventAction, OdeSystem};
use crate::scenario::Scenario;
use crate::trajectory::{Sample, SimOptions, StopReason, Trajectory, TurnState};
use crate::units::{Joules, Meters, MetersPerSecond, MetersPerSecondSquared, Radians};

/// Full turn, rad.
const TWO_PI: f64 = 2.0 * PI;

/// Which mass properties the turn uses (`docs/turn-model.md`, Conventions).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TurnVariant {
    /// Eqs. (73), (76): `I_C`, V to first order in b/r_k (model `turns`).
    Paper,
    /// Exact disk plus annular sector, so that eq. (88) holds (model `turns-exact`).
    Exact,
}

impl TurnVariant {
    /// The model id of this variant.
    pub fn kind(self) -> ModelKind {
        match self {
            TurnVariant::Paper => ModelKind::Turns,
            TurnVariant::Exact => ModelKind::TurnsExact,
        }
    }

    /// The variant of a turn model; `None` for the other models.
    pub fn of(kind: ModelKind) -> Option<Self> {
        match kind {
            ModelKind::Turns => Some(TurnVariant::Paper),
            ModelKind::TurnsExact => Some(TurnVariant::Exact),
            _ => None,
        }
    }
}

/// The coefficients of the common in-turn form (module doc), per unit `m_k`:
/// `I/m_k = 3r²/2 + c₁θ − c₂ sin θ` (m²),
/// `W/m_k = −G(rθ + e₁θ²/2 − e₂(1 − cos θ)) + C(e₃θ − e₂ sin θ)` (J/kg), and
/// accreted mass `m_s/m_k = μθ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InTurnCoefficients {
    /// c₁, m².
    pub c1: f64,
    /// c₂, m².
    pub c2: f64,
    /// e₁, m.
    pub e1: f64,
    /// e₂, m.
    pub e2: f64,
    /// e₃, m.
    pub e3: f64,
    /// μ, accreted mass per radian over m_k, 1/rad.
    pub accretion: f64,
}

impl InTurnCoefficients {
    /// Eq. (76) and eq. (62) with `r0 → r_k`: `c₁ = c₂ = 2br/π`,
    /// `e₁ = e₂ = e₃ = b/π`, `μ = b/(πr)` (eq. (38)).
    pub fn paper(r: Meters, b: Meters) -> Self {
        Self {
            c1: 2.0 * b * r / PI,
            c2: 2.0 * b * r / PI,
            e1: b / PI,
            e2: b / PI,
            e3: b / PI,
            accretion: b / (PI * r),
        }
    }
}

/// The in-turn dynamics of turn k: `I(θ)`, `W(θ)` per unit `m_k`, the
/// equation of motion `I θ̈ + ½ I′ θ̇² = −W′` and its energy integral
/// `θ̇²(θ) = [I(0) θ̇₀² − 2W(θ)]/I(θ)`.
///
/// ```
/// use snowroll::{TurnDynamics, TurnVariant};
/// let (g_along, g_normal) = (4.905, 8.496);
/// let turn = TurnDynamics::new(TurnVariant::Paper, 0.1, 0.01, g_along, g_normal);
/// // From rest, a = r(−W′(0))/I(0) = 2G/3.
/// assert!((turn.acceleration(0.0, 0.0) - 2.0 * g_along / 3.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnDynamics {
    r: Meters,
    g_along: MetersPerSecondSquared,
    g_normal: MetersPerSecondSquared,
    coeffs: InTurnCoefficients,
}

impl TurnDynamics {
    /// Turn of nominal radius `r` (= r_k) in snow of depth `b`, with
    /// `G = g sin α`, `C = g cos α`.
    pub fn new(variant: TurnVariant, r: Meters, b: Meters, g_along: f64, g_normal: f64) -> Self {
        let coeffs = match variant {
            TurnVariant::Paper => InTurnCoefficients::paper(r, b),
            TurnVariant::Exact => exact_turn_coefficients(r, b),
        };
        Self {
            r,
            g_along,
            g_normal,
            coeffs,
        }
    }

    /// Nominal radius r_k, m.
    pub fn radius(&self) -> Meters {
        self.r
    }

    /// The coefficients.
    pub fn coefficients(&self) -> InTurnCoefficients {
        self.coeffs
    }

    /// `(I, dI/dθ)` per unit `m_k`, m².
    pub fn inertia(&self, theta: Radians) -> (f64, f64) {
        let (s, c) = theta.sin_cos();
        self.inertia_sc(theta, s, c)
    }

    fn inertia_sc(&self, theta: f64, sin: f64, cos: f64) -> (f64, f64) {
        let k = &self.coeffs;
        (
            1.5 * self.r * self.r + k.c1 * theta - k.c2 * sin,
            k.c1 - k.c2 * cos,
        )
    }

    /// `(W, dW/dθ)` per unit `m_k`, J/kg, zero at θ = 0.
    pub fn potential(&self, theta: Radians) -> (f64, f64) {
        let (s, c) = theta.sin_cos();
        self.potential_sc(theta, s, c)
    }

    fn potential_sc(&self, theta: f64, sin: f64, cos: f64) -> (f64, f64) {
        let k = &self.coeffs;
        let (g, c_n, r) = (self.g_along, self.g_normal, self.r);
        (
            -g * (r * theta + k.e1 * theta * theta / 2.0 - k.e2 * (1.0 - cos))
                + c_n * (k.e3 * theta - k.e2 * sin),
            self.potential_slope_sc(theta, sin, cos),
        )
    }

    /// `dW/dθ` alone (the right-hand side needs no more).
    fn potential_slope_sc(&self, theta: f64, sin: f64, cos: f64) -> f64 {
        let k = &self.coeffs;
        -self.g_along * (self.r + k.e1 * theta - k.e2 * sin) + self.g_normal * (k.e3 - k.e2 * cos)
    }

    /// `θ̈ = (−W′ − ½ I′ θ̇²)/I`, rad/s².
    pub fn angular_acceleration(&self, theta: Radians, omega: f64) -> f64 {
        let (s, c) = theta.sin_cos();
        let (i, di) = self.inertia_sc(theta, s, c);
        (-self.potential_slope_sc(theta, s, c) - 0.5 * di * omega * omega) / i
    }

    /// `a = dv/dt = r_k θ̈`, m/s² (eq. (73) for `Paper`).
    pub fn acceleration(&self, theta: Radians, omega: f64) -> MetersPerSecondSquared {
        self.r * self.angular_acceleration(theta, omega)
    }

    /// Energy per unit `m_k`, `I θ̇²/2 + W`, J/kg: constant within the turn.
    pub fn energy(&self, theta: Radians, omega: f64) -> f64 {
        let (i, _) = self.inertia(theta);
        let (w, _) = self.potential(theta);
        i * omega * omega / 2.0 + w
    }

    /// `θ̇²` at θ from the energy integral, given `θ̇ = omega0` at θ = 0.
    pub fn omega_squared(&self, theta: Radians, omega0: f64) -> f64 {
        let (i, _) = self.inertia(theta);
        let (w, _) = self.potential(theta);
        (1.5 * self.r * self.r * omega0 * omega0 - 2.0 * w) / i
    }

    /// Acceleration at θ on the energy integral from `θ̇(0) = omega0`, m/s²
    /// (θ̇² clamped at 0 past a stall): `a = r(−W′ − ½I′θ̇²)/I` with
    /// `θ̇² = [I(0)θ̇₀² − 2W]/I`.
    pub fn acceleration_on_orbit(&self, theta: Radians, omega0: f64) -> MetersPerSecondSquared {
        let (s, c) = theta.sin_cos();
        let (i, di) = self.inertia_sc(theta, s, c);
        let (w, dw) = self.potential_sc(theta, s, c);
        let omega2 = ((1.5 * self.r * self.r * omega0 * omega0 - 2.0 * w) / i).max(0.0);
        self.r * (-dw - 0.5 * di * omega2) / i
    }

    /// Smallest and largest acceleration over a whole turn started with
    /// `θ̇(0) = omega0`, from the energy integral (no integration): a grid
    /// over [0, 2π] brackets each extreme, Brent's method refines it.
    pub fn acceleration_range(&self, omega0: f64) -> (f64, f64) {
        extremes::range_on(
            |theta| self.acceleration_on_orbit(theta, omega0),
            0.0,
            TWO_PI,
            RANGE_GRID,
            RANGE_THETA_TOL,
        )
    }
}

/// Grid intervals over a turn that bracket the extremes of a(θ): a(θ) has
/// one minimum and one maximum per turn (≈ (2/3)G − (G/3)(1 − cos θ) at
/// large k), so 16 intervals of 0.39 rad leave margin.
const RANGE_GRID: usize = 16;
/// Relative tolerance in θ of the refined extremes: a at the extreme is then
/// off by ~a″·(1e-8 · 2π)²/2 ≈ 2e-15 a″, a″ ~ G per rad².
const RANGE_THETA_TOL: f64 = 1e-8;

/// Speed just after the collision at the end of turn k, eq. (89) with
/// `I_C,end = m_{k+1}(r_{k+1}²/2 + r_k²)` (eq. (85)) and
/// `I_C,beg = 3m_{k+1}r_{k+1}²/2` (eq. (81)):
/// `v′ = v (r_{k+1}² + 2r_k²)/(3 r_k r_{k+1})`.
pub fn collision_speed(r_k: Meters, b: Meters, v_end: MetersPerSecond) -> MetersPerSecond {
    let r_next = r_k + b;
    v_end * (r_next * r_next + 2.0 * r_k * r_k) / (3.0 * r_k * r_next)
}

/// Kinetic energy of the circular log of radius `r_k` rolling at speed `v`
/// at the start of turn k, eq. (82) (0-based): `T = 3 m_k v²/4`, with
/// `m_k = π ρ l r_k²` and `rho_l` = ρ l, J.
pub fn kinetic_energy_at_turn_start(rho_l: f64, r_k: Meters, v: MetersPerSecond) -> Joules {
    0.75 * std::f64::consts::PI * rho_l * r_k * r_k * v * v
}

/// Kinetic energy at the end of turn k, just before the collision, eqs.
/// (85)–(86) (0-based): the log is round with radius `r_{k+1} = r_k + b`
/// but still touches at distance `r_k` from its centre, so
/// `T = m_{k+1} (1 + r_{k+1}²/(2 r_k²)) v²/2`, J.
pub fn kinetic_energy_at_turn_end(
    rho_l: f64,
    r_k: Meters,
    b: Meters,
    v_end: MetersPerSecond,
) -> Joules {
    let r_next = r_k + b;
    let m_next = std::f64::consts::PI * rho_l * r_next * r_next;
    m_next * (1.0 + r_next * r_next / (2.0 * r_k * r_k)) * v_end * v_end / 2.0
}

/// Event indices of [`TurnSystem`].
const EVENT_TURN_END: usize = 0;
const EVENT_STALL: usize = 1;
const EVENT_DISTANCE: usize = 2;

/// The ODE of the current turn, with the constants of turn k kept up to date
/// by [`OdeSystem::commit_event`] (the cost per turn does not grow with k).
pub(crate) struct TurnSystem {
    variant: TurnVariant,
    r0: Meters,
    b: Meters,
    g_along: f64,
    g_normal: f64,
    rho_l: f64,
    turns_limit: Option<u64>,
    x_end: Option<Meters>,
    /// Turn number k.
    turn: u64,
    /// Position of the contact line at the start of turn k, `X_k`, m.
    x_start: Meters,
    /// Mass at the start of turn k, `m_k = πρl r_k²`, kg.
    mass: f64,
    dynamics: TurnDynamics,
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
            turn: 0,
            x_start: 0.0,
            mass: 0.0,
            dynamics: TurnDynamics::new(variant, s.initial_radius(), 0.0, 0.0, 0.0),
        };
        system.enter_turn(0);
        system
    }

    /// Sets the constants of turn `k`: r_k, m_k, X_k (eq. (74)) and the
    /// in-turn coefficients, in O(1).
    fn enter_turn(&mut self, k: u64) {
        let kf = k as f64;
        let r = self.r0 + kf * self.b;
        self.turn = k;
        self.x_start = 2.0 * PI * kf * self.r0 + kf * (kf - 1.0) * PI * self.b;
        self.mass = PI * self.rho_l * r * r;
        self.dynamics = TurnDynamics::new(self.variant, r, self.b, self.g_along, self.g_normal);
    }

    /// Whether the turn now ending is the last one asked for.
    fn last_turn(&self) -> bool {
        self.turns_limit == Some(self.turn + 1)
    }

    /// The state `[0, θ̇′]` that starts turn k + 1 after the collision at
    /// the end of turn k, from `θ̇` at θ = 2π (eq. (89), [`collision_speed`]).
    fn collide(&self, omega_end: f64) -> [f64; 2] {
        let r = self.dynamics.radius();
        let v_after = collision_speed(r, self.b, r * omega_end);
        [0.0, v_after / (r + self.b)]
    }

    pub(crate) fn turn(&self) -> u64 {
        self.turn
    }

    pub(crate) fn dynamics(&self) -> &TurnDynamics {
        &self.dynamics
    }

    pub(crate) fn turn_start_x(&self) -> Meters {
        self.x_start
    }

    pub(crate) fn snow_depth(&self) -> Meters {
        self.b
    }

    pub(crate) fn rho_l(&self) -> f64 {
        self.rho_l
    }
}

impl OdeSystem<2> for TurnSystem {
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = self.dynamics.angular_acceleration(y[0], y[1]);
    }

    fn event_count(&self) -> usize {
        if self.x_end.is_some() {
            3
        } else {
            2
        }
    }

    fn event(&self, index: usize, _t: f64, y: &[f64; 2]) -> f64 {
        match index {
            EVENT_TURN_END => y[0] - TWO_PI,
            EVENT_STALL => y[1],
            _ => self.x_start + self.dynamics.radius() * y[0] - self.x_end.unwrap_or(f64::INFINITY),
        }
    }

    fn event_direction(&self, index: usize) -> Direction {
        match index {
            EVENT_STALL => Direction::Falling,
            _ => Direction::Rising,
        }
    }

    fn on_event(&self, index: usize, _t: f64, y: &[f64; 2]) -> EventAction<2> {
        match index {
            EVENT_TURN_END if !self.last_turn() => EventAction::Reset(self.collide(y[1])),
            _ => EventAction::Stop,
        }
    }

    fn commit_event(&mut self, index: usize, _t: f64, _y_before: &[f64; 2], _y_after: &[f64; 2]) {
        if index == EVENT_TURN_END && !self.last_turn() {
            self.enter_turn(self.turn + 1);
        }
    }
}

impl OdeModel<2> for TurnSystem {
    fn sample(&self, t: f64, y: &[f64; 2]) -> Sample {
        let (theta, omega) = (y[0], y[1]);
        let r = self.dynamics.radius();
        let forces = self.dynamics.contact_forces(self.mass, theta, omega);
        Sample {
            t_s: t,
            x_m: self.x_start + r * theta,
            v_m_s: r * omega,
            a_m_s2: self.dynamics.acceleration(theta, omega),
            r_m: r,
            mass_kg: self.mass * (1.0 + self.dynamics.coeffs.accretion * theta),
            normal_n: forces.normal_n,
            friction_n: forces.friction_n,
            friction_ratio: forces.friction_ratio(),
        }
    }

    fn turn_state(&self, _t: f64, y: &[f64; 2]) -> Option<TurnState> {
        Some(TurnState {
            turn: self.turn,
            theta_rad: y[0],
            omega_rad_s: y[1],
        })
    }

    fn stop_reason(&self, event: usize) -> StopReason {
        match event {
            EVENT_TURN_END => StopReason::Turns,
            EVENT_DISTANCE => StopReason::Distance,
            _ => StopReason::Stalled,
        }
    }
}

/// The turn-by-turn model of §3.4 (ids `turns`, `turns-exact`).
///
/// ```
/// use snowroll::{Model, Scenario, SimOptions, StopReason, TurnModel, TurnVariant};
/// let opts = SimOptions { turns: Some(3), t_end: 1e3, ..SimOptions::default() };
/// let traj = TurnModel::new(TurnVariant::Paper).simulate(&Scenario::default(), &opts)?;
/// assert_eq!(traj.stop.reason, StopReason::Turns);
/// assert_eq!(traj.turn_states.last().unwrap().turn, 2);
/// # Ok::<(), snowroll::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TurnModel {
    variant: TurnVariant,
}

impl TurnModel {
    /// The model with the mass properties of `variant`.
    pub fn new(variant: TurnVariant) -> Self {
        Self { variant }
    }

    /// Its variant.
    pub fn variant(&self) -> TurnVariant {
        self.variant
    }

    /// The initial state `[θ, θ̇] = [0, v0/r0]`.
    fn initial_state(s: &Scenario) -> [f64; 2] {
        [0.0, s.initial_speed() / s.initial_radius()]
    }
}

impl Model for TurnModel {
    fn kind(&self) -> ModelKind {
        self.variant.kind()
    }

    fn simulate(&self, scenario: &Scenario, opts: &SimOptions) -> Result<Trajectory, SimError> {
        opts.validate()?;
        let mut system = TurnSystem::new(self.variant, scenario, opts);
        run_ode(
            self.kind(),
            &mut system,
            Self::initial_state(scenario),
            opts,
        )
    }
}
