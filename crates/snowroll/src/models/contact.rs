//! Contact forces of the slope on the log: the normal force N and the
//! friction F that rolling without slipping requires (issue 10,
//! `docs/contact-forces.md`).
//!
//! The snow the log picks up is at rest before it joins, so `M a` is not the
//! net external force. The momentum balance of the body plus the snow that
//! joins during dt (`docs/contact-forces.md` §1) gives, with G = g sin α,
//! C = g cos α and p the momentum of the body,
//!
//! `N = dp_y/dt + M C`,  `F = M G − dp_x/dt`  (F positive up the slope).
//!
//! * Circular models (§2 of the note and of the doc), p = M(v, ṙ) with
//!   ṙ = b v/(2πr) (eq. (1)): [`circular_forces`].
//! * Turn models (§3.4), p = θ̇ (S_y, −S_x) with the first moment S of the
//!   body about the contact line: [`TurnDynamics::contact_forces`](super::TurnDynamics::contact_forces).
//!
//! Either way N and F are explicit functions of the state, so they serve as
//! event functions (hop: N = 0; slip: |F| − μN = 0).

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use super::coefficients::Coefficients;
use crate::scenario::{Scenario, Shape};
use crate::units::{Meters, MetersPerSecond, MetersPerSecondSquared, Newtons};

/// The force of the slope on the log, `(−F, N)` in the axes (x down the
/// slope, y away from it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ContactForces {
    /// Normal force N, positive when the slope pushes, N.
    pub normal_n: Newtons,
    /// Friction F, positive up the slope, N.
    pub friction_n: Newtons,
}

impl ContactForces {
    /// |F|/N, the smallest coefficient of static friction that keeps the log
    /// rolling here; `None` when N ≤ 0, where it is undefined (the log has
    /// left the ground and no friction can hold it). Never infinite or NaN:
    /// the outputs write `None` as an empty CSV cell and a JSON `null`.
    pub fn friction_ratio(&self) -> Option<f64> {
        (self.normal_n > 0.0).then(|| self.friction_n.abs() / self.normal_n)
    }

    /// The slip event function `|F| − μN` (`docs/contact-forces.md` §5),
    /// positive when the log would slip, N.
    pub fn slip_margin(&self, mu: f64) -> Newtons {
        self.friction_n.abs() - mu * self.normal_n
    }
}

/// Contact forces of a circular log (§2, App. A, fn. 4) of radius r(x) from
/// eq. (8) at speed `v` with acceleration `a` (the model's own dv/dt),
/// `docs/contact-forces.md` §2:
///
/// `N/M = C + b a/(2πr) + b² v²/(4π² r³)`,  `F/M = G − a − b v²/(π r²)`,
///
/// with M = πρl r² (eq. (8)). For the snowless cylinder (App. A, b = 0,
/// a = 2G/3) this is `N = m g cos α`, `F = m g sin α/3`.
///
/// For the ball, with p = M(v, ṙ) as for the log
/// (`docs/snowball-and-losses.md` §1.2):
/// `N/M = C + r′ a + (λ r′ + r″) v²`, `F/M = G − a − λ v²`, with r′, r″, λ of
/// its growth law ([`crate::physics::Growth`]); on the log's law these are
/// the formulae above. The snowless ball: N = M C, F = (2/7) M G. The same
/// general form serves a roll whose tube has a mass of its own
/// (`docs/unwinding.md`, "The core"): the tube moves with the centre, so p is
/// still M (v, ṙ), with M and λ of [`crate::body::Tube`].
pub fn circular_forces(
    coeffs: &Coefficients,
    s: &Scenario,
    x: Meters,
    v: MetersPerSecond,
    a: MetersPerSecondSquared,
) -> ContactForces {
    if s.shape() == Shape::Sphere || s.core_mass().is_some() {
        let gr = crate::physics::growth_at(s, x, coeffs.accretes);
        let normal = s.g_normal() + gr.dr_dx * a + (gr.lambda * gr.dr_dx + gr.d2r_dx2) * v * v;
        let friction = s.g_along() - a - gr.lambda * v * v;
        return ContactForces {
            normal_n: gr.mass * normal,
            friction_n: gr.mass * friction,
        };
    }
    let (b, r, m) = if coeffs.accretes {
        (
            s.snow_depth(),
            crate::physics::radius_at(s, x),
            crate::physics::mass_at(s, x),
        )
    } else {
        (0.0, s.initial_radius(), s.initial_mass())
    };
    let (g_along, g_normal) = (s.g_along(), s.g_normal());
    // q = b v²/(π r²), the momentum-drag group of §2.
    let q = b * v * v / (PI * r * r);
    let normal = g_normal + b / (2.0 * PI * r) * (a + q / 2.0);
    let friction = g_along - a - q;
    ContactForces {
        normal_n: m * normal,
        friction_n: m * friction,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::Derivation;

    /// Relative tolerance of "exact to rounding": a handful of operations on
    /// numbers of order one.
    const ROUNDING: f64 = 1e-14;

    #[test]
    fn app_a_snowless_forces_are_mg_cos_and_mg_sin_over_3() {
        let s = Scenario::default();
        let c = Derivation::Snowless.coefficients();
        let m = s.initial_mass();
        for (x, v) in [(0.0, 0.0), (1.0, 2.0), (5000.0, 60.0)] {
            let f = circular_forces(&c, &s, x, v, c.acceleration(&s, x, v));
            let n_want = m * s.gravity() * s.slope_angle().cos();
            let f_want = m * s.gravity() * s.slope_angle().sin() / 3.0;
            assert!((f.normal_n - n_want).abs() <= ROUNDING * n_want);
            assert!((f.friction_n - f_want).abs() <= ROUNDING * f_want);
            let ratio = s.slope_angle().tan() / 3.0;
            let got = f.friction_ratio().expect("N > 0 on the ground");
            assert!((got - ratio).abs() <= ROUNDING * ratio);
        }
    }

    #[test]
    fn the_friction_ratio_of_a_log_in_the_air_is_undefined() {
        for normal_n in [-1.0, 0.0, -0.0] {
            let f = ContactForces {
                normal_n,
                friction_n: 0.5,
            };
            assert_eq!(f.friction_ratio(), None);
        }
        let f = ContactForces {
            normal_n: -1.0,
            friction_n: 0.5,
        };
        // No μ ≥ 0 holds it: |F| − μN > 0 for every μ.
        assert!(f.slip_margin(0.3) > 0.0);
    }
}
