//! What can stop a fit ([`FitError`]), its message naming parameters by key.

use thiserror::Error;

use crate::error::{neutral_name, Namer};
use crate::params::render_keys;

/// A fit that cannot be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitError {
    /// The measured points: too few, not finite, times not increasing.
    #[error("bad data: {}", render_keys(.0, &neutral_name))]
    Data(String),
    /// A free parameter that is not one, or given twice, or without a start.
    /// Its text names parameters by key (`{free alpha_deg}`), which a front
    /// end spells ([`FitError::render`]).
    #[error("{}", render_keys(.0, &neutral_name))]
    Free(String),
    /// A model that cannot be run at the starting values.
    #[error("{model}: cannot run at the starting values: {reason}")]
    Start {
        /// The model's id.
        model: &'static str,
        /// Why.
        reason: String,
    },
}

impl FitError {
    /// The message with the parameters it names written by `name` (the
    /// command line's `--free alpha_deg`, Python's `free='alpha_deg'`).
    pub fn render(&self, name: Namer<'_>) -> String {
        match self {
            FitError::Data(text) => format!("bad data: {}", render_keys(text, name)),
            FitError::Free(text) => render_keys(text, name),
            other => other.to_string(),
        }
    }
}
