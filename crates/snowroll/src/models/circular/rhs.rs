//! The right-hand side of the circular models: the common form bound to one
//! scenario on the area law π r² = π r0² + b x (eq. (8)), the losses per
//! unit mass (`docs/snowball-and-losses.md` §2.1), and the [`Balance`]
//! itself where r(x) follows another law (the ball with a fixed swath or the
//! contact chord).

use std::f64::consts::PI;

use super::per_mass::{losses_per_mass, LossesPerMass};
use super::series::AreaSeries;
use super::{Balance, Coefficients, Derivation};
use crate::losses::Losses;
use crate::physics::growth_at;
use crate::scenario::{Scenario, Shape};

impl Coefficients {
    /// Acceleration at `(x, v)` of the common form (module doc), on the area
    /// law π r² = π r0² + b x.
    pub fn acceleration(&self, s: &Scenario, x: f64, v: f64) -> f64 {
        Acceleration::new(self, s).at(x, v)
    }
}

/// The common form of the module doc bound to one scenario, written in
/// `s = π r² = π r0² + b x` (eq. (8)):
///
/// `a = (2G/3 − c_v b v²/s − λ₁ C b/√(π s) − λ₂ C b²/(3s)) / (1 + κ b²/(6π s))`.
///
/// Every constant (G = g sin α, C = g cos α, π r0², the products with the
/// coefficients) is computed once in `AreaLaw::new`, so that one
/// evaluation costs a division, plus a square root and a second division
/// only for the models with lift or b² inertia terms. (Evaluating sin α and
/// cos α on every call took half the time of an integration.)
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct AreaLaw {
    /// 2G/3 (5G/7 for the ball), m/s².
    push: f64,
    /// π r0², m².
    s0: f64,
    /// b, m; 0 for a model that collects no snow.
    b: f64,
    /// c_v b, m.
    drag: f64,
    /// λ₁ C b/√π, m²/s².
    lift: f64,
    /// λ₂ C b²/3, m³/s².
    lift_b2: f64,
    /// κ b²/(6π), m².
    inertia: f64,
    /// c₃ b³/π, m³.
    drag_b3: f64,
    /// The losses, or `None` for a lossless run (whose arithmetic is then
    /// exactly that of the lossless equations).
    losses: Option<LossTerms>,
}

/// The losses of `docs/snowball-and-losses.md` §2.1 per unit mass, bound to
/// one scenario on the area law π r² = π r0² + b x (s = π r², 1/r = √(π/s)):
///
/// * drag `F_d/M = ½ ρ_a C_d A v²/M`: the log (A = 2 r l, M = π ρ l r²)
///   `ρ_a C_d v²/(π ρ r)`, the ball (A = π r², M = (4/3) π ρ r³)
///   `3 ρ_a C_d v²/(8 ρ r)`;
/// * compaction `F_c/M = e_c λ = e_c (n/2) b/s` (λ = n r′/r, r′ = b/(2πr));
/// * rolling resistance `c_rr N/M` with
///   `N/M = C + r′ a + (λ r′ + r″) v² = C + r′ (a + (n − 1) q/2)`,
///   q = b v²/s (r″ = −r′²/r), [`circular_forces`](crate::circular_forces).
#[derive(Debug, Clone, Copy, PartialEq)]
struct LossTerms {
    /// F_d/M = `air v² √(1/s)`: ρ_a C_d √π/(π ρ) (log), 3 ρ_a C_d √π/(8 ρ) (ball).
    air: f64,
    /// c_rr.
    rolling: f64,
    /// e_c (n/2) b (0 without accretion), J m/kg: `F_c/M = compaction/s`.
    compaction: f64,
    /// C = g cos α, m/s².
    g_normal: f64,
    /// 1/(1 + k): the rule G → G − (F_d + c_rr N + F_c)/M enters the common
    /// form (which has G/(1 + k)) with this factor.
    push: f64,
    /// (n − 1)/2, the coefficient of r′ q in N/M.
    normal_q: f64,
}

impl LossTerms {
    fn new(l: &Losses, s: &Scenario, shape: Shape, b: f64) -> Option<Self> {
        let (num, den) = shape.push_ratio();
        let n = shape.mass_exponent();
        let air = match shape {
            Shape::Cylinder => l.air_density * l.drag_coefficient / (PI * s.density()) * PI.sqrt(),
            Shape::Sphere => {
                3.0 * l.air_density * l.drag_coefficient / (8.0 * s.density()) * PI.sqrt()
            }
        };
        l.any().then(|| Self {
            air,
            rolling: l.rolling_resistance,
            compaction: l.compaction_energy * b * (n / 2.0),
            g_normal: s.g_normal(),
            push: num / den,
            normal_q: (n - 1.0) / 2.0,
        })
    }
}

/// The acceleration of one model on one scenario: the common form on the
/// area law, or the [`Balance`] itself for a ball with a fixed swath width or
/// the chord.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Acceleration {
    /// π r² = π r0² + b x: the log, and the ball with its natural swath.
    Area(AreaLaw),
    /// Any growth law, from [`growth_at`].
    General {
        balance: Balance,
        accretes: bool,
        scenario: Scenario,
        losses: Losses,
    },
}

impl Acceleration {
    fn new(c: &Coefficients, s: &Scenario) -> Self {
        Self::Area(AreaLaw::new(c, s, &Losses::default()))
    }

    /// The acceleration of `derivation` run with `c` on `s` with the losses
    /// `l`: the common form where r(x) follows the area law, else the balance
    /// (the ball with a fixed swath or the chord, and a roll whose tube has a
    /// mass of its own).
    pub(super) fn of(derivation: Derivation, c: &Coefficients, s: &Scenario, l: &Losses) -> Self {
        if s.has_common_form() {
            Self::Area(AreaLaw::new(c, s, l))
        } else {
            Self::General {
                balance: derivation.balance(),
                accretes: c.accretes,
                scenario: *s,
                losses: *l,
            }
        }
    }

    /// Acceleration at `(x, v)`, m/s².
    #[inline]
    pub(super) fn at(&self, x: f64, v: f64) -> f64 {
        match self {
            Self::Area(law) => law.at(x, v),
            Self::General {
                balance,
                accretes,
                scenario,
                losses,
            } => {
                let gr = growth_at(scenario, x, *accretes);
                if losses.any() {
                    balance.acceleration_with_losses(scenario, &gr, losses, v)
                } else {
                    balance.acceleration(scenario, &gr, v)
                }
            }
        }
    }

    /// Whether a run started at x = 0 with speed `v0` keeps a ≥ 0, and so
    /// v ≥ 0, for all time: true for the area law without losses, with
    /// every coefficient of the common form non-negative, when a(0, v0) ≥ 0.
    ///
    /// Proof: with s = π r0² + b x and `(1 + κ…/s) a = num(s, v)` (the common
    /// form), differentiating along the run gives
    /// `(1 + κ…/s) a′ = b v ∂num/∂s + (∂num/∂v + κ… b v/s²) a`, a linear
    /// equation `a′ = α(t) a + β(t)` whose source `β = b v ∂num/∂s/(1 + κ…/s)`
    /// is ≥ 0 while v ≥ 0, as `∂num/∂s = c_v b v²/s² + ½ λ₁ C b/√π s^(-3/2) +
    /// λ₂ C b²/(3 s²) + 2 c₃ b³ v²/(π s³)` is a sum of non-negative terms. So a
    /// that starts ≥ 0 stays ≥ 0, and v′ = a keeps v ≥ 0.
    pub(super) fn stays_non_negative_from(&self, v0: f64) -> bool {
        match self {
            Self::Area(law) => {
                let terms = [
                    law.b,
                    law.drag,
                    law.lift,
                    law.lift_b2,
                    law.inertia,
                    law.drag_b3,
                ];
                law.losses.is_none()
                    && terms.iter().all(|&c| c >= 0.0)
                    && v0 >= 0.0
                    && law.at(0.0, v0) >= 0.0
            }
            Self::General { .. } => false,
        }
    }

    /// The common form as the Taylor recurrence sees it, for the area law
    /// without losses (`series.rs`); `None` otherwise (the losses' |v| and the
    /// other growth laws are left to DOP853).
    pub(super) fn series(&self) -> Option<AreaSeries> {
        match self {
            Self::Area(law) if law.losses.is_none() => Some(AreaSeries {
                push: law.push,
                s0: law.s0,
                b: law.b,
                drag: law.drag,
                lift: law.lift,
                lift_b2: law.lift_b2,
                inertia: law.inertia,
                drag_b3: law.drag_b3,
            }),
            _ => None,
        }
    }

    /// F_d/M and F_c/M at `(x, v)`; zero without losses.
    pub(super) fn losses_at(&self, x: f64, v: f64) -> LossesPerMass {
        match self {
            Self::Area(law) => law.losses_at(x, v),
            Self::General {
                accretes,
                scenario,
                losses,
                ..
            } => losses_per_mass(scenario, &growth_at(scenario, x, *accretes), losses, v),
        }
    }
}

impl AreaLaw {
    fn new(c: &Coefficients, s: &Scenario, l: &Losses) -> Self {
        let b = if c.accretes { s.snow_depth() } else { 0.0 };
        let r0 = s.initial_radius();
        let gc = s.g_normal();
        let (num, den) = c.shape.push_ratio();
        Self {
            push: num * s.g_along() / den,
            s0: PI * r0 * r0,
            b,
            drag: c.drag * b,
            lift: c.lift * gc * b / PI.sqrt(),
            lift_b2: c.lift_b2 * gc * b * b / 3.0,
            inertia: c.inertia_b2 * b * b / (6.0 * PI),
            drag_b3: c.drag_b3 * b * b * b / PI,
            losses: LossTerms::new(l, s, c.shape, b),
        }
    }

    /// Acceleration at `(x, v)`, m/s².
    ///
    /// With losses, §2.1: the common form times 1 + k reads `(1 + k)(1 + κ…) a =
    /// G − …`, and G becomes `G − F_d/M − F_c/M − c_rr N/M` with
    /// `N/M = C + r′(a + (n − 1) q/2)`; solved for a, with p = 1/(1 + k),
    /// `a = [num − p (F_d/M + F_c/M + c_rr (C + (n − 1) r′q/2))] / (1 + κ… + p c_rr r′)`
    /// (p = 2/3, n = 2 for the log; 5/7, 3 for the ball).
    #[inline]
    fn at(&self, x: f64, v: f64) -> f64 {
        let inv_s = 1.0 / (self.s0 + self.b * x);
        let mut a = self.push - self.drag * v * v * inv_s;
        if self.lift != 0.0 || self.lift_b2 != 0.0 {
            a -= self.lift * inv_s.sqrt() + self.lift_b2 * inv_s;
        }
        if self.drag_b3 != 0.0 {
            a -= self.drag_b3 * v * v * inv_s * inv_s;
        }
        if let Some(l) = &self.losses {
            let per_mass = self.losses_per_mass(l, inv_s, v);
            // r′ = b/(2π r) = b √(π/s)/(2π); q = b v²/s.
            let r_prime = self.b * (inv_s / PI).sqrt() / 2.0;
            let q = self.b * v * v * inv_s;
            let normal_free = l.g_normal + r_prime * q * l.normal_q;
            a -= l.push * (per_mass.drag + per_mass.compaction + l.rolling * normal_free);
            return a / (1.0 + self.inertia * inv_s + l.push * l.rolling * r_prime);
        }
        if self.inertia != 0.0 {
            a /= 1.0 + self.inertia * inv_s;
        }
        a
    }

    /// F_d/M and F_c/M at `1/s` and `v`.
    fn losses_per_mass(&self, l: &LossTerms, inv_s: f64, v: f64) -> LossesPerMass {
        LossesPerMass {
            drag: l.air * v * v.abs() * inv_s.sqrt(),
            compaction: l.compaction * inv_s,
        }
    }

    /// The loss terms at `(x, v)`; zero without losses.
    fn losses_at(&self, x: f64, v: f64) -> LossesPerMass {
        let inv_s = 1.0 / (self.s0 + self.b * x);
        self.losses
            .map(|l| self.losses_per_mass(&l, inv_s, v))
            .unwrap_or_default()
    }
}
