//! A parameter's value, and the error of a value of the wrong kind.

use serde::ser::Serializer;
use serde::Serialize;

/// A value whose variant is not the parameter's [`Kind`](super::Kind).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WrongKind;

/// A value of a parameter.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// Not set: the feature is off (`x_end`, `mu`, the swath).
    None,
    /// A real number.
    Real(f64),
    /// A whole number.
    Count(u64),
    /// On or off.
    Flag(bool),
    /// A word: a choice's id, or recorded text.
    Word(String),
    /// A list of real numbers.
    Reals(Vec<f64>),
}

impl Value {
    pub(super) fn real(self) -> Result<f64, WrongKind> {
        match self {
            Value::Real(x) => Ok(x),
            _ => Err(WrongKind),
        }
    }

    pub(super) fn optional_real(self) -> Result<Option<f64>, WrongKind> {
        match self {
            Value::None => Ok(None),
            other => other.real().map(Some),
        }
    }

    pub(super) fn count(self) -> Result<u64, WrongKind> {
        match self {
            Value::Count(n) => Ok(n),
            _ => Err(WrongKind),
        }
    }

    pub(super) fn flag(self) -> Result<bool, WrongKind> {
        match self {
            Value::Flag(b) => Ok(b),
            _ => Err(WrongKind),
        }
    }

    pub(super) fn word(self) -> Result<String, WrongKind> {
        match self {
            Value::Word(w) => Ok(w),
            _ => Err(WrongKind),
        }
    }

    pub(super) fn of_option(x: Option<f64>) -> Value {
        x.map_or(Value::None, Value::Real)
    }
}

/// A number or a word, as a config file or a JSON output gives a parameter
/// of kind [`Kind::OptionalRealOr`](super::Kind::OptionalRealOr).
#[derive(Debug, Clone, PartialEq, serde::Deserialize)]
#[serde(untagged)]
pub enum RealOrWord {
    /// A number.
    Real(f64),
    /// A word (the parameter's setter checks it).
    Word(String),
}

impl From<RealOrWord> for Value {
    fn from(v: RealOrWord) -> Value {
        match v {
            RealOrWord::Real(x) => Value::Real(x),
            RealOrWord::Word(w) => Value::Word(w),
        }
    }
}

impl Serialize for Value {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Value::None => s.serialize_none(),
            Value::Real(x) => s.serialize_f64(*x),
            Value::Count(n) => s.serialize_u64(*n),
            Value::Flag(b) => s.serialize_bool(*b),
            Value::Word(w) => s.serialize_str(w),
            Value::Reals(xs) => xs.serialize(s),
        }
    }
}
