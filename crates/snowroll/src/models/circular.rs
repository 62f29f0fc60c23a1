//! §2.1–2.4: the log taken as circular at all times (unphysical, §2.1.3:
//! fresh snow would have to spread over the whole surface at once), and the
//! approximately circular log of §2.4.
//!
//! All eight equations of motion share one form and differ only in
//! coefficients ([`Coefficients`]):
//!
//! `a (1 + κ b²/(6π²r²)) = (2/3) G − c_v b v²/(π r²) − C (λ₁ b/(π r) + λ₂ b²/(3π r²))`
//!
//! with G = g sin α, C = g cos α and `π r² = π r0² + b x` (eq. (8)).
//! State `[x (m), v (m/s)]`. Valid to the order in b/r each derivation keeps.
//!
//! **The ball** (issue 11, `docs/snowball-and-losses.md` §1.2). No derivation
//! of §2 needs a cylinder: each is a balance ([`Balance`]) for a body with
//! I = k M r², M ∝ rⁿ, growing by r′ = dr/dx. With k = 2/5, n = 3 and the
//! ball's natural swath 2r, r(x) is again eq. (8) and the common form holds
//! with 2/3 replaced by 1/(1 + k) = 5/7, other coefficients
//! ([`Derivation::coefficients_for`]) and one more term,
//! `− c₃ b³ v²/(π³ r⁴)` ([`Coefficients::drag_b3`], zero for the log). A
//! ball with a fixed swath width grows by another law and is integrated from
//! the balance itself.

use std::f64::consts::PI;

use super::contact::{circular_forces, ContactForces};
use super::ledger;
use super::ode::{run_ode, stopped_at_start, OdeModel};
use super::{Model, ModelKind};
use crate::error::SimError;
use crate::integrate::{Direction, OdeSystem};
use crate::losses::Losses;
use crate::physics::{growth_at, Growth};
use crate::scenario::{Scenario, Shape};
use crate::trajectory::{LedgerRow, OnHop, RunEnd, Sample, SampleSink, SimOptions, StopReason};
use crate::units::Radians;

/// How an equation of motion of §2 was derived: its coefficients.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Derivation {
    /// App. A, eq. (95): no snow collected, `a = (2/3) g sin α`.
    Snowless,
    /// §2.1.1, eq. (4): torque about the centre, `a = 2G/3 − 7bv²/(6πr²)`.
    TorqueAboutCentre,
    /// §2.1.2, eq. (6): torque about the contact line, `a = 2G/3 − 3bv²/(2πr²)`.
    TorqueAboutContact,
    /// §2.2, eq. (14): energy conservation of eq. (11) with the b² terms,
    /// `a(1 + b²/6π²r²) = 2G/3 − bv²/(2πr²) − C(3br + b²)/(3πr²)`.
    /// Also the corrected Lagrangian result (`docs/errata.md`, (19)–(21)).
    Energy,
    /// §2.2, eq. (15): eq. (14) to first order in b,
    /// `a = 2G/3 − bv²/(2πr²) − gb cos α/(πr)`.
    EnergyLinearised,
    /// §2.3, eq. (21) exactly as printed,
    /// `a(1 + b²/6π²r²) = 2G/3 − bv²/(πr²) − C(3rb + b²)/(3πr²)`;
    /// it omits ∂T/∂x in eq. (19) (`docs/errata.md`, (19)–(21)), the corrected form is eq. (14).
    LagrangianPrinted,
    /// §2.4, eq. (32): `a = 2G/3 − bv²/(2πr²)`, r from eq. (27).
    QuasiCircular,
    /// §2.4, eq. (32) plus term (36): `a = 2G/3 − bv²/(2πr²) − gb cos α/(πr)`
    /// (the same equation as (15); `docs/turn-model.md` fixes r).
    QuasiCircularLift,
}

/// The coefficients of the common form of the circular equations of motion
/// (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// Whether snow is collected at all (false only for the snowless model).
    pub accretes: bool,
    /// c_v, the momentum-drag coefficient of `b v²/(π r²)`.
    pub drag: f64,
    /// λ₁, the coefficient of the lifting term `g b cos α/(π r)`.
    pub lift: f64,
    /// λ₂, the coefficient of `g b² cos α/(3π r²)`.
    pub lift_b2: f64,
    /// κ, the coefficient of the inertia correction `b²/(6π² r²)`.
    pub inertia_b2: f64,
    /// c₃, the coefficient of `b³ v²/(π³ r⁴)` (the ball's `energy` and
    /// `lagrangian-printed`; zero for every log model, where the terms
    /// cancel), `docs/snowball-and-losses.md` §1.2.
    pub drag_b3: f64,
    /// The shape: its 1/(1 + k) replaces the 2/3 of the log's form.
    pub shape: Shape,
}

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
        let k = s.shape().inertia_factor();
        let (r, r1, r2, lam) = (gr.r, gr.dr_dx, gr.d2r_dx2, gr.lambda);
        let inertia = 1.0 + k + self.inertia_r2 * r1 * r1;
        let v2_coeff = self.c_n * lam * inertia
            + (self.c_1 * (1.0 + k) + self.c_k * k) * r1 / r
            + self.inertia_r2 * self.c_rr * r1 * r2;
        let lift =
            s.g_normal() * (self.lift * (lam * r + r1) + self.lift_b * lam * s.snow_depth() / 2.0);
        (s.g_along() - v2_coeff * v * v - lift, inertia)
    }
}

/// F_d/M and F_c/M of a body of size and growth `gr` at speed `v`
/// (`docs/snowball-and-losses.md` §2.1): `F_d = ½ ρ_a C_d A v|v|` with the
/// frontal area A of [`crate::losses::frontal_area`], `F_c/M = e_c λ`.
fn losses_per_mass(s: &Scenario, gr: &Growth, l: &Losses, v: f64) -> LossesPerMass {
    LossesPerMass {
        drag: l.drag_factor() * crate::losses::frontal_area(s, gr.r) * v * v.abs() / gr.mass,
        compaction: l.compaction_energy * gr.lambda,
    }
}

impl Derivation {
    /// The coefficients; see each variant for its equation.
    pub const fn coefficients(self) -> Coefficients {
        let (accretes, drag, lift, lift_b2, inertia_b2) = match self {
            Derivation::Snowless => (false, 0.0, 0.0, 0.0, 0.0),
            Derivation::TorqueAboutCentre => (true, 7.0 / 6.0, 0.0, 0.0, 0.0),
            Derivation::TorqueAboutContact => (true, 1.5, 0.0, 0.0, 0.0),
            Derivation::Energy => (true, 0.5, 1.0, 1.0, 1.0),
            Derivation::EnergyLinearised => (true, 0.5, 1.0, 0.0, 0.0),
            Derivation::LagrangianPrinted => (true, 1.0, 1.0, 1.0, 1.0),
            Derivation::QuasiCircular => (true, 0.5, 0.0, 0.0, 0.0),
            Derivation::QuasiCircularLift => (true, 0.5, 1.0, 0.0, 0.0),
        };
        Coefficients {
            accretes,
            drag,
            lift,
            lift_b2,
            inertia_b2,
            drag_b3: 0.0,
            shape: Shape::Cylinder,
        }
    }

    /// How the derivation balances forces, torques or energy, for any shape
    /// ([`Balance`]).
    pub const fn balance(self) -> Balance {
        let (inertia_r2, c_n, c_1, c_k, c_rr, lift, lift_b) = match self {
            Derivation::Snowless => (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
            Derivation::TorqueAboutCentre => (0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0),
            Derivation::TorqueAboutContact => (0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0),
            Derivation::Energy => (1.0, 0.5, 0.0, 0.0, 1.0, 1.0, 1.0),
            Derivation::EnergyLinearised => (0.0, 0.5, 0.0, 0.0, 0.0, 1.0, 0.0),
            Derivation::LagrangianPrinted => (1.0, 1.0, 0.0, 0.0, 2.0, 1.0, 1.0),
            Derivation::QuasiCircular => (0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0),
            Derivation::QuasiCircularLift => (0.0, 0.5, 0.0, 0.0, 0.0, 1.0, 0.0),
        };
        Balance {
            inertia_r2,
            c_n,
            c_1,
            c_k,
            c_rr,
            lift,
            lift_b,
        }
    }

    /// The coefficients of the common form for a body of `shape` on the
    /// area law π r² = π r0² + b x (the log; the ball with its natural swath
    /// 2r). For the log, [`Derivation::coefficients`]; for the ball, from
    /// [`Derivation::balance`] with r′ = b/(2πr), r″ = −r′²/r, λ = n r′/r
    /// (`docs/snowball-and-losses.md` §1.2):
    /// `c_v = Σ/2`, `κ = 3ε/(2(1 + k))`, `λ₁ = ℓ(n + 1)/(2(1 + k))`,
    /// `λ₂ = 3 ℓ_b n/(4(1 + k))`, `c₃ = ε (c_n n − c_rr)/(8(1 + k))`.
    pub fn coefficients_for(self, shape: Shape) -> Coefficients {
        match shape {
            Shape::Cylinder => self.coefficients(),
            Shape::Sphere => self
                .balance()
                .area_law_coefficients(shape, self.coefficients().accretes),
        }
    }

    /// The model id of this derivation.
    pub fn kind(self) -> ModelKind {
        match self {
            Derivation::Snowless => ModelKind::Snowless,
            Derivation::TorqueAboutCentre => ModelKind::TorqueCm,
            Derivation::TorqueAboutContact => ModelKind::TorqueContact,
            Derivation::Energy => ModelKind::Energy,
            Derivation::EnergyLinearised => ModelKind::EnergyThin,
            Derivation::LagrangianPrinted => ModelKind::LagrangianPrinted,
            Derivation::QuasiCircular => ModelKind::QuasiCircular,
            Derivation::QuasiCircularLift => ModelKind::QuasiCircularLift,
        }
    }
}

impl Balance {
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
    /// fixed width or the log's length):
    /// `a∞/G = 1/[(1 + k)(1 + 2Σ/(n − p))]` (`docs/snowball-and-losses.md` §1.3).
    pub fn terminal_fraction(&self, shape: Shape, swath_power: f64) -> f64 {
        let (k, n) = (shape.inertia_factor(), shape.mass_exponent());
        1.0 / ((1.0 + k) * (1.0 + 2.0 * self.sigma(shape) / (n - swath_power)))
    }
}

impl Coefficients {
    /// Acceleration at `(x, v)` of the common form (module doc), on the area
    /// law π r² = π r0² + b x.
    pub fn acceleration(&self, s: &Scenario, x: f64, v: f64) -> f64 {
        Acceleration::new(self, s).at(x, v)
    }

    /// Late-time acceleration over g sin α for b > 0: with `π r² ≈ b x` and
    /// `v² ≈ 2 a x` the drag term tends to `2 c_v a`, the lift and b² terms
    /// vanish like 1/r, so `a∞ = (2G/3)/(1 + 2 c_v)`: G/5 for eq. (4)
    /// (fn. 4), G/6 for eq. (6), G/3 for eqs. (14), (15), (32) (eq. (35)),
    /// 2G/9 for eq. (21) as printed; 2/3 throughout for the snowless
    /// model (App. A, eq. (95)). Always `Some` for the circular models.
    ///
    /// For the ball on the area law 2/3 becomes 5/7: 1/6 (`torque-cm`), 1/7
    /// (`torque-contact`), 2/7 (the energy family), 5/28 (eq. (21) printed),
    /// `docs/snowball-and-losses.md` §1.3.
    pub fn terminal_fraction(&self) -> Option<f64> {
        let (num, den) = self.shape.push_ratio();
        if self.accretes {
            Some((num / den) / (1.0 + 2.0 * self.drag))
        } else {
            Some(num / den)
        }
    }

    /// Leading approach to the terminal value. With lift (λ₁ ≠ 0),
    /// `a − a∞ ≈ −λ₁ g b cos α /((1 + 4c_v) π r)` (from the particular
    /// solution `v² = A s + B s^{1/2}`, s = πr²); without it, the exact
    /// solution `v² = A s + K s^{−2c_v}` gives `a − a∞ ∝ s^{−(1 + 2c_v)} ∝ r^{−2(1 + 2c_v)}`.
    /// Returns the power p of `|a − a∞| ∝ r^{−p}`.
    pub fn approach_power_in_r(&self) -> Option<f64> {
        if !self.accretes {
            None
        } else if self.lift != 0.0 {
            Some(1.0)
        } else {
            Some(2.0 * (1.0 + 2.0 * self.drag))
        }
    }

    /// The initial acceleration with v = 0 is not positive below this slope
    /// (fn. 7: the snow must be lifted). From the common form at x = 0, v = 0:
    /// `tan α* = 3(λ₁ b r0 + λ₂ b²/3)/(2π r0²)` (for the ball 7/5 in place
    /// of 3/2). `None` when the model has no lift term (it always starts).
    pub fn stall_slope(&self, b: f64, r0: f64) -> Option<Radians> {
        if !self.accretes || (self.lift == 0.0 && self.lift_b2 == 0.0) {
            return None;
        }
        let (num, den) = self.shape.push_ratio();
        let tan = den * (self.lift * b * r0 + self.lift_b2 * b * b / 3.0) / (num * PI * r0 * r0);
        Some(tan.atan())
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
struct AreaLaw {
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
///   q = b v²/s (r″ = −r′²/r), [`circular_forces`].
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

/// The loss terms per unit mass at one state, m/s².
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct LossesPerMass {
    /// F_d/M.
    drag: f64,
    /// F_c/M.
    compaction: f64,
}

/// The acceleration of one model on one scenario: the common form on the
/// area law, or the [`Balance`] itself for a ball with a fixed swath width.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Acceleration {
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
    /// (the ball with a fixed swath).
    fn of(derivation: Derivation, c: &Coefficients, s: &Scenario, l: &Losses) -> Self {
        if s.follows_area_law() {
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
    fn at(&self, x: f64, v: f64) -> f64 {
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

    /// F_d/M and F_c/M at `(x, v)`; zero without losses.
    fn losses_at(&self, x: f64, v: f64) -> LossesPerMass {
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

/// A circular model of §2, one right-hand side for all derivations.
///
/// ```
/// use snowroll::{CircularModel, Derivation, Model, Scenario, SimOptions};
/// let model = CircularModel::new(Derivation::TorqueAboutCentre);
/// let traj = model.simulate(&Scenario::default(), &SimOptions::default())?;
/// assert!(traj.samples.last().unwrap().v_m_s > 0.0);
/// # Ok::<(), snowroll::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularModel {
    derivation: Derivation,
    coefficients: Coefficients,
    /// Whether `coefficients` were given ([`CircularModel::with_coefficients`])
    /// rather than taken from the scenario's shape.
    given: bool,
}

impl CircularModel {
    /// The model of `derivation`.
    pub fn new(derivation: Derivation) -> Self {
        Self {
            derivation,
            coefficients: derivation.coefficients(),
            given: false,
        }
    }

    /// The model of `derivation` run with other coefficients: a deliberately
    /// wrong model, for the tests that check a claim's verdict changes when
    /// its model is wrong. It still reports itself as `derivation`'s model.
    pub fn with_coefficients(derivation: Derivation, coefficients: Coefficients) -> Self {
        Self {
            derivation,
            coefficients,
            given: true,
        }
    }

    /// Its derivation.
    pub fn derivation(&self) -> Derivation {
        self.derivation
    }

    /// The coefficients it runs with on a log (on a ball:
    /// [`Derivation::coefficients_for`]).
    pub fn coefficients(&self) -> Coefficients {
        self.coefficients
    }

    /// The coefficients it runs with on `scenario`.
    pub fn coefficients_on(&self, scenario: &Scenario) -> Coefficients {
        if self.given {
            self.coefficients
        } else {
            self.derivation.coefficients_for(scenario.shape())
        }
    }
}

/// Event indices of [`CircularSystem`].
const EVENT_STALL: usize = 0;
const EVENT_DISTANCE: usize = 1;
const EVENT_HOP: usize = 2;
const EVENT_SLIP: usize = 3;
const EVENT_TERMINAL: usize = 4;

/// The ODE `x' = v, v' = a(x, v)` of one scenario, with the events stall
/// (v = 0), end distance, hop (N = 0), slip (|F| = μN), `docs/contact-forces.md`
/// §2, §5, and terminal velocity (`docs/snowball-and-losses.md` §2.2).
///
/// State `[x, v]` (N = 2), or with the energy ledger (N = 6)
/// `[x, v, D_drag, D_rr, D_comp, W_model]` (J): the dissipated works and the
/// model's own energy defect are integrated as extra states, quadratures on
/// the steps that x and v choose ([`OdeSystem::controlled_components`]):
/// the ledger then closes to the integrator tolerance at every sample,
/// dense output included, and recording it does not change the trajectory.
struct CircularSystem<const N: usize> {
    coeffs: Coefficients,
    scenario: Scenario,
    /// `coeffs` bound to `scenario`, for the right-hand side.
    accel: Acceleration,
    losses: Losses,
    x_end: Option<f64>,
    mu: Option<f64>,
    stop_on_hop: bool,
    /// `tol × (G − c_rr C)/(1 + k)`, m/s²: the terminal stop's threshold on
    /// |a|, armed only where a terminal velocity exists (§2.2).
    terminal_accel: Option<f64>,
}

impl<const N: usize> CircularSystem<N> {
    fn new(
        derivation: Derivation,
        coeffs: Coefficients,
        scenario: &Scenario,
        opts: &SimOptions,
    ) -> Self {
        let l = opts.losses;
        let drive = scenario.g_along() - l.rolling_resistance * scenario.g_normal();
        let (num, den) = coeffs.shape.push_ratio();
        let terminal_accel =
            (!coeffs.accretes && l.drag_coefficient > 0.0 && l.terminal_tol > 0.0 && drive > 0.0)
                .then(|| l.terminal_tol * drive * num / den);
        Self {
            coeffs,
            scenario: *scenario,
            accel: Acceleration::of(derivation, &coeffs, scenario, &l),
            losses: l,
            x_end: opts.x_end,
            mu: opts.mu,
            stop_on_hop: opts.on_hop == OnHop::Stop,
            terminal_accel,
        }
    }

    fn forces(&self, y: &[f64; N]) -> ContactForces {
        let (x, v) = (y[0], y[1]);
        let mut f = circular_forces(&self.coeffs, &self.scenario, x, v, self.accel.at(x, v));
        // Drag is a body force: F = M G − F_d − dp_x/dt (§2.1).
        f.friction_n -= self.mass(x) * self.accel.losses_at(x, v).drag;
        f
    }

    fn mass(&self, x: f64) -> f64 {
        if self.coeffs.accretes {
            crate::physics::mass_at(&self.scenario, x)
        } else {
            self.scenario.initial_mass()
        }
    }

    /// Hop, slip or terminal velocity already at the state `y` (the events
    /// see crossings only).
    fn stops_at(&self, y: &[f64; N]) -> Option<StopReason> {
        let f = self.forces(y);
        if self.stop_on_hop && f.normal_n <= 0.0 {
            Some(StopReason::Hop)
        } else if self.mu.is_some_and(|mu| f.slip_margin(mu) >= 0.0) {
            Some(StopReason::Slip)
        } else if self
            .terminal_accel
            .is_some_and(|tol| self.accel.at(y[0], y[1]).abs() <= tol)
        {
            Some(StopReason::Terminal)
        } else {
            None
        }
    }
}

impl<const N: usize> OdeSystem<N> for CircularSystem<N> {
    fn rhs(&self, _t: f64, y: &[f64; N], dy: &mut [f64; N]) {
        let (x, v) = (y[0], y[1]);
        let a = self.accel.at(x, v);
        dy[0] = v;
        dy[1] = a;
        if let Some(rates) = dy.get_mut(2..6) {
            let r = ledger::rates(&self.scenario, &self.coeffs, &self.losses, [x, v, a]);
            rates.copy_from_slice(&r);
        }
    }

    /// x and v; the ledger's works are quadratures (their rates may be
    /// rounding noise about 0, e.g. W_model of `energy`, which the step
    /// control must not chase).
    fn controlled_components(&self) -> usize {
        2
    }

    fn event_count(&self) -> usize {
        5
    }

    fn event(&self, index: usize, _t: f64, y: &[f64; N]) -> f64 {
        match index {
            EVENT_STALL => y[1],
            EVENT_DISTANCE => match self.x_end {
                Some(x_end) => y[0] - x_end,
                None => -1.0,
            },
            EVENT_HOP if self.stop_on_hop => self.forces(y).normal_n,
            EVENT_HOP => 1.0,
            EVENT_SLIP => match self.mu {
                Some(mu) => self.forces(y).slip_margin(mu),
                None => -1.0,
            },
            _ => match self.terminal_accel {
                Some(tol) => self.accel.at(y[0], y[1]).abs() - tol,
                None => 1.0,
            },
        }
    }

    fn event_direction(&self, index: usize) -> Direction {
        match index {
            EVENT_STALL | EVENT_HOP | EVENT_TERMINAL => Direction::Falling,
            _ => Direction::Rising,
        }
    }
}

impl<const N: usize> OdeModel<N> for CircularSystem<N> {
    fn sample(&self, t: f64, y: &[f64; N]) -> Sample {
        let s = &self.scenario;
        let (x, v) = (y[0], y[1]);
        let r = if self.coeffs.accretes {
            crate::physics::radius_at(s, x)
        } else {
            s.initial_radius()
        };
        let a = self.accel.at(x, v);
        let forces = self.forces(y);
        Sample {
            t_s: t,
            x_m: x,
            v_m_s: v,
            a_m_s2: a,
            r_m: r,
            mass_kg: self.mass(x),
            normal_n: forces.normal_n,
            friction_n: forces.friction_n,
            friction_ratio: forces.friction_ratio(),
        }
    }

    fn ledger(&self, _t: f64, y: &[f64; N]) -> Option<LedgerRow> {
        let works = y.get(2..6)?;
        let mut w = [0.0; 4];
        w.copy_from_slice(works);
        Some(ledger::row(&self.scenario, &self.coeffs, y[0], y[1], w))
    }

    fn stop_reason(&self, event: usize) -> StopReason {
        match event {
            EVENT_DISTANCE => StopReason::Distance,
            EVENT_HOP => StopReason::Hop,
            EVENT_SLIP => StopReason::Slip,
            EVENT_TERMINAL => StopReason::Terminal,
            _ => StopReason::Stalled,
        }
    }
}

impl CircularModel {
    /// Runs the system with `N` states (2, or 6 with the ledger).
    fn run<const N: usize>(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError> {
        let mut system = CircularSystem::<N>::new(
            self.derivation,
            self.coefficients_on(scenario),
            scenario,
            opts,
        );
        let mut y0 = [0.0; N];
        y0[1] = scenario.initial_speed();
        // fn. 7: from rest the log moves only if a(0) > 0 (with losses: if
        // the drive exceeds the static couples, §2.2).
        if y0[1] == 0.0 && system.accel.at(0.0, 0.0) <= 0.0 {
            return stopped_at_start(&system, y0, StopReason::DoesNotStart, sink);
        }
        if let Some(reason) = system.stops_at(&y0) {
            return stopped_at_start(&system, y0, reason, sink);
        }
        run_ode(&mut system, y0, opts, sink)
    }
}

impl Model for CircularModel {
    fn kind(&self) -> ModelKind {
        self.derivation.kind()
    }

    fn simulate_into(
        &self,
        scenario: &Scenario,
        opts: &SimOptions,
        sink: &mut dyn SampleSink,
    ) -> Result<RunEnd, SimError> {
        self.check(scenario, opts)?;
        if opts.losses.records_ledger() {
            self.run::<6>(scenario, opts, sink)
        } else {
            self.run::<2>(scenario, opts, sink)
        }
    }
}
