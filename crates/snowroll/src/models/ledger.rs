//! The energy ledger of the circular models, `docs/snowball-and-losses.md` §3.1.
//!
//! Zero of potential energy: the note's (eqs. (9)–(10)), body plus all the
//! snow it will collect, at the start. At every time
//!
//! `K + V + D_drag + D_rr + D_comp + W_model = E0 = K(0)`,
//!
//! with the dissipated works `D = ∫ (F_d, c_rr N, F_c) v dt` and W_model, the
//! energy the model's own equation destroys, `W_model = −∫ P dt`,
//!
//! `P = v [M I a + ½ M′ I v² + M r′ r″ v² + V′(x) + F_d + c_rr N + F_c]`,
//! `I = 1 + k + r′²` (k = ½ for the log, 2/5 for the ball),
//!
//! i.e. P is the rate of change of `K + V + ΣD` computed from the model's
//! own a and N. The rates are integrated as extra ODE states; K and V are
//! evaluated at each sample from eqs. (7) and (10) ([`crate::physics`]), so
//! the residual stays at the integration error only if P is the right rate.

use super::coefficients::Coefficients;
use super::contact::circular_forces;
use crate::losses::{frontal_area, Losses};
use crate::physics::{self, growth_at};
use crate::scenario::Scenario;
use crate::trajectory::LedgerRow;

/// The rates `[dD_drag, dD_rr, dD_comp, dW_model]/dt`, W, at `[x, v, a]`
/// (a the model's own acceleration), for the log and the ball alike: r, M,
/// r′, r″ and λ = M′/M from the body's growth law ([`growth_at`]), k from
/// its shape. The forces are computed here from their definitions,
/// independently of the equation of motion: for `energy` and `snowless`
/// the model's W then stays 0 only if the equation took the losses in
/// correctly.
pub(super) fn rates(
    s: &Scenario,
    coeffs: &Coefficients,
    l: &Losses,
    [x, v, a]: [f64; 3],
) -> [f64; 4] {
    let gr = growth_at(s, x, coeffs.accretes);
    let (r, m, r1, r2, lambda) = (gr.r, gr.mass, gr.dr_dx, gr.d2r_dx2, gr.lambda);
    let (g_along, g_normal) = (s.g_along(), s.g_normal());
    let b = if coeffs.accretes { s.snow_depth() } else { 0.0 };
    // The three losses, §2.1: F_d = ½ ρ_a C_d A v² (A = 2 r l, π r²),
    // c_rr N, F_c = e_c dM/dx (= e_c ρ b l, e_c ρ b w).
    let f_drag = l.drag_factor() * frontal_area(s, r) * v * v.abs();
    let normal = circular_forces(coeffs, s, x, v, a).normal_n;
    let f_rolling = l.rolling_resistance * normal;
    let dm_dx = lambda * m;
    let f_compaction = l.compaction_energy * dm_dx;
    // Rate of K + V, K = ½ M (1 + k + r′²) v²: dK/dt = v [M I a + ½ M′ I v² + M r′ r″ v²],
    // dV/dt = V′ v with V′ = M C [λ (r + b/2) + r′] − M G (§1.2).
    // With a tube of its own mass (`docs/unwinding.md`, "The core"), I/(M r²)
    // = j varies: dK/dt = v [M I a + ½ (M I)′ v² ...] with the r′² and spin
    // parts of (M I)′ apart: M′ (1 + r′²) + (I/r²)′ (the M r′ r″ term is
    // below), (I/r²)′ = M (i′ − 2 j r′/r); for a uniform body M′ I.
    let (inertia, inertia_rate) = match gr.tube {
        None => {
            let inertia = 1.0 + s.shape().inertia_factor() + r1 * r1;
            (inertia, dm_dx * inertia)
        }
        Some(t) => (
            1.0 + t.inertia + r1 * r1,
            dm_dx * (1.0 + r1 * r1) + m * (t.inertia_rate - 2.0 * t.inertia * r1 / r),
        ),
    };
    let v_prime = m * g_normal * (lambda * (r + b / 2.0) + r1) - m * g_along;
    let power = v
        * (m * inertia * a
            + 0.5 * inertia_rate * v * v
            + m * r1 * r2 * v * v
            + v_prime
            + f_drag
            + f_rolling
            + f_compaction);
    [f_drag * v, f_rolling * v, f_compaction * v, -power]
}

/// The ledger row at `(x, v)` with the integrated works
/// `[D_drag, D_rr, D_comp, W_model]`.
pub(super) fn row(s: &Scenario, coeffs: &Coefficients, x: f64, v: f64, w: [f64; 4]) -> LedgerRow {
    let (kinetic, potential, initial) = if coeffs.accretes {
        (
            physics::kinetic_energy(s, x, v),
            physics::potential_energy(s, x),
            physics::kinetic_energy(s, 0.0, s.initial_speed()),
        )
    } else {
        // App. A: K = ½ (1 + k) M v², V = −M G x.
        let gr = growth_at(s, 0.0, false);
        let m = gr.mass;
        let half = 0.5 * (1.0 + gr.tube.map_or(s.shape().inertia_factor(), |t| t.inertia));
        let v0 = s.initial_speed();
        (half * m * v * v, -m * s.g_along() * x, half * m * v0 * v0)
    };
    let [drag, rolling, compaction, model] = w;
    // `0.0 - V`, not `-V`: at x = 0 the released energy is +0, not −0.
    let released = 0.0 - potential;
    LedgerRow {
        kinetic_j: kinetic,
        released_j: released,
        drag_j: drag,
        rolling_j: rolling,
        compaction_j: compaction,
        model_j: model,
        collision_j: 0.0,
        created_j: 0.0,
        residual_j: kinetic + drag + rolling + compaction + model - released - initial,
    }
}
