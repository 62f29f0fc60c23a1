//! [`SimOptions`]: the options of one run, their defaults and their
//! validation.

#[cfg(doc)]
use super::StopReason;
use super::{CollisionModel, OnHop, Sampling};
use crate::error::ParamError;
use crate::integrate::Tolerances;
use crate::losses::Losses;
use crate::units::{Meters, Seconds};

/// Default of [`SimOptions::max_rows`]: 10^8 rows, about 10 GB of CSV.
pub const DEFAULT_MAX_ROWS: u64 = 100_000_000;

/// Options of one simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct SimOptions {
    /// End time, s. Default 100.
    pub t_end: Seconds,
    /// Stop when x reaches this distance, m. Default: none.
    pub x_end: Option<Meters>,
    /// Stop after this many full turns (turn models only). Default: none.
    pub turns: Option<u64>,
    /// Integrator tolerances. Default rtol 1e-10, atol 1e-12.
    pub tolerances: Tolerances,
    /// What to record. Default: every step.
    pub sampling: Sampling,
    /// Coefficient of static friction μ (dimensionless): the run stops with
    /// [`StopReason::Slip`] where |F| reaches μ N. Default: none (no slip check).
    pub mu: Option<f64>,
    /// What happens where N reaches 0. Default: [`OnHop::Stop`], the run
    /// stops with [`StopReason::Hop`] (nothing is computed past the model's validity).
    pub on_hop: OnHop,
    /// How the turn models climb the step of each new layer. Default: the
    /// note's eq. (89), [`CollisionModel::Note`].
    pub collision: CollisionModel,
    /// Most samples one run records, at least 1. Default
    /// [`DEFAULT_MAX_ROWS`]. A run whose count is known in advance
    /// ([`known_rows`](Self::known_rows)) and larger is refused by
    /// [`validate`](Self::validate); otherwise the run stops there with
    /// [`StopReason::RowLimit`].
    pub max_rows: u64,
    /// Air drag, rolling resistance, compaction, the ledger and the
    /// terminal-velocity stop. Default: no losses (fn. 5's idealisation).
    pub losses: Losses,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            t_end: 100.0,
            x_end: None,
            turns: None,
            tolerances: Tolerances::default(),
            sampling: Sampling::Steps,
            mu: None,
            on_hop: OnHop::Stop,
            collision: CollisionModel::Note,
            max_rows: DEFAULT_MAX_ROWS,
            losses: Losses::default(),
        }
    }
}

impl SimOptions {
    /// The number of samples this run records, when it is known before the
    /// run: [`Sampling::known_rows`] up to `t_end`, except for a grid
    /// (`Every`) with a turn count or an end distance, which gives `None`.
    /// Such a run stops after [`turns`](Self::turns) turns or at
    /// [`x_end`](Self::x_end), and how long that takes has no bound known
    /// in advance (a log that slows towards a stall may take any time), so
    /// the grid count up to `t_end` is then only an upper bound: the run is
    /// not refused, and stops at `max_rows` rows if it gets there.
    pub fn known_rows(&self) -> Option<f64> {
        let other_end = self.turns.is_some() || self.x_end.is_some();
        match &self.sampling {
            Sampling::Every(_) if other_end => None,
            sampling => sampling.known_rows(self.t_end),
        }
    }

    /// Checks every option.
    ///
    /// # Errors
    /// [`ParamError`] naming the first bad option.
    pub fn validate(&self) -> Result<(), ParamError> {
        let bad = |name, value, expected| ParamError::InvalidParameter {
            name,
            value,
            expected,
        };
        if !(self.t_end.is_finite() && self.t_end > 0.0) {
            return Err(bad("t_end (s)", self.t_end, "0 < t_end < infinity s"));
        }
        // An end that is subnormal cannot be reached by steps that carry a
        // time's full precision (issue 33, item 4).
        if !self.t_end.is_normal() {
            return Err(bad(
                "t_end (s)",
                self.t_end,
                "0 < t_end < infinity s, at least 2.2250738585072014e-308 s (not subnormal)",
            ));
        }
        if let Some(x) = self.x_end {
            if !(x.is_finite() && x > 0.0) {
                return Err(bad("x_end (m)", x, "0 < x_end < infinity m"));
            }
            if !x.is_normal() {
                return Err(bad(
                    "x_end (m)",
                    x,
                    "0 < x_end < infinity m, at least 2.2250738585072014e-308 m (not subnormal)",
                ));
            }
        }
        if let Sampling::Times(ts) = &self.sampling {
            let after: Vec<f64> = ts.iter().copied().filter(|t| *t > self.t_end).collect();
            if let Some(&first) = after.first() {
                return Err(ParamError::TimesAfterEnd {
                    count: after.len(),
                    total: ts.len(),
                    first,
                    t_end: self.t_end,
                });
            }
        }
        if let Some(mu) = self.mu {
            if !(mu.is_finite() && mu > 0.0) {
                return Err(bad("mu", mu, "0 < mu < infinity"));
            }
        }
        self.losses.validate()?;
        if self.turns == Some(0) {
            return Err(bad("turns", 0.0, "turns >= 1"));
        }
        self.tolerances.validate()?;
        if let Some(x_end) = self.x_end.filter(|&x| x < self.tolerances.atol) {
            return Err(ParamError::EndBelowTolerance {
                x_end,
                atol: self.tolerances.atol,
            });
        }
        if self.max_rows == 0 {
            return Err(bad("max_rows", 0.0, "max_rows >= 1"));
        }
        self.sampling.validate()?;
        match self.known_rows() {
            Some(rows) if rows > self.max_rows as f64 => Err(ParamError::TooManyRows {
                rows,
                max_rows: self.max_rows,
            }),
            _ => Ok(()),
        }
    }
}
