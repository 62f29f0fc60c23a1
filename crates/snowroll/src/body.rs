//! The body that rolls, and everything the models need of its shape
//! (`docs/snowball-and-losses.md` §1): the factor k of its moment of
//! inertia, its mass as a function of its radius M(r), its radius after
//! rolling a distance r(x) with the snow it collects, the width of the swath
//! it picks up, and its frontal area for the drag. Every model reaches the
//! body through [`Body`] (from [`crate::Scenario::body`]), so that a new
//! shape is one more variant here.

use crate::portable::Portable as _;
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
    // `--help` shows these lines beside the flags' own, which write powers
    // in ASCII (`kg/m^3`, `pi r^2`): so do these, not one of each
    // (issue 36, item 4).
    /// A uniform cylinder of length l (the note's log): I = M r^2/2,
    /// M = pi rho l r^2, swath = l, so pi r^2 = pi r0^2 + b x (eq. (8)).
    #[default]
    Cylinder,
    /// A uniform ball: I = (2/5) M r^2, M = (4/3) pi rho r^3, swath 2r by
    /// default (again pi r^2 = pi r0^2 + b x), a fixed width w
    /// ((4 pi/3)(r^3 - r0^3) = b w x), or the contact chord
    /// 2 sqrt(2 r b - b^2), `docs/snowball-and-losses.md` §1.1.
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

/// The width of the swath of snow a ball picks up
/// (`docs/snowball-and-losses.md` §1.1); the log's is its length.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Swath {
    /// The ball's diameter 2r (the default): π r² = π r0² + b x, as for the
    /// log, and each turn adds a shell.
    #[default]
    Diameter,
    /// A fixed width w, m: (4π/3)(r³ − r0³) = b w x.
    Fixed(Meters),
    /// The chord 2√(2rb − b²) that the layer's top cuts from a ball pressed
    /// through it to the ground (b ≤ r): 4π r² dr = 2√(2rb − b²) b dx.
    Chord,
}

impl Swath {
    /// p of w ∝ r^p at large r (r ≫ b for the chord, w → 2√(2rb)): 1 for
    /// the diameter, 0 for a fixed width, ½ for the chord. The terminal
    /// fractions depend on it (`docs/snowball-and-losses.md` §1.3).
    pub fn power(self) -> f64 {
        match self {
            Swath::Diameter => 1.0,
            Swath::Fixed(_) => 0.0,
            Swath::Chord => 0.5,
        }
    }
}

/// The swath of a ball as a scenario file and the parameter table give it:
/// a width in metres, or the word `chord`; absent for the diameter 2r.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum SwathWidth {
    /// A fixed width, m.
    Metres(f64),
    /// The contact chord ([`Swath::Chord`]).
    Chord(ChordWord),
}

/// The one word of [`SwathWidth::Chord`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ChordWord {
    /// `chord`.
    Chord,
}

impl ChordWord {
    /// The word, as `--swath-width` takes it.
    pub const ID: &'static str = "chord";
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
    /// A ball's swath ([`Swath::Diameter`] for the log, whose swath is its
    /// length whatever this says).
    pub swath: Swath,
    /// The tube of an unwinding roll, when it has a mass of its own; `None`:
    /// the body is of one material down to its centre.
    pub tube: Option<Tube>,
}

/// The core of an unwinding roll as a body of its own (`docs/unwinding.md`,
/// "The core"): a thin-walled tube of radius `radius` and mass `mass` (a
/// thin spherical shell for the ball), hollow inside. The roll's material
/// lies between it and r, so
///
/// `M(r) = m_c + M_u(r) − M_u(r_c)`,  `I(r) = I_c + I_u(r) − I_u(r_c)`,
///
/// with M_u, I_u = k M_u r² those of the uniform body and `I_c = m_c r_c²`
/// (the ball's shell: `(2/3) m_c r_c²`). dM/dx and dI/dx are the uniform
/// body's: the tube only shifts M and I by constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tube {
    /// Its radius r_c, m (the scenario's core radius).
    pub radius: Meters,
    /// Its mass m_c, kg.
    pub mass: Kilograms,
}

impl Body {
    /// k = I/(M r²): ½ for the log, 2/5 for the ball.
    pub fn inertia_factor(&self) -> f64 {
        self.shape.inertia_factor()
    }

    /// M(r), kg: π ρ l r² for the log (eq. (37)), (4/3) π ρ r³ for the ball;
    /// with a [`Tube`], `m_c + M_u(r) − M_u(r_c)`, the difference written as a
    /// product so that it does not cancel near the core.
    pub fn mass_of_radius(&self, r: Meters) -> Kilograms {
        let Some(t) = self.tube else {
            return self.uniform_mass(r);
        };
        let c = t.radius;
        let shell = match self.shape {
            Shape::Cylinder => PI * self.density * self.length * (r - c) * (r + c),
            Shape::Sphere => 4.0 * PI * self.density * (r - c) * (r * r + r * c + c * c) / 3.0,
        };
        t.mass + shell
    }

    /// The mass the tube adds to the uniform body, m_c − M_u(r_c), kg (0
    /// without one; negative when the tube is lighter than the material it
    /// replaces).
    pub fn tube_offset(&self) -> Kilograms {
        self.tube
            .map_or(0.0, |t| t.mass - self.uniform_mass(t.radius))
    }

    /// M_u(r) of the uniform body, kg: π ρ l r², (4/3) π ρ r³.
    fn uniform_mass(&self, r: Meters) -> Kilograms {
        match self.shape {
            Shape::Cylinder => PI * self.density * self.length * r * r,
            Shape::Sphere => 4.0 * PI * self.density * r * r * r / 3.0,
        }
    }

    /// I(r) about the centre, kg m²: k M(r) r² for a uniform body; with a
    /// [`Tube`], `I_c + I_u(r) − I_u(r_c)` ([`Tube`]), the difference as a
    /// product: `(π ρ l/2)(r − r_c)(r + r_c)(r² + r_c²)` for the log,
    /// `(8π ρ/15)(r − r_c)(r⁴ + r³r_c + r²r_c² + r r_c³ + r_c⁴)` for the ball.
    pub fn moment_of_inertia(&self, r: Meters) -> f64 {
        let k = self.inertia_factor();
        let Some(t) = self.tube else {
            return k * self.uniform_mass(r) * r * r;
        };
        let c = t.radius;
        let (shell, tube) = match self.shape {
            Shape::Cylinder => (
                PI * self.density * self.length * (r - c) * (r + c) * (r * r + c * c) / 2.0,
                t.mass * c * c,
            ),
            Shape::Sphere => (
                8.0 * PI
                    * self.density
                    * (r - c)
                    * (r.powi(4) + r.powi(3) * c + r * r * c * c + r * c.powi(3) + c.powi(4))
                    / 15.0,
                2.0 * t.mass * c * c / 3.0,
            ),
        };
        tube + shell
    }

    /// m0 = M(r0), kg.
    pub fn initial_mass(&self) -> Kilograms {
        self.mass_of_radius(self.r0)
    }

    /// Radius after rolling a distance `x`: `π r² = π r0² + b x` (eq. (8)) for
    /// the log and for the ball with its natural swath 2r; for a ball with a
    /// fixed swath w, `(4π/3)(r³ − r0³) = b w x`; for the chord, the root of
    /// [`Body::chord_distance`] (`docs/snowball-and-losses.md` §1.1).
    pub fn radius_at(&self, x: Meters) -> Meters {
        let (r0, b) = (self.r0, self.snow_depth);
        match self.ball_swath() {
            Swath::Diameter => (r0 * r0 + b * x / PI).sqrt(),
            Swath::Fixed(w) => (r0 * r0 * r0 + 3.0 * b * w * x / (4.0 * PI)).cbrt_p(),
            Swath::Chord => self.chord_radius(x),
        }
    }

    /// The distance rolled where the radius is `r`, m, the inverse of
    /// [`Body::radius_at`] on the area law (`π (r² − r0²)/b`, eq. (8)) and
    /// on a fixed swath (`4π (r³ − r0³)/(3 b w)`); `None` without a layer
    /// (b = 0) and on the chord swath (the unwinding roll's core, whose
    /// radius the run stops at, is reached only with b < 0).
    pub fn distance_to_radius(&self, r: Meters) -> Option<Meters> {
        let (r0, b) = (self.r0, self.snow_depth);
        if b == 0.0 {
            return None;
        }
        match self.ball_swath() {
            Swath::Diameter => Some(PI * (r - r0) * (r + r0) / b),
            Swath::Fixed(w) => {
                Some(4.0 * PI * (r - r0) * (r * r + r * r0 + r0 * r0) / (3.0 * b * w))
            }
            Swath::Chord => None,
        }
    }

    /// The swath that sets the growth: the ball's own, the log's length
    /// (which follows the area law as [`Swath::Diameter`] does).
    fn ball_swath(&self) -> Swath {
        match self.shape {
            Shape::Cylinder => Swath::Diameter,
            Shape::Sphere => self.swath,
        }
    }

    /// The distance a ball on the chord swath rolls while its radius grows
    /// from r0 to `r` (b ≤ r0 ≤ r), m: with u = b(2r − b) and s = √u,
    /// `x = (π/(4b⁴)) [F(s) − F(s0)]`, `F(s) = (2/5)s⁵ + (4/3)b²s³ + 2b⁴s`
    /// (`docs/snowball-and-losses.md` §1.1), written as (s − s0) times a sum
    /// of positive terms so that it does not cancel near r0.
    pub fn chord_distance(&self, r: Meters) -> Meters {
        let (r0, b) = (self.r0, self.snow_depth);
        let (s, s0) = ((b * (2.0 * r - b)).sqrt(), (b * (2.0 * r0 - b)).sqrt());
        let ds = 2.0 * b * (r - r0) / (s + s0);
        let (s2, s02) = (s * s, s0 * s0);
        let quartic = s2 * s2 + s2 * s * s0 + s2 * s02 + s * s0 * s02 + s02 * s02;
        let b2 = b * b;
        let sum = 0.4 * quartic + 4.0 * b2 * (s2 + s * s0 + s02) / 3.0 + 2.0 * b2 * b2;
        PI * ds * sum / (4.0 * b2 * b2)
    }

    /// r(x) on the chord swath: Newton's method on [`Body::chord_distance`],
    /// which is increasing and convex in r, from a start above the root
    /// (F(s) > (2/5)s⁵), so that the iterates fall monotonically to it.
    fn chord_radius(&self, x: Meters) -> Meters {
        let (r0, b) = (self.r0, self.snow_depth);
        if b == 0.0 || x <= 0.0 {
            return r0;
        }
        let s0 = (b * (2.0 * r0 - b)).sqrt();
        let f0 = 0.4 * s0.powi(5) + 4.0 * b * b * s0.powi(3) / 3.0 + 2.0 * b.powi(4) * s0;
        let s = (2.5 * (4.0 * b.powi(4) * x / PI + f0)).powf_p(0.2);
        let mut r = (s * s / b + b) / 2.0;
        for _ in 0..200 {
            let slope = 4.0 * PI * r * r / (b * self.swath(r));
            let step = (self.chord_distance(r) - x) / slope;
            r -= step;
            if step.abs() <= 2.0 * f64::EPSILON * r {
                break;
            }
        }
        r.max(r0)
    }

    /// Mass after rolling `x`, kg: `m = m0 + ρ b l x` (= π ρ l r², eq. (8)) for
    /// the log; M(r(x)) for the ball, which is `m0 + ρ b w x` with a fixed
    /// swath w.
    pub fn mass_at(&self, x: Meters) -> Kilograms {
        let (rho, b) = (self.density, self.snow_depth);
        match (self.shape, self.swath) {
            (Shape::Cylinder, _) => self.initial_mass() + rho * b * self.length * x,
            (Shape::Sphere, Swath::Fixed(w)) => self.initial_mass() + rho * b * w * x,
            (Shape::Sphere, _) => self.mass_of_radius(self.radius_at(x)),
        }
    }

    /// The width of the swath of snow picked up at radius `r`, m: the log's
    /// length, a ball's fixed width w, its chord 2√(2rb − b²), else its
    /// diameter 2r.
    pub fn swath(&self, r: Meters) -> Meters {
        let b = self.snow_depth;
        match (self.shape, self.swath) {
            (Shape::Cylinder, _) => self.length,
            (Shape::Sphere, Swath::Diameter) => 2.0 * r,
            (Shape::Sphere, Swath::Fixed(w)) => w,
            (Shape::Sphere, Swath::Chord) => 2.0 * (b * (2.0 * r - b)).max(0.0).sqrt(),
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
            let (r, mass) = (self.r0, self.initial_mass());
            return Growth {
                r,
                mass,
                dr_dx: 0.0,
                d2r_dx2: 0.0,
                lambda: 0.0,
                tube: self.tube.map(|_| TubeShares {
                    inertia: self.moment_of_inertia(r) / (mass * r * r),
                    inertia_rate: 0.0,
                }),
            };
        }
        let r = self.radius_at(x);
        // r″ = −bend r′²/r.
        let (dr_dx, bend) = match self.ball_swath() {
            Swath::Diameter => (b / (2.0 * PI * r), 1.0),
            Swath::Fixed(w) => (b * w / (4.0 * PI * r * r), 2.0),
            Swath::Chord => {
                // r′ = b w/(4πr²), w′ = 4b/w: r″ = r′²(2/r − 4b/w²)·(−1).
                let w = self.swath(r);
                (b * w / (4.0 * PI * r * r), 2.0 - 4.0 * b * r / (w * w))
            }
        };
        let n = self.shape.mass_exponent();
        let mass = self.mass_at(x);
        // dM/dx = n M_u r′/r whatever the tube (it shifts M by a constant);
        // dI/dx = (n + 2) k M_u r r′.
        let (lambda, tube) = match self.tube {
            None => (n * dr_dx / r, None),
            Some(_) => {
                let uniform = self.uniform_mass(r) / mass;
                let k = self.inertia_factor();
                (
                    n * uniform * dr_dx / r,
                    Some(TubeShares {
                        inertia: self.moment_of_inertia(r) / (mass * r * r),
                        inertia_rate: (n + 2.0) * k * uniform * dr_dx / r,
                    }),
                )
            }
        };
        Growth {
            r,
            mass,
            dr_dx,
            d2r_dx2: -bend * dr_dx * dr_dx / r,
            lambda,
            tube,
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
    /// fixed swath w or the chord w = 2√(2rb − b²).
    pub dr_dx: f64,
    /// r″ = d²r/dx², 1/m: −r′²/r on the area law, −2r′²/r for a fixed swath,
    /// −r′²(2/r − 4b/w²) for the chord.
    pub d2r_dx2: f64,
    /// λ = (dM/dx)/M, 1/m: n r′/r (M ∝ rⁿ); with a [`Tube`],
    /// n (M_u/M) r′/r.
    pub lambda: f64,
    /// With a [`Tube`], the moment of inertia per unit mass, which is then no
    /// longer k r²; `None` for a uniform body.
    pub tube: Option<TubeShares>,
}

/// The moment of inertia of a body with a [`Tube`] per M r²
/// (`docs/unwinding.md`, "The core"); for a uniform body these would be k
/// and k (n + 2) r′/r.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TubeShares {
    /// j = I/(M r²).
    pub inertia: f64,
    /// (dI/dx)/(M r²), 1/m.
    pub inertia_rate: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bodies() -> [Body; 4] {
        let log = Body {
            shape: Shape::Cylinder,
            density: 400.0,
            length: 1.0,
            r0: 0.1,
            snow_depth: 0.01,
            swath: Swath::Diameter,
            tube: None,
        };
        let ball = Body {
            shape: Shape::Sphere,
            ..log
        };
        let ball_w = Body {
            swath: Swath::Fixed(0.05),
            ..ball
        };
        let ball_chord = Body {
            swath: Swath::Chord,
            ..ball
        };
        [log, ball, ball_w, ball_chord]
    }

    /// The chord's r(x) is the inverse of its distance law: x(r(x)) = x to
    /// rounding (1e-12 relative: Newton stops at a step of 2 ulp in r, and
    /// x(r) has condition number (dx/dr) r/x ≤ 5/2 + 1 there), from 1 mm to
    /// 10⁸ m; and the chord is the geometry's, w² = 4(r² − (r − b)²).
    #[test]
    fn chord_radius_inverts_its_distance_law() {
        let ball = bodies()[3];
        for x in [1e-3, 0.5, 5.0, 50.0, 1e4, 1e8] {
            let r = ball.radius_at(x);
            let back = ball.chord_distance(r);
            assert!((back / x - 1.0).abs() < 1e-12, "x = {x}: {back}");
            let (w, b) = (ball.swath(r), ball.snow_depth);
            let depth = r - b;
            assert!((w * w / (4.0 * (r * r - depth * depth)) - 1.0).abs() < 1e-12);
        }
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
