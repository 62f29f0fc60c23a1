//! Where the two turn models part ways: the first-order `turns` (eq. (73))
//! and `turns-exact` agree for thin snow and differ qualitatively for thick
//! snow (`docs/turn-model.md`, "Range of validity").

use snowroll::error::SimError;
use snowroll::models::{validity_warnings, ModelKind};
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::trajectory::{Sampling, SimOptions, StopReason};

/// How a turn model's first turn from rest ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FirstTurn {
    /// It completed the turn at this speed, m/s.
    Completed {
        /// Speed at the end of the turn, m/s.
        v_end_m_s: f64,
    },
    /// It stalled inside the turn at this time, s.
    Stalled {
        /// Time of the stall, s.
        t_s: f64,
    },
}

/// One scenario of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct PartingRow {
    /// Slope, degrees.
    pub alpha_deg: f64,
    /// Snow depth b, m.
    pub snow_depth: f64,
    /// Initial radius r0, m.
    pub r0: f64,
    /// Slope below which each model stalls in turn 0 from rest, degrees: `turns`, `turns-exact`.
    pub stall_slope_deg: (f64, f64),
    /// How turn 0 ended: `turns`, `turns-exact`.
    pub first_turn: (FirstTurn, FirstTurn),
    /// How many validity warnings `turns` gets here ([`validity_warnings`]).
    pub turns_warnings: usize,
}

/// Snow depths of the table over r0, thin to thick.
const B_OVER_R0: [f64; 5] = [0.01, 0.03, 0.1, 0.3, 1.0];

/// The table: for the slope and radius of `scenario`, from rest, at the
/// depths b = (0.01 … 1) r0, and the thick-snow case α = 40°, b = 0.2 m,
/// r0 = 0.15 m.
///
/// # Errors
/// [`SimError`] if a run fails.
pub fn where_turn_models_part_ways(scenario: &Scenario) -> Result<Vec<PartingRow>, SimError> {
    let base = ScenarioFile::from(*scenario);
    let mut cases: Vec<ScenarioFile> = B_OVER_R0
        .iter()
        .map(|q| ScenarioFile {
            snow_depth: q * base.r0,
            v0: 0.0,
            ..base
        })
        .collect();
    cases.push(ScenarioFile {
        alpha_deg: 40.0,
        snow_depth: 0.2,
        r0: 0.15,
        v0: 0.0,
        ..base
    });
    let opts = SimOptions {
        t_end: 1e4,
        turns: Some(1),
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    let mut rows = Vec::with_capacity(cases.len());
    for file in cases {
        let s = Scenario::new(file)?;
        let first_turn = |kind: ModelKind| -> Result<FirstTurn, SimError> {
            let traj = kind.build().simulate(&s, &opts)?;
            Ok(if traj.stop.reason == StopReason::Stalled {
                FirstTurn::Stalled { t_s: traj.stop.t_s }
            } else {
                FirstTurn::Completed {
                    v_end_m_s: traj.samples.last().map_or(f64::NAN, |p| p.v_m_s),
                }
            })
        };
        let stall = |kind: ModelKind| {
            kind.stall_threshold(s.snow_depth(), s.initial_radius())
                .map_or(f64::NAN, |t| t.slope.to_degrees())
        };
        rows.push(PartingRow {
            alpha_deg: file.alpha_deg,
            snow_depth: file.snow_depth,
            r0: file.r0,
            stall_slope_deg: (stall(ModelKind::Turns), stall(ModelKind::TurnsExact)),
            first_turn: (
                first_turn(ModelKind::Turns)?,
                first_turn(ModelKind::TurnsExact)?,
            ),
            turns_warnings: validity_warnings(ModelKind::Turns, &s).len(),
        });
    }
    Ok(rows)
}
