//! The physical set-up: slope, snow, log. Validated once, SI inside.

use crate::portable::Portable as _;
use serde::{Deserialize, Serialize};

use crate::body::{Body, Tube};
use crate::error::ParamError;
use crate::units::{
    Kilograms, KilogramsPerCubicMeter, Meters, MetersPerSecond, MetersPerSecondSquared, Radians,
};

/// A validated scenario: a log of radius `r0` starting at `x = 0` with speed
/// `v0` on a slope of angle `alpha` covered by snow of depth `b` (normal to
/// the slope; the snow occupies `-b < y < 0` below the plane the core rolls
/// on, `docs/turn-model.md`, Conventions).
///
/// Build it with [`Scenario::new`] from a [`ScenarioFile`]; every field is
/// checked there, so a `Scenario` that exists is a valid one.
///
/// ```
/// use snowroll::{Scenario, ScenarioFile};
/// let s = Scenario::new(ScenarioFile { alpha_deg: 30.0, ..ScenarioFile::default() })?;
/// assert!((s.slope_angle().to_degrees() - 30.0).abs() < 1e-12);
/// # Ok::<(), snowroll::ParamError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "ScenarioFile", into = "ScenarioFile")]
pub struct Scenario {
    alpha: Radians,
    /// The angle as given, kept so that outputs record exactly what was asked.
    alpha_deg: f64,
    b: Meters,
    r0: Meters,
    g: MetersPerSecondSquared,
    rho: KilogramsPerCubicMeter,
    l: Meters,
    v0: MetersPerSecond,
    shape: Shape,
    swath: Swath,
    /// g sin alpha and g cos alpha, computed once (every run and every
    /// sweep row reads them several times; the same bits as computing them
    /// on each call).
    gravity_parts: (MetersPerSecondSquared, MetersPerSecondSquared),
    /// The core radius of an unwinding roll (b < 0), m.
    core: Option<Meters>,
    /// The mass of that core's tube, kg; `None`: the core is taken as the
    /// roll's own material (`docs/unwinding.md`, "The core").
    core_mass: Option<Kilograms>,
}

/// (g sin alpha, g cos alpha).
fn gravity_parts(g: f64, alpha: f64) -> (f64, f64) {
    (g * alpha.sin_p(), g * alpha.cos_p())
}

mod scales;
mod unwinding;

pub use crate::body::{ChordWord, Shape, Swath, SwathWidth};

/// The user-facing form of a [`Scenario`], in the project's one parameter
/// vocabulary: each field is named as the command line's long flag in
/// snake_case (`--alpha-deg` is `alpha_deg`, `--snow-depth` is `snow_depth`),
/// and the same names are the keys of config files, of the parameters every
/// output records, and of the Python package's keywords. Units are SI, angles
/// in degrees. The names of earlier outputs (`slope_deg`, `snow_depth_m`,
/// `r0_m`, `g_m_s2`, `density_kg_m3`, `length_m`, `v0_m_s`) are accepted as
/// aliases when reading.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ScenarioFile {
    /// Slope angle alpha, degrees, 0 < alpha < 90 (0 <= alpha for an
    /// unwinding roll, b < 0). Default 30.
    #[serde(alias = "slope_deg", alias = "alpha-deg")]
    pub alpha_deg: f64,
    /// Snow depth b normal to the slope, m (0 = no snow). Default 0.01.
    /// Negative: the unwinding roll (`docs/unwinding.md`), which lays a
    /// layer of thickness |b| down per unit of distance instead of picking
    /// one up (π r² = π r0² + b x, eq. (8), with b < 0), down to
    /// [`core_radius`](Self::core_radius).
    #[serde(alias = "snow_depth_m", alias = "snow-depth")]
    pub snow_depth: f64,
    /// Initial radius r0 of the log, m, > 0. Default 0.1.
    #[serde(alias = "r0_m")]
    pub r0: f64,
    /// Gravitational acceleration g, m/s², > 0. Default 9.81.
    #[serde(alias = "g_m_s2")]
    pub g: f64,
    /// Density rho of log and snow, kg/m³, > 0. Default 400.
    #[serde(alias = "density_kg_m3")]
    pub density: f64,
    /// Length l of the log, m, > 0. Default 1.
    #[serde(alias = "length_m")]
    pub length: f64,
    /// Initial speed v0 down the slope, m/s, >= 0. Default 0.
    #[serde(alias = "v0_m_s")]
    pub v0: f64,
    /// The body: `cylinder` (the log) or `sphere` (the snowball). Default
    /// `cylinder`. The length applies to the cylinder only.
    pub shape: Shape,
    /// Width w of the swath of snow a ball picks up, m, > 0, or `chord` (the
    /// contact chord 2√(2rb − b²), b ≤ r0); `None` (the default) = the
    /// ball's diameter 2r, which grows with it
    /// (`docs/snowball-and-losses.md` §1.1). Only for `shape = sphere`: a
    /// log's swath is its length.
    #[serde(alias = "swath-width", skip_serializing_if = "Option::is_none")]
    pub swath_width: Option<SwathWidth>,
    /// Radius of the core of an unwinding roll (b < 0), m, 0 < core < r0:
    /// the run stops with `unwound` where r reaches it (`docs/unwinding.md`).
    /// Required with b < 0, refused with b >= 0.
    #[serde(alias = "core-radius", skip_serializing_if = "Option::is_none")]
    pub core_radius: Option<f64>,
    /// Mass of the core's tube, kg, > 0 (only with `core_radius`): a
    /// thin-walled tube (a ball's core: a thin shell) of that mass at the
    /// core radius, inside which the roll is hollow. `None` (the default):
    /// the roll is of one material down to its centre, as the note's log
    /// (`docs/unwinding.md`, "The core").
    #[serde(alias = "core-mass", skip_serializing_if = "Option::is_none")]
    pub core_mass: Option<f64>,
}

impl Default for ScenarioFile {
    fn default() -> Self {
        Self {
            alpha_deg: 30.0,
            snow_depth: 0.01,
            r0: 0.1,
            g: 9.81,
            density: 400.0,
            length: 1.0,
            v0: 0.0,
            shape: Shape::Cylinder,
            swath_width: None,
            core_radius: None,
            core_mass: None,
        }
    }
}

pub(crate) fn check(
    name: &'static str,
    value: f64,
    ok: impl Fn(f64) -> bool,
    expected: &'static str,
) -> Result<f64, ParamError> {
    if value.is_finite() && ok(value) {
        Ok(value)
    } else {
        Err(ParamError::InvalidParameter {
            name,
            value,
            expected,
        })
    }
}

/// The largest magnitude of any parameter or derived quantity (SI units).
///
/// The models multiply such quantities in pairs (m v², I ω², b x, r²): two
/// numbers at most 1e150 have a product at most 1e300, below the largest
/// `f64` (1.8e308), so a scenario inside this window cannot overflow in its
/// first steps; what a long run still pushes out of range is refused by the
/// writers (`snowroll_io::check_finite`).
pub const MAX_MAGNITUDE: f64 = 1e150;

/// The smallest non-zero magnitude of any parameter or derived quantity (SI
/// units): the product of two is at least 1e-300, above the smallest
/// normal `f64` (2.2e-308), so nothing underflows to zero or loses its
/// precision to subnormals.
pub const MIN_MAGNITUDE: f64 = 1e-150;

/// Checks that `value` is zero (when `zero_ok`) or has a magnitude in
/// [`MIN_MAGNITUDE`, `MAX_MAGNITUDE`].
pub(crate) fn check_scale(
    quantity: &'static str,
    value: f64,
    zero_ok: bool,
    hint: &'static str,
) -> Result<(), ParamError> {
    let a = value.abs();
    if (zero_ok && a == 0.0) || (MIN_MAGNITUDE..=MAX_MAGNITUDE).contains(&a) {
        Ok(())
    } else {
        Err(ParamError::OutOfScale {
            quantity,
            value,
            allowed: format!(
                "{}{MIN_MAGNITUDE:e} <= |value| <= {MAX_MAGNITUDE:e} in SI units",
                if zero_ok { "0 or " } else { "" }
            ),
            hint,
        })
    }
}

impl Scenario {
    /// Validates `file` and converts it to SI (degrees to radians).
    ///
    /// Each parameter must be in its physical range, and each parameter and
    /// each quantity derived from them at the start of the run (area, mass,
    /// moment of inertia, weight, energies) must be zero or of a magnitude
    /// between [`MIN_MAGNITUDE`] and [`MAX_MAGNITUDE`].
    ///
    /// # Errors
    /// [`ParamError::InvalidParameter`] naming the first parameter out of
    /// range; [`ParamError::OutOfScale`] naming the first quantity out of
    /// scale.
    pub fn new(file: ScenarioFile) -> Result<Self, ParamError> {
        let s = Self::new_unscaled(file)?;
        s.check_scales()?;
        Ok(s)
    }

    /// [`Scenario::new`] without the checks of scale.
    fn new_unscaled(file: ScenarioFile) -> Result<Self, ParamError> {
        let unwinding = file.snow_depth < 0.0;
        let alpha_deg = check(
            "alpha_deg (degrees)",
            file.alpha_deg,
            |a| (a > 0.0 || (unwinding && a == 0.0)) && a < 90.0,
            "0 < alpha_deg < 90 degrees (0 <= alpha_deg for an unwinding roll, snow_depth < 0)",
        )?;
        let b = check(
            "snow_depth (m)",
            file.snow_depth,
            |_| true,
            "finite snow_depth m (< 0: an unwinding roll, with core_radius)",
        )?;
        let r0 = check("r0 (m)", file.r0, |r| r > 0.0, "r0 > 0 m")?;
        let mut s = Self {
            alpha: alpha_deg.to_radians(),
            alpha_deg,
            b,
            r0,
            g: check("g (m/s^2)", file.g, |g| g > 0.0, "g > 0 m/s^2")?,
            rho: check(
                "density (kg/m^3)",
                file.density,
                |d| d > 0.0,
                "density > 0 kg/m^3",
            )?,
            l: check("length (m)", file.length, |l| l > 0.0, "length > 0 m")?,
            v0: check("v0 (m/s)", file.v0, |v| v >= 0.0, "v0 >= 0 m/s")?,
            shape: file.shape,
            swath: swath_of(&file)?,
            core: unwinding::core_of(&file)?,
            core_mass: unwinding::core_mass_of(&file)?,
            gravity_parts: (0.0, 0.0),
        };
        s.gravity_parts = gravity_parts(s.g, s.alpha);
        Ok(s)
    }

    /// Slope angle alpha, rad.
    pub fn slope_angle(&self) -> Radians {
        self.alpha
    }
    /// Snow depth b, m.
    pub fn snow_depth(&self) -> Meters {
        self.b
    }
    /// Initial radius r0, m.
    pub fn initial_radius(&self) -> Meters {
        self.r0
    }
    /// Gravitational acceleration g, m/s².
    pub fn gravity(&self) -> MetersPerSecondSquared {
        self.g
    }
    /// Density rho of log and snow, kg/m³.
    pub fn density(&self) -> KilogramsPerCubicMeter {
        self.rho
    }
    /// Length l of the log, m.
    pub fn length(&self) -> Meters {
        self.l
    }
    /// Initial speed v0, m/s.
    pub fn initial_speed(&self) -> MetersPerSecond {
        self.v0
    }
    /// G = g sin alpha, the slope component of gravity, m/s².
    pub fn g_along(&self) -> MetersPerSecondSquared {
        self.gravity_parts.0
    }
    /// C = g cos alpha, the normal component of gravity, m/s².
    pub fn g_normal(&self) -> MetersPerSecondSquared {
        self.gravity_parts.1
    }
    /// The core radius of an unwinding roll (b < 0), m; `None` otherwise.
    pub fn core_radius(&self) -> Option<Meters> {
        self.core
    }
    /// The mass of the unwinding roll's tube, kg; `None` when the core is
    /// the roll's own material, or the roll does not unwind.
    pub fn core_mass(&self) -> Option<Kilograms> {
        self.core_mass
    }
    /// Whether the equations of motion take the common form of §2
    /// (`models/circular`): r(x) on the area law (eq. (8)) and a uniform
    /// body, M ∝ rⁿ and I = k M r². A tube of its own mass
    /// ([`core_mass`](Self::core_mass)) breaks the second.
    pub fn has_common_form(&self) -> bool {
        self.follows_area_law() && self.core_mass.is_none()
    }
    /// The same scenario with the core of the roll's own material
    /// (no [`core_mass`](Self::core_mass)).
    pub(crate) fn uniform(&self) -> Scenario {
        Scenario {
            core_mass: None,
            ..*self
        }
    }
    /// Whether the body lays a layer down (b < 0, the unwinding roll)
    /// rather than picking one up.
    pub fn unwinds(&self) -> bool {
        self.b < 0.0
    }
    /// The distance rolled where an unwinding roll reaches its core, m
    /// ([`Body::distance_to_radius`]); `None` when it does not unwind.
    pub fn unwound_at(&self) -> Option<Meters> {
        self.body().distance_to_radius(self.core?)
    }
    /// The body's shape.
    pub fn shape(&self) -> Shape {
        self.shape
    }
    /// The fixed swath width w of a ball, m; `None` for the ball's natural
    /// swath 2r and for the chord, and always for the cylinder (its swath is
    /// its length).
    pub fn swath_width(&self) -> Option<Meters> {
        match self.swath {
            Swath::Fixed(w) => Some(w),
            Swath::Diameter | Swath::Chord => None,
        }
    }
    /// The ball's swath ([`Swath::Diameter`] for the cylinder).
    pub fn swath(&self) -> Swath {
        self.swath
    }
    /// Whether r(x) follows the area law π r² = π r0² + b x (eq. (8)): the
    /// log, and the ball with its natural swath 2r.
    pub fn follows_area_law(&self) -> bool {
        self.swath == Swath::Diameter
    }
    /// Initial mass, kg: m0 = π ρ l r0² for the log (eq. (37)),
    /// (4/3) π ρ r0³ for the ball.
    pub fn initial_mass(&self) -> f64 {
        self.body().initial_mass()
    }

    /// The body: its shape, size and growth law (k, M(r), r(x), swath,
    /// frontal area).
    pub fn body(&self) -> Body {
        Body {
            shape: self.shape,
            density: self.rho,
            length: self.l,
            r0: self.r0,
            snow_depth: self.b,
            swath: self.swath,
            tube: match (self.core, self.core_mass) {
                (Some(radius), Some(mass)) => Some(Tube { radius, mass }),
                _ => None,
            },
        }
    }
}

/// The ball's swath of a scenario file, checked: a width w > 0, or the
/// chord, which needs the layer no deeper than the ball's radius
/// (b ≤ r0); none for the log.
fn swath_of(file: &ScenarioFile) -> Result<Swath, ParamError> {
    const NAME: &str = "swath_width (m)";
    match (file.shape, file.swath_width) {
        (_, None) => Ok(Swath::Diameter),
        (Shape::Sphere, Some(SwathWidth::Metres(w))) => Ok(Swath::Fixed(check(
            NAME,
            w,
            |w| w > 0.0,
            "swath_width > 0 m, or chord",
        )?)),
        (Shape::Sphere, Some(SwathWidth::Chord(_))) if file.snow_depth > file.r0 => {
            Err(ParamError::InvalidParameter {
                name: "snow_depth (m)",
                value: file.snow_depth,
                expected: "snow_depth <= r0 with swath_width = chord (the chord 2 sqrt(2 r b - b^2) is where the \
                           layer's top cuts a ball resting on the ground under it); give a \
                           larger {r0}, a smaller {snow_depth} or another {swath_width}",
            })
        }
        (Shape::Sphere, Some(SwathWidth::Chord(_))) => Ok(Swath::Chord),
        (Shape::Cylinder, Some(w)) => Err(ParamError::InvalidParameter {
            name: NAME,
            value: match w {
                SwathWidth::Metres(w) => w,
                SwathWidth::Chord(_) => f64::NAN,
            },
            expected: "no swath width for shape = cylinder (a log's swath is its \
                       length); give {shape sphere} or drop {swath_width}",
        }),
    }
}

impl TryFrom<ScenarioFile> for Scenario {
    type Error = ParamError;
    fn try_from(file: ScenarioFile) -> Result<Self, ParamError> {
        Scenario::new(file)
    }
}

impl From<Scenario> for ScenarioFile {
    fn from(s: Scenario) -> Self {
        Self {
            alpha_deg: s.alpha_deg,
            snow_depth: s.b,
            r0: s.r0,
            g: s.g,
            density: s.rho,
            length: s.l,
            v0: s.v0,
            shape: s.shape,
            swath_width: match s.swath {
                Swath::Diameter => None,
                Swath::Fixed(w) => Some(SwathWidth::Metres(w)),
                Swath::Chord => Some(SwathWidth::Chord(ChordWord::Chord)),
            },
            core_radius: s.core,
            core_mass: s.core_mass,
        }
    }
}

impl Default for Scenario {
    /// The defaults of [`ScenarioFile`]: 30°, b = 1 cm, r0 = 10 cm, g = 9.81.
    fn default() -> Self {
        // The defaults are inside every range checked by `new`; build the
        // struct directly so that `default` cannot fail.
        let f = ScenarioFile::default();
        Self {
            alpha: f.alpha_deg.to_radians(),
            alpha_deg: f.alpha_deg,
            b: f.snow_depth,
            r0: f.r0,
            g: f.g,
            rho: f.density,
            l: f.length,
            v0: f.v0,
            shape: f.shape,
            swath: Swath::Diameter,
            gravity_parts: gravity_parts(f.g, f.alpha_deg.to_radians()),
            core: None,
            core_mass: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scale checks use the ball's own mass (4/3) π ρ r0³, not the log's
    /// π ρ l r0²: with ρ = 5e149 kg/m³, r0 = 1 m, l = 1 mm the ball's m0 ≈ 2.1e150 kg
    /// is out of scale, the log's ≈ 1.6e147 kg is not.
    #[test]
    fn scale_checks_name_the_balls_own_formulae() {
        let heavy = ScenarioFile {
            r0: 1.0,
            length: 1e-3,
            density: 5e149,
            shape: Shape::Sphere,
            ..Default::default()
        };
        let err = Scenario::new(heavy).unwrap_err();
        let msg = err.to_string();
        assert!(msg.contains("4 pi rho r0^3/3"), "{msg}");
        assert!(!err.named_keys().contains(&"length"), "{msg}");
        let log = ScenarioFile {
            shape: Shape::Cylinder,
            ..heavy
        };
        assert!(Scenario::new(log).is_ok());
    }

    #[test]
    fn rejects_each_bad_value_by_name() {
        let bad = [
            (
                ScenarioFile {
                    alpha_deg: 90.0,
                    ..Default::default()
                },
                "alpha_deg (degrees) = ",
            ),
            (
                ScenarioFile {
                    alpha_deg: 0.0,
                    ..Default::default()
                },
                "alpha_deg (degrees) = ",
            ),
            (
                ScenarioFile {
                    snow_depth: -0.1,
                    ..Default::default()
                },
                "snow_depth (m) = ",
            ),
            (
                ScenarioFile {
                    r0: 0.0,
                    ..Default::default()
                },
                "r0",
            ),
            (
                ScenarioFile {
                    g: f64::NAN,
                    ..Default::default()
                },
                "g",
            ),
            (
                ScenarioFile {
                    density: -1.0,
                    ..Default::default()
                },
                "density",
            ),
            (
                ScenarioFile {
                    length: f64::INFINITY,
                    ..Default::default()
                },
                "length",
            ),
            (
                ScenarioFile {
                    v0: -1.0,
                    ..Default::default()
                },
                "v0",
            ),
        ];
        for (file, name) in bad {
            let err = Scenario::new(file).unwrap_err().to_string();
            assert!(err.contains(name), "{err} should name {name}");
        }
    }

    #[test]
    fn default_is_valid_and_round_trips() {
        let s = Scenario::default();
        assert_eq!(Scenario::new(ScenarioFile::from(s)).unwrap(), s);
    }
}
