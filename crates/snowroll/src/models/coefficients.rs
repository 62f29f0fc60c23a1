//! The coefficients of the common form of the circular equations of motion
//! of §2 (the record only; the table of each derivation's values and the
//! right-hand side built from them are in `circular`). It sits here, below
//! `circular`, `contact` and `ledger`, so that the contact forces and the
//! energy ledger read the coefficients without depending on the model that
//! uses them.

use crate::scenario::Shape;

/// The coefficients of the common form of the circular equations of motion
/// (`models/circular`'s module doc):
///
/// `a (1 + κ b²/(6π²r²)) = (2/3) G − c_v b v²/(π r²) − C (λ₁ b/(π r) + λ₂ b²/(3π r²))`
/// (for the ball 5/7 in place of 2/3, and `− c₃ b³ v²/(π³ r⁴)`).
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
