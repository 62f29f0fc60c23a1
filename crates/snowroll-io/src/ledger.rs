//! The energy ledger in the outputs (`docs/snowball-and-losses.md` §3): a
//! sample of a run that records one is [`Sample`](snowroll::Sample) plus
//! [`LedgerRow`](snowroll::LedgerRow) in one row ([`Row`](super::row::Row)),
//! and a snowless run with drag states its closed-form terminal velocity.

use super::RunParams;
use snowroll::losses::terminal_velocity;
use snowroll::models::ModelKind;
use snowroll::scenario::Scenario;

/// The closed-form terminal velocity of the run, m/s, where one exists:
/// the snowless log with drag (§2.2); `None` for every other run.
pub(crate) fn closed_form_terminal_velocity(model: ModelKind, params: &RunParams) -> Option<f64> {
    let losses = params.losses()?;
    if model != ModelKind::Snowless {
        return None;
    }
    let scenario = Scenario::new(params.settings.scenario).ok()?;
    terminal_velocity(&scenario, &losses)
}
