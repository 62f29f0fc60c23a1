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
//! ball with a fixed swath width or on the contact chord grows by another law
//! and is integrated from the balance itself.
//!
//! The module is split by role: this file holds the coefficient table
//! ([`Derivation`]; the record [`Coefficients`] itself lives one level
//! down, in `models/coefficients.rs`, where the contact forces and the
//! energy ledger read it too); `balance.rs` the derivations for a
//! body of any shape ([`Balance`]); `rhs.rs` the right-hand side bound to
//! one scenario, losses included; `terminal.rs` the terminal values and the
//! stall slope; `system.rs` the ODE with its contact forces and stop
//! events; `model.rs` the model ([`CircularModel`]) and its run.

mod balance;
mod contact_bound;
mod model;
mod per_mass;
mod rhs;
mod series;
mod system;
mod terminal;

pub use balance::Balance;
pub use model::CircularModel;

pub use super::coefficients::Coefficients;
use super::ModelKind;
use crate::scenario::Shape;

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
