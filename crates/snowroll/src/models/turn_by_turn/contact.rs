//! Contact forces within a turn of §3.4 (`docs/contact-forces.md` §3).
//!
//! During turn k the body (disk of radius r = r_k plus the annular sector
//! of the snow picked up) rotates rigidly about the contact line C at rate
//! θ̇, so its momentum is `p = θ̇ (S_y, −S_x)` with the first moment about C,
//! per unit m_k, `S_x/m_k = −e₂(1 − cos θ)`, `S_y/m_k = r(1 + μθ) − e₂ sin θ`.
//! Differentiating along the motion and using the momentum balance of the
//! accreting body (`N = dp_y/dt + M C`, `F = M G − dp_x/dt`):
//!
//! `N/m_k = (1 + μθ) C + e₂ [θ̈ (1 − cos θ) + θ̇² sin θ]`
//!
//! `F/m_k = (1 + μθ) G − θ̈ [r(1 + μθ) − e₂ sin θ] − θ̇² (e₁ − e₂ cos θ)`
//!
//! with the coefficients μ, e₁, e₂ of [`InTurnCoefficients`](super::InTurnCoefficients)
//! (μ r = e₁ in both variants) and θ̈ the model's own (eq. (64), the
//! energy equation). Exact for the `Exact` variant, first order in b/r for
//! `Paper`. As b → 0: N = m C, F = m G/3 (App. A).

use crate::portable::Portable as _;
use std::cell::Cell;
use std::sync::OnceLock;

use super::jet::{Jet, Real};
use super::{extremes, TurnDynamics, TWO_PI};
use crate::models::contact::ContactForces;
use crate::units::Radians;

/// Grid intervals over a turn that bracket the extremes of N(θ) and of
/// |F|/N(θ): each has one minimum and one maximum per turn in late turns
/// (N ≈ C + (G/2) sin θ, §4.2), so 32 intervals of 0.2 rad leave margin for
/// the skewed early turns.
const FORCE_GRID: usize = 32;
/// Grid intervals over a turn whose θ̇² varies by less than
/// [`SMOOTH_SPREAD`] of its start value ([`TurnDynamics::is_smooth_turn`]):
/// a, N and F are then within that fraction of their late-turn forms
/// `A + B cos θ + C sin θ` (§4.2), one minimum and one maximum per turn
/// each, π apart, and 8 intervals of 0.79 rad bracket them as 32 do (the
/// refinement then searches the two intervals around the best sample).
const SMOOTH_GRID: usize = 8;
/// Largest variation of `I θ̇²` over a turn, as a fraction of its start
/// value, for [`SMOOTH_GRID`].
const SMOOTH_SPREAD: f64 = 0.05;
/// Absolute tolerance in θ of the refined extremes, rad (the value at the
/// extreme is then off by ~f″ · 1e-16).
const FORCE_THETA_TOL: f64 = 1e-8;

impl TurnDynamics {
    /// `(N, F)` per unit `m_k` at `(θ, θ̇)`, m/s² (module doc, `docs/contact-forces.md` §3).
    pub fn contact_per_mass(&self, theta: Radians, omega: f64) -> (f64, f64) {
        let (s, c) = super::sin_cos(theta);
        self.contact_per_mass_sc(theta, s, c, omega * omega)
    }

    /// [`Self::contact_per_mass`] from `sin θ`, `cos θ` and `θ̇²`.
    fn contact_per_mass_sc(&self, theta: f64, s: f64, c: f64, w2: f64) -> (f64, f64) {
        let k = &self.coeffs;
        let (i, di) = self.inertia_sc(theta, s, c);
        let alpha = (-self.potential_slope_sc(theta, s, c) - 0.5 * di * w2) / i;
        let grown = 1.0 + k.accretion * theta;
        let normal = grown * self.g_normal + k.e2 * (alpha * (1.0 - c) + w2 * s);
        let friction =
            grown * self.g_along - alpha * (self.r * grown - k.e2 * s) - w2 * (k.e1 - k.e2 * c);
        (normal, friction)
    }

    /// N and F on a log of start mass `m_k` (kg) at `(θ, θ̇)`.
    pub fn contact_forces(&self, m_k: f64, theta: Radians, omega: f64) -> ContactForces {
        let (n, f) = self.contact_per_mass(theta, omega);
        ContactForces {
            normal_n: m_k * n,
            friction_n: m_k * f,
        }
    }

    /// `(a, N, F)` at θ on the energy integral of a turn started with
    /// `θ̇(0) = omega0` (θ̇² clamped at 0 past a stall), from `sin θ`, `cos θ`:
    /// a in m/s², N and F per unit `m_k` in m/s². In any [`Real`]: values
    /// (`f64`), or values with their derivatives in θ ([`Jet`]) for Newton's
    /// method on the extremes.
    #[inline(always)]
    fn orbit_sc<T: Real>(&self, theta: T, s: T, c: T, omega0: f64) -> (T, T, T) {
        let k = &self.coeffs;
        let (g, c_n, r) = (self.g_along, self.g_normal, self.r);
        // I and I′ (`inertia_sc`), W and W′ (`potential_sc`), written in T.
        let i = (theta * k.c1 + 1.5 * r * r) - s * k.c2;
        let di = -(c * k.c2 - k.c1);
        let one_minus_cos = -(c - 1.0);
        let w = -(((theta * r) + theta * theta * (k.e1 / 2.0)) - one_minus_cos * k.e2) * g
            + (theta * k.e3 - s * k.e2) * c_n;
        let dw = -((theta * k.e1 + r) - s * k.e2) * g + (-(c * k.e2 - k.e3)) * c_n;
        let inv_i = i.recip();
        let w2 = ((-(w * 2.0) + 1.5 * r * r * omega0 * omega0) * inv_i).at_least_zero();
        let alpha = (-dw - di * w2 * 0.5) * inv_i;
        let grown = theta * k.accretion + 1.0;
        let normal = grown * c_n + (alpha * one_minus_cos + w2 * s) * k.e2;
        let friction = grown * g - alpha * (grown * r - s * k.e2) - w2 * (-(c * k.e2 - k.e1));
        (alpha * r, normal, friction)
    }

    /// [`Self::orbit_sc`] at θ with the first two derivatives in θ (inlined,
    /// so that a caller that uses one of the three computes only that one).
    #[inline(always)]
    fn orbit_jet(&self, theta: f64, omega0: f64) -> (Jet, Jet, Jet) {
        let (s, c) = super::sin_cos(theta);
        let (js, jc) = Jet::sin_cos(s, c);
        self.orbit_sc(Jet::variable(theta), js, jc, omega0)
    }

    /// `(a, N, F)` at θ on the energy integral ([`Self::orbit_sc`]).
    fn orbit(&self, theta: f64, omega0: f64) -> (f64, f64, f64) {
        let (s, c) = super::sin_cos(theta);
        self.orbit_sc(theta, s, c, omega0)
    }

    /// Over a turn started with `θ̇(0) = omega0`, for θ ∈ [0, `theta_max`],
    /// from the energy integral (no integration): the extremes of N and of
    /// |F|/N, and where N first reaches 0. The ratio is undefined (`None`)
    /// if N reaches 0.
    pub fn contact_range(&self, omega0: f64, theta_max: Radians) -> ContactRange {
        self.scan(omega0, theta_max, false, &mut Hints::default())
            .contact
    }

    /// The first θ in [0, `theta_max`] where N reaches 0 on the energy
    /// integral of a turn started with `θ̇(0) = omega0`, if any
    /// ([`ContactRange::first_zero_normal`]): found from N(θ), not from the
    /// steps of an integrator, so a dip of N below 0 narrower than a step is
    /// not stepped over and, for a given `omega0`, the answer does not
    /// depend on the tolerance (the integrator's path plans a hop its error
    /// could decide from the closed form's `θ̇(0)`, `docs/contact-forces.md` §4.4).
    pub fn first_hop(&self, omega0: f64, theta_max: Radians) -> Option<Radians> {
        self.contact_range(omega0, theta_max).first_zero_normal
    }

    /// [`Self::contact_range`] over the whole turn together with
    /// [`Self::acceleration_range`] (the same values, to the refinement's
    /// tolerance), from one grid: what each row of the turn table needs.
    pub fn turn_extremes(&self, omega0: f64) -> TurnExtremes {
        self.scan(omega0, std::f64::consts::TAU, true, &mut Hints::default())
    }

    /// [`Self::turn_extremes`] with Newton's method started where `hints`
    /// says the extremes of the turn before were (consecutive turns have
    /// theirs within ~1/k² rad of each other late in a run, one Newton step
    /// instead of two or three), and `hints` updated. A hint outside the
    /// grid interval next to this turn's sampled extreme is not used; the
    /// values are those of [`Self::turn_extremes`] to the refinement's
    /// accuracy, a few ulp.
    pub(crate) fn turn_extremes_hinted(&self, omega0: f64, hints: &mut Hints) -> TurnExtremes {
        self.scan(omega0, std::f64::consts::TAU, true, hints)
    }

    /// One grid of [`FORCE_GRID`] intervals over [0, `theta_max`]
    /// ([`SMOOTH_GRID`] where the turn is smooth) samples a, N, N/(M g) and
    /// |F|/N together ([`Self::samples`]); Newton's method on jets (Brent's
    /// method where it does not apply, [`extremes::refine_min_jet`]) then
    /// refines each wanted extreme from its own grid point, with one
    /// `sin_cos` per evaluation. The extremes of a are refined only if
    /// `with_a`. N is refined at every local minimum of its samples
    /// ([`Self::normal_minima`]), which also gives where N first reaches 0.
    fn scan(
        &self,
        omega0: f64,
        theta_max: Radians,
        with_a: bool,
        hints: &mut Hints,
    ) -> TurnExtremes {
        if self.is_smooth_turn(omega0, theta_max) {
            self.scan_on::<{ SMOOTH_GRID + 1 }>(omega0, theta_max, with_a, hints)
        } else {
            self.scan_on::<{ FORCE_GRID + 1 }>(omega0, theta_max, with_a, hints)
        }
    }

    /// a, −a, N, N/(M g), −|F|/N (each refined at its smallest) at the
    /// `POINTS` points `i step` of [`Self::scan_on`]'s grid (sin and cos by
    /// the rotation recurrence), in a loop without a dependence between its
    /// passes (the compiler runs two points at once).
    fn samples<const POINTS: usize>(&self, omega0: f64, step: f64, g: f64) -> [[f64; POINTS]; 5] {
        let mu = self.coeffs.accretion;
        let (sh, ch) = grid_rotation(step);
        let mut sin_cos = [(0.0, 1.0); POINTS];
        for i in 1..POINTS {
            let (s, c) = sin_cos[i - 1];
            sin_cos[i] = (s * ch + c * sh, c * ch - s * sh);
        }
        let mut samples = [[0.0; POINTS]; 5];
        for (i, &(s, c)) in sin_cos.iter().enumerate() {
            let theta = i as f64 * step;
            let (a, n, f) = self.orbit_sc(theta, s, c, omega0);
            let values = [a, -a, n, n / ((1.0 + mu * theta) * g), -f.abs() / n];
            for (row, value) in samples.iter_mut().zip(values) {
                row[i] = value;
            }
        }
        samples
    }

    /// [`Self::scan`] on a grid of `POINTS` points (its arrays on the stack,
    /// of that size).
    fn scan_on<const POINTS: usize>(
        &self,
        omega0: f64,
        theta_max: Radians,
        with_a: bool,
        hints: &mut Hints,
    ) -> TurnExtremes {
        let (mu, g) = (self.coeffs.accretion, self.g_along.hypot_p(self.g_normal));
        let step = theta_max / (POINTS - 1) as f64;
        let samples = self.samples::<POINTS>(omega0, step, g);
        let [a_s, neg_a_s, normal, mg_s, neg_ratio_s] = &samples;
        let [h_min, h_max, h_normal, h_mg, h_ratio] = &mut hints.theta;
        let (a_min, a_max) = if with_a {
            (
                refine(
                    |theta| self.orbit_jet(theta, omega0).0,
                    a_s,
                    step,
                    (h_min, None),
                ),
                -refine(
                    |theta| -self.orbit_jet(theta, omega0).0,
                    neg_a_s,
                    step,
                    (h_max, None),
                ),
            )
        } else {
            (f64::NAN, f64::NAN)
        };
        let (n_min, first_zero_normal, at_n_min) =
            self.normal_minima(omega0, normal, step, h_normal);
        // N/(M g) = N/((1 + μθ) g) has its minimum within ~μ N/N″ of N's: its
        // Newton's method starts from N's last evaluation (late in a run
        // that one is already within the step tolerance).
        let over_mg = |theta: f64, n: Jet| n / ((Jet::variable(theta) * mu + 1.0) * g);
        let min_normal_over_mg = refine(
            |theta| over_mg(theta, self.orbit_jet(theta, omega0).1),
            mg_s,
            step,
            (h_mg, at_n_min.map(|(theta, n)| (theta, over_mg(theta, n)))),
        );
        let max_friction_ratio = (n_min > 0.0).then(|| {
            -refine(
                |theta| {
                    let (_, n, f) = self.orbit_jet(theta, omega0);
                    -(f.abs() / n)
                },
                neg_ratio_s,
                step,
                (h_ratio, None),
            )
        });
        TurnExtremes {
            a_min,
            a_max,
            contact: ContactRange {
                min_normal_per_mk: n_min,
                min_normal_over_mg,
                max_friction_ratio,
                first_zero_normal,
            },
        }
    }

    /// Whether `I θ̇²` (= `I(0)θ̇₀² − 2W`, eq. (T1)) varies over [0,
    /// `theta_max`] by less than [`SMOOTH_SPREAD`] of its start value, by a
    /// bound on |W| term by term.
    fn is_smooth_turn(&self, omega0: f64, theta_max: Radians) -> bool {
        let k = &self.coeffs;
        let (g, c_n, r, t) = (self.g_along.abs(), self.g_normal.abs(), self.r, theta_max);
        let w_bound = g * (r * t + k.e1.abs() * t * t / 2.0 + 2.0 * k.e2.abs())
            + c_n * (k.e3.abs() * t + k.e2.abs());
        2.0 * w_bound < SMOOTH_SPREAD * 1.5 * r * r * omega0 * omega0
    }

    /// From the samples `normal[i]` of N at θ = i `step` on the energy
    /// integral: the smallest N, the first θ where N ≤ 0, if any, and the
    /// last evaluation of N (θ and N with its derivatives) in the
    /// refinement that found the smallest, where one did.
    ///
    /// Every local minimum of the samples (the first of a run of equal
    /// ones) is refined over its two intervals ([`extremes::refine_min_jet`];
    /// none is needed at θ = 0 where N rises, see below), so a dip
    /// of N below 0 that opens and closes between grid points is seen. In
    /// θ order, the first sample with N ≤ 0 or the first refined minimum
    /// with N ≤ 0 closes a bracket whose other end (the last grid point
    /// before it) has N > 0; bisection then narrows it until the two ends
    /// are adjacent doubles, and the end with N ≤ 0 is the hop.
    fn normal_minima(
        &self,
        omega0: f64,
        normal: &[f64],
        step: f64,
        hint: &mut Option<f64>,
    ) -> (f64, Option<Radians>, Option<(f64, Jet)>) {
        let n_at = |theta: f64| self.orbit(theta, omega0).1;
        let last = normal.len() - 1;
        let (mut n_min, mut first_zero, mut evaluated) = (f64::INFINITY, None, None);
        // The next turn starts from where the smallest minimum was (not an
        // end of the turn that is a minimum of the samples too).
        let (start, mut at_min) = (*hint, None);
        // N′(0) = μC + e₂θ̇₀² (the module doc's N at θ = 0, where sin θ = 0
        // and 1 − cos θ = 0 take out every other term): with each term ≥ 0
        // N does not fall after θ = 0, and a minimum of the samples there is
        // the end value itself, which the refinement would find from the
        // sign of that same sum (no evaluation needed).
        let k = &self.coeffs;
        let rises_at_start = k.accretion >= 0.0 && self.g_normal >= 0.0 && k.e2 >= 0.0;
        for (i, &n_i) in normal.iter().enumerate() {
            let theta_i = i as f64 * step;
            n_min = n_min.min(n_i);
            if first_zero.is_none() && n_i <= 0.0 {
                first_zero = Some(match i {
                    0 => 0.0,
                    _ => extremes::first_root(n_at, theta_i - step, theta_i),
                });
            }
            let local = (i == 0 || n_i < normal[i - 1]) && (i == last || n_i <= normal[i + 1]);
            if !local || (i == 0 && rises_at_start) {
                continue;
            }
            let latest = Cell::new(None);
            let (theta_m, n_m) = extremes::refine_min_jet(
                |theta| {
                    let n = self.orbit_jet(theta, omega0).1;
                    latest.set(Some((theta, n)));
                    n
                },
                (0.0, step),
                normal,
                i,
                (start, None),
                FORCE_THETA_TOL,
            );
            if n_m < n_min {
                evaluated = latest.get();
                at_min = Some(theta_m);
            }
            n_min = n_min.min(n_m);
            if first_zero.is_none() && n_m <= 0.0 {
                // N > 0 at every grid point up to θ_i (and θ_m ≥ θ_{i−1}).
                let lo = if theta_m > theta_i {
                    theta_i
                } else {
                    theta_i - step
                };
                first_zero = Some(extremes::first_root(n_at, lo, theta_m));
            }
        }
        if at_min.is_some() {
            *hint = at_min;
        }
        (n_min, first_zero, evaluated)
    }

    /// `(N, F)` per unit `m_k` on the energy integral ([`Self::orbit`]).
    fn contact_on_orbit(&self, theta: Radians, omega0: f64) -> (f64, f64) {
        let (_, n, f) = self.orbit(theta, omega0);
        (n, f)
    }
}

impl TurnDynamics {
    /// The first θ in [0, `theta_max`] where |F| reaches μN on the energy
    /// integral of a turn started with `θ̇(0) = omega0`, if any: a grid of
    /// 32 intervals brackets a crossing, or the neighbourhood of
    /// the largest sampled |F| − μN holds a narrow peak (golden section finds
    /// its top); bisection then narrows the crossing until its ends are
    /// adjacent doubles, and the end where |F| ≥ μN is the slip (the root
    /// of a margin of slope O(1) per rad, so to ~1e-15 rad).
    /// The slip event of a turn is `θ − θ_slip`, so that a peak of |F|/N
    /// barely above μ, narrower than a step, is not stepped over.
    pub fn first_slip(&self, omega0: f64, mu: f64, theta_max: Radians) -> Option<Radians> {
        let margin = |theta: f64| {
            let (n, f) = self.contact_on_orbit(theta, omega0);
            f.abs() - mu * n
        };
        let h = theta_max / FORCE_GRID as f64;
        // The crossing in (lo, hi], margin(lo) < 0 ≤ margin(hi): bisection
        // to adjacent doubles, as for the hop ([`extremes::first_root`] on
        // μN − |F|, which is ≤ 0 exactly where the log slips).
        let bisect = |lo: f64, hi: f64| extremes::first_root(|theta| -margin(theta), lo, hi);
        if margin(0.0) >= 0.0 {
            return Some(0.0);
        }
        let mut best = (0.0, f64::NEG_INFINITY);
        for i in 1..=FORCE_GRID {
            let theta = i as f64 * h;
            let m = margin(theta);
            if m >= 0.0 {
                return Some(bisect(theta - h, theta));
            }
            if m > best.1 {
                best = (theta, m);
            }
        }
        // No sampled point slips: look for a narrow peak around the largest sample.
        let (mut a, mut b) = ((best.0 - h).max(0.0), (best.0 + h).min(theta_max));
        const INV_PHI: f64 = 0.618_033_988_749_894_9;
        while b - a > FORCE_THETA_TOL {
            let (c, d) = (b - INV_PHI * (b - a), a + INV_PHI * (b - a));
            if margin(c) > margin(d) {
                b = d;
            } else {
                a = c;
            }
        }
        let top = 0.5 * (a + b);
        (margin(top) >= 0.0).then(|| bisect((best.0 - h).max(0.0), top))
    }
}

/// Where the extremes of the last turn were found: the starts of Newton's
/// method for the next ([`TurnDynamics::turn_extremes_hinted`]), for the
/// smallest and largest a, the smallest N, N/(M g) and the largest |F|/N.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Hints {
    theta: [Option<Radians>; 5],
}

/// Extremes of a, N and |F|/N over a whole turn, [`TurnDynamics::turn_extremes`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnExtremes {
    /// Smallest acceleration, m/s² (NaN where not asked for).
    pub a_min: f64,
    /// Largest acceleration, m/s² (NaN where not asked for).
    pub a_max: f64,
    /// Extremes of the contact forces.
    pub contact: ContactRange,
}

/// Extremes of the contact forces over (part of) a turn, [`TurnDynamics::contact_range`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactRange {
    /// Smallest N per unit m_k, m/s².
    pub min_normal_per_mk: f64,
    /// Smallest N/(M g), M = m_k(1 + μθ) the mass there.
    pub min_normal_over_mg: f64,
    /// Largest |F|/N; `None` (undefined) when N ≤ 0 somewhere in the range.
    pub max_friction_ratio: Option<f64>,
    /// The first θ of the range where N ≤ 0 (where the log hops, `docs/contact-forces.md`
    /// §4), to the rounding of θ; `None` when N > 0 throughout.
    pub first_zero_normal: Option<Radians>,
}

/// The smallest value of `h` near the smallest of its grid samples
/// `values` ([`extremes::refine_min_jet`]), Newton's method started from
/// `known` or `hint`, which becomes where this one was. Generic in `h`, so
/// that each function's evaluation is compiled with only the parts of
/// (a, N, F) it uses.
fn refine(
    h: impl Fn(f64) -> Jet,
    values: &[f64],
    step: f64,
    (hint, known): (&mut Option<f64>, Option<(f64, Jet)>),
) -> f64 {
    let i = extremes::least(values);
    let (theta, value) =
        extremes::refine_min_jet(h, (0.0, step), values, i, (*hint, known), FORCE_THETA_TOL);
    *hint = Some(theta);
    value
}

/// `(sin h, cos h)` of a grid step `h`: of a whole turn's two grids from a
/// table made once, else from the library (the same bits either way).
fn grid_rotation(step: f64) -> (f64, f64) {
    static TURN: OnceLock<[(f64, (f64, f64)); 2]> = OnceLock::new();
    let table = TURN.get_or_init(|| {
        [SMOOTH_GRID, FORCE_GRID].map(|n| {
            let h = TWO_PI / n as f64;
            (h, h.sin_cos_p())
        })
    });
    match table.iter().find(|(h, _)| h.to_bits() == step.to_bits()) {
        Some(&(_, sc)) => sc,
        None => step.sin_cos_p(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::TurnVariant;

    /// Rounding of a few operations on numbers of order g.
    const ROUNDING: f64 = 1e-13;

    #[test]
    fn b_to_zero_gives_the_snowless_forces() {
        let (g, c) = (4.905, 8.496_0);
        for variant in [TurnVariant::Paper, TurnVariant::Exact] {
            let turn = TurnDynamics::new(variant, 0.1, 0.0, g, c);
            for (theta, omega) in [(0.0, 0.0), (1.0, 3.0), (4.7, 20.0)] {
                let (n, f) = turn.contact_per_mass(theta, omega);
                assert!((n - c).abs() < ROUNDING * c);
                assert!((f - g / 3.0).abs() < ROUNDING * g);
            }
        }
    }

    /// Late turns, §4.2: with (b/π)θ̇² = G/2 the normal force is C + (G/2) sin θ
    /// to O(b/r). Tolerance: b/r = 1e-4 here, times coefficients of order 10 g.
    #[test]
    fn late_turn_normal_force_is_c_plus_half_g_sin_theta() {
        let (g, c, b, r) = (4.905, 8.496_0, 0.01, 100.0);
        let turn = TurnDynamics::new(TurnVariant::Exact, r, b, g, c);
        let omega = (std::f64::consts::PI * g / (2.0 * b)).sqrt();
        for theta in [0.5, 2.0, 4.712_388_98, 5.5] {
            let (n, _) = turn.contact_per_mass(theta, omega);
            let want = c + 0.5 * g * f64::sin(theta);
            assert!((n - want).abs() < 1e-2, "θ = {theta}: {n} vs {want}");
        }
    }

    /// Hints only move where Newton's method starts: with the hints of the
    /// turn before, with hints far off (wrong ends of the turn) and with
    /// none, a late turn's extremes agree to a few ulp (1e-14 of g; the
    /// refinement's own error is ~1e-16 g). Also an early turn (32 grid
    /// intervals) with the late turn's hints.
    #[test]
    fn hinted_extremes_equal_the_unhinted() {
        let g = 9.81;
        let (sa, ca) = 30f64.to_radians().sin_cos();
        let late = |r: f64| TurnDynamics::new(TurnVariant::Paper, r, 0.01, g * sa, g * ca);
        let fields = |e: &TurnExtremes| {
            let c = &e.contact;
            [
                e.a_min,
                e.a_max,
                c.min_normal_per_mk,
                c.min_normal_over_mg,
                c.max_friction_ratio.unwrap_or(f64::NAN),
            ]
        };
        let same = |a: &TurnExtremes, b: &TurnExtremes| {
            for (x, y) in fields(a).into_iter().zip(fields(b)) {
                assert!((x - y).abs() < 1e-14 * g, "{x} vs {y}");
            }
        };
        let (turn, omega0) = (late(5.0), 27.0);
        let plain = turn.turn_extremes(omega0);
        let mut hints = Hints::default();
        late(4.99).turn_extremes_hinted(omega0 * 1.001, &mut hints);
        same(&plain, &turn.turn_extremes_hinted(omega0, &mut hints));
        let far = [Some(6.0), Some(3.0), Some(0.1), Some(6.2), Some(0.5)];
        same(
            &plain,
            &turn.turn_extremes_hinted(omega0, &mut Hints { theta: far }),
        );
        let early = late(0.12);
        same(
            &early.turn_extremes(2.0),
            &early.turn_extremes_hinted(2.0, &mut hints),
        );
    }

    /// The one-grid scan against a dense sampling of the public, separately
    /// written formulas (`omega_squared`, `contact_per_mass`, `acceleration`):
    /// the refined minimum is never above the dense one (it is a true value
    /// of the function, up to rounding 1e-12), and not below it by more than
    /// the dense grid's own miss, |f″| h²/8 with h = 2π/2·10⁵ and |f″| of a
    /// few hundred m/s² per rad² in an early turn: 1e-7 m/s² relative to g.
    #[test]
    fn one_grid_scan_matches_dense_sampling() {
        let g = 9.81;
        for (alpha_deg, r, omega0) in [(30.0_f64, 0.1, 0.5), (30.0, 0.11, 25.0), (70.0, 0.3, 8.0)] {
            let (sa, ca) = alpha_deg.to_radians().sin_cos();
            for variant in [TurnVariant::Paper, TurnVariant::Exact] {
                let turn = TurnDynamics::new(variant, r, 0.01, g * sa, g * ca);
                let got = turn.turn_extremes(omega0);
                let mu = turn.coefficients().accretion;
                let samples = 200_000;
                let (mut a_lo, mut a_hi, mut n_lo, mut mg_lo, mut ratio_hi) = (
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::INFINITY,
                    0.0f64,
                );
                for i in 0..=samples {
                    let theta = std::f64::consts::TAU * i as f64 / samples as f64;
                    let omega = turn.omega_squared(theta, omega0).max(0.0).sqrt();
                    let a = turn.acceleration(theta, omega);
                    let (n, f) = turn.contact_per_mass(theta, omega);
                    a_lo = a_lo.min(a);
                    a_hi = a_hi.max(a);
                    n_lo = n_lo.min(n);
                    mg_lo = mg_lo.min(n / ((1.0 + mu * theta) * g));
                    ratio_hi = ratio_hi.max(f.abs() / n);
                }
                let close = |refined: f64, dense: f64, scale: f64| {
                    refined <= dense + 1e-12 * scale && refined >= dense - 1e-7 * scale
                };
                let c = got.contact;
                assert!(close(got.a_min, a_lo, g), "{} vs {a_lo}", got.a_min);
                assert!(close(-got.a_max, -a_hi, g), "{} vs {a_hi}", got.a_max);
                assert!(close(c.min_normal_per_mk, n_lo, g));
                assert!(close(c.min_normal_over_mg, mg_lo, 1.0));
                match c.max_friction_ratio {
                    Some(ratio) => assert!(n_lo > 0.0 && close(-ratio, -ratio_hi, 1.0)),
                    // Undefined exactly where the contact is lost somewhere in the turn.
                    None => assert!(n_lo <= 0.0, "{n_lo}"),
                }
                let (a_min, a_max) = turn.acceleration_range(omega0);
                assert!((a_min - got.a_min).abs() < 1e-12 * g);
                assert!((a_max - got.a_max).abs() < 1e-12 * g);
            }
        }
    }
}
