//! The physical set-up: slope, snow, log. Validated once, SI inside.

use serde::{Deserialize, Serialize};

use crate::error::ParamError;
use crate::units::{
    KilogramsPerCubicMeter, Meters, MetersPerSecond, MetersPerSecondSquared, Radians,
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
}

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
    /// Slope angle alpha, degrees, 0 < alpha < 90. Default 30.
    #[serde(alias = "slope_deg", alias = "alpha-deg")]
    pub alpha_deg: f64,
    /// Snow depth b normal to the slope, m, b >= 0 (0 = no snow). Default 0.01.
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
        }
    }
}

fn check(
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

impl Scenario {
    /// Validates `file` and converts it to SI (degrees to radians).
    ///
    /// # Errors
    /// [`ParamError::InvalidParameter`] naming the first parameter out of range.
    pub fn new(file: ScenarioFile) -> Result<Self, ParamError> {
        let alpha_deg = check(
            "slope angle (degrees)",
            file.alpha_deg,
            |a| a > 0.0 && a < 90.0,
            "0 < alpha < 90 degrees",
        )?;
        Ok(Self {
            alpha: alpha_deg.to_radians(),
            alpha_deg,
            b: check("snow depth (m)", file.snow_depth, |b| b >= 0.0, "b >= 0 m")?,
            r0: check("initial radius r0 (m)", file.r0, |r| r > 0.0, "r0 > 0 m")?,
            g: check("g (m/s^2)", file.g, |g| g > 0.0, "g > 0 m/s^2")?,
            rho: check(
                "density (kg/m^3)",
                file.density,
                |d| d > 0.0,
                "density > 0 kg/m^3",
            )?,
            l: check("log length (m)", file.length, |l| l > 0.0, "length > 0 m")?,
            v0: check(
                "initial speed v0 (m/s)",
                file.v0,
                |v| v >= 0.0,
                "v0 >= 0 m/s",
            )?,
        })
    }

    /// The same scenario with another snow depth (validated).
    ///
    /// # Errors
    /// As [`Scenario::new`].
    pub fn with_snow_depth(&self, b: Meters) -> Result<Self, ParamError> {
        Self::new(ScenarioFile {
            snow_depth: b,
            ..ScenarioFile::from(*self)
        })
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
        self.g * self.alpha.sin()
    }
    /// C = g cos alpha, the normal component of gravity, m/s².
    pub fn g_normal(&self) -> MetersPerSecondSquared {
        self.g * self.alpha.cos()
    }
    /// Initial mass m0 = pi rho l r0², eq. (37), kg.
    pub fn initial_mass(&self) -> f64 {
        std::f64::consts::PI * self.rho * self.l * self.r0 * self.r0
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
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_each_bad_value_by_name() {
        let bad = [
            (
                ScenarioFile {
                    alpha_deg: 90.0,
                    ..Default::default()
                },
                "slope",
            ),
            (
                ScenarioFile {
                    alpha_deg: 0.0,
                    ..Default::default()
                },
                "slope",
            ),
            (
                ScenarioFile {
                    snow_depth: -0.1,
                    ..Default::default()
                },
                "snow depth",
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
