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
mod observer;
mod row;
mod runner;
mod stall;
mod summary;

pub use collision::{charged_collision_speed, CollisionModel, PivotImpact};
pub use contact::{ContactRange, TurnExtremes};
pub use row::{TurnRow, TurnSink};
pub use runner::{run_turns, run_turns_into, TurnModel, TurnRunEnd, TurnTable};
pub use stall::first_turn_stall_slope;
use summary::SummaryBuilder;
pub use summary::{TurnCheckpoint, TurnSummary};

use std::f64::consts::PI;

use super::contact::ContactForces;
use super::exact_geometry::exact_turn_coefficients;
use super::ode::OdeModel;
use super::ModelKind;
use crate::error::ParamError;
use crate::integrate::{Direction, EventAction, OdeSystem};
use crate::scenario::Scenario;
use crate::trajectory::{LedgerRow, OnHop, Sample, SimOptions, StopReason, TurnState};
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

    /// The variant of a turn model; `None` for the other models (those that
    /// [`MODEL_TABLE`](crate::model_kind::MODEL_TABLE) does not mark as turn models).
    pub fn of(kind: ModelKind) -> Option<Self> {
        match kind {
            ModelKind::Turns => Some(TurnVariant::Paper),
            ModelKind::TurnsExact => Some(TurnVariant::Exact),
            _ => None,
        }
        .filter(|_| kind.is_turn_model())
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

    /// `θ̇²` at θ from the energy integral, given `θ̇ = omega0` at θ = 0
    /// (for the tests, which check the written formulas against it).
    #[cfg(test)]
    pub(crate) fn omega_squared(&self, theta: Radians, omega0: f64) -> f64 {
        let (i, _) = self.inertia(theta);
        let (w, _) = self.potential(theta);
        self.energy_integral(i, w, omega0)
    }

    /// The energy integral `θ̇² = [I(0)θ̇₀² − 2W]/I` with `I(0) = 3r²/2`,
    /// for `I` and `W` at the angle in question.
    fn energy_integral(&self, i: f64, w: f64, omega0: f64) -> f64 {
        (1.5 * self.r * self.r * omega0 * omega0 - 2.0 * w) / i
    }

    /// Acceleration at θ on the energy integral from `θ̇(0) = omega0`, m/s²
    /// (θ̇² clamped at 0 past a stall): `a = r(−W′ − ½I′θ̇²)/I` with
    /// `θ̇² = [I(0)θ̇₀² − 2W]/I`.
    pub fn acceleration_on_orbit(&self, theta: Radians, omega0: f64) -> MetersPerSecondSquared {
        let (s, c) = theta.sin_cos();
        let (i, di) = self.inertia_sc(theta, s, c);
        let (w, dw) = self.potential_sc(theta, s, c);
        let omega2 = self.energy_integral(i, w, omega0).max(0.0);
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

/// Checks the masses the turns asked for reach: after N turns the log has
/// radius `r_N = r0 + N b` and mass `m_N = π ρ l r_N²` (eq. (37) with
/// `r_k = r0 + k b`), and its moment of inertia about the contact line is
/// `3 m_N r_N²/2` (eq. (81)); each must stay within
/// [`crate::scenario::MAX_MAGNITUDE`] like the quantities of the start.
/// The turn models check this before they run; callers that want the error
/// before anything else (the command line) call it themselves.
///
/// # Errors
/// [`ParamError::OutOfScale`](crate::ParamError::OutOfScale) naming the quantity.
pub fn check_turn_scale(s: &Scenario, opts: &SimOptions) -> Result<(), crate::ParamError> {
    let Some(n) = opts.turns else {
        return Ok(());
    };
    let r_n = s.initial_radius() + n as f64 * s.snow_depth();
    let m_n = std::f64::consts::PI * s.density() * s.length() * r_n * r_n;
    let hint = "ask for fewer --turns, or change --snow-depth, --density, --length or --r0";
    crate::scenario::check_scale(
        "mass after the turns asked for pi rho l (r0 + N b)^2, eq. (37) (kg)",
        m_n,
        false,
        hint,
    )?;
    crate::scenario::check_scale(
        "moment of inertia after the turns asked for 3 m_N r_N^2/2, eq. (81) (kg m^2)",
        1.5 * m_n * r_n * r_n,
        false,
        hint,
    )
}

/// The turn models record the energy ledger (`--ledger`,
/// `docs/snowball-and-losses.md` §3.2) but take none of the losses of fn. 5:
/// where a turn slips, the smallest N and the range of a over a turn, and
/// the pivot's impact all come from the energy integral of the turn
/// (`I θ̇²/2 + W` constant), which drag, rolling resistance and compaction
/// break (§2.1). They refuse rather than run with those parts wrong.
pub(crate) fn check_turn_losses(kind: ModelKind, opts: &SimOptions) -> Result<(), ParamError> {
    let l = &opts.losses;
    let what = if l.drag_coefficient > 0.0 {
        "--drag-coefficient"
    } else if l.rolling_resistance > 0.0 {
        "--rolling-resistance"
    } else if l.compaction_energy > 0.0 {
        "--compaction-energy"
    } else {
        return Ok(());
    };
    Err(ParamError::Unsupported {
        model: kind.id(),
        what,
        reason: "the turn models take no losses: their slip, smallest normal force, range of a \
                 per turn and pivot impact come from the energy integral of a turn, which \
                 losses break (docs/snowball-and-losses.md §2.1); --ledger alone is recorded. \
                 Use a circular model (torque-cm, energy, quasi-circular, ...) or snowless",
    })
}

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
/// the pivot about the edge E until θ = 2π.
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
    /// The energy ledger, when the run records one.
    ledger: Option<TurnLedger>,
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
            ledger: None,
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
        let r = self.r0 + kf * self.b;
        self.turn = k;
        self.x_start = 2.0 * PI * kf * self.r0 + kf * (kf - 1.0) * PI * self.b + self.pivot_shift;
        self.mass = PI * self.rho_l * r * r;
        self.dynamics = TurnDynamics::new(self.variant, r, self.b, self.g_along, self.g_normal);
        self.impact = PivotImpact::new(r, self.b);
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
        let r_next = r + self.b;
        match self.collision {
            CollisionModel::Note => Some(collision_speed(r, self.b, r * omega_end) / r_next),
            CollisionModel::Charged => {
                charged_collision_speed(r, self.b, self.g_normal, r * omega_end).map(|v| v / r_next)
            }
            CollisionModel::Pivot => {
                self.impact
                    .omega_next(r, self.b, omega_end, self.g_along, self.g_normal)
            }
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
    /// at the start); otherwise plans the slip of turn 0.
    pub(crate) fn start(&mut self, y0: &[f64; 2]) -> Option<StopReason> {
        let (n, f) = self.contact_per_mass(y0[0], y0[1]);
        if let Err(reason) = self.check_contact(n, f) {
            return Some(reason);
        }
        self.plan_slip(y0[1]);
        None
    }

    /// Where the turn just entered with `θ̇(0) = omega0` slips while rolling, if it does.
    fn plan_slip(&mut self, omega0: f64) {
        let theta_max = match self.collision {
            CollisionModel::Pivot => self.impact.theta_c,
            _ => TWO_PI,
        };
        self.slip_theta = self
            .mu
            .and_then(|mu| self.dynamics.first_slip(omega0, mu, theta_max));
    }

    /// Position of the nominal centre along the slope: `X_k + r_k θ` while
    /// rolling; during the pivot `x_E − (r + b) sin(δ − φ)`, φ = θ − θ_c,
    /// continuous from x_C to x_E, m.
    fn position(&self, theta: f64) -> Meters {
        let r = self.dynamics.radius();
        if self.pivoting {
            let p = &self.impact;
            let x_e = self.x_start + r * p.theta_c + p.d;
            x_e - (r + self.b) * (p.delta - (theta - p.theta_c)).sin()
        } else {
            self.x_start + r * theta
        }
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

    pub(crate) fn collision(&self) -> CollisionModel {
        self.collision
    }

    pub(crate) fn start_mass(&self) -> f64 {
        self.mass
    }

    pub(crate) fn pivot_impact(&self) -> &PivotImpact {
        &self.impact
    }
}

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
            EVENT_HOP if self.stop_on_hop => self.contact_per_mass(y[0], y[1]).0,
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

    fn commit_event(&mut self, index: usize, _t: f64, y_before: &[f64; 2], y_after: &[f64; 2]) {
        let outcome = match index {
            EVENT_TURN_END => self.turn_end_outcome(y_before[1]),
            EVENT_IMPACT => self.impact_outcome(y_before[1]),
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
                self.enter_turn(self.turn + 1);
                self.plan_slip(y_after[1]);
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
            let (s, c) = (p.delta - phi).sin_cos();
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
