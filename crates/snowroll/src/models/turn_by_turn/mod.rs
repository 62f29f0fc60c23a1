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

use crate::portable::Portable as _;
mod collision;
mod contact;
mod dd;
mod dynamics;
mod extremes;
mod jet;
mod observer;
mod orbit;
mod row;
mod runner;
mod stall;
mod summary;
mod system;

use collision::after_collision;
pub use collision::{charged_collision_speed, CollisionModel, PivotImpact};
pub(crate) use contact::Hints;
pub use contact::{ContactRange, TurnExtremes};
pub use dynamics::{InTurnCoefficients, TurnDynamics, TurnVariant};
pub use row::{TurnRow, TurnSink};
pub use runner::{run_turns, run_turns_into, TurnMethod, TurnModel, TurnRunEnd, TurnTable};
pub use stall::first_turn_stall_slope;
use summary::SummaryBuilder;
pub use summary::{TurnCheckpoint, TurnSummary};
pub(crate) use system::{run_closed, TurnSystem, EVENT_TURN_END};

use std::f64::consts::PI;

use super::ModelKind;
use crate::error::ParamError;
use crate::scenario::Scenario;
use crate::trajectory::SimOptions;
use crate::units::{Joules, Meters, MetersPerSecond};

/// Full turn, rad.
const TWO_PI: f64 = 2.0 * PI;
/// sin([`TWO_PI`]): the double nearest 2π is 2π − 2.449…e-16, so its sine
/// is that difference negated (correctly rounded; a test holds it to the
/// library's `sin`).
const SIN_TWO_PI: f64 = -2.449_293_598_294_706_4e-16;

/// `(sin θ, cos θ)`, where every turn starts and ends (θ = 0, θ = 2π, each
/// turn's collision and the next turn's start) from the known values
/// without a call, else from the library: the same bits either way.
#[inline]
fn sin_cos(theta: f64) -> (f64, f64) {
    if theta == TWO_PI {
        (SIN_TWO_PI, 1.0)
    } else if theta == 0.0 {
        // ±0 keeps its sign in sin, as the library's does.
        (theta, 1.0)
    } else {
        theta.sin_cos_p()
    }
}

/// `r_k = r0 + k b`, the radius at the start of turn k (module doc,
/// 0-based): one function for the run and for the turns it computes ahead,
/// so that both have the same bits.
fn turn_radius(r0: Meters, b: Meters, k: u64) -> Meters {
    r0 + k as f64 * b
}

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

/// The turn models refuse the unwinding roll (b < 0, `docs/unwinding.md`):
/// their log is a circle of radius r on a layer it climbs at the end of each
/// turn (eqs. (37)–(76), the collision of eqs. (81)–(89)), and a roll that
/// lays its layer down under itself meets no such step.
pub(crate) fn check_turn_unwinding(kind: ModelKind, scenario: &Scenario) -> Result<(), ParamError> {
    if !scenario.unwinds() {
        return Ok(());
    }
    Err(ParamError::Unsupported {
        model: kind.id(),
        what: "a negative --snow-depth (an unwinding roll)",
        reason: "the turn models follow a log that climbs a step of height b onto the new layer \
                 at the end of each turn (eqs. (37)-(76), the collision of eqs. (81)-(89)); an \
                 unwinding roll lays its layer down under itself and meets no step, so their \
                 geometry does not describe it (docs/unwinding.md). Use a circular model \
                 (energy-thin, energy, torque-cm, ...)",
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shortcut's values are the library's, bit for bit (so outputs do
    /// not depend on which path computed them), and other angles go to the
    /// library. Checked once with the sine of 2π set to 0, which this failed.
    #[test]
    fn known_sines_and_cosines_are_the_librarys() {
        for theta in [0.0, -0.0, TWO_PI, 1.0, PI, 1e-300] {
            let (s, c) = sin_cos(theta);
            let (s_lib, c_lib) = theta.sin_cos();
            assert_eq!(
                (s.to_bits(), c.to_bits()),
                (s_lib.to_bits(), c_lib.to_bits()),
                "{theta}"
            );
        }
    }
}
