//! One turn in closed form (`docs/turn-model.md`, "The closed-form path"):
//! within turn k the energy `I(θ)θ̇²/2 + W(θ)` is constant, so
//!
//! `E(θ) := I(θ) θ̇²(θ) = I(0) θ̇₀² − 2W(θ)`, `θ̇(θ) = √(E/I)` (eq. (T1)),
//!
//! and everything the integrator would find is a one-dimensional problem:
//! the stall is the first zero of E (eq. (T2)), the time to reach θ is the
//! quadrature `t(θ) = ∫₀^θ √(I/E) dθ′` (eq. (T3)), and the angle reached at
//! a given time is the root of t(θ) − τ. The hop and slip angles and the
//! extremes of a, N and |F|/N come from the same integral
//! ([`TurnDynamics::turn_extremes`], [`TurnDynamics::first_slip`]).
//!
//! The quadrature is adaptive Gauss–Kronrod (7/15 points, [`kronrod`]): a
//! panel is accepted when the 7-point Gauss result and the 15-point Kronrod
//! result differ by at most [`PANEL_TOL`] of the panel's value. That
//! difference is the error estimate of the 7-point rule; the 15-point
//! result that is kept is exact to degree 23 against 13 and is far more
//! accurate still, so the time of a turn is within about 1e-15 of its
//! value relative, below the rounding of the time summed over turns. Where
//! θ̇ vanishes at an end (a start from rest, a stall), `θ = s²` (or
//! `θ = θ_s − s²`) takes out the inverse square root, so the panels see a
//! smooth integrand. Where θ̇ comes close to 0 inside the interval (a
//! minimum of E below a tenth of its largest value, [`Orbit::dips`]), the
//! quadrature is split at the minimum and `θ = θ_m ± w sinh v` on each side
//! takes out the tall, narrow peak of √(I/E) there, with E near θ_m
//! evaluated without cancellation ([`Dip`]): the time of a turn 1e-10°
//! above a stall slope is then good to ~1e-15 relative for the model's
//! doubles (`docs/turn-model.md`, "A turn that nearly stalls").

use crate::portable::Portable as _;
use std::f64::consts::PI;
use std::sync::OnceLock;

use super::dd::Dd;
use super::{TurnDynamics, TWO_PI};
use crate::quadrature::{gauss_legendre, kronrod};

mod dips;

/// Grid intervals of the stall search over a turn: between grid points E
/// cannot dip by more than `|E″|max h²/8` (h = 2π/16), so a grid value
/// above that proves E > 0 on both sides.
const STALL_GRID: usize = 16;
/// Absolute tolerance in θ of the minimum of E on an interval the bounds
/// do not clear, rad: E there is then off by ~E″ · 1e-24, far below rounding.
const STALL_X_TOL: f64 = 1e-12;
/// A minimum of E below this fraction of its largest sampled value over
/// the interval is split at and mapped ([`Dip`], [`Orbit::time_across_dips`]).
const DIP_FRACTION: f64 = 0.1;
/// Farthest [`Orbit::refine_stall`] moves a stall angle from where
/// bisection in double put it, rad (it moves it by ~1e-10 rad at most).
const STALL_REFINE_REACH: f64 = 1e-6;
/// Acceptance of a panel: |K15 − G7| ≤ this × |K15| (module doc).
pub(super) const PANEL_TOL: f64 = 1e-14;
/// Deepest bisection of a panel (2⁻³⁰ of the interval; the integrands of a
/// turn need a few levels where θ̇ comes close to 0, none elsewhere).
const MAX_DEPTH: usize = 30;
/// Most panels of one quadrature: past this (rounding noise larger than
/// the tolerance, on a scenario at the edge of the ranges) every panel left
/// is kept as it is, so the work stays bounded.
const MAX_PANELS: usize = 4096;
/// Newton steps of [`Orbit::angle_at_time`] (each one quadrature; it
/// converges quadratically from a start within a few per cent).
const MAX_NEWTON: usize = 60;

/// The energy integral of one turn started with `θ̇(0) = omega0` (eq. (T1)).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Orbit<'a> {
    turn: &'a TurnDynamics,
    /// `I(0) θ̇₀² = (3/2) r² θ̇₀²`, m²/s².
    e0: f64,
}

impl<'a> Orbit<'a> {
    /// The orbit of `turn` from `θ̇(0) = omega0`.
    pub(crate) fn new(turn: &'a TurnDynamics, omega0: f64) -> Self {
        let r = turn.radius();
        Self {
            turn,
            e0: 1.5 * r * r * omega0 * omega0,
        }
    }

    /// `E(θ) = I(0)θ̇₀² − 2W(θ)` from `sin θ`, `cos θ`, m²/s².
    fn energy_sc(&self, theta: f64, s: f64, c: f64) -> f64 {
        self.e0 - 2.0 * self.turn.potential_sc(theta, s, c).0
    }

    /// `E(θ)`, m²/s².
    pub(crate) fn energy(&self, theta: f64) -> f64 {
        let (s, c) = super::sin_cos(theta);
        self.energy_sc(theta, s, c)
    }

    /// `θ̇(θ) = √(E/I)` (0 past a stall), rad/s.
    pub(crate) fn omega(&self, theta: f64) -> f64 {
        let (s, c) = super::sin_cos(theta);
        let e = self.energy_sc(theta, s, c);
        let (i, _) = self.turn.inertia_sc(theta, s, c);
        (e / i).max(0.0).sqrt()
    }

    /// A bound on |E″(θ)| = |2W″(θ)| = 2|G(e₁ − e₂ cos θ) − C e₂ sin θ|, m²/s².
    fn curvature_bound(&self) -> f64 {
        let k = &self.turn.coeffs;
        let (g, c) = (self.turn.g_along.abs(), self.turn.g_normal.abs());
        2.0 * (g * (k.e1.abs() + k.e2.abs()) + c * k.e2.abs())
    }

    /// The first θ in (0, `theta_max`] where E(θ) ≤ 0, where the log stalls
    /// (eq. (T2)), if any. On each grid interval E ≥ min(E at its ends) −
    /// |E″|max h²/8, and on the first E ≥ E(0) + E′(0)θ − |E″|max θ²/2; an
    /// interval these bounds do not clear is searched by Brent's method for
    /// the minimum of E, and a minimum at or below 0 (or an end at or below
    /// 0) brackets the first zero, which bisection finds to adjacent doubles.
    pub(crate) fn first_stall(&self, theta_max: f64) -> Option<f64> {
        if self.e0 > 2.0 * self.potential_bound(theta_max) {
            return None;
        }
        let h = theta_max / STALL_GRID as f64;
        let m2 = self.curvature_bound();
        let dip = m2 * h * h / 8.0;
        let slope0 = -2.0 * self.turn.potential_slope_sc(0.0, 0.0, 1.0);
        // E > 0 on (0, h] by Taylor's bound at θ = 0.
        let first_clear = self.e0 >= 0.0 && slope0 > 0.0 && 2.0 * slope0 >= m2 * h;
        let mut e_lo = self.e0;
        for i in 1..=STALL_GRID {
            let (lo, hi) = ((i - 1) as f64 * h, i as f64 * h);
            let e_hi = self.energy(hi);
            if e_hi <= 0.0 {
                let root = super::extremes::first_root(|x| self.energy(x), lo, hi);
                return Some(self.refine_stall(root));
            }
            let clear = e_lo.min(e_hi) > dip || (i == 1 && first_clear);
            if !clear {
                let (x, e_x) = super::extremes::brent_min(|x| self.energy(x), lo, hi, STALL_X_TOL);
                if e_x <= 0.0 {
                    let root = super::extremes::first_root(|x| self.energy(x), lo, x);
                    return Some(self.refine_stall(root));
                }
            }
            e_lo = e_hi;
        }
        None
    }

    /// E(θ) and W′(θ) evaluated in double-double arithmetic from the
    /// model's doubles ([`Dd`]), rounded once at the end; with sin θ and
    /// cos θ. Where E is a small difference of large terms (near a stall,
    /// at a minimum of E close to 0) this keeps every digit of it.
    fn energy_precise(&self, theta: f64) -> Precise {
        let turn = self.turn;
        let k = &turn.coeffs;
        let (g, c_n, r) = (turn.g_along, turn.g_normal, turn.r);
        let (sin, cos) = Dd::sin_cos(theta);
        let th = Dd::from(theta);
        let th2 = Dd::product(theta, theta);
        let vers = Dd::from(1.0).sub(cos);
        // W = −G(rθ + e₁θ²/2 − e₂(1 − cos θ)) + C(e₃θ − e₂ sin θ).
        let along = Dd::product(r, theta)
            .add(th2.scale(k.e1).scale(0.5))
            .sub(vers.scale(k.e2));
        let normal = th.scale(k.e3).sub(sin.scale(k.e2));
        let w = along.scale(-g).add(normal.scale(c_n));
        // W′ = −G(r + e₁θ − e₂ sin θ) + C(e₃ − e₂ cos θ).
        let along1 = Dd::from(r).add(th.scale(k.e1)).sub(sin.scale(k.e2));
        let normal1 = Dd::from(k.e3).sub(cos.scale(k.e2));
        Precise {
            energy: Dd::from(self.e0).sub(w.scale(2.0)).value(),
            potential_slope: along1.scale(-g).add(normal1.scale(c_n)).value(),
            sin: sin.value(),
            cos: cos.value(),
        }
    }

    /// The stall angle `theta` that bisection on E in double found, made
    /// the first double where E ≤ 0 by [`Self::energy_precise`]: near a
    /// stall slope E falls through 0 at a slope E′ as small as 1e-6 m²/s²
    /// per rad, so the rounding of E in double (~1e-16 m²/s²) moves its
    /// zero by 1e-10 rad, and the time to reach it, which the quadrature
    /// takes as the zero of E, by ~1e-7 relative (at 1e-10° below the
    /// turn-0 stall slope). Newton's method on E (E′ = −2W′ in double,
    /// enough for its steps), then single steps of one ulp; left as found
    /// where E′ ≥ 0 (E touching 0) or a step would go far.
    fn refine_stall(&self, theta: f64) -> f64 {
        let e_at = |x: f64| self.energy_precise(x).energy;
        let mut x = theta;
        for _ in 0..8 {
            let (d1, _) = self.energy_slopes(x);
            if d1 >= 0.0 || !d1.is_finite() {
                return theta;
            }
            let next = x - e_at(x) / d1;
            // A step that goes far (or is NaN) leaves the angle as found.
            let reach = (next - theta).abs();
            if reach.is_nan() || reach > STALL_REFINE_REACH {
                return theta;
            }
            if next.to_bits() == x.to_bits() {
                break;
            }
            x = next;
        }
        for _ in 0..4 {
            if e_at(x) > 0.0 {
                x = x.next_up();
            } else if e_at(x.next_down()) <= 0.0 {
                x = x.next_down();
            } else {
                break;
            }
        }
        x
    }

    /// An upper bound on W over [0, `theta_max`], J/kg: with
    /// `W = θ(C e₃ − G r) − θ² G e₁/2 + G e₂(1 − cos θ) − C e₂ sin θ`, the
    /// last two terms are at most 2|G e₂| + |C e₂|, and the quadratic's
    /// largest value is at an end or at its vertex. E > 0 throughout when
    /// `E(0) > 2 ×` this: no stall, with no evaluation of the turn.
    fn potential_bound(&self, theta_max: f64) -> f64 {
        let [lin, quad, vers, sin] = self.turn.potential_terms();
        let p = |x: f64| x * lin + x * x * quad;
        let mut top = p(0.0).max(p(theta_max));
        if quad < 0.0 {
            let vertex = -lin / (2.0 * quad);
            if vertex > 0.0 && vertex < theta_max {
                top = top.max(p(vertex));
            }
        }
        // A relative margin for the rounding of the terms.
        let trig = 2.0 * vers.abs() + sin.abs();
        (top + trig) + 1e-12 * (top.abs() + trig + (lin.abs() + quad.abs() * theta_max) * theta_max)
    }

    /// `√(I/E)` at θ, s/rad.
    fn slowness(&self, theta: f64) -> f64 {
        let (s, c) = theta.sin_cos_p();
        let (i, _) = self.turn.inertia_sc(theta, s, c);
        (i / self.energy_sc(theta, s, c)).sqrt()
    }

    /// `√(I/(E(θ₁ − u) − E(θ₁)))` at θ = θ₁ − u, the differences of θ, θ²,
    /// cos θ and sin θ written so that nothing cancels as u → 0 (E(θ₁) is
    /// the stall's 0 to rounding), s/rad.
    fn slowness_before(&self, theta1: f64, u: f64) -> f64 {
        let k = &self.turn.coeffs;
        let (g, c_n, r) = (self.turn.g_along, self.turn.g_normal, self.turn.r);
        let theta = theta1 - u;
        let s_half = (0.5 * u).sin_p();
        let (s_mid, c_mid) = (theta1 - 0.5 * u).sin_cos_p();
        // cos θ − cos θ₁ = 2 sin(θ₁ − u/2) sin(u/2); sin θ − sin θ₁ = −2 cos(θ₁ − u/2) sin(u/2).
        let d_cos = 2.0 * s_mid * s_half;
        let d_sin = -2.0 * c_mid * s_half;
        // W(θ) − W(θ₁), with θ − θ₁ = −u and θ² − θ₁² = −u(2θ₁ − u).
        let d_w = -g * (-r * u - k.e1 * u * (2.0 * theta1 - u) / 2.0 + k.e2 * d_cos)
            + c_n * (-k.e3 * u - k.e2 * d_sin);
        let (s, c) = theta.sin_cos_p();
        let (i, _) = self.turn.inertia_sc(theta, s, c);
        (i / (-2.0 * d_w)).sqrt()
    }

    /// The time from θ = 0 to `theta1`, eq. (T3). `stalls`: θ̇ vanishes at
    /// `theta1` (the stall angle of [`Self::first_stall`]); θ̇ must not
    /// vanish in between. A start from rest (`θ̇₀ = 0`) is taken care of by
    /// `θ = s²`, a stall by `θ = θ₁ − s²`, each over half the interval.
    pub(crate) fn time_to(&self, theta1: f64, stalls: bool) -> f64 {
        if theta1 <= 0.0 {
            return 0.0;
        }
        let from_rest = self.e0 <= 0.0;
        // A minimum of E just past θ₁ (an angle short of it asked for by
        // [`Self::angle_at_time`]) peaks √(I/E) at θ₁ as one inside does.
        let reach = if stalls { theta1 } else { theta1.max(TWO_PI) };
        let dips = self.dips(reach);
        if !dips.is_empty() {
            return self.time_across_dips(theta1, stalls, &dips);
        }
        if theta1 == TWO_PI && !from_rest && !stalls {
            if let Some(t) = self.turn_time() {
                return t;
            }
        }
        let mid = if from_rest || stalls {
            0.5 * theta1
        } else {
            theta1
        };
        let head = if from_rest {
            // θ = s², dθ = 2s ds.
            adaptive(|s: f64| 2.0 * s * self.slowness(s * s), 0.0, mid.sqrt())
        } else {
            adaptive(|x| self.slowness(x), 0.0, mid)
        };
        if !(from_rest || stalls) {
            return head;
        }
        let tail = if stalls {
            // θ = θ₁ − s².
            let width = (theta1 - mid).sqrt();
            adaptive(
                |s: f64| 2.0 * s * self.slowness_before(theta1, s * s),
                0.0,
                width,
            )
        } else {
            adaptive(|x| self.slowness(x), mid, theta1)
        };
        head + tail
    }

    /// The time of a whole turn, eq. (T3) over [0, 2π], by the fixed
    /// Gauss–Legendre rules of [`TurnNodes`] (sin and cos of their nodes
    /// computed once): the 20-point result when the 12-point one agrees
    /// with it to [`PANEL_TOL`] (the 12-point rule's error is then below
    /// that, the 20-point one's far below: each converges geometrically at
    /// the same rate in n); `None`, for the adaptive rule, when they do not
    /// (an early turn, a slow one near a stall).
    fn turn_time(&self) -> Option<f64> {
        let nodes = TurnNodes::get();
        // I ([`TurnDynamics::inertia_sc`]; its I′ is not used) and
        // E = I(0)θ̇₀² − 2W, W term by term ([`TurnDynamics::potential_terms`]), by node.
        let [w_th, w_th2, w_vers, w_sin] = self.turn.potential_terms();
        let sum = |rule: &Rule| {
            // Four nodes at a time into four partial sums: independent
            // lanes, which the compiler runs two at a time.
            let mut lanes = [0.0; 4];
            for q in &rule.quads {
                for (l, lane) in lanes.iter_mut().enumerate() {
                    let cos = 1.0 - q.versine[l];
                    let (i, _) = self.turn.inertia_sc(q.theta[l], q.sin[l], cos);
                    let pot = w_th * q.theta[l]
                        + w_th2 * q.theta2[l]
                        + w_vers * q.versine[l]
                        + w_sin * q.sin[l];
                    *lane += q.weight[l] * (i / (self.e0 - 2.0 * pot)).sqrt();
                }
            }
            (lanes[0] + lanes[1]) + (lanes[2] + lanes[3])
        };
        let coarse = sum(&nodes.coarse);
        let fine = sum(&nodes.fine);
        ((fine - coarse).abs() <= PANEL_TOL * fine.abs()).then_some(fine)
    }

    /// The angle θ ∈ [0, `theta_max`] reached at time τ after the turn's
    /// start, given `t(theta_max) ≥ τ` (`stalls` as for [`Self::time_to`]):
    /// Newton's method on t(θ) − τ (t′ = 1/θ̇), kept inside a bracket that
    /// bisection narrows whenever a step would leave it.
    pub(crate) fn angle_at_time(&self, tau: f64, theta_max: f64, stalls: bool) -> f64 {
        let t_max = self.time_to(theta_max, stalls);
        if tau >= t_max {
            return theta_max;
        }
        let (mut lo, mut hi) = (0.0, theta_max);
        let mut theta = theta_max * tau / t_max;
        for _ in 0..MAX_NEWTON {
            let miss = tau - self.time_to(theta, false);
            if miss > 0.0 {
                lo = theta;
            } else {
                hi = theta;
            }
            let next = theta + miss * self.omega(theta);
            let next = if next > lo && next < hi {
                next
            } else {
                0.5 * (lo + hi)
            };
            if (next - theta).abs() <= 4.0 * f64::EPSILON * theta_max || hi - lo <= f64::EPSILON {
                return next;
            }
            theta = next;
        }
        theta
    }
}

/// [`Orbit::energy_precise`]'s values at θ.
#[derive(Debug, Clone, Copy)]
struct Precise {
    /// E(θ), m²/s².
    energy: f64,
    /// W′(θ), J/kg per rad.
    potential_slope: f64,
    sin: f64,
    cos: f64,
}

/// Four nodes of a rule over one whole turn: θ, θ², 1 − cos θ, sin θ and
/// the weights.
#[derive(Debug, Clone, Copy, Default)]
struct Quad {
    theta: [f64; 4],
    theta2: [f64; 4],
    versine: [f64; 4],
    sin: [f64; 4],
    weight: [f64; 4],
}

/// A rule over one whole turn, four nodes at a time (a node count that is
/// not a multiple of four is padded with nodes of weight 0).
struct Rule {
    quads: Vec<Quad>,
}

impl Rule {
    /// The n-point Gauss–Legendre rule mapped to [0, 2π].
    fn over_turn(n: usize) -> Self {
        let rule = gauss_legendre(n);
        let quads = rule
            .chunks(4)
            .map(|nodes| {
                let mut q = Quad::default();
                for (l, &(x, w)) in nodes.iter().enumerate() {
                    let theta = PI * (1.0 + x);
                    q.theta[l] = theta;
                    q.theta2[l] = theta * theta;
                    q.versine[l] = 1.0 - theta.cos_p();
                    q.sin[l] = theta.sin_p();
                    q.weight[l] = PI * w;
                }
                q
            })
            .collect();
        Rule { quads }
    }
}

/// The 12- and 20-point Gauss–Legendre rules over [0, 2π] of
/// [`Orbit::turn_time`].
struct TurnNodes {
    coarse: Rule,
    fine: Rule,
}

impl TurnNodes {
    fn get() -> &'static TurnNodes {
        static NODES: OnceLock<TurnNodes> = OnceLock::new();
        NODES.get_or_init(|| TurnNodes {
            coarse: Rule::over_turn(12),
            fine: Rule::over_turn(20),
        })
    }
}

/// `∫ f` over `[a, b]` by adaptive Gauss–Kronrod: a panel whose error
/// estimate exceeds [`PANEL_TOL`] of its value is halved, depth first (the
/// module doc states the accuracy).
pub(super) fn adaptive(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    let (whole, err) = kronrod(&mut f, a, b);
    if err <= PANEL_TOL * whole.abs() || !err.is_finite() {
        return whole;
    }
    // A panel may also meet its share of the whole's tolerance (its
    // rounding may keep it from meeting its own where it is small).
    let share = PANEL_TOL * whole.abs() / (b - a);
    let mut total = 0.0;
    // Panels still to do, as (lo, hi, depth); depth first, so at most
    // MAX_DEPTH + 1 wait at once.
    let mut stack = [(0.0, 0.0, 0usize); MAX_DEPTH + 2];
    let mid = 0.5 * (a + b);
    stack[0] = (mid, b, 1);
    stack[1] = (a, mid, 1);
    let mut n = 2;
    let mut panels = 0;
    while n > 0 {
        n -= 1;
        panels += 1;
        let (lo, hi, depth) = stack[n];
        let (value, err) = kronrod(&mut f, lo, hi);
        // A non-finite panel is not split further: its NaN or infinity
        // reaches the result, and the caller refuses it.
        let own = PANEL_TOL * value.abs();
        let spent = depth >= MAX_DEPTH || panels >= MAX_PANELS;
        if err <= own.max(share * (hi - lo)) || spent || !err.is_finite() {
            total += value;
            continue;
        }
        let mid = 0.5 * (lo + hi);
        stack[n] = (mid, hi, depth + 1);
        stack[n + 1] = (lo, mid, depth + 1);
        n += 2;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TurnVariant;

    /// Issue 32, item 1: the time of a turn whose E dips close to 0 against
    /// `scripts/derivations/reference/near_stall_times.csv` (tanh-sinh at
    /// 50 digits, split at the minimum, on the program's doubles: its error
    /// estimates are below 1e-25 of the time). Both models; turn 0 from
    /// rest 1e-3 .. 1e-10 degrees above the stall slope, turn 0 at 1° from
    /// v0 = v*(1 + δ) and turn 3 from θ̇₀ = ω*(1 + δ), δ = 1e-3 .. 1e-10;
    /// and turn 0 from rest 1e-3 .. 1e-10° below the stall slope, where the
    /// log stalls: its stall angle to 2 ulp and the time to it.
    /// The doubles G, C, r and the coefficients are first checked to be
    /// the reference's to the bit (the time is ill-conditioned in them:
    /// 1 ulp of G moves it by ~1e-7 at 1e-10°). Tolerance 1e-10 relative,
    /// the goal (the split quadrature meets ~1e-14).
    #[test]
    fn nearly_stalling_turns_take_the_reference_time() {
        let text =
            include_str!("../../../../../../scripts/derivations/reference/near_stall_times.csv");
        let mut worst = 0.0f64;
        let mut rows = 0;
        for line in text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with("model"))
        {
            let f: Vec<&str> = line.split(',').collect();
            let x = |i: usize| f[i].parse::<f64>().unwrap();
            let variant = match f[0] {
                "turns" => TurnVariant::Paper,
                _ => TurnVariant::Exact,
            };
            let (omega0, r, g, c) = (x(6), x(7), x(8), x(9));
            let turn = TurnDynamics::new(variant, r, 0.01, g, c);
            let k = turn.coeffs;
            for (i, have) in [k.c1, k.c2, k.e1, k.e2, k.e3].into_iter().enumerate() {
                assert_eq!(
                    have.to_bits(),
                    x(10 + i).to_bits(),
                    "{line}: coefficient {i}"
                );
            }
            let orbit = Orbit::new(&turn, omega0);
            let want = x(17);
            if f[1] == "stall" {
                // The stall angle, to the double (E′ there is −1.4e-6 m²/s²
                // per rad at 1e-10°: 1 ulp of θ is 1.2e-21 m²/s² of E), and the time to it.
                let theta_s = orbit.first_stall(TWO_PI).expect(line);
                let miss = (theta_s - x(15)).abs();
                assert!(
                    miss <= 2.0 * f64::EPSILON * theta_s,
                    "{line}: stall at {theta_s}"
                );
                let t = orbit.time_to(theta_s, true);
                let rel = (t - want).abs() / want;
                assert!(rel < 1e-10, "{line}: {t} ({rel:e})");
                worst = worst.max(rel);
                rows += 1;
                continue;
            }
            assert_eq!(orbit.first_stall(TWO_PI), None, "{line}");
            let t = orbit.time_to(TWO_PI, false);
            let rel = (t - want).abs() / want;
            assert!(rel < 1e-10, "{line}: {t} ({rel:e})");
            worst = worst.max(rel);
            rows += 1;
        }
        assert_eq!(rows, 64);
        eprintln!("largest relative error {worst:e}");
    }
}
