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

/// Keys a message may name besides those of [`crate::PARAMS`]: the model
/// list of a run or sweep.
const OTHER_KEYS: [&str; 1] = ["model"];

/// The parameters `text` names: each `{key}` or `{key word}` whose key is in
/// the parameter table (or [`OTHER_KEYS`]), with its word and where it
/// stands, in order.
fn placeholders(text: &str) -> Vec<(std::ops::Range<usize>, &str, Option<&str>)> {
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(open) = text[from..].find('{').map(|i| i + from) {
        let Some(close) = text[open..].find('}').map(|i| i + open) else {
            break;
        };
        let inner = &text[open + 1..close];
        let (key, word) = match inner.split_once(' ') {
            Some((k, w)) => (k, Some(w)),
            None => (inner, None),
        };
        let known = crate::params::Param::of_key(key).is_some() || OTHER_KEYS.contains(&key);
        if known && word.is_none_or(|w| !w.is_empty() && !w.contains(' ')) {
            out.push((open..close + 1, key, word));
        }
        from = close + 1;
    }
    out
}

/// `text` with each parameter it names (`{snow_depth}`, `{shape sphere}`)
/// written by `name`; the rest as it is.
pub fn render_keys(text: &str, name: Namer<'_>) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    let mut at = 0;
    for (range, key, word) in placeholders(text) {
        out.push_str(&text[at..range.start]);
        out.push_str(&name(key, word));
        at = range.end;
    }
    out.push_str(&text[at..]);
    out
}

/// The keys `text` names ([`render_keys`]).
pub fn named_keys(text: &str) -> Vec<&str> {
    placeholders(text).into_iter().map(|(_, k, _)| k).collect()
}

impl ParamError {
    /// The message with the parameters it names written by `name` (the
    /// command line's flags, Python's keywords): the one text of each
    /// error, which `Display` writes with [`neutral_name`].
    pub fn render(&self, name: Namer<'_>) -> String {
        let keys = |text: &str| render_keys(text, name);
        match self {
            ParamError::UnknownShape { given } => {
                format!("unknown shape {given:?}: expected cylinder or sphere")
            }
            ParamError::ShapeNotSupported {
                model,
                shape,
                reason,
            } => format!(
                "model {model} does not support shape = {shape}: {}",
                keys(reason)
            ),
            ParamError::InvalidParameter {
                name,
                value,
                expected,
            } => format!(
                "invalid {name} = {}: expected {}",
                number(*value),
                keys(expected)
            ),
            ParamError::UnknownModel { given, expected } => {
                format!("unknown model {given:?}: expected one of {expected}")
            }
            ParamError::OutOfScale {
                quantity,
                value,
                allowed,
                hint,
            } => format!(
                "{quantity} = {} is out of range: expected {} ({})",
                number(*value),
                keys(allowed),
                keys(hint)
            ),
            ParamError::TimesAfterEnd {
                count,
                total,
                first,
                t_end,
            } => format!(
                "{count} of the {total} requested output times are after t_end = {} s (the first: \
                 {} s); raise {} or drop them",
                number(*t_end),
                number(*first),
                name("t_end", None)
            ),
            ParamError::EndBelowTolerance { x_end, atol } => format!(
                "invalid x_end (m) = {}: expected x_end >= atol = {} (positions are computed to \
                 within atol, so a shorter end distance cannot be located); give a smaller {} or \
                 a longer {}",
                number(*x_end),
                number(*atol),
                name("atol", None),
                name("x_end", None)
            ),
            ParamError::TooManyRows { rows, max_rows } => format!(
                "the run would record {} rows, more than max_rows = {max_rows}",
                number(*rows)
            ),
            ParamError::Unsupported {
                model,
                what,
                reason,
            } => format!(
                "model {model} does not support {}: {}",
                name(what, None),
                keys(reason)
            ),
            ParamError::InvalidTimes { reason } => format!("invalid output times: {reason}"),
            ParamError::WrongKind { key, expected } => format!("{key}: expected {expected}"),
            ParamError::UnknownChoice {
                key,
                given,
                expected,
            } => format!("unknown {key} {given:?}: expected one of {expected}"),
        }
    }

    /// The parameters of the table the message names by key (its hints,
    /// ranges and reasons), in order.
    pub fn named_keys(&self) -> Vec<&str> {
        match self {
            ParamError::ShapeNotSupported { reason, .. } => named_keys(reason),
            ParamError::InvalidParameter { expected, .. } => named_keys(expected),
            ParamError::OutOfScale { allowed, hint, .. } => {
                let mut k = named_keys(allowed);
                k.extend(named_keys(hint));
                k
            }
            ParamError::TimesAfterEnd { .. } => vec!["t_end"],
            ParamError::EndBelowTolerance { .. } => vec!["atol", "x_end"],
            ParamError::Unsupported { what, reason, .. } => {
                let mut k = vec![*what];
                k.extend(named_keys(reason));
                k
            }
            _ => Vec::new(),
        }
    }
}

impl std::fmt::Display for ParamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.render(&neutral_name))
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

impl SimError {
    /// The message with the parameters it names written by `name`
    /// ([`ParamError::render`]); other failures name none.
    pub fn render(&self, name: Namer<'_>) -> String {
        match self {
            SimError::Param(p) => p.render(name),
            other => other.to_string(),
        }
    }
}

/// The message of [`GridError::NoModel`](crate::sweep::GridError::NoModel), the models' parameter written by `name`.
pub(crate) fn no_model(name: Namer<'_>) -> String {
    format!(
        "no model given: pass {} ID[,ID...] (`snowroll models` lists them)",
        name("model", None)
    )
}

impl crate::sweep::GridError {
    /// The message with the parameters it names written by `name`
    /// ([`ParamError::render`]).
    pub fn render(&self, name: Namer<'_>) -> String {
        match self {
            crate::sweep::GridError::Value { error, .. } => error.render(name),
            crate::sweep::GridError::NoModel => no_model(name),
            other => other.to_string(),
        }
    }
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
