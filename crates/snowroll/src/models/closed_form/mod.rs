//! The closed-form solver of the circular equations of motion: the speed in
//! closed form, the time by quadrature and a series, no ODE solver. It is
//! Loney's solution of eq. (4) (fn. 4, [`LoneyModel`]) and the sweep's fast
//! path ([`circular_end`]) for every circular model.
//!
//! Every circular equation of motion has the common form of
//! [`crate::models::Coefficients`]. With `u = v²`, `du/dx = 2a`,
//! `s = π r² = s0 + b x` (eq. (8)), `ds = b dx`, it reads
//!
//! `(du/ds)(s + k) = (2/b)(P s − D u − L √s − M)`,
//!
//! with `P = G/(1 + k)` (2G/3 for the log, 5G/7 for the ball on its natural
//! swath 2r, [`crate::scenario::Shape::push_ratio`]), `D = c_v b`, `L = λ₁ C b/√π`, `M = λ₂ C b²/3` and
//! `k = κ b²/(6π)` (G = g sin α, C = g cos α): a linear first-order equation
//! in u. (Here k is the inertia term; the body's k = I/(M r²) enters only
//! through P.) For eq. (4), L = M = k = 0 and n = 7/3 on the log, n = 23/7 on
//! the ball (`docs/snowball-and-losses.md` §1.4), and (F1) is fn. 4:
//! `u = v0² (s0/s)^n + 2P/(1+n) · (s0/b) [s/s0 − (s0/s)^n]`. With `n = 2D/b = 2c_v` its integrating factor is `(s + k)^n`:
//!
//! `F(s) = u (s + k)^n = u0 (s0 + k)^n + (2/b) ∫_{s0}^{s} (Pσ − L√σ − M)(σ + k)^{n−1} dσ`.  (F1)
//!
//! The integral is elementary in the two cases the models need:
//!
//! - `k = 0` (every model but eqs. (14) and (21)), any n: with
//!   `q = ln(s/s0)`, `m = (s0/s)^n − 1`, `ρ = √(s/s0)`,
//!   `u = (1 + m) u0 + (2 s0/b) [P (s/s0 − 1 − m)/(n+1) − (L/√s0)(ρ − 1 − m)/(n+½) + (M/s0) m/n]`.
//!   Each difference is a sum of two terms of one sign (`−m ≥ 0`), computed
//!   from `ln_1p` and `exp_m1`: no cancellation near the start.
//! - `k ≠ 0` with n a small whole number (eq. (14): n = 1; eq. (21) as
//!   printed: n = 2): with `σ = s0 τ²` the integrand of (F1) is a polynomial
//!   in τ, `Σ c_j τ^j`, and `∫_1^ρ τ^j dτ = (ρ − 1)(1 + ρ + … + ρ^j)/(j + 1)`.
//!
//! The log stalls where F = 0. F' has the sign of `P s − L √s − M`, which
//! is negative below `√s* = (L + √(L² + 4PM))/(2P)` and positive above, so
//! F is least at `max(s0, s*)`; where that minimum is not comfortably above
//! zero (a stall, or a start from rest on a slope too gentle, fn. 7) the
//! ODE path is used instead.
//!
//! Time is `t(x) = ∫ dx/√u`. In `w = √x` it is `∫ 2w dw/√u(w²)`, whose
//! integrand is smooth also at a start from rest (u ≈ 2 a0 x there). The
//! integrand's complex singularities lie at distances of order
//! `√(s0/b)` and `√(v0²/2P)` from the origin, so panels that double in
//! length from the smaller of these need few Gauss–Kronrod points each. The
//! time `t_end` is reached by Newton's method in the panel that contains it.
//!
//! For the models without lift and inertia term (eqs. (4), (6), (32)) the
//! panels stop soon after the start: beyond it t is a convergent series in
//! `s^(−(n+1))` (submodule `series`), and Newton's method runs on that series.
//!
//! Submodules: `series` (that series), `end` (where a run ends, the sweep's
//! [`circular_end`]), `clock` (t(x) and x(t) at any point, for samples) and
//! `loney` ([`LoneyModel`], [`DragOnlyClosedForm`]: contact events located
//! by a scan, and the samples).

use crate::portable::Portable as _;
use std::cell::Cell;
use std::f64::consts::PI;

use crate::models::Coefficients;
use crate::quadrature::kronrod;
use crate::scenario::Scenario;

mod clock;
mod end;
mod loney;
mod series;

pub use end::{circular_end, FastEnd};
pub use loney::{DragOnlyClosedForm, LoneyModel};

/// Largest whole n = 2c_v handled with the inertia term k ≠ 0 (eq. (21)
/// as printed has n = 2): the polynomial of (F1) has degree 2n + 1.
const MAX_POLY_N: usize = 4;
/// Coefficients of that polynomial.
const POLY_LEN: usize = 2 * MAX_POLY_N + 2;

/// Relative accuracy asked of each panel's quadrature: three orders above
/// f64 rounding, so that t, x and v are good to about 1e-12, well within
/// the 1e-9 to which the ODE path is checked against them.
const QUAD_RTOL: f64 = 1e-13;
/// Bisections allowed in one panel (a smooth panel needs none or a few).
const MAX_BISECTIONS: u32 = 60;
/// The fast path is not used below this minimum of u over its initial
/// speed squared: near a stall the integrand peaks and the ODE path, which
/// also finds the stall, is the better tool.
const MIN_U_OVER_U0: f64 = 0.01;
/// Below this growth b x/s0 of the cross-section, (s0/s)^n − 1 is computed
/// with `exp_m1`: above it its magnitude exceeds 1 − 1.25^(−n) ≥ 0.2 for
/// every model (n ≥ 1), so `exp(..) − 1` costs at most two bits of its
/// relative accuracy there.
const EXP_M1_BELOW: f64 = 0.25;
/// Intervals shorter than this fraction of w take the 5-point Gauss rule
/// (the later Newton steps).
const SHORT: f64 = 1e-3;
/// 5-point Gauss–Legendre nodes and weights on [−1, 1], the symmetric half
/// (the centre first; it is counted twice by the sum and once subtracted).
const GAUSS5: [(f64, f64); 3] = [
    (0.0, 0.568_888_888_888_888_9),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];
/// The least normal force, and friction margin over μ, of a run on the
/// fast path, as a fraction of M g cos α: far enough from a hop or a slip
/// that none can hide between two quadrature nodes.
const CONTACT_MARGIN: f64 = 0.05;
/// Panels before giving up (each doubles w, so 2^200 times the first).
const MAX_PANELS: usize = 200;
/// Newton iterations before giving up.
const MAX_NEWTON: usize = 60;
/// Newton stops when its step is below this fraction of w: t is known to
/// about [`QUAD_RTOL`], so w cannot be pinned down any closer than that and
/// smaller steps would chase the quadrature's rounding.
const NEWTON_RTOL: f64 = 1e-14;

/// How u depends on s.
#[derive(Debug, Clone, Copy)]
enum Form {
    /// No snow collected (or b = 0): constant acceleration P.
    Constant,
    /// k = 0: `P`, `L/√s0`, `M/s0` and n.
    Power { p: f64, l: f64, m: f64, n: f64 },
    /// k ≠ 0, whole n: suffix sums `D_i = Σ_{j ≥ i} c_j/(j + 1)` of the
    /// polynomial of (F1), `u0 (s0 + k)^n`, k and n.
    Poly {
        suffix: [f64; POLY_LEN],
        f0: f64,
        k: f64,
        n: i32,
    },
}

/// The speed squared `u(x) = v(x)²` of one circular model in one scenario,
/// from (F1).
#[derive(Debug, Clone)]
pub struct SpeedSquared {
    form: Form,
    /// s0 = π r0², m².
    s0: f64,
    /// b, m.
    b: f64,
    /// v0², m²/s².
    u0: f64,
    /// P = G/(1 + k): 2G/3 (log) or 5G/7 (ball), m/s².
    push: f64,
    /// √s* of the module doc (0 without lift), m.
    sqrt_s_min: f64,
    /// G = g sin α and C = g cos α, m/s².
    g_along: f64,
    g_normal: f64,
    /// D = c_v b (m), L (m²/s²), M (m³/s²) and k (m²) of the module doc.
    drag: f64,
    lift: f64,
    lift_b2: f64,
    inertia: f64,
    /// (n − 1)/2 and n/2 for M ∝ rⁿ: the coefficients of q in N/M and F/M
    /// (½ and 1 for the log, 1 and 3/2 for the ball).
    normal_q: f64,
    friction_q: f64,
    /// What the contact forces must not do.
    contact: ContactCheck,
    /// Cleared when a node of the quadrature comes near a hop or a slip.
    contact_ok: Cell<bool>,
    /// The last `(x, u(x))` of [`SpeedSquared::at`], as bits: the end of a
    /// run is asked for twice (its contact check, its speed).
    last_at: Cell<Option<(u64, f64)>>,
}

/// The contact events the run watches for ([`crate::SimOptions::on_hop`],
/// [`crate::SimOptions::mu`]). The fast path does not locate them: it checks
/// at every quadrature node (dense on the scale on which the forces change)
/// that the normal force N and the friction margin μN − |F| stay above
/// `CONTACT_MARGIN` of M g cos α, and leaves the run to the ODE otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactCheck {
    /// Whether N = 0 (a hop) would end the run.
    pub stop_on_hop: bool,
    /// The coefficient of friction whose slip would end the run, if any.
    pub mu: Option<f64>,
}

impl SpeedSquared {
    /// The closed form of `c` in `scenario`, or `None` where (F1) is not
    /// elementary here (k ≠ 0 and n not a whole number up to 4) or does not
    /// hold: coefficients of another shape than the scenario's, a `b³`
    /// drag term (`drag_b3`, the ball's energy models), or a ball whose
    /// fixed swath breaks the area law π r² = π r0² + b x.
    pub fn new(
        c: &Coefficients,
        scenario: &Scenario,
        contact: ContactCheck,
    ) -> Option<SpeedSquared> {
        let u = Self::with_power_form(c, scenario, contact)?;
        if u.inertia == 0.0 || u.b == 0.0 {
            return Some(u);
        }
        let (n, s0, k) = (2.0 * c.drag, u.s0, u.inertia);
        let form = poly_form(u.push, u.lift, u.lift_b2, s0, k, n, u.u0)?;
        Some(SpeedSquared {
            form,
            last_at: Cell::new(None),
            ..u
        })
    }

    /// As [`new`](Self::new), with the form of k = 0 (the inertia term
    /// left out of u, not of the acceleration): `None` only where (F1)
    /// does not hold.
    fn with_power_form(
        c: &Coefficients,
        scenario: &Scenario,
        contact: ContactCheck,
    ) -> Option<SpeedSquared> {
        let shape = scenario.shape();
        if c.shape != shape || c.drag_b3 != 0.0 || !scenario.has_common_form() {
            return None;
        }
        let b = if c.accretes {
            scenario.snow_depth()
        } else {
            0.0
        };
        let r0 = scenario.initial_radius();
        let s0 = PI * r0 * r0;
        let gc = scenario.g_normal();
        let (num, den) = shape.push_ratio();
        let push = num * scenario.g_along() / den;
        let mass_n = shape.mass_exponent();
        let u0 = scenario.initial_speed().powi(2);
        let big_l = c.lift * gc * b / PI.sqrt();
        let big_m = c.lift_b2 * gc * b * b / 3.0;
        let k = c.inertia_b2 * b * b / (6.0 * PI);
        let n = 2.0 * c.drag;
        let sqrt_s_min = (big_l + (big_l * big_l + 4.0 * push * big_m).sqrt()) / (2.0 * push);
        let form = if b == 0.0 {
            Form::Constant
        } else {
            Form::Power {
                p: push,
                l: big_l / s0.sqrt(),
                m: big_m / s0,
                n,
            }
        };
        Some(SpeedSquared {
            form,
            s0,
            b,
            u0,
            push,
            sqrt_s_min,
            g_along: scenario.g_along(),
            g_normal: gc,
            drag: c.drag * b,
            lift: big_l,
            lift_b2: big_m,
            inertia: k,
            normal_q: (mass_n - 1.0) / 2.0,
            friction_q: mass_n / 2.0,
            contact,
            contact_ok: Cell::new(true),
            last_at: Cell::new(None),
        })
    }

    /// u = v² after rolling `x`, m²/s².
    pub fn at(&self, x: f64) -> f64 {
        if let Some((key, u)) = self.last_at.get() {
            if key == x.to_bits() {
                return u;
            }
        }
        let u = self.at_uncached(x);
        self.last_at.set(Some((x.to_bits(), u)));
        u
    }

    /// [`SpeedSquared::at`], computed.
    fn at_uncached(&self, x: f64) -> f64 {
        let (s0, b) = (self.s0, self.b);
        match self.form {
            Form::Constant => self.u0 + 2.0 * self.push * x,
            Form::Power { p, l, m, n } => {
                let growth = b * x / s0;
                // em = (s0/s)^n − 1 ∈ (−1, 0]. Away from the start
                // |em| ≥ 1 − (1 + EXP_M1_BELOW)^(−n) is not small, and
                // exp(), cheaper than exp_m1(), loses nothing to the − 1.
                let em = if growth < EXP_M1_BELOW {
                    (-n * growth.ln_1p_p()).exp_m1_p()
                } else {
                    (-n * (1.0 + growth).ln_p()).exp_p() - 1.0
                };
                let mut bracket = p * (growth - em) / (n + 1.0);
                if l != 0.0 || m != 0.0 {
                    let rho_m1 = growth / ((1.0 + growth).sqrt() + 1.0);
                    bracket += -l * (rho_m1 - em) / (n + 0.5) + m * em / n;
                }
                (1.0 + em) * self.u0 + 2.0 * s0 / b * bracket
            }
            Form::Poly { suffix, f0, k, n } => {
                let growth = b * x / s0;
                let rho = (1.0 + growth).sqrt();
                let rho_m1 = growth / (rho + 1.0);
                let horner = suffix.iter().rev().fold(0.0, |acc, d| acc * rho + d);
                let f = f0 + 2.0 / b * rho_m1 * horner;
                f / (s0 + b * x + k).powi(n)
            }
        }
    }

    /// Whether u stays comfortably positive for every x ≥ 0 (the module
    /// doc): the least u, at `s*` when that lies beyond s0, is at least
    /// [`MIN_U_OVER_U0`] of u0; from rest, the log must accelerate at once.
    fn never_stalls(&self) -> bool {
        let s_min = self.sqrt_s_min * self.sqrt_s_min;
        if matches!(self.form, Form::Constant) || s_min <= self.s0 {
            // u grows from u0; from rest it needs a(0) > 0, i.e. s* < s0.
            return self.u0 > 0.0 || s_min < self.s0;
        }
        let x_min = (s_min - self.s0) / self.b;
        self.at(x_min) >= MIN_U_OVER_U0 * self.u0 && self.u0 > 0.0
    }

    /// 2w/√u(w²): the integrand of t in w = √x; checks the contact forces
    /// there.
    fn dt_dw(&self, w: f64) -> f64 {
        let x = w * w;
        let u = self.at(x);
        if !self.contact_holds(x, u) {
            self.contact_ok.set(false);
        }
        2.0 * w / u.sqrt()
    }

    /// The acceleration `a = (P − D u/s − L/√s − M/s)/(1 + k/s)` of the
    /// common form at `x` with `v² = u`, m/s² (`½ du/dx` when u = u(x)).
    fn acceleration_at(&self, x: f64, u: f64) -> f64 {
        let s = self.s0 + self.b * x;
        (self.push - self.drag * u / s - self.lift / s.sqrt() - self.lift_b2 / s)
            / (1.0 + self.inertia / s)
    }

    /// The acceleration after rolling `x` on the closed form, m/s².
    pub fn acceleration(&self, x: f64) -> f64 {
        self.acceleration_at(x, self.at(x))
    }

    /// Whether N and μN − |F| (`docs/contact-forces.md` §2, as
    /// [`crate::circular_forces`]: `N/M = C + b(a + (n−1)q/2)/(2πr)`,
    /// `F/M = G − a − n q/2`, q = b v²/(π r²), M ∝ rⁿ: `a + q/2` and `q`
    /// for the log) are at least [`CONTACT_MARGIN`] C at (x, v² = u), for
    /// the events the run watches.
    fn contact_holds(&self, x: f64, u: f64) -> bool {
        let c = &self.contact;
        if !c.stop_on_hop && c.mu.is_none() {
            return true;
        }
        let s = self.s0 + self.b * x;
        let a = self.acceleration_at(x, u);
        let q = self.b * u / s;
        let r = (s / PI).sqrt();
        let normal = self.g_normal + self.b / (2.0 * PI * r) * (a + self.normal_q * q);
        let friction = self.g_along - a - self.friction_q * q;
        let margin = CONTACT_MARGIN * self.g_normal;
        let hop_ok = !c.stop_on_hop || normal >= margin;
        let slip_ok =
            c.mu.is_none_or(|mu| mu * normal - friction.abs() >= mu * margin);
        hop_ok && slip_ok
    }

    /// The first panel's end in w: the smaller of the scales on which u
    /// changes its form, √(s0/b) and √(u0/(2P)).
    fn first_panel(&self) -> f64 {
        let snow = if self.b > 0.0 {
            (self.s0 / self.b).sqrt()
        } else {
            f64::INFINITY
        };
        let speed = (self.u0 / (2.0 * self.push)).sqrt();
        let w = if speed > 0.0 { snow.min(speed) } else { snow };
        if w.is_finite() {
            w
        } else {
            1.0
        }
    }

    /// ∫ dt from w = a to w = b (either order).
    fn time_between(&self, a: f64, b: f64) -> f64 {
        let mut f = |w: f64| self.dt_dw(w);
        let (lo, hi, sign) = if a <= b { (a, b, 1.0) } else { (b, a, -1.0) };
        if hi - lo <= SHORT * lo {
            // 5-point Gauss–Legendre: f varies on the scale of w itself, so
            // its error, of order (h/w)^10 relative, is below 1e-30 here.
            let (c, h) = (0.5 * (lo + hi), 0.5 * (hi - lo));
            let sum: f64 = GAUSS5
                .iter()
                .map(|&(node, weight)| weight * (f(c - h * node) + f(c + h * node)))
                .sum::<f64>()
                - GAUSS5[0].1 * f(c);
            return sign * h * sum;
        }
        let mut budget = MAX_BISECTIONS;
        sign * adaptive(&mut f, lo, hi, &mut budget)
    }
}

/// The form of (F1) for k ≠ 0 and a whole n up to [`MAX_POLY_N`]: with
/// σ = s0 τ² its integrand is the polynomial `(P s0 τ² − L √s0 τ − M)(s0 τ²
/// + k)^{n−1} · 2 s0 τ`, kept as the suffix sums of its coefficients over
/// j + 1; `None` for any other n.
fn poly_form(push: f64, big_l: f64, big_m: f64, s0: f64, k: f64, n: f64, u0: f64) -> Option<Form> {
    let whole = n.round();
    if (n - whole).abs() > 1e-12 || !(1.0..=MAX_POLY_N as f64).contains(&whole) {
        return None;
    }
    let n = whole as i32;
    let mut c = [0.0; POLY_LEN];
    c[0] = -big_m;
    c[1] = -big_l * s0.sqrt();
    c[2] = push * s0;
    let mut degree = 2;
    for _ in 1..n {
        for j in (0..=degree + 2).rev() {
            let keep = if j <= degree { k * c[j] } else { 0.0 };
            let raised = if j >= 2 { s0 * c[j - 2] } else { 0.0 };
            c[j] = keep + raised;
        }
        degree += 2;
    }
    for j in (0..=degree).rev() {
        c[j + 1] = 2.0 * s0 * c[j];
    }
    c[0] = 0.0;
    degree += 1;
    let mut suffix = [0.0; POLY_LEN];
    let mut sum = 0.0;
    for j in (0..=degree).rev() {
        sum += c[j] / (j as f64 + 1.0);
        suffix[j] = sum;
    }
    Some(Form::Poly {
        suffix,
        f0: u0 * (s0 + k).powi(n),
        k,
        n,
    })
}

/// ∫ₗₒʰⁱ f by the 15-point Kronrod rule, bisected where QUADPACK's error
/// estimate `(200 |K − G|)^{3/2}` (relative) exceeds [`QUAD_RTOL`].
fn adaptive(f: &mut impl FnMut(f64) -> f64, lo: f64, hi: f64, budget: &mut u32) -> f64 {
    let (value, diff) = kronrod(f, lo, hi);
    let scale = value.abs().max(f64::MIN_POSITIVE);
    let err = (200.0 * diff / scale).powf_p(1.5);
    if err <= QUAD_RTOL || *budget == 0 || !err.is_finite() {
        return value;
    }
    *budget -= 1;
    let mid = 0.5 * (lo + hi);
    adaptive(f, lo, mid, budget) + adaptive(f, mid, hi, budget)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::Derivation;
    use crate::scenario::ScenarioFile;

    fn scenario(alpha: f64, b: f64, v0: f64) -> Scenario {
        Scenario::new(ScenarioFile {
            alpha_deg: alpha,
            snow_depth: b,
            v0,
            ..ScenarioFile::default()
        })
        .unwrap()
    }

    /// u(x) solves du/dx = 2a(x, √u): checked by central differences with
    /// step h = 1e-4 x, whose error (h² u'''/6 against u') is below 1e-8
    /// relative for these smooth u.
    #[test]
    fn closed_form_solves_the_equation_of_motion() {
        const FD_TOL: f64 = 1e-7;
        let all = [
            Derivation::TorqueAboutCentre,
            Derivation::TorqueAboutContact,
            Derivation::Energy,
            Derivation::EnergyLinearised,
            Derivation::LagrangianPrinted,
            Derivation::QuasiCircular,
            Derivation::QuasiCircularLift,
        ];
        for d in all {
            let c = d.coefficients();
            for (alpha, b, v0) in [(30.0, 0.01, 0.0), (60.0, 0.2, 0.0), (10.0, 0.05, 3.0)] {
                let s = scenario(alpha, b, v0);
                let u = SpeedSquared::new(
                    &c,
                    &s,
                    ContactCheck {
                        stop_on_hop: false,
                        mu: None,
                    },
                )
                .unwrap();
                assert!((u.at(0.0) - v0 * v0).abs() < 1e-14, "{d:?}");
                for x in [1e-3, 0.1, 1.0, 10.0, 1e3] {
                    let h = 1e-4 * x;
                    let du = (u.at(x + h) - u.at(x - h)) / (2.0 * h);
                    let want = 2.0 * c.acceleration(&s, x, u.at(x).sqrt());
                    assert!(
                        (du - want).abs() <= FD_TOL * want.abs().max(1e-3),
                        "{d:?} alpha {alpha} b {b} x {x}: {du} vs {want}"
                    );
                }
            }
        }
    }
}

#[cfg(test)]
mod gauss_tests {
    use super::*;

    /// Regression of issue 7 (fuzzing): `simulate --model loney --v0 1e308`
    /// hung, its integrand overflowing so that no interval ever met its
    /// tolerance and the bisection tree grew to 2^40 leaves. The bisection
    /// budget bounds the effort of one panel.
    #[test]
    fn regression_7_an_integrand_that_never_converges_costs_a_bounded_effort() {
        for f in [
            (|x: f64| if x > 0.5 { f64::INFINITY } else { x }) as fn(f64) -> f64,
            |_| f64::NAN,
            // Not integrable at 0: the error estimate never meets the tolerance.
            |x| 1.0 / x,
        ] {
            let mut calls = 0u64;
            let mut budget = MAX_BISECTIONS;
            let mut g = |x| {
                calls += 1;
                f(x)
            };
            let _ = adaptive(&mut g, 0.0, 1.0, &mut budget);
            assert!(
                calls <= 15 * (2 * u64::from(MAX_BISECTIONS) + 1),
                "{calls} evaluations"
            );
        }
    }

    /// The 5-point rule integrates polynomials of degree 9 exactly (to
    /// rounding of a 5-term sum).
    #[test]
    fn gauss5_is_exact_to_degree_9() {
        for k in 0..=9 {
            let sum: f64 = GAUSS5
                .iter()
                .map(|&(x, w)| w * (x.powi(k) + (-x).powi(k)))
                .sum::<f64>()
                - GAUSS5[0].1 * 0f64.powi(k);
            let want = if k % 2 == 0 {
                2.0 / (k as f64 + 1.0)
            } else {
                0.0
            };
            assert!((sum - want).abs() < 1e-15, "degree {k}: {sum} vs {want}");
        }
    }
}
