//! The minima of E that put a near-singular peak in a turn's time
//! t = ∫ √(I/E) dθ (eq. (T3) of `docs/turn-model.md`): a turn that nearly
//! stalls. They are found ([`Orbit::dips`]), and the time is integrated
//! across each with θ = θ_m ± w sinh v and E near θ_m in double-double
//! arithmetic ([`Dip`]); `docs/turn-model.md` says why and how well.

use super::*;

impl Orbit<'_> {
    /// The minima of E inside (0, `theta1`) low enough to make a peak of
    /// √(I/E) that the panels could step over ([`Dip`]; in θ order). None,
    /// with no evaluation of the turn, when E ≥ e0/10 throughout by the
    /// bound of [`Self::potential_bound`] (every turn of a long run but the
    /// first few). Otherwise E is sampled on [`STALL_GRID`] intervals, each
    /// local minimum of the samples refined by Newton's method on E′ = −2W′
    /// (E″ = −2W″) inside its two intervals, and a minimum kept when it is
    /// interior and below [`DIP_FRACTION`] of the largest sample.
    pub(super) fn dips(&self, theta1: f64) -> Vec<Dip> {
        if self.e0 > 2.0 * self.potential_bound(theta1) / (1.0 - DIP_FRACTION) {
            return Vec::new();
        }
        let h = theta1 / STALL_GRID as f64;
        let samples: Vec<f64> = (0..=STALL_GRID)
            .map(|i| self.energy(i as f64 * h))
            .collect();
        let top = samples.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let mut dips: Vec<Dip> = Vec::new();
        for i in 0..=STALL_GRID {
            let left = i == 0 || samples[i] < samples[i - 1];
            let right = i == STALL_GRID || samples[i] <= samples[i + 1];
            if !(left && right) {
                continue;
            }
            let lo = i.saturating_sub(1) as f64 * h;
            let hi = (i + 1).min(STALL_GRID) as f64 * h;
            let Some(theta) = self.newton_min(i as f64 * h, lo, hi) else {
                continue;
            };
            if theta <= 0.0 || theta >= theta1 {
                continue;
            }
            let dip = Dip::at(self, theta);
            if dip.positive
                && dip.e_min < DIP_FRACTION * top
                && dip.curvature > 0.0
                && dips.last().is_none_or(|d| d.theta < theta)
            {
                dips.push(dip);
            }
        }
        dips
    }

    /// Newton's method on E′(θ) = 0 from `start`, kept in [lo, hi] (a step
    /// out of it, or where E″ ≤ 0, bisects the bracket that the sign of E′
    /// keeps): the minimum of E there to rounding, `None` when it is at
    /// (within 1e-9 rad of) an end of [lo, hi].
    pub(super) fn newton_min(&self, start: f64, lo: f64, hi: f64) -> Option<f64> {
        let (mut a, mut b) = (lo, hi);
        let mut x = start;
        for _ in 0..MAX_NEWTON {
            let (d1, d2) = self.energy_slopes(x);
            if d1 > 0.0 {
                b = x;
            } else {
                a = x;
            }
            let next = x - d1 / d2;
            let next = if d2 > 0.0 && next > a && next < b {
                next
            } else {
                0.5 * (a + b)
            };
            let done = (next - x).abs() <= 4.0 * f64::EPSILON * x.abs().max(1.0)
                || b - a <= 4.0 * f64::EPSILON * x.abs().max(1.0);
            x = next;
            if done {
                break;
            }
        }
        let margin = 1e-9 * hi.abs().max(1.0);
        (x > lo + margin && x < hi - margin).then_some(x)
    }

    /// `(E′, E″)` at θ (E′ = −2W′, E″ = −2W″), m²/s² per rad and per rad².
    pub(super) fn energy_slopes(&self, theta: f64) -> (f64, f64) {
        let (s, c) = theta.sin_cos();
        let k = &self.turn.coeffs;
        let (g, c_n) = (self.turn.g_along, self.turn.g_normal);
        let w1 = self.turn.potential_slope_sc(theta, s, c);
        let w2 = -g * (k.e1 - k.e2 * c) + c_n * k.e2 * s;
        (-2.0 * w1, -2.0 * w2)
    }

    /// The time from 0 to `theta1` split at each [`Dip`]: on each side of a
    /// dip θ = θ_m ± w sinh v, w = √(2E_m/E″) the half-width of the peak,
    /// which makes the integrand √(I/E) w cosh v ≈ √(2I/E″) smooth in v
    /// (Johnston & Elliott's sinh transformation for a near-singular
    /// integrand), with E from [`Dip::energy`] (no cancellation near θ_m).
    /// A piece between two special ends (a start from rest, a dip, the
    /// stall) is halved so that each half has one.
    pub(super) fn time_across_dips(&self, theta1: f64, stalls: bool, dips: &[Dip]) -> f64 {
        let from_rest = self.e0 <= 0.0;
        let mut total = 0.0;
        let mut a = (0.0, if from_rest { End::Rest } else { End::Plain });
        // The last piece ends at the stall, or next to a minimum past θ₁.
        let last = match dips.iter().find(|d| d.theta >= theta1) {
            _ if stalls => End::Stall,
            Some(d) => End::Dip(d),
            None => End::Plain,
        };
        let ends = dips
            .iter()
            .filter(|d| d.theta < theta1)
            .map(|d| (d.theta, End::Dip(d)))
            .chain(std::iter::once((theta1, last)));
        for b in ends {
            let special = |e: &End| !matches!(e, End::Plain);
            if special(&a.1) && special(&b.1) {
                let mid = 0.5 * (a.0 + b.0);
                total += self.piece(a, (mid, End::Plain));
                total += self.piece((mid, End::Plain), b);
            } else {
                total += self.piece(a, b);
            }
            a = b;
        }
        total
    }

    /// One piece of [`Self::time_across_dips`], at most one end special.
    pub(super) fn piece(&self, (a, left): (f64, End), (b, right): (f64, End)) -> f64 {
        match (left, right) {
            (End::Rest, _) => adaptive(|s: f64| 2.0 * s * self.slowness(s * s), 0.0, b.sqrt()),
            (_, End::Stall) => adaptive(
                |s: f64| 2.0 * s * self.slowness_before(b, s * s),
                0.0,
                (b - a).sqrt(),
            ),
            (End::Dip(d), _) | (_, End::Dip(d)) => self.across_dip(d, a, b),
            _ => adaptive(|x| self.slowness(x), a, b),
        }
    }

    /// ∫ √(I/E) dθ over [a, b], which lies on one side of the dip's θ_m,
    /// with θ = θ_m ± w sinh v (+ where θ_m ≤ a, − where θ_m ≥ b).
    pub(super) fn across_dip(&self, d: &Dip, a: f64, b: f64) -> f64 {
        let w = d.half_width();
        let (sign, near, far) = if d.theta <= a {
            (1.0, a - d.theta, b - d.theta)
        } else {
            (-1.0, d.theta - b, d.theta - a)
        };
        adaptive(
            |v: f64| {
                let u = sign * w * v.sinh();
                let theta = d.theta + u;
                let (s, c) = theta.sin_cos();
                let (i, _) = self.turn.inertia_sc(theta, s, c);
                (i / d.energy(u)).sqrt() * w * v.cosh()
            },
            (near.max(0.0) / w).asinh(),
            (far / w).asinh(),
        )
    }
}

/// A minimum of E at θ_m inside the interval of a quadrature, low enough
/// that √(I/E) peaks there ([`Orbit::dips`]): E near it written as
/// `E(θ_m + u) = E_m − 2[W′_m u + q u² + A (1 − cos u) + B (sin u − u)]`
/// (W = aθ + qθ² + v(1 − cos θ) + d sin θ, A = v cos θ_m − d sin θ_m,
/// B = v sin θ_m + d cos θ_m: an identity), with E_m and W′_m evaluated in
/// double-double arithmetic from the model's doubles ([`Dd`]). So E is
/// exact to ~1e-16 of its own size near θ_m, where a direct evaluation
/// loses all but log₁₀(E_m/|terms|) + 16 digits (at 1e-10° above a stall
/// slope, E_m/|terms| ~ 5e-11: 6 digits, and the time 7).
#[derive(Debug, Clone, Copy)]
pub(super) struct Dip {
    theta: f64,
    /// E_m, m²/s² (at least the smallest positive double: a minimum at
    /// 0 to rounding keeps a finite, if very long, time).
    e_min: f64,
    /// Whether E_m > 0 as evaluated (not a minimum past a stall).
    positive: bool,
    /// W′(θ_m), J/kg per rad (0 but for the rounding of θ_m).
    slope: f64,
    /// q = −G e₁/2, J/kg per rad².
    quad: f64,
    /// A and B of the doc above.
    a: f64,
    b: f64,
    /// E″(θ_m) = −2(2q + A), m²/s² per rad².
    curvature: f64,
}

impl Dip {
    pub(super) fn at(orbit: &Orbit, theta: f64) -> Self {
        let turn = orbit.turn;
        let precise = orbit.energy_precise(theta);
        let e_min = precise.energy;
        let slope = precise.potential_slope;
        let (s, c) = (precise.sin, precise.cos);
        let [_, quad, vers_c, sin_c] = turn.potential_terms();
        let a = vers_c * c - sin_c * s;
        let b = vers_c * s + sin_c * c;
        Self {
            theta,
            e_min: e_min.max(f64::MIN_POSITIVE),
            positive: e_min > 0.0,
            slope,
            quad,
            a,
            b,
            curvature: -2.0 * (2.0 * quad + a),
        }
    }

    /// E(θ_m + u), m²/s² (not below E_m: past rounding a dip does not reach 0).
    pub(super) fn energy(&self, u: f64) -> f64 {
        let half = (0.5 * u).sin();
        let d_w = self.slope * u
            + self.quad * u * u
            + self.a * 2.0 * half * half
            + self.b * sin_minus_x(u);
        (self.e_min - 2.0 * d_w).max(self.e_min)
    }

    /// w = √(2E_m/E″): where E has doubled, rad.
    pub(super) fn half_width(&self) -> f64 {
        (2.0 * self.e_min / self.curvature).sqrt()
    }
}

/// sin u − u without cancellation: its series for |u| < 1/2 (the first
/// term left out is u¹⁷/17!, below 1e-16 of u³/6), else directly.
fn sin_minus_x(u: f64) -> f64 {
    if u.abs() >= 0.5 {
        return u.sin() - u;
    }
    // (−1)ⁿ/(2n + 1)! for n = 1..7, by Horner's rule in u².
    const C: [f64; 7] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
    ];
    let u2 = u * u;
    let p = C.iter().rev().fold(0.0, |p, &c| c + u2 * p);
    u * u2 * p
}

/// An end of a piece of [`Orbit::time_across_dips`].
#[derive(Debug, Clone, Copy)]
pub(super) enum End<'d> {
    /// Nothing special.
    Plain,
    /// θ = 0 of a start from rest (E ∝ θ).
    Rest,
    /// The stall (E ∝ θ₁ − θ).
    Stall,
    /// A dip of E.
    Dip(&'d Dip),
}
