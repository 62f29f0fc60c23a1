//! The losses of fn. 5 and the energy ledger (issue 11,
//! `docs/snowball-and-losses.md` §2–§3).
//!
//! Three mechanisms, each off by default:
//!
//! | loss | parameter | force or couple | power |
//! |---|---|---|---|
//! | air drag | `drag_coefficient` C_d, `air_density` ρ_a | `F_d = ½ ρ_a C_d A v²` at the centre, A = 2 r l (log), π r² (ball) | `F_d v` |
//! | rolling resistance | `rolling_resistance` c_rr | couple `c_rr N r` | `c_rr N v` |
//! | compaction | `compaction_energy` e_c, J/kg | couple `F_c r`, `F_c = e_c dM/dx` (ρ b l, ρ b w) | `e_c Ṁ` |
//!
//! Every circular equation of motion has g sin α with coefficient 1 once it
//! is written as `(1 + k) a = G − …`; the losses enter by the one rule of
//! §2.1, `G → G − (F_d + c_rr N + F_c)/M`, with N linear in a.
//!
//! A true terminal velocity exists only without accretion and with drag
//! (§2.2): [`terminal_velocity`] gives its closed form.

use serde::{Deserialize, Serialize};

use crate::error::ParamError;

use crate::scenario::Scenario;
use crate::units::{KilogramsPerCubicMeter, Meters, MetersPerSecond};

/// Air density when the caller does not say, kg/m³ (sea level, about 15 °C).
pub const AIR_DENSITY_DEFAULT: KilogramsPerCubicMeter = 1.2;

/// The terminal-velocity stop's default tolerance: the run stops where
/// `|a| ≤ 1e-9 × (g sin α − c_rr g cos α)/(1 + k)`, i.e. where
/// `|1 − v²/v_t²| ≤ 1e-9` (so `|1 − v/v_t| ≤ 5e-10`), [`Losses::terminal_tol`].
pub const TERMINAL_TOL_DEFAULT: f64 = 1e-9;

/// The largest drag coefficient accepted: bluff bodies have C_d of order 1;
/// 100 leaves room for exploration while keeping the numbers in scale.
const MAX_DRAG_COEFFICIENT: f64 = 100.0;

/// The losses of a run and its energy bookkeeping (`docs/snowball-and-losses.md` §2, §3).
///
/// ```
/// use snowroll::Losses;
/// let l = Losses { drag_coefficient: 1.0, ..Losses::default() };
/// l.validate()?;
/// assert!(l.any());
/// assert!(!Losses::default().any());
/// # Ok::<(), snowroll::ParamError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Losses {
    /// Air drag coefficient C_d, dimensionless, 0 <= C_d <= 100. Default 0 (no drag).
    pub drag_coefficient: f64,
    /// Air density ρ_a, kg/m³, > 0. Default 1.2.
    pub air_density: KilogramsPerCubicMeter,
    /// Rolling-resistance coefficient c_rr, dimensionless, 0 <= c_rr < 10:
    /// the couple `c_rr N r`. Default 0.
    pub rolling_resistance: f64,
    /// Work of compacting the snow picked up, J per kg, >= 0. Default 0.
    pub compaction_energy: f64,
    /// Record the energy ledger even without losses. Default false (a run
    /// with losses always records it).
    pub ledger: bool,
    /// Tolerance of the terminal-velocity stop, relative to the initial
    /// drive `(G − c_rr C)/(1 + k)`; 0 = never stop there. Default 1e-9.
    pub terminal_tol: f64,
}

impl Default for Losses {
    fn default() -> Self {
        Self {
            drag_coefficient: 0.0,
            air_density: AIR_DENSITY_DEFAULT,
            rolling_resistance: 0.0,
            compaction_energy: 0.0,
            ledger: false,
            terminal_tol: TERMINAL_TOL_DEFAULT,
        }
    }
}

impl Losses {
    /// Whether any loss is on.
    pub fn any(&self) -> bool {
        self.drag_coefficient > 0.0 || self.rolling_resistance > 0.0 || self.compaction_energy > 0.0
    }

    /// Whether the run records the energy ledger: with any loss, or when asked.
    pub fn records_ledger(&self) -> bool {
        self.ledger || self.any()
    }

    /// Checks every field.
    ///
    /// # Errors
    /// [`ParamError::InvalidParameter`] naming the first bad value and its range.
    pub fn validate(&self) -> Result<(), ParamError> {
        let check = |name, value: f64, ok: bool, expected| {
            if value.is_finite() && ok {
                Ok(())
            } else {
                Err(ParamError::InvalidParameter {
                    name,
                    value,
                    expected,
                })
            }
        };
        let d = self.drag_coefficient;
        check(
            "drag_coefficient",
            d,
            (0.0..=MAX_DRAG_COEFFICIENT).contains(&d),
            "0 <= drag_coefficient <= 100",
        )?;
        let rho = self.air_density;
        check(
            "air_density (kg/m^3)",
            rho,
            rho > 0.0 && rho <= 1e4,
            "0 < air_density <= 1e4 kg/m^3",
        )?;
        let c = self.rolling_resistance;
        check(
            "rolling_resistance",
            c,
            (0.0..10.0).contains(&c),
            "0 <= rolling_resistance < 10",
        )?;
        let e = self.compaction_energy;
        check(
            "compaction_energy (J/kg)",
            e,
            (0.0..=1e12).contains(&e),
            "0 <= compaction_energy <= 1e12 J/kg",
        )?;
        let t = self.terminal_tol;
        check(
            "terminal_tol",
            t,
            (0.0..1.0).contains(&t),
            "0 <= terminal_tol < 1 (0 = do not stop at the terminal velocity)",
        )
    }

    /// `½ ρ_a C_d`, kg/m³: the drag force is this times `A v²`.
    pub fn drag_factor(&self) -> f64 {
        0.5 * self.air_density * self.drag_coefficient
    }
}

/// The frontal area A of the body at radius `r`, m² (§2.1): `2 r l` for the
/// log, `π r²` for the ball.
pub fn frontal_area(s: &Scenario, r: Meters) -> f64 {
    s.body().frontal_area(r)
}

/// The closed-form terminal velocity of the snowless body with drag,
/// `docs/snowball-and-losses.md` §2.2:
/// `v_t² = M (G − c_rr C)/(½ ρ_a C_d A)`, i.e. for the log (M = π ρ l r0²,
/// A = 2 r0 l) `v_t² = π ρ r0 (G − c_rr C)/(ρ_a C_d)`, for the ball
/// (M = (4/3) π ρ r0³, A = π r0²) `v_t² = (8/3) ρ r0 (G − c_rr C)/(ρ_a C_d)`.
///
/// `None` without drag, or when rolling resistance holds the body
/// (`c_rr ≥ tan α`): then there is no terminal velocity.
///
/// ```
/// use snowroll::{losses::terminal_velocity, Losses, Scenario};
/// let l = Losses { drag_coefficient: 1.0, ..Losses::default() };
/// let vt = terminal_velocity(&Scenario::default(), &l).unwrap();
/// assert!((vt - 22.664).abs() < 1e-3); // §2.2, the defaults at 30°
/// ```
pub fn terminal_velocity(s: &Scenario, l: &Losses) -> Option<MetersPerSecond> {
    let drive = s.g_along() - l.rolling_resistance * s.g_normal();
    if l.drag_coefficient <= 0.0 || drive <= 0.0 {
        return None;
    }
    let r0 = s.initial_radius();
    let mass = s.initial_mass();
    let area = frontal_area(s, r0);
    Some((mass * drive / (l.drag_factor() * area)).sqrt())
}

/// The time constant of the approach to [`terminal_velocity`], §2.2:
/// `τ = (1 + k) v_t/(G − c_rr C)` (k = ½ for the log, 2/5 for the ball), s;
/// then `v(t) = v_t tanh(t/τ + artanh(v0/v_t))`.
pub fn terminal_time_constant(s: &Scenario, l: &Losses) -> Option<f64> {
    let vt = terminal_velocity(s, l)?;
    let drive = s.g_along() - l.rolling_resistance * s.g_normal();
    let (num, den) = s.shape().push_ratio();
    Some(den / num * vt / drive)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_names_the_value_and_range() {
        let bad = Losses {
            rolling_resistance: -0.1,
            ..Losses::default()
        };
        let msg = bad.validate().unwrap_err().to_string();
        assert!(
            msg.contains("rolling_resistance") && msg.contains("-0.1"),
            "{msg}"
        );
        let bad = Losses {
            air_density: 0.0,
            ..Losses::default()
        };
        assert!(bad
            .validate()
            .unwrap_err()
            .to_string()
            .contains("air_density"));
        assert!(Losses::default().validate().is_ok());
    }

    #[test]
    fn no_terminal_velocity_without_drag_or_when_held() {
        let s = Scenario::default();
        assert!(terminal_velocity(&s, &Losses::default()).is_none());
        let held = Losses {
            drag_coefficient: 1.0,
            rolling_resistance: 0.6, // > tan 30° = 0.577
            ..Losses::default()
        };
        assert!(terminal_velocity(&s, &held).is_none());
    }
}
