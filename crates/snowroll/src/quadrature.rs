//! The Gauss–Kronrod (7/15-point) rule for the smooth integrals of the
//! closed forms (t(x) of fn. 4); the adaptive bisection over it is the
//! closed-form solver's (`models/closed_form`).
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
}
