//! The table of where the turn models part ways.

use crate::{where_turn_models_part_ways, FirstTurn, Lab, ReportError, Table};
use snowroll::models::THIN_SNOW_MAX_B_OVER_R0;

/// The table of where the turn models part ways (see [`where_turn_models_part_ways`]).
pub(super) fn parting_table(lab: &Lab) -> Result<Table, ReportError> {
    let rows = where_turn_models_part_ways(lab.scenario())?;
    let outcome = |f: FirstTurn| match f {
        FirstTurn::Completed { v_end_m_s } => format!("rolls on, v = {v_end_m_s:.4} m/s"),
        FirstTurn::Stalled { t_s } => format!("stalls at t = {t_s:.3} s"),
    };
    Ok(Table {
        title: "Where the models part ways".to_string(),
        caption: format!(
            "The first-order turn model (turns, eq. (73)) against the exact geometry (turns-exact), from rest, in turn 0. \
             Their stall slopes (fn. 7 in §3) differ by a relative O(b/r0); for thick snow one stalls where the other rolls on. \
             snowroll simulate and snowroll turns warn on stderr when turns runs beyond b/r0 = {THIN_SNOW_MAX_B_OVER_R0} or where the two disagree about stalling."
        ),
        header: [
            "α (°)",
            "b (m)",
            "r0 (m)",
            "b/r0",
            "stall slope, turns (°)",
            "stall slope, turns-exact (°)",
            "turn 0, turns",
            "turn 0, turns-exact",
            "warnings for turns",
        ]
        .map(String::from)
        .to_vec(),
        rows: rows
            .iter()
            .map(|r| {
                vec![
                    format!("{:.0}", r.alpha_deg),
                    format!("{:.3}", r.snow_depth),
                    format!("{:.2}", r.r0),
                    format!("{:.3}", r.snow_depth / r.r0),
                    format!("{:.4}", r.stall_slope_deg.0),
                    format!("{:.4}", r.stall_slope_deg.1),
                    outcome(r.first_turn.0),
                    outcome(r.first_turn.1),
                    r.turns_warnings.to_string(),
                ]
            })
            .collect(),
    })
}
