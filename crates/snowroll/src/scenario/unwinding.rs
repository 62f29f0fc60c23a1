//! The checks of the unwinding roll's set-up (b < 0, `docs/unwinding.md`):
//! its core radius, and what it goes with.

use super::{check, ScenarioFile, SwathWidth};
use crate::error::ParamError;
use crate::units::{Kilograms, Meters};

/// The core radius of a scenario file, checked: required for an unwinding
/// roll (b < 0), where 0 < core_radius < r0; refused otherwise. The ball's
/// chord swath is refused with b < 0 (the chord is where a layer's top cuts
/// a ball pressed into it: there is no such layer to press into).
pub(crate) fn core_of(file: &ScenarioFile) -> Result<Option<Meters>, ParamError> {
    const NAME: &str = "core_radius (m)";
    let core = match file.core_radius {
        Some(c) => Some(check(NAME, c, |c| c > 0.0 && c < file.r0, CORE_RANGE)?),
        None => None,
    };
    match core {
        Some(c) if file.snow_depth >= 0.0 => Err(ParamError::InvalidParameter {
            name: NAME,
            value: c,
            expected: "no core_radius with snow_depth >= 0: the core is where an unwinding \
                       roll (snow_depth < 0) stops; drop {core_radius} or give a negative \
                       {snow_depth}",
        }),
        None if file.snow_depth < 0.0 => Err(ParamError::InvalidParameter {
            name: "snow_depth (m)",
            value: file.snow_depth,
            expected: "snow_depth >= 0 without core_radius: a negative snow depth is an \
                       unwinding roll, which needs {core_radius} (0 < core_radius < r0), the \
                       radius where it stops",
        }),
        _ if file.snow_depth < 0.0 && matches!(file.swath_width, Some(SwathWidth::Chord(_))) => {
            Err(ParamError::InvalidParameter {
                name: "snow_depth (m)",
                value: file.snow_depth,
                expected: "snow_depth >= 0 with swath_width = chord (an unwinding ball lays \
                           its layer on its diameter or a fixed width); give another \
                           {swath_width}",
            })
        }
        core => Ok(core),
    }
}

/// The range of the core radius, as the parameter table states it.
const CORE_RANGE: &str = "0 < core_radius < r0 m (only with snow_depth < 0)";

/// The core's own mass of a scenario file, checked: > 0 kg, and only with a
/// core radius (so only for an unwinding roll). A massless hollow core is
/// refused: the last layer would leave a body of no mass and no moment of
/// inertia, and the speed of every model would grow without bound as it does.
pub(crate) fn core_mass_of(file: &ScenarioFile) -> Result<Option<Kilograms>, ParamError> {
    const NAME: &str = "core_mass (kg)";
    let Some(m) = file.core_mass else {
        return Ok(None);
    };
    let m = check(NAME, m, |m| m > 0.0, CORE_MASS_RANGE)?;
    if file.core_radius.is_none() {
        return Err(ParamError::InvalidParameter {
            name: NAME,
            value: m,
            expected: "no core_mass without core_radius: it is the mass of the tube an \
                       unwinding roll (snow_depth < 0) ends on; give {core_radius} or drop \
                       {core_mass}",
        });
    }
    Ok(Some(m))
}

/// The range of the core's mass, as the parameter table states it.
const CORE_MASS_RANGE: &str = "core_mass > 0 kg (only with core_radius)";
