//! The dynamics within one turn (`docs/turn-model.md`): the two sets of
//! mass properties ([`TurnVariant`]), the coefficients of the common in-turn
//! form ([`InTurnCoefficients`], one level down in `models/in_turn.rs`) and
//! the equation of motion with its energy integral ([`TurnDynamics`]).

use crate::portable::Portable as _;

use super::{extremes, TWO_PI};

use crate::models::exact_geometry::exact_turn_coefficients;
use crate::models::in_turn::InTurnCoefficients;
use crate::models::ModelKind;
use crate::units::{Meters, MetersPerSecondSquared, Radians};

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
    pub(super) r: Meters,
    pub(super) g_along: MetersPerSecondSquared,
    pub(super) g_normal: MetersPerSecondSquared,
    pub(super) coeffs: InTurnCoefficients,
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
        let (s, c) = theta.sin_cos_p();
        self.inertia_sc(theta, s, c)
    }

    pub(super) fn inertia_sc(&self, theta: f64, sin: f64, cos: f64) -> (f64, f64) {
        let k = &self.coeffs;
        (
            1.5 * self.r * self.r + k.c1 * theta - k.c2 * sin,
            k.c1 - k.c2 * cos,
        )
    }

    /// `(W, dW/dθ)` per unit `m_k`, J/kg, zero at θ = 0.
    pub fn potential(&self, theta: Radians) -> (f64, f64) {
        let (s, c) = theta.sin_cos_p();
        self.potential_sc(theta, s, c)
    }

    pub(super) fn potential_sc(&self, theta: f64, sin: f64, cos: f64) -> (f64, f64) {
        let k = &self.coeffs;
        let (g, c_n, r) = (self.g_along, self.g_normal, self.r);
        (
            -g * (r * theta + k.e1 * theta * theta / 2.0 - k.e2 * (1.0 - cos))
                + c_n * (k.e3 * theta - k.e2 * sin),
            self.potential_slope_sc(theta, sin, cos),
        )
    }

    /// W per unit `m_k` term by term, `W = a θ + b θ² + c (1 − cos θ) + d sin θ`
    /// with `(a, b, c, d) = (C e₃ − G r, −G e₁/2, G e₂, −C e₂)` (the common
    /// in-turn form, eqs. (73), (76)): for bounds on W over a turn and for
    /// sums over fixed nodes whose sin and cos are known.
    pub(super) fn potential_terms(&self) -> [f64; 4] {
        let k = &self.coeffs;
        let (g, c_n, r) = (self.g_along, self.g_normal, self.r);
        [c_n * k.e3 - g * r, -0.5 * g * k.e1, g * k.e2, -c_n * k.e2]
    }

    /// `dW/dθ` alone (the right-hand side needs no more).
    pub(super) fn potential_slope_sc(&self, theta: f64, sin: f64, cos: f64) -> f64 {
        let k = &self.coeffs;
        -self.g_along * (self.r + k.e1 * theta - k.e2 * sin) + self.g_normal * (k.e3 - k.e2 * cos)
    }

    /// `θ̈ = (−W′ − ½ I′ θ̇²)/I`, rad/s².
    pub fn angular_acceleration(&self, theta: Radians, omega: f64) -> f64 {
        let (s, c) = theta.sin_cos_p();
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
        let (s, c) = theta.sin_cos_p();
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
