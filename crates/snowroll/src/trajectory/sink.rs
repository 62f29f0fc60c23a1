//! Where the samples of a run go: a [`SampleSink`] receives them one at a
//! time; [`Collected`] gathers them into a [`Trajectory`].

#[cfg(doc)]
use super::Sampling;
use super::{LedgerRow, RunEnd, Sample, Stop, TurnState};
use crate::error::SinkError;
use crate::integrate::Stats;
use crate::model_kind::ModelKind;

/// Receives the samples of a run one at a time, as they are computed, so a
/// run of any length needs memory for one sample only
/// ([`Model::simulate_into`](crate::Model::simulate_into)).
pub trait SampleSink {
    /// One sample, with the turn state for the turn models (`None` for the others).
    ///
    /// # Errors
    /// A [`SinkError`] ends the run at once; the model returns it as
    /// [`SimError::Sink`](crate::SimError::Sink).
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError>;

    /// The energy ledger of the sample that comes next, for a run that
    /// records one ([`Losses::records_ledger`](crate::Losses::records_ledger));
    /// sent just before that [`sample`](Self::sample). Ignored by default.
    ///
    /// # Errors
    /// As [`sample`](Self::sample).
    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        let _ = row;
        Ok(())
    }
}

/// The samples of a run gathered in memory: the sink behind
/// [`Model::simulate`](crate::Model::simulate).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Collected {
    /// Samples in time order.
    pub samples: Vec<Sample>,
    /// The turn states of the samples that had one.
    pub turn_states: Vec<TurnState>,
    /// The ledger rows of the samples that had one.
    pub ledger: Vec<LedgerRow>,
}

impl SampleSink for Collected {
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError> {
        self.samples.push(*sample);
        if let Some(k) = turn {
            self.turn_states.push(*k);
        }
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.ledger.push(*row);
        Ok(())
    }
}

impl Collected {
    /// The trajectory of `model` made of these samples and `end`.
    pub fn into_trajectory(self, model: ModelKind, end: RunEnd) -> Trajectory {
        Trajectory {
            model,
            samples: self.samples,
            turn_states: self.turn_states,
            stop: end.stop,
            stats: end.stats,
            ledger: self.ledger,
        }
    }
}

/// The result of one simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// Which model produced it.
    pub model: ModelKind,
    /// Samples in time order, as asked for by [`Sampling`].
    pub samples: Vec<Sample>,
    /// For the turn models, the turn state of each sample; empty otherwise.
    pub turn_states: Vec<TurnState>,
    /// How the run ended.
    pub stop: Stop,
    /// Integrator counts (zero for closed forms).
    pub stats: Stats,
    /// The energy ledger of each sample when the run records one
    /// ([`Losses::records_ledger`](crate::Losses::records_ledger)); empty otherwise.
    pub ledger: Vec<LedgerRow>,
}
