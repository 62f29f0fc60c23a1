//! The energy ledger in the outputs: a sample of a run that records one
//! is [`Sample`] plus [`LedgerRow`] in one CSV row or JSON object
//! (`docs/snowball-and-losses.md` §3).

use serde::Serialize;

use super::RunParams;
use crate::losses::terminal_velocity;
use crate::models::ModelKind;
use crate::scenario::Scenario;
use crate::trajectory::{LedgerRow, Sample};

/// The columns [`LedgerSample`] adds to those of [`Sample`], in its field order.
pub(crate) const LEDGER_COLUMNS: [&str; 9] = [
    "kinetic_j",
    "released_j",
    "drag_j",
    "rolling_j",
    "compaction_j",
    "model_j",
    "collision_j",
    "created_j",
    "residual_j",
];

/// One sample with its ledger, columns in a fixed order, units in the names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub(crate) struct LedgerSample {
    t_s: f64,
    x_m: f64,
    v_m_s: f64,
    a_m_s2: f64,
    r_m: f64,
    mass_kg: f64,
    normal_n: f64,
    friction_n: f64,
    friction_ratio: Option<f64>,
    kinetic_j: f64,
    released_j: f64,
    drag_j: f64,
    rolling_j: f64,
    compaction_j: f64,
    model_j: f64,
    collision_j: f64,
    created_j: f64,
    residual_j: f64,
}

impl LedgerSample {
    pub(crate) fn new(s: &Sample, l: &LedgerRow) -> Self {
        Self {
            t_s: s.t_s,
            x_m: s.x_m,
            v_m_s: s.v_m_s,
            a_m_s2: s.a_m_s2,
            r_m: s.r_m,
            mass_kg: s.mass_kg,
            normal_n: s.normal_n,
            friction_n: s.friction_n,
            friction_ratio: s.friction_ratio,
            kinetic_j: l.kinetic_j,
            released_j: l.released_j,
            drag_j: l.drag_j,
            rolling_j: l.rolling_j,
            compaction_j: l.compaction_j,
            model_j: l.model_j,
            collision_j: l.collision_j,
            created_j: l.created_j,
            residual_j: l.residual_j,
        }
    }
}

/// The closed-form terminal velocity of the run, m/s, where one exists:
/// the snowless log with drag (§2.2); `None` for every other run.
pub(crate) fn closed_form_terminal_velocity(model: ModelKind, params: &RunParams) -> Option<f64> {
    let losses = params.losses?;
    if model != ModelKind::Snowless {
        return None;
    }
    let scenario = Scenario::new(params.scenario).ok()?;
    terminal_velocity(&scenario, &losses)
}
