//! The body that rolls, and everything the models need of its shape
//! (`docs/snowball-and-losses.md` §1): the factor k of its moment of
//! inertia, its mass as a function of its radius M(r), its radius after
//! rolling a distance r(x) with the snow it collects, the width of the swath
//! it picks up, and its frontal area for the drag. Every model reaches the
//! body through [`Body`] (from [`crate::Scenario::body`]), so that a new
//! shape is one more variant here.

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use crate::error::ParamError;
use crate::units::{Kilograms, Meters};

/// The body that rolls (issue 11, `docs/snowball-and-losses.md` §1): the
/// note's log, or a ball. Both are taken as round at all times by the
/// circular models; the turn models know only the log.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Shape {
    /// A uniform cylinder of length l (the note's log): I = ½ M r²,
    /// M = πρl r², swath = l, so π r² = π r0² + b x (eq. (8)).
    #[default]
    Cylinder,
    /// A uniform ball: I = (2/5) M r², M = (4/3)πρ r³, swath 2r by default
    /// (again π r² = π r0² + b x), or a fixed width w
    /// ((4π/3)(r³ − r0³) = b w x), `docs/snowball-and-losses.md` §1.1.
    Sphere,
}

impl Shape {
    /// Both shapes, the default first.
    pub const ALL: [Shape; 2] = [Shape::Cylinder, Shape::Sphere];

    /// The kebab-case name, as `--shape` takes it.
    pub fn id(self) -> &'static str {
        match self {
            Shape::Cylinder => "cylinder",
            Shape::Sphere => "sphere",
        }
    }

    /// k = I/(M r²): ½ for the cylinder, 2/5 for the ball.
    pub fn inertia_factor(self) -> f64 {
        let (num, den) = self.inertia_ratio();
        num / den
    }

    /// k as a ratio of small whole numbers, (1, 2) or (2, 5).
    pub fn inertia_ratio(self) -> (f64, f64) {
        match self {
            Shape::Cylinder => (1.0, 2.0),
            Shape::Sphere => (2.0, 5.0),
        }
    }

    /// 1/(1 + k) as a ratio of whole numbers: (2, 3) for the cylinder
    /// (App. A: a = 2G/3), (5, 7) for the ball (a = 5G/7). The formulae
    /// evaluate `num * G / den`, so that the snowless accelerations are the
    /// correctly rounded 2G/3 and 5G/7.
    pub fn push_ratio(self) -> (f64, f64) {
        match self {
            Shape::Cylinder => (2.0, 3.0),
            Shape::Sphere => (5.0, 7.0),
        }
    }

    /// n of M ∝ rⁿ: 2 for the cylinder, 3 for the ball.
    pub fn mass_exponent(self) -> f64 {
        match self {
            Shape::Cylinder => 2.0,
            Shape::Sphere => 3.0,
        }
    }
}

impl std::fmt::Display for Shape {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

impl std::str::FromStr for Shape {
    type Err = ParamError;

    /// `cylinder` or `sphere`, in any case.
    fn from_str(s: &str) -> Result<Self, ParamError> {
        let wanted = s.trim().to_ascii_lowercase();
        Shape::ALL
            .into_iter()
            .find(|k| k.id() == wanted)
            .ok_or_else(|| ParamError::UnknownShape {
                given: s.to_string(),
            })
    }
}

/// A body of a scenario: its shape, and the quantities its size and growth
/// depend on, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Cylinder or ball.
    pub shape: Shape,
    /// Density ρ of body and snow, kg/m³.
    pub density: f64,
    /// Length l of the log, m (not used for the ball).
    pub length: Meters,
    /// Initial radius r0, m.
    pub r0: Meters,
    /// Snow depth b, m.
    pub snow_depth: Meters,
    /// A ball's fixed swath width w, m; `None` for its natural swath 2r (and
    /// always for the log, whose swath is its length).
    pub swath_width: Option<Meters>,
}

impl Body {
    /// k = I/(M r²): ½ for the log, 2/5 for the ball.
    pub fn inertia_factor(&self) -> f64 {
        self.shape.inertia_factor()
    }

    /// M(r), kg: π ρ l r² for the log (eq. (37)), (4/3) π ρ r³ for the ball.
    pub fn mass_of_radius(&self, r: Meters) -> Kilograms {
        match self.shape {
            Shape::Cylinder => PI * self.density * self.length * r * r,
            Shape::Sphere => 4.0 * PI * self.density * r * r * r / 3.0,
        }
    }

    /// m0 = M(r0), kg.
    pub fn initial_mass(&self) -> Kilograms {
        self.mass_of_radius(self.r0)
    }

    /// Radius after rolling a distance `x`: `π r² = π r0² + b x` (eq. (8)) for
    /// the log and for the ball with its natural swath 2r; for a ball with a
    /// fixed swath w, `(4π/3)(r³ − r0³) = b w x` (`docs/snowball-and-losses.md` §1.1).
    pub fn radius_at(&self, x: Meters) -> Meters {
        let (r0, b) = (self.r0, self.snow_depth);
        match self.swath_width {
            None => (r0 * r0 + b * x / PI).sqrt(),
            Some(w) => (r0 * r0 * r0 + 3.0 * b * w * x / (4.0 * PI)).cbrt(),
        }
    }

    /// Mass after rolling `x`, kg: `m = m0 + ρ b l x` (= π ρ l r², eq. (8)) for
    /// the log; M(r(x)) for the ball, which is `m0 + ρ b w x` with a fixed
    /// swath w.
    pub fn mass_at(&self, x: Meters) -> Kilograms {
        let (rho, b) = (self.density, self.snow_depth);
        match (self.shape, self.swath_width) {
            (Shape::Cylinder, _) => self.initial_mass() + rho * b * self.length * x,
            (Shape::Sphere, Some(w)) => self.initial_mass() + rho * b * w * x,
            (Shape::Sphere, None) => self.mass_of_radius(self.radius_at(x)),
        }
    }

    /// The width of the swath of snow picked up at radius `r`, m: the log's
    /// length, a ball's fixed width w, else its diameter 2r.
    pub fn swath(&self, r: Meters) -> Meters {
        match self.shape {
            Shape::Cylinder => self.length,
            Shape::Sphere => self.swath_width.unwrap_or(2.0 * r),
        }
    }

    /// The frontal area A at radius `r`, m² (the drag of §2.1): `2 r l` for
    /// the log, `π r²` for the ball.
    pub fn frontal_area(&self, r: Meters) -> f64 {
        match self.shape {
            Shape::Cylinder => 2.0 * r * self.length,
            Shape::Sphere => PI * r * r,
        }
    }

    /// [`Growth`] at distance `x`; a body that collects no snow (`accretes`
    /// false, or b = 0) keeps r0, with r′ = r″ = λ = 0.
    pub fn growth_at(&self, x: Meters, accretes: bool) -> Growth {
        let b = self.snow_depth;
        if !accretes || b == 0.0 {
            return Growth {
                r: self.r0,
                mass: self.initial_mass(),
                dr_dx: 0.0,
                d2r_dx2: 0.0,
                lambda: 0.0,
            };
        }
        let r = self.radius_at(x);
        let (dr_dx, bend) = match self.swath_width {
            None => (b / (2.0 * PI * r), 1.0),
            Some(w) => (b * w / (4.0 * PI * r * r), 2.0),
        };
        Growth {
            r,
            mass: self.mass_at(x),
            dr_dx,
            d2r_dx2: -bend * dr_dx * dr_dx / r,
            lambda: self.shape.mass_exponent() * dr_dx / r,
        }
    }
}

/// The body's size and its rate of growth at distance `x`
/// (`docs/snowball-and-losses.md` §1.1), for the equations of motion and the
/// contact forces of any shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Growth {
    /// r, m.
    pub r: Meters,
    /// M, kg.
    pub mass: Kilograms,
    /// r′ = dr/dx: b/(2πr) on the area law, b w/(4πr²) for a ball with a
    /// fixed swath w.
    pub dr_dx: f64,
    /// r″ = d²r/dx², 1/m: −r′²/r on the area law, −2r′²/r for a fixed swath.
    pub d2r_dx2: f64,
    /// λ = (dM/dx)/M = n r′/r (M ∝ rⁿ), 1/m.
    pub lambda: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bodies() -> [Body; 3] {
        let log = Body {
            shape: Shape::Cylinder,
            density: 400.0,
            length: 1.0,
            r0: 0.1,
            snow_depth: 0.01,
            swath_width: None,
        };
        let ball = Body {
            shape: Shape::Sphere,
            ..log
        };
        let ball_w = Body {
            swath_width: Some(0.05),
            ..ball
        };
        [log, ball, ball_w]
    }

    /// The snow picked up per metre rolled is ρ b times the swath: the
    /// derivative of M(x), by central differences, against the swath
    /// formula. Tolerance 1e-7 relative: the O(h²) truncation at h = 1e-3 m
    /// on a scale of metres, with rounding far below it.
    #[test]
    fn mass_grows_by_the_snow_of_the_swath() {
        let h = 1e-3;
        for body in bodies() {
            for x in [0.5, 5.0, 50.0] {
                let dm_dx = (body.mass_at(x + h) - body.mass_at(x - h)) / (2.0 * h);
                let want = body.density * body.snow_depth * body.swath(body.radius_at(x));
                assert!(
                    (dm_dx / want - 1.0).abs() < 1e-7,
                    "{:?} x = {x}: {dm_dx} vs {want}",
                    body.shape
                );
                // M(r(x)) is the same mass.
                let m = body.mass_of_radius(body.radius_at(x));
                assert!((m / body.mass_at(x) - 1.0).abs() < 1e-13);
            }
        }
    }

    /// Growth's λ = (dM/dx)/M and r′ = dr/dx agree with differences of
    /// M(x) and r(x) (same tolerance and reason as above).
    #[test]
    fn growth_rates_are_the_derivatives() {
        let h = 1e-3;
        for body in bodies() {
            let x = 3.0;
            let g = body.growth_at(x, true);
            let dr = (body.radius_at(x + h) - body.radius_at(x - h)) / (2.0 * h);
            let dm = (body.mass_at(x + h) - body.mass_at(x - h)) / (2.0 * h);
            assert!((g.dr_dx / dr - 1.0).abs() < 1e-7, "{:?}", body.shape);
            assert!(
                (g.lambda / (dm / g.mass) - 1.0).abs() < 1e-7,
                "{:?}",
                body.shape
            );
            let d2r =
                (body.radius_at(x + h) - 2.0 * body.radius_at(x) + body.radius_at(x - h)) / (h * h);
            assert!((g.d2r_dx2 / d2r - 1.0).abs() < 1e-4, "{:?}", body.shape);
        }
    }
}
