//! What the common form says without integrating it: the late-time
//! acceleration (eq. (35), fn. 4, App. A), how fast a run approaches it, and
//! the slope below which a log at rest does not start (fn. 7).

use crate::portable::Portable as _;
use std::f64::consts::{FRAC_PI_2, PI};

use super::rhs::Acceleration;
use super::{Coefficients, Derivation};
use crate::losses::Losses;
use crate::scenario::{Scenario, ScenarioFile};
use crate::units::Radians;

impl Coefficients {
    /// Late-time acceleration over g sin α for b > 0: with `π r² ≈ b x` and
    /// `v² ≈ 2 a x` the drag term tends to `2 c_v a`, the lift and b² terms
    /// vanish like 1/r, so `a∞ = (2G/3)/(1 + 2 c_v)`: G/5 for eq. (4)
    /// (fn. 4), G/6 for eq. (6), G/3 for eqs. (14), (15), (32) (eq. (35)),
    /// 2G/9 for eq. (21) as printed; 2/3 throughout for the snowless
    /// model (App. A, eq. (95)). Always `Some` for the circular models.
    ///
    /// For the ball on the area law 2/3 becomes 5/7: 1/6 (`torque-cm`), 1/7
    /// (`torque-contact`), 2/7 (the energy family), 5/28 (eq. (21) printed),
    /// `docs/snowball-and-losses.md` §1.3.
    pub fn terminal_fraction(&self) -> Option<f64> {
        let (num, den) = self.shape.push_ratio();
        if self.accretes {
            Some((num / den) / (1.0 + 2.0 * self.drag))
        } else {
            Some(num / den)
        }
    }

    /// Leading approach to the terminal value. With lift (λ₁ ≠ 0),
    /// `a − a∞ ≈ −λ₁ g b cos α /((1 + 4c_v) π r)` (from the particular
    /// solution `v² = A s + B s^{1/2}`, s = πr²); without it, the exact
    /// solution `v² = A s + K s^{−2c_v}` gives `a − a∞ ∝ s^{−(1 + 2c_v)} ∝ r^{−2(1 + 2c_v)}`.
    /// Returns the power p of `|a − a∞| ∝ r^{−p}`.
    pub fn approach_power_in_r(&self) -> Option<f64> {
        if !self.accretes {
            None
        } else if self.lift != 0.0 {
            Some(1.0)
        } else {
            Some(2.0 * (1.0 + 2.0 * self.drag))
        }
    }

    /// The initial acceleration with v = 0 is not positive below this slope
    /// (fn. 7: the snow must be lifted). From the common form at x = 0, v = 0:
    /// `tan α* = 3(λ₁ b r0 + λ₂ b²/3)/(2π r0²)` (for the ball 7/5 in place
    /// of 3/2). `None` when the model has no lift term (it always starts),
    /// and for an unwinding roll (b < 0) whose lift term pushes (|b| < 3r0
    /// for eq. (14)): it starts on every slope, and on a level floor too
    /// (`docs/unwinding.md`).
    pub fn stall_slope(&self, b: f64, r0: f64) -> Option<Radians> {
        if !self.accretes || (self.lift == 0.0 && self.lift_b2 == 0.0) {
            return None;
        }
        let (num, den) = self.shape.push_ratio();
        let tan = den * (self.lift * b * r0 + self.lift_b2 * b * b / 3.0) / (num * PI * r0 * r0);
        if b < 0.0 && tan <= 0.0 {
            return None;
        }
        Some(tan.atan_p())
    }
}

impl Derivation {
    /// The slope α* below which this model, started from rest on `s` (its
    /// body, swath and snow) with the losses `l`, does not start (fn. 7):
    /// where its acceleration at rest a(0) falls to zero. `None` when it
    /// starts on every slope; π/2 when on none (compaction or rolling
    /// resistance at least the drive of a vertical wall).
    ///
    /// a(0) is the model's own right-hand side at x = 0, v = 0, so the
    /// threshold follows the body and the losses the run has. Without
    /// losses on the area law it is [`Coefficients::stall_slope`]'s closed
    /// form; otherwise a(0) = A sin α − B cos α − E (A > 0, B, E ≥ 0: the
    /// drive, the lift and rolling resistance, compaction) increases with α
    /// and its zero is found by bisection to rounding.
    pub fn stall_slope_in(self, s: &Scenario, l: &Losses) -> Option<Radians> {
        let c = self.coefficients_for(s.shape());
        if !l.any() && s.has_common_form() {
            return c.stall_slope(s.snow_depth(), s.initial_radius());
        }
        let at_rest = |alpha: f64| -> Option<f64> {
            let file = ScenarioFile {
                alpha_deg: alpha.to_degrees(),
                v0: 0.0,
                ..ScenarioFile::from(*s)
            };
            let s = Scenario::new(file).ok()?;
            Some(Acceleration::of(self, &c, &s, l).at(0.0, 0.0))
        };
        // The open interval of slopes a scenario takes, less a margin that
        // keeps sin and cos away from 0.
        let (mut lo, mut hi) = (1e-9, FRAC_PI_2 - 1e-9);
        if at_rest(lo)? > 0.0 {
            return None;
        }
        if at_rest(hi)? <= 0.0 {
            return Some(FRAC_PI_2);
        }
        while hi - lo > 4.0 * f64::EPSILON * hi {
            let mid = 0.5 * (lo + hi);
            if at_rest(mid)? > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(0.5 * (lo + hi))
    }
}
