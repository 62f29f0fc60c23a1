//! [`Balance`]: each derivation of §2 written for a body of any shape,
//! I = k M r², M ∝ rⁿ (`docs/snowball-and-losses.md` §1.2). The ball's
//! coefficients on the area law and its terminal values follow from it, and
//! a ball with a fixed swath width or the chord is integrated from it directly.

use super::per_mass::losses_per_mass;
use super::Coefficients;
#[cfg(doc)]
use super::Derivation;
use crate::body::TubeShares;
use crate::losses::Losses;
use crate::physics::Growth;
use crate::scenario::{Scenario, Shape};

/// A derivation of §2 for a body of any shape, I = k M r², M ∝ rⁿ
/// (`docs/snowball-and-losses.md` §1.2, checked by
/// `scripts/derivations/sphere.py`):
///
/// `(1 + k + ε r′²) a = G − [c_n λ (1 + k + ε r′²) + (c_1 (1 + k) + c_k k) r′/r + ε c_rr r′ r″] v²
///  − C [ℓ (λ r + r′) + ℓ_b λ b/2]`,
///
/// with λ = (dM/dx)/M = n r′/r. With k = ½ and the log's growth it is
/// eqs. (4), (6), (14), (15), (21), (32), (32)+(36).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Balance {
    /// ε: 1 where the kinetic energy's r′² v²/2 (the radial growth, eq. (7)) is kept.
    pub inertia_r2: f64,
    /// c_n: the coefficient of λ (the momentum of the snow picked up).
    pub c_n: f64,
    /// c_1: the coefficient of (1 + k) r′/r (torque about the contact line).
    pub c_1: f64,
    /// c_k: the coefficient of k r′/r (torque about the centre).
    pub c_k: f64,
    /// c_rr: the coefficient of ε r′ r″.
    pub c_rr: f64,
    /// ℓ: the coefficient of the lift C (λ r + r′) (term (36)).
    pub lift: f64,
    /// ℓ_b: the coefficient of the slab's half depth, C λ b/2.
    pub lift_b: f64,
}

impl Balance {
    /// Σ, the coefficient of (r′/r) v² in `a` at large r:
    /// `a ≈ G/(1 + k) − Σ (r′/r) v²`, with `Σ = c_n n + c_1 + c_k k/(1 + k)`.
    pub fn sigma(&self, shape: Shape) -> f64 {
        let (k, n) = (shape.inertia_factor(), shape.mass_exponent());
        self.c_n * n + self.c_1 + self.c_k * k / (1.0 + k)
    }

    /// The acceleration, m/s², at speed `v` for a body of `shape` of size
    /// and growth `gr` (the equation of the type doc).
    pub fn acceleration(&self, s: &Scenario, gr: &Growth, v: f64) -> f64 {
        let (drive, inertia) = self.drive_and_inertia(s, gr, v);
        drive / inertia
    }

    /// The acceleration with the losses `l` by the rule of
    /// `docs/snowball-and-losses.md` §2.1, G → G − (F_d + c_rr N + F_c)/M,
    /// with `N/M = C + r′ a + (λ r′ + r″) v²` solved for a:
    ///
    /// `a = [RHS − F_d/M − e_c λ − c_rr (C + (λ r′ + r″) v²)] / (1 + k + ε r′² + c_rr r′)`.
    pub fn acceleration_with_losses(&self, s: &Scenario, gr: &Growth, l: &Losses, v: f64) -> f64 {
        let (drive, inertia) = self.drive_and_inertia(s, gr, v);
        let per_mass = losses_per_mass(s, gr, l, v);
        let normal_free = s.g_normal() + (gr.lambda * gr.dr_dx + gr.d2r_dx2) * v * v;
        let rolling = l.rolling_resistance;
        (drive - per_mass.drag - per_mass.compaction - rolling * normal_free)
            / (inertia + rolling * gr.dr_dx)
    }

    /// The right-hand side `G − …` of the type doc's equation and its
    /// inertia factor `1 + k + ε r′²`.
    fn drive_and_inertia(&self, s: &Scenario, gr: &Growth, v: f64) -> (f64, f64) {
        let (r, r1, r2, lam) = (gr.r, gr.dr_dx, gr.d2r_dx2, gr.lambda);
        let (inertia, v2_coeff) = match gr.tube {
            None => {
                let k = s.shape().inertia_factor();
                let inertia = 1.0 + k + self.inertia_r2 * r1 * r1;
                let v2_coeff = self.c_n * lam * inertia
                    + (self.c_1 * (1.0 + k) + self.c_k * k) * r1 / r
                    + self.inertia_r2 * self.c_rr * r1 * r2;
                (inertia, v2_coeff)
            }
            Some(t) => self.with_tube(gr, t),
        };
        let lift =
            s.g_normal() * (self.lift * (lam * r + r1) + self.lift_b * lam * s.snow_depth() / 2.0);
        (s.g_along() - v2_coeff * v * v - lift, inertia)
    }
}

impl Balance {
    /// The inertia factor and the coefficient of v² of the type doc's
    /// equation for a body whose moment of inertia is not k M r² (the
    /// unwinding roll's [`Tube`](crate::body::Tube), `docs/unwinding.md`,
    /// "The core"). Each balance written with M(x) and I(x) and divided by
    /// M, with j = I/(M r²) and i′ = (dI/dx)/(M r²):
    ///
    /// `(1 + j + ε r′²) a = G − [c_n (λ (1 + ε r′²) + i′ − 2 j r′/r) + ε c_rr r′ r″
    ///  + (c_1 + c_k) j r′/r + c_1 r′/r] v² − lift`.
    ///
    /// (eq. (3): d(Mv)/dt + d(I v/r)/dt/r = M G; eq. (5): d((I + M r²) v/r)/dt
    /// = M G r; the energy balances: d(½ (M (1 + ε r′²) + I/r²) v²)/dt =
    /// −dV/dt, eq. (21) without ∂T/∂x.) With j = k, i′ = k (λ + 2 r′/r) it is
    /// the uniform body's form.
    fn with_tube(&self, gr: &Growth, t: TubeShares) -> (f64, f64) {
        let (r, r1, r2, lam) = (gr.r, gr.dr_dx, gr.d2r_dx2, gr.lambda);
        let (j, i1) = (t.inertia, t.inertia_rate);
        let radial = 1.0 + self.inertia_r2 * r1 * r1;
        let v2_coeff = self.c_n * (lam * radial + i1 - 2.0 * j * r1 / r)
            + self.inertia_r2 * self.c_rr * r1 * r2
            + (self.c_1 + self.c_k) * j * r1 / r
            + self.c_1 * r1 / r;
        (radial + j, v2_coeff)
    }

    /// The common form's coefficients of this balance for `shape` on the
    /// area law ([`Derivation::coefficients_for`]).
    pub fn area_law_coefficients(&self, shape: Shape, accretes: bool) -> Coefficients {
        let (k, n) = (shape.inertia_factor(), shape.mass_exponent());
        Coefficients {
            accretes,
            drag: self.sigma(shape) / 2.0,
            lift: self.lift * (n + 1.0) / (2.0 * (1.0 + k)),
            lift_b2: 3.0 * self.lift_b * n / (4.0 * (1.0 + k)),
            inertia_b2: 3.0 * self.inertia_r2 / (2.0 * (1.0 + k)),
            drag_b3: self.inertia_r2 * (self.c_n * n - self.c_rr) / (8.0 * (1.0 + k)),
            shape,
        }
    }

    /// The late-time acceleration over g sin α of a body of `shape` whose
    /// swath grows like r^p (p = 1 for the ball's natural swath 2r, 0 for a
    /// fixed width or the log's length, ½ for the chord at r ≫ b):
    /// `a∞/G = 1/[(1 + k)(1 + 2Σ/(n − p))]` (`docs/snowball-and-losses.md` §1.3).
    pub fn terminal_fraction(&self, shape: Shape, swath_power: f64) -> f64 {
        let (k, n) = (shape.inertia_factor(), shape.mass_exponent());
        1.0 / ((1.0 + k) * (1.0 + 2.0 * self.sigma(shape) / (n - swath_power)))
    }
}
