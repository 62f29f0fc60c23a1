//! The Taylor coefficients of a circular model's run on the area law without
//! losses, for the integrator's Taylor steps
//! ([`OdeSystem::taylor_coefficients`](crate::integrate::OdeSystem::taylor_coefficients)).
//!
//! The common form ([`super::rhs`]) multiplied by s = π r0² + b x (eq. (8)) is
//!
//! `a (s + κ…) = P s − c_v b q − λ₁… √s − λ₂… − c₃… q/s`,  q = v²,
//!
//! and x′ = v, v′ = a. On truncated power series in t (`u_k = u⁽ᵏ⁾/k!`) every
//! operation here is a short recurrence: `s_k = b x_k` (k ≥ 1), `q_k = Σ v_j
//! v_(k−j)`, `√s` from `r² = s`, `q/s` and `a` from `z s = q` and `a (s + κ…) =
//! num`, each solved for its newest coefficient; then `x_(k+1) = v_k/(k+1)`,
//! `v_(k+1) = a_k/(k+1)`. Order k costs about 1.5 k multiply-adds (2.5 k
//! with the lift's square root, 3.5 k with the b³ drag).

use crate::integrate::TAYLOR_MAX_ORDER;

/// Coefficients kept per series.
const TERMS: usize = TAYLOR_MAX_ORDER + 1;

/// `1/(k + 1)` for k = 0..TERMS (a division per order is on no critical path,
/// but a table costs nothing).
const RECIPROCALS: [f64; TERMS] = {
    let mut table = [0.0; TERMS];
    let mut k = 0;
    while k < TERMS {
        table[k] = 1.0 / (k + 1) as f64;
        k += 1;
    }
    table
};

/// The common form on the area law without losses, with its constants
/// bound to one scenario (the fields of `AreaLaw`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct AreaSeries {
    /// P = 2G/3 (5G/7 for the ball), m/s².
    pub(super) push: f64,
    /// π r0², m².
    pub(super) s0: f64,
    /// b, m (0 for a model that collects no snow).
    pub(super) b: f64,
    /// c_v b, m.
    pub(super) drag: f64,
    /// λ₁ C b/√π, m²/s².
    pub(super) lift: f64,
    /// λ₂ C b²/3, m³/s².
    pub(super) lift_b2: f64,
    /// κ b²/(6π), m².
    pub(super) inertia: f64,
    /// c₃ b³/π, m³.
    pub(super) drag_b3: f64,
}

/// `Σ a_i b_i` in four interleaved partial sums (a fixed order, so the same
/// bits on every target), for the convolutions' older terms: their sum does
/// not wait for the newest coefficient, so it overlaps the recurrence's
/// chain instead of lengthening it.
#[inline(always)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = [0.0; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let tail: f64 = (ca.remainder().iter().zip(cb.remainder()))
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in ca.zip(cb) {
        for i in 0..4 {
            acc[i] += x[i] * y[i];
        }
    }
    ((acc[0] + acc[2]) + (acc[1] + acc[3])) + tail
}

/// A series kept twice, forwards and backwards, so that each convolution
/// sum `Σ u_j w_(k−j)` is a dot product of two forward slices.
struct Series {
    fwd: [f64; TERMS],
    rev: [f64; TERMS],
}

impl Series {
    fn new() -> Self {
        Self {
            fwd: [0.0; TERMS],
            rev: [0.0; TERMS],
        }
    }

    #[inline(always)]
    fn set(&mut self, k: usize, value: f64) {
        self.fwd[k] = value;
        self.rev[TERMS - 1 - k] = value;
    }

    /// `Σ_{j=lo}^{hi} u_j w_(k−j)` with `self = w`, `u` forwards (lo ≤ hi ≤ k).
    #[inline(always)]
    fn conv(&self, u: &[f64; TERMS], k: usize, lo: usize, hi: usize) -> f64 {
        if lo > hi {
            return 0.0;
        }
        // w_(k−j) for j = lo..=hi is rev[TERMS − 1 − k + j].
        let start = TERMS - 1 - k + lo;
        dot(&u[lo..=hi], &self.rev[start..=start + (hi - lo)])
    }
}

/// `Σ_{j=1}^{k} s_j w_(k−j)` (k ≥ 1) with the two newest terms last:
/// j = 2..k−1, then `s_k w₀` (s_k follows from v_(k−1)) and `s₁ w_(k−1)`.
#[inline(always)]
fn newest_last(w: &Series, s: &[f64; TERMS], k: usize) -> f64 {
    if k == 1 {
        return s[1] * w.fwd[0];
    }
    w.conv(s, k, 2, k - 1) + s[k] * w.fwd[0] + s[1] * w.fwd[k - 1]
}

impl AreaSeries {
    /// Writes `c[k] = [x_k, v_k]` (the first two components of each
    /// coefficient; the rest are left alone), k = 0..c.len(), of the run
    /// through `(x, v)`. `c.len()` is at most [`TAYLOR_MAX_ORDER`] + 1.
    pub(super) fn coefficients<const N: usize>(&self, x: f64, v: f64, c: &mut [[f64; N]]) {
        let p = c.len().clamp(1, TERMS) - 1;
        let (mut xs, mut vs, mut a) = (Series::new(), Series::new(), Series::new());
        let (mut s, mut r, mut z) = ([0.0; TERMS], Series::new(), Series::new());
        xs.set(0, x);
        vs.set(0, v);
        s[0] = self.s0 + self.b * x;
        let inv_s0 = 1.0 / s[0];
        let inv_e0 = 1.0 / (s[0] + self.inertia);
        let (with_lift, with_b3) = (self.lift != 0.0, self.drag_b3 != 0.0);
        r.set(0, s[0].sqrt());
        let inv_2r0 = 0.5 / r.fwd[0];
        for k in 0..p {
            // Each sum: its older terms first (a dot product that need not
            // wait for this order), the newest last.
            let (q, conv) = if k == 0 {
                (v * v, 0.0)
            } else {
                s[k] = self.b * xs.fwd[k];
                // q = v²: Σ_{j=1}^{k−1} v_j v_(k−j) (each pair once, doubled,
                // and v_(k/2)² for even k), then 2 v₀ v_k.
                let mut older = 2.0 * vs.conv(&vs.fwd, k, 1, (k - 1) / 2);
                if k % 2 == 0 {
                    older += vs.fwd[k / 2] * vs.fwd[k / 2];
                }
                let q = older + 2.0 * vs.fwd[0] * vs.fwd[k];
                (q, newest_last(&a, &s, k))
            };
            let mut num = self.push * s[k] - self.drag * q;
            if k == 0 {
                num -= self.lift_b2;
            }
            if with_lift {
                if k > 0 {
                    // r² = s: 2 r₀ r_k = s_k − Σ_{j=1}^{k−1} r_j r_(k−j).
                    r.set(k, (s[k] - r.conv(&r.fwd, k, 1, k - 1)) * inv_2r0);
                }
                num -= self.lift * r.fwd[k];
            }
            if with_b3 {
                // z s = q: s₀ z_k = q_k − Σ_{j=1}^{k} s_j z_(k−j).
                let zk = if k == 0 {
                    q * inv_s0
                } else {
                    (q - newest_last(&z, &s, k)) * inv_s0
                };
                z.set(k, zk);
                num -= self.drag_b3 * zk;
            }
            // a (s + κ…) = num: (s₀ + κ…) a_k = num_k − Σ_{j=1}^{k} s_j a_(k−j).
            let ak = (num - conv) * inv_e0;
            a.set(k, ak);
            xs.set(k + 1, vs.fwd[k] * RECIPROCALS[k]);
            vs.set(k + 1, ak * RECIPROCALS[k]);
        }
        for (ck, (&xk, &vk)) in c.iter_mut().zip(xs.fwd.iter().zip(&vs.fwd)) {
            ck[0] = xk;
            ck[1] = vk;
        }
    }
}
