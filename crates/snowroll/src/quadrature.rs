//! The Gauss–Kronrod (7/15-point) rule for the smooth integrals of the
//! closed forms (t(x) of fn. 4); the adaptive bisection over it is the
//! closed-form solver's (`models/closed_form`).
//!
//! Written here because the need is one small, smooth, one-dimensional
//! integral per call at near machine precision; the quadrature crates either
//! pull in heavy numeric stacks or use double-exponential rules that are
//! slower on smooth integrands. The nodes and weights are QUADPACK's (Piessens
//! et al., 1983); a test checks that the rule is exact to degree 23.

use crate::portable::Portable as _;

/// Kronrod nodes on [0, 1) (the symmetric half), the 7-point Gauss nodes are
/// the odd entries.
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights for `XGK`.
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights for `XGK[1], XGK[3], XGK[5], XGK[7]`.
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// The n-point Gauss–Legendre rule on [−1, 1] as `(node, weight)` pairs:
/// the roots of P_n by Newton's method from Tricomi's estimate
/// `cos(π(i − 1/4)/(n + 1/2))`, P_n and P_n′ from the three-term recurrence,
/// weights `2/((1 − x²) P_n′(x)²)` (Abramowitz & Stegun 25.4.29). Computed
/// once per use site rather than typed in, so no constant can be mistyped;
/// a test checks exactness to degree 2n − 1.
pub(crate) fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (1..=n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos_p();
            let mut dp = 1.0;
            // Newton converges quadratically from the estimate: a few steps.
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for j in 2..=n {
                    let jf = j as f64;
                    (p0, p1) = (p1, ((2.0 * jf - 1.0) * x * p1 - (jf - 1.0) * p0) / jf);
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() <= 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// One 15-point Kronrod estimate on `[a, b]` and the difference from the
/// embedded 7-point Gauss rule (the error estimate).
pub(crate) fn kronrod(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut k = WGK[7] * fc;
    let mut g = WG[3] * fc;
    for j in 0..7 {
        let dx = h * XGK[j];
        let s = f(c - dx) + f(c + dx);
        k += WGK[j] * s;
        if j % 2 == 1 {
            g += WG[j / 2] * s;
        }
    }
    (k * h, ((k - g) * h).abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The n-point rule integrates x^d exactly for d ≤ 2n − 1 (2/(d + 1)
    /// for even d, 0 for odd) and misses x^{2n} by its error term; e^x to
    /// 1e-15 with 12 points.
    /// Tolerance: rounding of ~n terms of order 1.
    #[test]
    fn gauss_legendre_is_exact_to_degree_2n_minus_1() {
        for n in [1, 2, 5, 12, 20] {
            let rule = gauss_legendre(n);
            let integral = |d: i32| rule.iter().map(|&(x, w)| w * x.powi(d)).sum::<f64>();
            for d in 0..(2 * n as i32) {
                let want = if d % 2 == 0 {
                    2.0 / (d as f64 + 1.0)
                } else {
                    0.0
                };
                assert!((integral(d) - want).abs() < 1e-14, "n = {n}, x^{d}");
            }
            // x^{2n} is not: the rule misses by 2^{2n+1}/((2n + 1) C(2n, n)²)
            // (the Gauss–Legendre error term with f^{(2n)} = (2n)!).
            let d = 2 * n as i32;
            let binomial = (1..=n).fold(1.0, |c, j| c * (n + j) as f64 / j as f64);
            let miss = 2f64.powi(d + 1) / ((d as f64 + 1.0) * binomial * binomial);
            let got = 2.0 / (d as f64 + 1.0) - integral(d);
            assert!((got - miss).abs() < 1e-14, "n = {n}: {got} vs {miss}");
        }
        let e = gauss_legendre(12)
            .iter()
            .map(|&(x, w)| w * x.exp_p())
            .sum::<f64>();
        assert!((e - (1f64.exp_p() - (-1f64).exp_p())).abs() < 1e-15);
    }

    /// Rounding of a 15-term sum of O(1) terms.
    const EXACT_TOL: f64 = 1e-14;

    #[test]
    fn rule_is_exact_to_degree_23() {
        for k in 0..=23 {
            let (v, _) = kronrod(&mut |x: f64| x.powi(k), -1.0, 1.0);
            let want = if k % 2 == 0 {
                2.0 / (k as f64 + 1.0)
            } else {
                0.0
            };
            assert!((v - want).abs() < EXACT_TOL, "degree {k}: {v} vs {want}");
        }
    }
}
