//! What can be wrong with a sweep's grid ([`GridError`]).

use thiserror::Error;

use super::AxisParam;
use crate::error::ParamError;

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
        param: AxisParam,
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
    #[error("{}", crate::error::no_model(&crate::error::neutral_name))]
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
        /// [`MAX_GRID_POINTS`](crate::sweep::MAX_GRID_POINTS).
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

impl GridError {
    /// The message with the parameters it names written by `name`
    /// ([`ParamError::render`]).
    pub fn render(&self, name: crate::error::Namer<'_>) -> String {
        match self {
            GridError::Value { error, .. } => error.render(name),
            GridError::NoModel => crate::error::no_model(name),
            other => other.to_string(),
        }
    }
}
