//! The time beyond the start as a convergent series, for the circular
//! models without lift (`L = M = 0`) and without the inertia term (`k = 0`):
//! eqs. (4), (6) and the quasi-circular eq. (32) without lift.
//!
//! There (F1) of the parent module reads, with `z = s/s0` (eq. (8)) and
//! `α1 = 2 s0 P/(b (n + 1))`,
//!
//! `u = α1 z + (u0 − α1) z^(−n) = α1 z (1 + β z^(−(n+1))),   β = u0/α1 − 1 ≥ −1`,
//!
//! so that, with `dx = (s0/b) dz` and `c = s0/(b √α1)`,
//!
//! `t(Z) = c ∫ z^(−1/2) (1 + β z^(−(n+1)))^(−1/2) dz`.                  (T1)
//!
//! Where `ε = β z^(−(n+1))` is small, the binomial series
//! `(1 + ε)^(−1/2) = Σ a_k ε^k` (`a_0 = 1`, `a_k = −a_{k−1} (2k − 1)/(2k)`)
//! integrates term by term:
//!
//! `S(z) = Σ a_k β^k z^(e_k)/e_k = √z Σ a_k ε^k/e_k,   e_k = 1/2 − k (n + 1)`,  (T2)
//!
//! and `t(Z) = t(z1) + c (S(Z) − S(z1))` for `Z ≥ z1`. From `z1`, where
//! `|ε| ≤ 1/8`, each term is at most an eighth of the one before, so about
//! twenty terms reach f64 rounding. The start, `z < z1` (with its
//! integrable `1/√x` from rest), stays with the quadrature; the time is then
//! a few series evaluations instead of quadrature panels out to the end.
//!
//! From rest (`u0 = 0`, `β = −1`) the start needs no quadrature either.
//! With `τ = z^(−(n+1))` (T1) becomes `(c/(n+1)) ∫_τ^1 τ'^(a−1) (1 − τ')^(−1/2) dτ'`,
//! `a = −1/(2(n+1))`: an incomplete beta integral, and (T2) is its expansion
//! about τ = 0, so that
//!
//! `t(Z) = c (B(a, 1/2)/(n + 1) + S(Z))`,   `B(a, 1/2) = Γ(a) Γ(1/2)/Γ(a + 1/2)`,   (T3)
//!
//! Euler's beta function continued to `a < 0` (the constant is fixed by
//! `t(1) = 0`). The series is summed only from `z1`; an end before that
//! is found by the quadrature.
//!
//! Contact forces: here `u/s = (α1 + (u0 − α1) z^(−(n+1)))/s0` is monotone
//! in z, and with `a = P − D u/s`, `q = b u/s` the normal force and the
//! friction force that `SpeedSquared::contact_holds` checks are bilinear in
//! `(1/r, u/s)`. Over `[z1, Z]` those two range over a rectangle spanned by
//! their values at the ends, and a bilinear function takes its least value
//! on a rectangle at a corner: checking the four corners bounds the forces
//! along the whole run (conservatively).

use crate::portable::Portable as _;
use std::cell::Cell;
use std::f64::consts::PI;

use super::{Form, SpeedSquared};

/// Largest `|ε| = |β| z1^(−(n+1))` at the start of the series.
const MAX_RATIO: f64 = 0.125;
/// Terms of (T2) at most: `(1/8)^40` is far below f64 rounding.
const MAX_TERMS: u32 = 40;
/// A term below this fraction of the sum ends (T2).
const TERM_RTOL: f64 = 1e-17;

/// (T1)–(T2) for one model in one scenario.
#[derive(Debug, Clone, Copy)]
pub(super) struct Series {
    /// β = u0/α1 − 1.
    beta: f64,
    /// n + 1.
    np1: f64,
    /// c = s0/(b √α1), s.
    scale: f64,
    /// z1: where the series takes over.
    pub(super) z1: f64,
    /// S(z1).
    s_z1: f64,
    /// t(z1) from (T3) when the run starts from rest, s.
    pub(super) t_z1: Option<f64>,
}

impl SpeedSquared {
    /// The series of the module doc, or `None` for a model with lift or the
    /// inertia term (or without snow).
    pub(super) fn series(&self) -> Option<Series> {
        let Form::Power { p, l, m, n } = self.form else {
            return None;
        };
        if l != 0.0 || m != 0.0 || self.b <= 0.0 {
            return None;
        }
        let alpha1 = 2.0 * self.s0 * p / (self.b * (n + 1.0));
        let beta = self.u0 / alpha1 - 1.0;
        let np1 = n + 1.0;
        // |β| z1^(−(n+1)) ≤ MAX_RATIO, and z1 ≥ 1 (the start).
        let z1 = (beta.abs() / MAX_RATIO).powf_p(1.0 / np1).max(1.0);
        let mut series = Series {
            beta,
            np1,
            scale: self.s0 / (self.b * alpha1.sqrt()),
            z1,
            s_z1: 0.0,
            t_z1: None,
        };
        series.s_z1 = series.antiderivative(z1);
        if self.u0 == 0.0 {
            series.t_z1 = Some(series.scale * (beta_over_np1(np1) + series.s_z1));
        }
        (series.scale.is_finite() && series.s_z1.is_finite()).then_some(series)
    }

    /// x at `z = s/s0`, m.
    pub(super) fn x_of_z(&self, z: f64) -> f64 {
        self.s0 * (z - 1.0) / self.b
    }

    /// Whether the contact forces hold over `[z1, z_end]` of the series
    /// (the corners of the module doc).
    pub(super) fn contact_holds_between(&self, z1: f64, z_end: f64) -> bool {
        let ends = [z1, z_end];
        let per_area = ends.map(|z| self.at(self.x_of_z(z)) / (self.s0 * z));
        ends.iter().all(|&z| {
            per_area
                .iter()
                .all(|&p| self.contact_holds(self.x_of_z(z), p * self.s0 * z))
        })
    }
}

/// `B(a, 1/2)/(n + 1)` of (T3), `a = −1/(2(n+1))`. It depends on the
/// model only, so each thread keeps the last one: a sweep of one model
/// evaluates Γ once per thread, not once per row (the value is the same
/// either way).
fn beta_over_np1(np1: f64) -> f64 {
    thread_local! {
        static LAST: Cell<(u64, f64)> = const { Cell::new((u64::MAX, 0.0)) };
    }
    LAST.with(|last| {
        let (key, value) = last.get();
        if key == np1.to_bits() {
            return value;
        }
        let a = -0.5 / np1;
        let value = libm::tgamma(a) * PI.sqrt() / libm::tgamma(a + 0.5) / np1;
        last.set((np1.to_bits(), value));
        value
    })
}

impl Series {
    /// S(z) of (T2).
    fn antiderivative(&self, z: f64) -> f64 {
        self.antiderivative_at(z, z.powf_p(-self.np1))
    }

    /// S(z) of (T2), given `z_pow = z^(−(n+1))`.
    fn antiderivative_at(&self, z: f64, z_pow: f64) -> f64 {
        let eps = self.beta * z_pow;
        let mut coeff = 1.0;
        let mut sum = 2.0;
        for k in 1..=MAX_TERMS {
            let k = f64::from(k);
            coeff *= -eps * (2.0 * k - 1.0) / (2.0 * k);
            let term = coeff / (0.5 - k * self.np1);
            sum += term;
            if term.abs() <= TERM_RTOL * sum.abs() {
                break;
            }
        }
        z.sqrt() * sum
    }

    /// t(Z) − t(z1), s.
    pub(super) fn time_from_z1(&self, z: f64) -> f64 {
        self.scale * (self.antiderivative(z) - self.s_z1)
    }

    /// dt/dy at `y = √z`: `2c/√(1 + β z^(−(n+1)))` from (T1), given
    /// `z_pow = z^(−(n+1))`.
    fn dt_dy(&self, z_pow: f64) -> f64 {
        2.0 * self.scale / (1.0 + self.beta * z_pow).sqrt()
    }

    /// The `z ≥ z1` at which `t(z1) + t(Z) − t(z1) = t_end`, given
    /// `t1 = t(z1) < t_end`: Newton's method in `y = √z`, in which t is
    /// nearly linear (dt/dy → 2c), kept above the last point found short.
    pub(super) fn solve_time(&self, t1: f64, t_end: f64) -> Option<f64> {
        const MAX_NEWTON: usize = 60;
        const STEP_RTOL: f64 = 1e-14;
        let mut short = self.z1.sqrt();
        let mut y = short + (t_end - t1) / (2.0 * self.scale);
        for _ in 0..MAX_NEWTON {
            // z^(−(n+1)) once for both t and dt/dy (the same bits as two calls).
            let z = y * y;
            let z_pow = z.powf_p(-self.np1);
            let g = t1 + self.scale * (self.antiderivative_at(z, z_pow) - self.s_z1) - t_end;
            if g < 0.0 {
                short = short.max(y);
            }
            let next = y - g / self.dt_dy(z_pow);
            if !next.is_finite() {
                return None;
            }
            if (next - y).abs() <= STEP_RTOL * y {
                return Some(next.max(short) * next.max(short));
            }
            y = if next > short {
                next
            } else {
                0.5 * (short + y)
            };
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::super::ContactCheck;
    use super::*;
    use crate::models::Derivation;
    use crate::scenario::{Scenario, ScenarioFile};

    /// t(z1) + (T2) equals the adaptive quadrature of dt = dx/√u from the
    /// start (an independent computation of the same integral, good to
    /// about 1e-13) at points from just past z1 to far out, for the models
    /// without lift, from rest and moving (β from −1 to well above 1).
    /// Tolerance 1e-12: the quadrature's per-panel 1e-13, summed.
    #[test]
    fn series_time_matches_the_quadrature() {
        const AGREE: f64 = 1e-12;
        let no_contact = ContactCheck {
            stop_on_hop: false,
            mu: None,
        };
        let models = [
            Derivation::TorqueAboutCentre,
            Derivation::TorqueAboutContact,
            Derivation::QuasiCircular,
        ];
        for d in models {
            for (alpha, b, v0) in [
                (30.0, 0.01, 0.0),
                (60.0, 0.2, 0.0),
                (10.0, 0.05, 3.0),
                (45.0, 0.01, 1.0),
            ] {
                let s = Scenario::new(ScenarioFile {
                    alpha_deg: alpha,
                    snow_depth: b,
                    v0,
                    ..ScenarioFile::default()
                })
                .unwrap();
                let u = SpeedSquared::new(&d.coefficients(), &s, no_contact).unwrap();
                let sr = u.series().unwrap();
                let w1 = u.x_of_z(sr.z1).sqrt();
                let t1 = u.time_between(0.0, w1);
                for factor in [1.0 + 1e-6, 1.5, 4.0, 100.0, 1e4] {
                    let z = sr.z1 * factor;
                    let by_series = t1 + sr.time_from_z1(z);
                    let by_quadrature = t1 + u.time_between(w1, u.x_of_z(z).sqrt());
                    assert!(
                        (by_series - by_quadrature).abs() <= AGREE * by_quadrature,
                        "{d:?} alpha {alpha} b {b} v0 {v0} z {z}: {by_series} vs {by_quadrature}"
                    );
                    // And Newton finds z back from its time.
                    let back = sr.solve_time(t1, by_series).unwrap();
                    assert!((back - z).abs() <= 1e-12 * z, "{d:?}: z {z} back {back}");
                }
            }
        }
    }

    /// From rest, t(z1) of (T3) equals the quadrature of dt from the start
    /// (to its 1e-12), for the three exponents n = 7/3, 3, 1 and two
    /// slopes and depths.
    #[test]
    fn t3_time_from_rest_matches_the_quadrature() {
        const AGREE: f64 = 1e-12;
        let contact = ContactCheck {
            stop_on_hop: true,
            mu: None,
        };
        for d in [
            Derivation::TorqueAboutCentre,
            Derivation::TorqueAboutContact,
            Derivation::QuasiCircular,
        ] {
            for (alpha, b) in [(30.0, 0.01), (60.0, 0.2)] {
                let s = Scenario::new(ScenarioFile {
                    alpha_deg: alpha,
                    snow_depth: b,
                    ..ScenarioFile::default()
                })
                .unwrap();
                let u = SpeedSquared::new(&d.coefficients(), &s, contact).unwrap();
                let sr = u.series().unwrap();
                let t3 = sr.t_z1.unwrap();
                let quad = u.time_between(0.0, u.x_of_z(sr.z1).sqrt());
                assert!((t3 - quad).abs() <= AGREE * quad, "{d:?}: {t3} vs {quad}");
            }
        }
    }

    /// Models with lift or the inertia term have no series.
    #[test]
    fn only_models_without_lift_have_a_series() {
        let s = Scenario::new(ScenarioFile::default()).unwrap();
        let contact = ContactCheck {
            stop_on_hop: true,
            mu: None,
        };
        for d in [
            Derivation::Energy,
            Derivation::EnergyLinearised,
            Derivation::LagrangianPrinted,
            Derivation::QuasiCircularLift,
            Derivation::Snowless,
        ] {
            let u = SpeedSquared::new(&d.coefficients(), &s, contact).unwrap();
            assert!(u.series().is_none(), "{d:?}");
        }
    }
}
