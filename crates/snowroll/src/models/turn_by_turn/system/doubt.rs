//! Where the first hop cannot be confirmed by the closed form: the
//! integrator's path of a run the closed form does not cover
//! (`--collision pivot`, or a start from rest it does not take) carries an
//! estimate of the error of `θ̇²` along, and names the first turn whose
//! least N is within the distance that error can move it
//! (`docs/contact-forces.md`, "The first hop and the tolerance").
//!
//! The estimate: every phase of a turn (rolling about C, pivoting about E)
//! has an energy integral, so at its end the integrator's `θ̇²` is compared
//! with the integral's from the phase's own start: the difference is the
//! phase's local error. The error carried in from before goes through each
//! phase and each collision as those maps move it (they are affine in `θ̇²`:
//! rolling `θ̇²(θ) = [I(0)θ̇₀² − 2W]/I`, the impact `θ̇₊ = k θ̇₋`, the pivot
//! `θ̇² = θ̇₊² − 2U/I_E`, the collision's algebra), and the local errors add.
//! N is affine in `θ̇²` at each angle, so the error of the least N follows
//! (twice the bound, as the hop's margin with the closed form).

use super::*;
pub use crate::trajectory::HopDoubt;

/// Golden ratio conjugate, for the golden-section refinement of the pivot's least N.
const GOLDEN: f64 = 0.618_033_988_749_894_8;
/// Intervals of the grid over the pivot's angle range.
const PIVOT_GRID: usize = 64;

/// The estimate carried along ([`TurnSystem::doubt`]).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct DoubtTracker {
    /// Whether the run needs it: a hop stops it and no exact start speed is carried.
    on: bool,
    /// The estimated error of `θ̇²` at the start of the current phase, rad²/s².
    error: f64,
    /// The integrator's `θ̇` at the start of the current phase, rad/s.
    phase_omega: f64,
    /// The first turn in doubt.
    first: Option<HopDoubt>,
}

impl TurnSystem {
    /// Switches the estimate on where a hop stops the run and the closed
    /// form's start speeds are not carried along; after [`Self::track_exact_starts`].
    pub(super) fn track_doubt(&mut self) {
        self.doubt = DoubtTracker {
            on: self.stop_on_hop && self.exact_omega0.is_none(),
            ..DoubtTracker::default()
        };
    }

    /// The first turn whose hop the integrator's error could decide, if any.
    pub(crate) fn hop_doubt(&self) -> Option<HopDoubt> {
        self.doubt.first
    }

    /// The magnitude of g, for N over g.
    fn g(&self) -> f64 {
        self.g_along.hypot(self.g_normal)
    }

    /// Records turn k as in doubt when `least` (N per unit m_k, m/s²) is
    /// within `error` of 0; the first such turn is kept.
    fn judge(&mut self, least: f64, error: f64) {
        let error = error + 1e-12 * self.g_normal.abs();
        if self.doubt.first.is_none() && least.abs() <= error {
            self.doubt.first = Some(HopDoubt {
                turn: self.turn,
                least_normal_over_mkg: least / self.g(),
                error_over_mkg: error / self.g(),
            });
        }
    }

    /// At the start of a turn, `θ̇(0) = omega0`: its rolling part's least N
    /// (from the plan of its hop) against the error carried in.
    pub(super) fn doubt_turn_start(&mut self, omega0: f64) {
        if !self.doubt.on {
            return;
        }
        self.doubt.phase_omega = omega0;
        if let Some((_, e)) = self.planned {
            let r = self.dynamics.radius();
            let error = 2.0 * self.normal_slope() * 1.5 * r * r * self.doubt.error;
            self.judge(e.contact.min_normal_per_mk, error);
        }
    }

    /// The rolling phase ended at `theta` with the integrator's `omega`:
    /// its local error added to the error carried through it.
    fn end_rolling(&mut self, theta: f64, omega: f64) {
        let e0 = self.dynamics.energy(0.0, self.doubt.phase_omega);
        let (i, _) = self.dynamics.inertia(theta);
        let (w, _) = self.dynamics.potential(theta);
        let exact = 2.0 * (e0 - w) / i;
        let r = self.dynamics.radius();
        self.doubt.error = self.doubt.error * 1.5 * r * r / i + (omega * omega - exact).abs();
    }

    /// The pivot's `θ̇²` at rotation φ about E from `θ̇₊`, clamped at 0.
    fn pivot_omega2(&self, phi: f64, omega_plus: f64) -> f64 {
        let u = self
            .impact
            .pivot_potential(phi, self.g_along, self.g_normal);
        (omega_plus * omega_plus - 2.0 * u / self.impact.inertia_e).max(0.0)
    }

    /// The least N per unit m_k over the pivot from `θ̇₊`, φ ∈ [0, δ]
    /// (up to a stall): the grid's least sample refined by golden section
    /// between its neighbours, m/s².
    fn pivot_least_normal(&self, omega_plus: f64) -> f64 {
        let p = self.impact;
        let n = |phi: f64| {
            let w2 = self.pivot_omega2(phi, omega_plus);
            p.contact_per_mass(phi, w2.sqrt(), self.g_along, self.g_normal)
                .0
        };
        let h = p.delta / PIVOT_GRID as f64;
        let (mut best, mut at) = (f64::INFINITY, 0);
        for j in 0..=PIVOT_GRID {
            let v = n(j as f64 * h);
            if v < best {
                (best, at) = (v, j);
            }
        }
        let (mut a, mut b) = (
            at.saturating_sub(1) as f64 * h,
            (at + 1).min(PIVOT_GRID) as f64 * h,
        );
        for _ in 0..60 {
            let (x1, x2) = (b - GOLDEN * (b - a), a + GOLDEN * (b - a));
            if n(x1) < n(x2) {
                b = x2;
            } else {
                a = x1;
            }
        }
        best.min(n(0.5 * (a + b)))
    }

    /// At the impact of `--collision pivot`, the integrator's `θ̇₋`: the
    /// rolling phase's error, through the impact, and the pivot's least N
    /// (the impact's own N included) against it.
    pub(super) fn doubt_impact(&mut self, omega_before: f64) {
        if !self.doubt.on {
            return;
        }
        self.end_rolling(self.impact.theta_c, omega_before);
        let k = self.impact.omega_after(1.0);
        self.doubt.error *= k * k;
        let omega_plus = self.impact.omega_after(omega_before);
        self.doubt.phase_omega = omega_plus;
        let least = self.pivot_least_normal(omega_plus);
        // ∂N/∂θ̇² = −M ρ_E cos ψ at each φ.
        let slope = self.impact.mass * self.impact.rho_e;
        self.judge(least, 2.0 * slope * self.doubt.error);
    }

    /// At the end of turn k, the integrator's `θ̇(2π)`: the last phase's
    /// error, then through the collision to the next turn's start.
    pub(super) fn doubt_turn_end(&mut self, omega_end: f64) {
        if !self.doubt.on {
            return;
        }
        if self.pivoting {
            let exact = self.pivot_omega2(self.impact.delta, self.doubt.phase_omega);
            self.doubt.error += (omega_end * omega_end - exact).abs();
        } else {
            self.end_rolling(TWO_PI, omega_end);
        }
        let shifted = (omega_end * omega_end + self.doubt.error).sqrt();
        if let (Some(w0), Some(w1)) = (self.omega_next(omega_end), self.omega_next(shifted)) {
            self.doubt.error = (w1 * w1 - w0 * w0).abs();
        }
    }
}
