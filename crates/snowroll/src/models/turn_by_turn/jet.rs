//! Second-order jets in θ: a value with its first two derivatives, carried
//! through `+ − × ÷` by the product and quotient rules, so that the
//! extremes of a, N and |F|/N within a turn are refined by Newton's method
//! on the derivative (two or three steps from a grid point) instead of by
//! Brent's method on values (about a dozen). Written here rather than taken
//! from an automatic-differentiation crate: four operators and two
//! derivatives are all the turn's formulas need, and a crate's general
//! dual numbers would cost more per operation in the hot loop.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// `(f, f′, f″)` at one θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Jet {
    /// f(θ).
    pub(super) v: f64,
    /// f′(θ).
    pub(super) d: f64,
    /// f″(θ).
    pub(super) dd: f64,
}

impl Jet {
    /// θ itself: `(θ, 1, 0)`.
    pub(super) fn variable(theta: f64) -> Self {
        Self {
            v: theta,
            d: 1.0,
            dd: 0.0,
        }
    }

    /// `(sin θ, cos θ)` as jets from their values.
    pub(super) fn sin_cos(s: f64, c: f64) -> (Self, Self) {
        (
            Self { v: s, d: c, dd: -s },
            Self {
                v: c,
                d: -s,
                dd: -c,
            },
        )
    }

    /// |f| (f ≠ 0: the sign of f is kept through the derivatives).
    pub(super) fn abs(self) -> Self {
        if self.v < 0.0 {
            -self
        } else {
            self
        }
    }
}

/// The arithmetic the turn's formulas are written in: `f64` for values,
/// [`Jet`] for values with derivatives (the same expression serves both,
/// so the two cannot disagree).
pub(super) trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
    + Mul<f64, Output = Self>
{
    /// 0 where the value is negative, else itself (θ̇² past a stall).
    fn at_least_zero(self) -> Self;
    /// 1/f (one division, where a formula divides by f twice).
    fn recip(self) -> Self;
}

impl Real for f64 {
    fn at_least_zero(self) -> Self {
        self.max(0.0)
    }
    fn recip(self) -> Self {
        1.0 / self
    }
}

impl Real for Jet {
    /// `(1/f)′ = −f′/f²`, `(1/f)″ = (2f′²/f − f″)/f²`.
    fn recip(self) -> Self {
        let r = 1.0 / self.v;
        let r2 = r * r;
        Self {
            v: r,
            d: -self.d * r2,
            dd: (2.0 * self.d * self.d * r - self.dd) * r2,
        }
    }
    fn at_least_zero(self) -> Self {
        if self.v < 0.0 {
            Self {
                v: 0.0,
                d: 0.0,
                dd: 0.0,
            }
        } else {
            self
        }
    }
}

impl Add for Jet {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self {
            v: self.v + o.v,
            d: self.d + o.d,
            dd: self.dd + o.dd,
        }
    }
}

impl Sub for Jet {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self {
            v: self.v - o.v,
            d: self.d - o.d,
            dd: self.dd - o.dd,
        }
    }
}

impl Neg for Jet {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            v: -self.v,
            d: -self.d,
            dd: -self.dd,
        }
    }
}

impl Mul for Jet {
    type Output = Self;
    /// `(fg)′ = f′g + fg′`, `(fg)″ = f″g + 2f′g′ + fg″`.
    fn mul(self, o: Self) -> Self {
        Self {
            v: self.v * o.v,
            d: self.d * o.v + self.v * o.d,
            dd: self.dd * o.v + 2.0 * self.d * o.d + self.v * o.dd,
        }
    }
}

impl Div for Jet {
    type Output = Self;
    /// q = f/g: `q′ = (f′ − q g′)/g`, `q″ = (f″ − 2q′g′ − q g″)/g`.
    fn div(self, o: Self) -> Self {
        let inv = 1.0 / o.v;
        let q = self.v * inv;
        let dq = (self.d - q * o.d) * inv;
        Self {
            v: q,
            d: dq,
            dd: (self.dd - 2.0 * dq * o.d - q * o.dd) * inv,
        }
    }
}

impl Add<f64> for Jet {
    type Output = Self;
    fn add(self, x: f64) -> Self {
        Self {
            v: self.v + x,
            ..self
        }
    }
}

impl Sub<f64> for Jet {
    type Output = Self;
    fn sub(self, x: f64) -> Self {
        Self {
            v: self.v - x,
            ..self
        }
    }
}

impl Mul<f64> for Jet {
    type Output = Self;
    fn mul(self, x: f64) -> Self {
        Self {
            v: self.v * x,
            d: self.d * x,
            dd: self.dd * x,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A composite of every operator against its derivatives written out
    /// by hand: f(θ) = (θ sin θ + 2)/(cos θ + 3) − θ³ at θ = 0.7.
    /// Tolerance: a few roundings of numbers of order 1.
    #[test]
    fn product_and_quotient_rules_match_the_derivatives_by_hand() {
        let theta = 0.7_f64;
        let (s, c) = theta.sin_cos();
        let (js, jc) = Jet::sin_cos(s, c);
        let t = Jet::variable(theta);
        let f = (t * js + 2.0) / (jc + 3.0) - t * t * t;
        // u = θ sin θ + 2, u′ = sin θ + θ cos θ, u″ = 2 cos θ − θ sin θ;
        // w = cos θ + 3, w′ = −sin θ, w″ = −cos θ.
        let (u, du, ddu) = (theta * s + 2.0, s + theta * c, 2.0 * c - theta * s);
        let (w, dw, ddw) = (c + 3.0, -s, -c);
        let q = u / w;
        let dq = (du * w - u * dw) / (w * w);
        let ddq = (ddu * w - u * ddw) / (w * w) - 2.0 * dw * (du * w - u * dw) / (w * w * w);
        let want = (
            q - theta.powi(3),
            dq - 3.0 * theta * theta,
            ddq - 6.0 * theta,
        );
        for (got, want) in [(f.v, want.0), (f.d, want.1), (f.dd, want.2)] {
            assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        }
        let inv = (jc + 3.0).recip();
        let want_inv = (1.0 / w, -dw / (w * w), (2.0 * dw * dw / w - ddw) / (w * w));
        for (got, want) in [
            (inv.v, want_inv.0),
            (inv.d, want_inv.1),
            (inv.dd, want_inv.2),
        ] {
            assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        }
        let neg = (-f).abs();
        assert_eq!((neg.v, neg.d), (f.v.abs(), f.d * f.v.signum()));
    }
}
