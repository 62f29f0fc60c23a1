//! The axes of a sweep: the parameters a sweep can vary ([`Param`]), the
//! values of one axis ([`Values`], a list or a range never expanded into
//! memory), and what can be wrong with them ([`GridError`]).

use std::fmt;

use thiserror::Error;

use crate::error::ParamError;
use crate::number::format_number;

/// A parameter that a sweep can vary. The names are the command line's
/// (`--alpha-deg`) in snake case (`alpha_deg`), as in config files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Param {
    /// Slope angle α, degrees, 0 < α < 90.
    AlphaDeg,
    /// Snow depth b, m, b ≥ 0.
    SnowDepth,
    /// Initial radius r0, m, r0 > 0.
    R0,
    /// Gravitational acceleration g, m/s², g > 0.
    G,
    /// Density ρ, kg/m³, ρ > 0.
    Density,
    /// Length l of the log, m, l > 0.
    Length,
    /// Initial speed v0, m/s, v0 ≥ 0.
    V0,
    /// End time, s, t_end > 0.
    TEnd,
    /// End distance, m, x_end > 0 (none when not swept).
    XEnd,
    /// Relative tolerance of the integrator.
    Rtol,
    /// Absolute tolerance of the integrator.
    Atol,
    /// Coefficient of static friction μ, μ > 0: the run stops with `slip`
    /// where |F| reaches μ N (none, no slip check, when not swept).
    Mu,
}

impl Param {
    /// Every parameter, in grid order (the last varies fastest).
    pub const ALL: [Param; 12] = [
        Param::AlphaDeg,
        Param::SnowDepth,
        Param::R0,
        Param::G,
        Param::Density,
        Param::Length,
        Param::V0,
        Param::TEnd,
        Param::XEnd,
        Param::Rtol,
        Param::Atol,
        Param::Mu,
    ];

    /// The snake-case key (config files, CSV columns, metadata).
    pub fn key(self) -> &'static str {
        match self {
            Param::AlphaDeg => "alpha_deg",
            Param::SnowDepth => "snow_depth",
            Param::R0 => "r0",
            Param::G => "g",
            Param::Density => "density",
            Param::Length => "length",
            Param::V0 => "v0",
            Param::TEnd => "t_end",
            Param::XEnd => "x_end",
            Param::Rtol => "rtol",
            Param::Atol => "atol",
            Param::Mu => "mu",
        }
    }

    /// The parameter of a snake-case key or a kebab-case flag name.
    pub fn from_key(key: &str) -> Option<Param> {
        let key = key.replace('-', "_");
        Param::ALL.into_iter().find(|p| p.key() == key)
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// A grid that cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum GridError {
    /// An axis that does not parse.
    #[error("{param}: cannot read {text:?}: {reason}")]
    Syntax {
        /// The axis.
        param: String,
        /// What was given.
        text: String,
        /// What is wrong, in words.
        reason: String,
    },
    /// A value outside the parameter's range.
    ///
    /// The message is the check's own, which names the parameter; it is not
    /// the error's source, so that a printed chain says it once.
    #[error("{error}")]
    Value {
        /// The axis.
        param: Param,
        /// The range check that failed.
        error: ParamError,
    },
    /// The same parameter given twice.
    #[error("{param} is given twice")]
    Duplicate {
        /// The axis.
        param: String,
    },
    /// No model to run.
    #[error("no model given: pass --model ID[,ID...] (`snowroll models` lists them)")]
    NoModel,
    /// Too many points.
    #[error(
        "the grid has {} points, more than the limit of {limit}: fewer values on some axis, \
         or several sweeps",
        count_text(*points)
    )]
    TooLarge {
        /// The product of the axis lengths (saturating).
        points: u128,
        /// [`MAX_GRID_POINTS`](super::MAX_GRID_POINTS).
        limit: u64,
    },
}

/// A count as the outputs write numbers: whole up to 10^15, beyond that
/// in the shortest exponent form that reads back to the same `f64` (`1e24`,
/// not 25 digits; issue 33, item 5). A saturated count (`u128::MAX`) is
/// "more than 3.4e38".
pub(crate) fn count_text(n: u128) -> String {
    /// Counts printed whole: every one of them is exact in an `f64`.
    const WHOLE: u128 = 1_000_000_000_000_000;
    if n <= WHOLE {
        n.to_string()
    } else if n == u128::MAX {
        "more than 3.4e38".to_string()
    } else {
        format!("{:e}", n as f64)
    }
}

/// The values of one axis: a list, or an evenly spaced range that is never
/// expanded into memory.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// These values, in this order.
    List(Vec<f64>),
    /// `count` values from `start` to `end` inclusive, evenly spaced.
    Range {
        /// First value.
        start: f64,
        /// Last value.
        end: f64,
        /// How many, ≥ 1 (1 only when `start == end`).
        count: u64,
    },
}

impl Values {
    /// Parses `a,b,c` (a list) or `start:end:count` (a range, both ends
    /// included).
    ///
    /// # Errors
    /// [`GridError::Syntax`] naming `param` for anything else, for non-finite
    /// numbers, and for a count of 0 (or of 1 with different ends).
    pub fn parse(param: &str, text: &str) -> Result<Values, GridError> {
        let bad = |reason: &str| GridError::Syntax {
            param: param.to_string(),
            text: text.to_string(),
            reason: reason.to_string(),
        };
        let number = |s: &str| -> Result<f64, GridError> {
            let s = s.trim();
            match s.parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(x),
                Ok(_) => Err(bad(&format!("{s} is not a finite number"))),
                Err(_) => Err(bad(&format!("{s:?} is not a number"))),
            }
        };
        if text.contains(':') {
            let parts: Vec<&str> = text.split(':').collect();
            let [start, end, count] = parts[..] else {
                return Err(bad("a range is start:end:count, e.g. 5:60:12"));
            };
            let (start, end) = (number(start)?, number(end)?);
            let count: u64 = count.trim().parse().map_err(|_| {
                bad(&format!(
                    "the count {:?} is not a whole number >= 1",
                    count.trim()
                ))
            })?;
            if count == 0 {
                return Err(bad("the count of a range must be at least 1"));
            }
            if count == 1 && start.to_bits() != end.to_bits() {
                return Err(bad(
                    "a range of 1 value needs start = end (give one value instead)",
                ));
            }
            return Ok(Values::Range { start, end, count });
        }
        let list = text
            .split(',')
            .map(|s| {
                if s.trim().is_empty() {
                    Err(bad("empty item in the list"))
                } else {
                    number(s)
                }
            })
            .collect::<Result<Vec<f64>, GridError>>()?;
        Ok(Values::List(list))
    }

    /// How many values.
    pub fn len(&self) -> u64 {
        match self {
            Values::List(v) => v.len() as u64,
            Values::Range { count, .. } => *count,
        }
    }

    /// Whether there are none (never, for a parsed axis).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `k`-th value, `k < len()`: for a range
    /// `start + (end − start)·k/(count − 1)`, with the last one exactly `end`.
    pub fn get(&self, k: u64) -> f64 {
        match self {
            Values::List(v) => v.get(k as usize).copied().unwrap_or(f64::NAN),
            Values::Range { start, end, count } => {
                if k + 1 >= *count {
                    *end
                } else {
                    start + (end - start) * (k as f64 / (*count - 1) as f64)
                }
            }
        }
    }

    /// The smallest and largest values: every value lies between them, so
    /// checking these two checks the axis against an interval.
    pub(super) fn bounds(&self) -> (f64, f64) {
        match self {
            Values::List(v) => v
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                    (lo.min(x), hi.max(x))
                }),
            Values::Range { start, end, .. } => (start.min(*end), start.max(*end)),
        }
    }
}

impl fmt::Display for Values {
    /// As it would be typed: `a,b,c` or `start:end:count`, each number as
    /// every output writes one ([`format_number`]: exponent form outside
    /// 1e-4..1e9, the shortest text that reads back to the same value).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Values::List(v) => {
                let items: Vec<String> = v.iter().map(|&x| format_number(x)).collect();
                f.write_str(&items.join(","))
            }
            Values::Range { start, end, count } => write!(
                f,
                "{}:{}:{count}",
                format_number(*start),
                format_number(*end)
            ),
        }
    }
}

/// One swept parameter and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Which parameter.
    pub param: Param,
    /// Its values.
    pub values: Values,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A header's axis line reads back to the values it was written from,
    /// bit for bit, and a tiny or huge value is in exponent form (issue 20:
    /// `# alpha_deg: 0.000…0001` had a hundred digits).
    #[test]
    fn values_print_in_exponent_form_outside_the_plain_range_and_read_back() {
        for text in [
            "1e-100,0.5",
            "1e-10,0.0001,1e9,2.5e12",
            "1e-12:1e-6:3",
            "5:60:12",
        ] {
            let values = Values::parse("rtol", text).unwrap();
            let shown = values.to_string();
            assert!(shown.len() < 40, "{text} shown as {shown}");
            assert_eq!(Values::parse("rtol", &shown).unwrap(), values, "{shown}");
        }
        let shown = Values::parse("rtol", "1e-100,0.5").unwrap().to_string();
        assert_eq!(shown, "1e-100,0.5");
    }
}
