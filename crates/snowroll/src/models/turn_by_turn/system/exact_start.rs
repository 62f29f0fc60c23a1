//! The closed form's start speed of each turn, carried along the
//! integrator's path where the closed form covers the run, so that a hop
//! within the integrator's error of 0 is planned from the exact `θ̇(0)`
//! (the first hop does not depend on the tolerance; `docs/contact-forces.md`).

use super::*;

impl TurnSystem {
    /// How far the least N per unit m_k of this turn can move when `θ̇(0)`
    /// goes from `omega` to `exact`, m/s²: N is affine in E(0) = I(0)θ̇₀²
    /// at each θ (θ̇² = (E(0) − 2W)/I and θ̈ = (−W′ − ½I′θ̇²)/I), with
    /// ∂N/∂E(0) = e₂[sin θ/I − (1 − cos θ)I′/(2I²)], at most
    /// |e₂|(1/I_min + |I′|max/I_min²) with I ≥ 3r²/2 − |c₂| and
    /// |I′| ≤ |c₁| + |c₂|; twice that, plus 1e-12 C for the rounding of the
    /// refined minimum.
    pub(super) fn hop_margin(&self, omega: f64, exact: f64) -> f64 {
        let r = self.dynamics.radius();
        let shift = 1.5 * r * r * (omega * omega - exact * exact).abs();
        2.0 * self.normal_slope() * shift + 1e-12 * self.g_normal.abs()
    }

    /// The bound on |∂N/∂E(0)| over the turn of [`Self::hop_margin`],
    /// `|e₂|(1/I_min + |I′|max/I_min²)`, 1/m.
    pub(super) fn normal_slope(&self) -> f64 {
        let k = self.dynamics.coefficients();
        let r = self.dynamics.radius();
        let i_min = 1.5 * r * r - k.c2.abs();
        k.e2.abs() * (1.0 / i_min + (k.c1.abs() + k.c2.abs()) / (i_min * i_min))
    }

    /// Has the integrator's path carry the closed form's `θ̇(0)` of each
    /// turn along (`exact_omega0`), from the start `y0`, where the closed
    /// form covers the run; before [`Self::start`].
    pub(crate) fn track_exact_starts(&mut self, y0: &[f64; 2]) {
        self.exact_omega0 = self.closed_form_covers(y0).then_some(y0[1]);
        self.track_doubt();
    }

    /// The closed form's `θ̇(0)` of the turn after this one, from this
    /// one's ([`Self::track_exact_starts`]); `None` when it stalls or the
    /// log is stuck at the step.
    pub(super) fn exact_next(&self, omega0: f64) -> Option<f64> {
        let orbit = super::super::orbit::Orbit::new(&self.dynamics, omega0);
        if orbit.first_stall(TWO_PI).is_some() {
            return None;
        }
        let r = self.dynamics.radius();
        after_collision(
            self.collision,
            r,
            self.b,
            self.g_normal,
            orbit.omega(TWO_PI),
        )
        .map(|(w, _)| w)
    }
}
