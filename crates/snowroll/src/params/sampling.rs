//! How a run's rows were chosen, as its outputs record it: a closed set of
//! forms, written in words (`sampling = every 0.5 s`) and read back from them.

use std::fmt;
use std::str::FromStr;

use crate::number::format_number;
use crate::trajectory::Sampling;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// The `sampling` an output records. Written as words; a config file read
/// back tells a turn table ([`RecordedSampling::PerTurn`]) from a trajectory
/// by it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RecordedSampling {
    /// Every accepted integrator step (`every accepted step`).
    Steps,
    /// This many requested times, s (`3 requested times`).
    Times(usize),
    /// A regular grid of this spacing, s (`every 0.5 s`).
    Every(f64),
    /// The start and the end of the run (`start and end`).
    Ends,
    /// One row per completed turn, `snowroll turns` (`one row per turn`).
    PerTurn,
}

impl From<&Sampling> for RecordedSampling {
    fn from(sampling: &Sampling) -> Self {
        match sampling {
            Sampling::Steps => Self::Steps,
            Sampling::Times(ts) => Self::Times(ts.len()),
            Sampling::Every(dt) => Self::Every(*dt),
            Sampling::Ends => Self::Ends,
        }
    }
}

impl fmt::Display for RecordedSampling {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Steps => f.write_str("every accepted step"),
            Self::Times(n) => write!(f, "{n} requested times"),
            Self::Every(dt) => write!(f, "every {} s", format_number(*dt)),
            Self::Ends => f.write_str("start and end"),
            Self::PerTurn => f.write_str("one row per turn"),
        }
    }
}

/// Text that is none of the forms [`RecordedSampling`] writes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownSampling(pub String);

impl fmt::Display for UnknownSampling {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` is not a sampling snowroll writes", self.0)
    }
}

impl std::error::Error for UnknownSampling {}

impl FromStr for RecordedSampling {
    type Err = UnknownSampling;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let unknown = || UnknownSampling(s.to_string());
        match s {
            "every accepted step" => return Ok(Self::Steps),
            "start and end" => return Ok(Self::Ends),
            "one row per turn" => return Ok(Self::PerTurn),
            _ => {}
        }
        if let Some(n) = s.strip_suffix(" requested times") {
            return n.parse().map(Self::Times).map_err(|_| unknown());
        }
        let dt = s.strip_prefix("every ").and_then(|r| r.strip_suffix(" s"));
        dt.and_then(|d| d.parse().ok())
            .map(Self::Every)
            .ok_or_else(unknown)
    }
}

impl Serialize for RecordedSampling {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for RecordedSampling {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = String::deserialize(deserializer)?;
        text.parse().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every form reads back as itself from the words it writes.
    #[test]
    fn every_form_round_trips_through_its_words() {
        for s in [
            RecordedSampling::Steps,
            RecordedSampling::Times(3),
            RecordedSampling::Every(0.5),
            RecordedSampling::Every(1e-300),
            RecordedSampling::Ends,
            RecordedSampling::PerTurn,
        ] {
            assert_eq!(s.to_string().parse::<RecordedSampling>(), Ok(s));
        }
        assert!("every other turn".parse::<RecordedSampling>().is_err());
        assert!("x requested times".parse::<RecordedSampling>().is_err());
    }
}
