//! The checks of scale of a scenario ([`Scenario::new`]): each parameter and
//! each quantity derived from them at the start (area, mass, moment of
//! inertia, weight, energies) zero or of a magnitude the arithmetic keeps.

use super::{check_scale, Scenario, Shape};
use crate::error::ParamError;

impl Scenario {
    /// The checks of the scales, in the order a reader would change them.
    pub(super) fn check_scales(&self) -> Result<(), ParamError> {
        use std::f64::consts::PI;
        let (b, r0, g, rho, l, v0) = (self.b, self.r0, self.g, self.rho, self.l, self.v0);
        check_scale("snow depth b (m)", b, true, "change {snow_depth}")?;
        check_scale("initial radius r0 (m)", r0, false, "change {r0}")?;
        check_scale("g (m/s^2)", g, false, "change {g}")?;
        check_scale("density (kg/m^3)", rho, false, "change {density}")?;
        check_scale("log length (m)", l, false, "change {length}")?;
        check_scale("initial speed v0 (m/s)", v0, true, "change {v0}")?;
        if let Some(m) = self.core_mass {
            check_scale("core mass (kg)", m, false, "change {core_mass}")?;
        }
        // The slope component of gravity g sin alpha divides accelerations
        // (a over g sin alpha): a subnormal alpha_deg (4.9e-324) becomes 0 rad.
        // A level floor (exactly 0) is allowed for the unwinding roll only.
        check_scale(
            "slope angle alpha (rad)",
            self.alpha,
            b < 0.0,
            "change {alpha_deg}",
        )?;
        let area = PI * r0 * r0;
        check_scale(
            "initial cross-section pi r0^2 (m^2)",
            area,
            false,
            "change {r0}",
        )?;
        let m0 = self.initial_mass();
        // The shape's own formulae (`docs/snowball-and-losses.md` §1.1):
        // mass, moment of inertia about the contact line (1 + k) m0 r0²,
        // kinetic energy ½ (1 + k) m0 v0², snow picked up per metre ρ b × swath.
        let (mass, inertia, kinetic, picked, hint, picked_hint) = match self.shape {
            Shape::Cylinder => (
                "initial mass m0 = pi rho l r0^2, eq. (37) (kg)",
                "moment of inertia about the contact line 3 m0 r0^2/2, eq. (56) (kg m^2)",
                "initial kinetic energy 3 m0 v0^2/4, eq. (7) (J)",
                "snow picked up per metre rolled rho l b, eq. (8) (kg/m)",
                "change {density}, {length} or {r0}",
                "change {snow_depth}, {density} or {length}",
            ),
            Shape::Sphere => (
                "initial mass of the ball m0 = 4 pi rho r0^3/3 (kg)",
                "moment of inertia of the ball about the contact point 7 m0 r0^2/5 (kg m^2)",
                "initial kinetic energy of the ball 7 m0 v0^2/10 (J)",
                "snow picked up per metre rolled rho b w, w the swath width (kg/m)",
                "change {density} or {r0}",
                "change {snow_depth}, {density}, {swath_width} or {r0}",
            ),
        };
        let one_plus_k = 1.0 + self.shape.inertia_factor();
        check_scale(mass, m0, false, hint)?;
        check_scale(inertia, one_plus_k * m0 * r0 * r0, false, hint)?;
        let hint = match self.shape {
            Shape::Cylinder => "change {g}, {density}, {length} or {r0}",
            Shape::Sphere => "change {g}, {density} or {r0}",
        };
        check_scale("weight m0 g (N)", m0 * g, false, hint)?;
        check_scale(
            "potential energy scale m0 g r0 (J)",
            m0 * g * r0,
            false,
            hint,
        )?;
        let hint = match self.shape {
            Shape::Cylinder => "change {v0}, {density}, {length} or {r0}",
            Shape::Sphere => "change {v0}, {density} or {r0}",
        };
        check_scale(kinetic, 0.5 * one_plus_k * m0 * v0 * v0, true, hint)?;
        let swath = self.body().swath(r0);
        check_scale(picked, rho * b * swath, true, picked_hint)?;
        check_scale(
            "area picked up per metre rolled b/pi relative to r0^2 (1/m)",
            b / (PI * r0 * r0),
            true,
            "change {snow_depth} or {r0}",
        )
    }
}
