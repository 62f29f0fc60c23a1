//! Type aliases that say which SI unit a plain `f64` carries.

/// Length, m.
pub type Meters = f64;
/// Time, s.
pub type Seconds = f64;
/// Angle, rad.
pub type Radians = f64;
/// Speed, m/s.
pub type MetersPerSecond = f64;
/// Acceleration, m/s².
pub type MetersPerSecondSquared = f64;
/// Mass, kg.
pub type Kilograms = f64;
/// Density, kg/m³.
pub type KilogramsPerCubicMeter = f64;
/// Energy, J.
pub type Joules = f64;
/// Force, N.
pub type Newtons = f64;
