//! Adaptive Gauss–Kronrod (7/15-point) quadrature for the smooth integrals of
//! the closed forms (t(x) of fn. 4).
//!
//! Written here because the need is one small, smooth, one-dimensional
//! integral per call at near machine precision; the quadrature crates either
//! pull in heavy numeric stacks or use double-exponential rules that are
//! slower on smooth integrands. The nodes and weights are QUADPACK's (Piessens
//! et al., 1983); a test checks that the rule is exact to degree 23.

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

/// Most bisections of one integral: far more than a smooth integrand needs
/// at machine precision (tens), few enough that one that never meets its
/// tolerance costs milliseconds, not the 2^40 rule evaluations of a full
/// bisection tree.
const MAX_BISECTIONS: u32 = 1000;

/// ∫ₐᵇ f with relative tolerance `rtol` (absolute floor `atol`), by
/// recursive bisection of the 15-point rule, at most 40 levels deep and
/// [`MAX_BISECTIONS`] bisections in all. An interval whose error estimate is
/// not finite (an integrand that overflowed) is not bisected: its estimate
/// is returned as it is, for the caller to find non-finite.
pub(crate) fn integrate(
    f: &mut impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    rtol: f64,
    atol: f64,
) -> f64 {
    fn recurse(
        f: &mut impl FnMut(f64) -> f64,
        a: f64,
        b: f64,
        whole: (f64, f64),
        tol: f64,
        depth: u32,
        budget: &mut u32,
    ) -> f64 {
        let (value, err) = whole;
        if err <= tol || depth == 0 || !err.is_finite() || *budget == 0 {
            return value;
        }
        *budget -= 1;
        let m = 0.5 * (a + b);
        let left = kronrod(f, a, m);
        let right = kronrod(f, m, b);
        recurse(f, a, m, left, 0.5 * tol, depth - 1, budget)
            + recurse(f, m, b, right, 0.5 * tol, depth - 1, budget)
    }
    if b <= a {
        return 0.0;
    }
    let whole = kronrod(f, a, b);
    let tol = (rtol * whole.0.abs()).max(atol);
    let mut budget = MAX_BISECTIONS;
    recurse(f, a, b, whole, tol, 40, &mut budget)
}

#[cfg(test)]
mod tests {
    use super::*;

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

    /// Regression of issue 7 (fuzzing): `simulate --model loney --v0 1e308`
    /// hung, its integrand overflowing so that no interval ever met its
    /// tolerance and the bisection tree grew to 2^40 leaves.
    #[test]
    fn regression_7_an_integrand_that_never_converges_costs_a_bounded_effort() {
        for f in [
            (|x: f64| if x > 0.5 { f64::INFINITY } else { x }) as fn(f64) -> f64,
            |_| f64::NAN,
            // Not integrable at 0: the error estimate never meets the tolerance.
            |x| 1.0 / x,
        ] {
            let mut calls = 0u64;
            let _ = integrate(
                &mut |x| {
                    calls += 1;
                    f(x)
                },
                0.0,
                1.0,
                1e-15,
                0.0,
            );
            assert!(
                calls <= 15 * (2 * u64::from(MAX_BISECTIONS) + 1),
                "{calls} evaluations"
            );
        }
    }

    #[test]
    fn adaptive_reaches_machine_precision_on_smooth_integrands() {
        let v = integrate(&mut |x: f64| x.exp(), 0.0, 10.0, 1e-15, 0.0);
        let want = 10f64.exp_m1();
        assert!(((v - want) / want).abs() < 4e-15, "{v} vs {want}");
        // A peaked integrand needs subdivision.
        let v = integrate(&mut |x: f64| 1.0 / (1e-4 + x * x), -1.0, 1.0, 1e-13, 0.0);
        let want = 2.0 * (1.0f64 / 1e-2).atan() / 1e-2;
        assert!(((v - want) / want).abs() < 1e-12, "{v} vs {want}");
    }
}
