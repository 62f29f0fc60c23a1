//! Double-double arithmetic (a value as the unevaluated sum `hi + lo` of
//! two doubles, ~32 significant digits; Dekker 1971, Bailey's QD library),
//! just what [`Orbit`](super::orbit::Orbit) needs to evaluate the energy of
//! a turn at its minimum without cancellation: near a stall `E(θ_m)` is the
//! difference of terms up to 1e10 times larger, and the time of the turn
//! depends on it logarithmically (`docs/turn-model.md`, (T3)).

/// `hi + lo` with `|lo| ≤ ulp(hi)/2`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Dd {
    pub(super) hi: f64,
    pub(super) lo: f64,
}

/// `a + b` exactly as `s + e` (Knuth's two-sum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` for `|a| ≥ |b|`.
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a b` exactly as `p + e` (a fused multiply-add gives the error).
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    pub(super) fn from(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// The exact product of two doubles.
    pub(super) fn product(a: f64, b: f64) -> Self {
        let (hi, lo) = two_prod(a, b);
        Self { hi, lo }
    }

    /// The nearest double.
    pub(super) fn value(self) -> f64 {
        self.hi + self.lo
    }

    pub(super) fn add(self, b: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        Dd { hi, lo }
    }

    pub(super) fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    pub(super) fn sub(self, b: Dd) -> Dd {
        self.add(b.neg())
    }

    pub(super) fn mul(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        let (hi, lo) = quick_two_sum(p, e + (self.hi * b.lo + self.lo * b.hi));
        Dd { hi, lo }
    }

    pub(super) fn scale(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi, b);
        let (hi, lo) = quick_two_sum(p, e + self.lo * b);
        Dd { hi, lo }
    }

    /// `self / b`: the double quotient and one correction.
    fn div(self, b: f64) -> Dd {
        let q1 = self.hi / b;
        let rest = self.sub(Dd::product(q1, b));
        let (hi, lo) = quick_two_sum(q1, rest.hi / b);
        Dd { hi, lo }
    }

    /// `(sin x, cos x)` of a double x with |x| ≤ 16 to ~1e-31: x − kπ/2
    /// with π/2 in three parts, then the Taylor series on |y| ≤ π/4.
    pub(super) fn sin_cos(x: f64) -> (Dd, Dd) {
        // π/2 = PIO2[0] + PIO2[1] + PIO2[2] to ~1e-49 (the first is the double nearest).
        const PIO2: [f64; 3] = [
            std::f64::consts::FRAC_PI_2,
            6.123_233_995_736_766e-17,
            -1.497_384_904_859_169_8e-33,
        ];
        let k = (x / PIO2[0]).round();
        let y = Dd::from(x)
            .sub(Dd::product(k, PIO2[0]))
            .sub(Dd::product(k, PIO2[1]))
            .sub(Dd::from(k * PIO2[2]));
        let y2 = y.mul(y);
        // sin y = Σ (−1)ⁿ y^(2n+1)/(2n+1)!, cos y = Σ (−1)ⁿ y^(2n)/(2n)!;
        // 17 terms each reach (π/4)^34/34! ~ 1e-42.
        let (mut s, mut c) = (y, Dd::from(1.0));
        let (mut ts, mut tc) = (y, Dd::from(1.0));
        for n in 1..=17 {
            let m = 2.0 * n as f64;
            ts = ts.mul(y2).div(-(m * (m + 1.0)));
            tc = tc.mul(y2).div(-(m * (m - 1.0)));
            s = s.add(ts);
            c = c.add(tc);
        }
        match (k as i64).rem_euclid(4) {
            0 => (s, c),
            1 => (c, s.neg()),
            2 => (s.neg(), c.neg()),
            _ => (c.neg(), s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// sin² + cos² = 1 to double-double rounding, the doubles' own sin and
    /// cos to 2 ulp, and sin x at x = 1 and x = 4.3648137341026265 (a
    /// minimum of E of issue 32) against mpmath at 50 digits, split into
    /// hi + lo: 1e-31.
    #[test]
    fn sin_cos_to_double_double() {
        let tau = std::f64::consts::TAU;
        for x in [0.1, 1.0, 2.5, 3.0, 4.36, 5.9, tau, 7.5, -1.2] {
            let (s, c) = Dd::sin_cos(x);
            let one = s.mul(s).add(c.mul(c)).sub(Dd::from(1.0));
            assert!(one.value().abs() < 1e-30, "{x}: {one:?}");
            assert!((s.value() - x.sin()).abs() <= 2.0 * f64::EPSILON, "{x}");
            assert!((c.value() - x.cos()).abs() <= 2.0 * f64::EPSILON, "{x}");
        }
        for (x, hi, lo) in [
            (1.0, 0.8414709848078965, 1.776845092935536e-18),
            (
                4.3648137341026265,
                -0.9402013932791642,
                -2.3919780091411228e-17,
            ),
        ] {
            let (s, _) = Dd::sin_cos(x);
            let miss = s.sub(Dd { hi, lo }).value();
            assert!(miss.abs() < 1e-31, "{x}: {miss:e}");
        }
    }
}
