//! Values given for some parameters, applied over the defaults.

use super::{Param, Settings, Value};
use crate::error::ParamError;

/// Values given for some parameters (on a command line, in a config file,
/// as Python keywords); the others keep their defaults. In table order,
/// each parameter at most once.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Given {
    values: Vec<(&'static Param, Value)>,
}

impl Given {
    /// No value given.
    pub fn new() -> Self {
        Self::default()
    }

    /// Gives `value` to `param`, replacing an earlier value.
    pub fn insert(&mut self, param: &'static Param, value: Value) {
        match self.values.iter_mut().find(|(p, _)| p.key == param.key) {
            Some(slot) => slot.1 = value,
            None => {
                self.values.push((param, value));
                self.values.sort_by_key(|(p, _)| p.position());
            }
        }
    }

    /// The value given to `param`, if any.
    pub fn get(&self, param: &Param) -> Option<&Value> {
        self.values
            .iter()
            .find(|(p, _)| p.key == param.key)
            .map(|(_, v)| v)
    }

    /// Removes and returns the value given to `param`.
    pub fn take(&mut self, param: &Param) -> Option<Value> {
        let i = self.values.iter().position(|(p, _)| p.key == param.key)?;
        Some(self.values.remove(i).1)
    }

    /// Whether nothing is given.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// The given values, in table order.
    pub fn iter(&self) -> impl Iterator<Item = (&'static Param, &Value)> {
        self.values.iter().map(|(p, v)| (*p, v))
    }

    /// These values, with every parameter not given here taken from `other`.
    pub fn or(mut self, other: &Given) -> Given {
        for (p, v) in other.iter() {
            if self.get(p).is_none() {
                self.insert(p, v.clone());
            }
        }
        self
    }

    /// `base` with these values set.
    ///
    /// # Errors
    /// The first value that is not of its parameter's kind or choices.
    pub fn apply(&self, mut base: Settings) -> Result<Settings, ParamError> {
        for (p, v) in self.iter() {
            p.set(&mut base, v.clone())?;
        }
        Ok(base)
    }
}
