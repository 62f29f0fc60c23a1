//! How an error's message names the parameters it is about: the `{key}`
//! placeholders of the library's texts, recognised against the parameter
//! table and written by a front end's [`Namer`] (the command line's flags,
//! Python's keywords). Here, above the errors and the table both, so that the
//! errors need not know the table (issue 37, item 4: no module circle).

use crate::error::{neutral_name, Namer, ParamError, SimError};
use crate::number::format_number as number;
use crate::params::Param;

/// Keys a message may name besides those of [`crate::PARAMS`]: the model
/// list of a run or sweep, and the free parameters of a fit.
const OTHER_KEYS: [&str; 2] = ["model", "free"];

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
        let known = Param::of_key(key).is_some() || OTHER_KEYS.contains(&key);
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
