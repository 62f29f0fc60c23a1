//! Errors of the library: bad parameters, failed integrations, failed output.

use std::sync::Arc;

use thiserror::Error;

use crate::number::format_number as number;

/// A parameter outside its physical or numerical range.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ParamError {
    /// A shape name that is not `cylinder` or `sphere`.
    UnknownShape {
        /// What was asked for.
        given: String,
    },
    /// A model whose derivation does not carry over to the scenario's shape
    /// (`docs/snowball-and-losses.md` §1.2).
    ShapeNotSupported {
        /// The model id.
        model: &'static str,
        /// The shape asked for.
        shape: &'static str,
        /// Why, in words.
        reason: &'static str,
    },
    /// A numeric parameter is out of range (or not finite).
    InvalidParameter {
        /// Parameter name as the user spells it.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
    /// A model id or alias that is not in [`crate::ModelKind`].
    UnknownModel {
        /// What was asked for.
        given: String,
        /// The accepted ids.
        expected: String,
    },
    /// A parameter, or a quantity derived from several (a mass, an energy),
    /// outside the range of magnitudes the program computes in.
    OutOfScale {
        /// The quantity, with its formula and unit.
        quantity: &'static str,
        /// Its value (may be infinite when it overflowed).
        value: f64,
        /// The allowed range, in words, with numbers.
        allowed: String,
        /// Which parameters to change.
        hint: &'static str,
    },
    /// Requested output times after the end time: they could never be
    /// written.
    TimesAfterEnd {
        /// How many are after `t_end`.
        count: usize,
        /// How many were requested.
        total: usize,
        /// The first of them, s.
        first: f64,
        /// The end time, s.
        t_end: f64,
    },
    /// An end distance shorter than the absolute tolerance: the integrator
    /// knows positions only to `atol`, so such an end cannot be located
    /// (issue 33, item 4: `--x-end 1e-100` stopped at x = 1.6e-8 m and
    /// reported the end distance reached).
    EndBelowTolerance {
        /// The end distance, m.
        x_end: f64,
        /// The absolute tolerance.
        atol: f64,
    },
    /// A run whose row count, known before it starts, exceeds the limit.
    TooManyRows {
        /// Rows the run would record (a float: `t_end/dt` may exceed any integer).
        rows: f64,
        /// The limit.
        max_rows: u64,
    },
    /// A loss (or the energy ledger) asked of a model that does not define
    /// it (`docs/snowball-and-losses.md` §2.1).
    Unsupported {
        /// The model id.
        model: &'static str,
        /// The option's key in the parameter table (`drag_coefficient`).
        what: &'static str,
        /// Why, and what to use instead.
        reason: &'static str,
    },
    /// Requested output times that are not finite, negative or not ascending.
    InvalidTimes {
        /// What is wrong with them.
        reason: &'static str,
    },
    /// A value of the wrong kind for its parameter (a word for a number).
    WrongKind {
        /// The parameter's key.
        key: &'static str,
        /// The kind it takes, in words.
        expected: &'static str,
    },
    /// A word outside a parameter's closed set (`--collision`, `--on-hop`).
    UnknownChoice {
        /// The parameter's key.
        key: &'static str,
        /// What was asked for.
        given: String,
        /// The words it takes.
        expected: String,
    },
}

/// How a front end writes a parameter that a message names: from its key in
/// the parameter table ([`crate::PARAMS`]) and the word given with it, if
/// any (`shape` and `sphere`). The command line writes `--shape sphere`,
/// Python `shape='sphere'`; [`ParamError`]'s `Display` writes
/// [`neutral_name`].
pub type Namer<'a> = &'a dyn Fn(&str, Option<&str>) -> String;

/// The library's own spelling of a named parameter: the key, and
/// `key = word` with a word (`Display` of the errors).
pub fn neutral_name(key: &str, word: Option<&str>) -> String {
    match word {
        Some(w) => format!("{key} = {w}"),
        None => key.to_string(),
    }
}

impl std::error::Error for ParamError {}

/// A simulation that could not be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SimError {
    /// The scenario or the options were invalid.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The step size underflowed: the equations are singular near `t`.
    #[error("step size {h:e} s too small at t = {} s (the equations are singular there, or the scenario is out of scale)", number(*t))]
    StepSizeTooSmall {
        /// Time of the failure, s.
        t: f64,
        /// The step that was too small, s.
        h: f64,
    },
    /// The [`SampleSink`](crate::SampleSink) that received the samples
    /// failed; the run stopped at once.
    #[error("the output of the samples failed")]
    Sink(#[source] SinkError),
    /// The state became NaN or infinite.
    #[error("the state became non-finite at t = {} s", number(*t))]
    NonFiniteState {
        /// Time of the failure, s.
        t: f64,
    },
    /// A system declared more event functions than the integrator supports.
    #[error("{count} event functions, at most {max} are supported")]
    TooManyEvents {
        /// Declared.
        count: usize,
        /// Supported.
        max: usize,
    },
    /// The closed-form time–distance relation could not be inverted.
    #[error("could not invert t(x) at t = {t} s")]
    Inversion {
        /// Requested time, s.
        t: f64,
    },
    /// The closed form's time t(x) = ∫ dx/v could not be integrated (a
    /// quadrature panel that is not finite, or too many panels).
    #[error("could not integrate t(x) up to x = {} m", number(*x))]
    TimeIntegral {
        /// The distance asked for, m.
        x: f64,
    },
}

/// The message of [`GridError::NoModel`](crate::sweep::GridError::NoModel), the models' parameter written by `name`.
pub(crate) fn no_model(name: Namer<'_>) -> String {
    format!(
        "no model given: pass {} ID[,ID...] (`snowroll models` lists them)",
        name("model", None)
    )
}

/// A failure of a [`SampleSink`](crate::SampleSink), kept whole (its
/// source chain is the sink's own error) and shared, so that
/// [`SimError`] stays `Clone`.
#[derive(Debug, Clone, Error)]
#[error(transparent)]
pub struct SinkError(Arc<dyn std::error::Error + Send + Sync>);

impl SinkError {
    /// Wraps the sink's error.
    pub fn new(error: impl std::error::Error + Send + Sync + 'static) -> Self {
        Self(Arc::new(error))
    }

    /// The sink's error.
    pub fn inner(&self) -> &(dyn std::error::Error + Send + Sync + 'static) {
        &*self.0
    }
}

/// Two sink errors are equal when they are the same failure (one shared value).
impl PartialEq for SinkError {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}
