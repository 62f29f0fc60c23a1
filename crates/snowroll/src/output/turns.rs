//! Writing the per-turn table of §3.4 ([`TurnTable`]) as CSV or JSON, with
//! the same header as [`write_trajectory`](super::write_trajectory): version,
//! model, parameters, stop; then the long-run statistics; then the rows.

use std::io::Write;

use serde::Serialize;

use super::{check_finite, Format, JsonStop, ModelInfo, RunParams, VERSION};
use crate::error::OutputError;
use crate::models::{TurnRow, TurnSummary, TurnTable};

#[derive(Serialize)]
struct JsonTurnTable<'a> {
    snowroll_version: &'static str,
    model: ModelInfo,
    params: &'a RunParams,
    stop: JsonStop,
    summary: &'a TurnSummary,
    turns: &'a [TurnRow],
}

/// Writes `table` in `format`, recording the version, the model and `params`.
///
/// CSV: `#` lines (version, model, parameters, stop, then one line per
/// checkpoint of [`TurnSummary`]), then one row per turn with the columns of
/// [`TurnRow`]. JSON: one object with `summary` and `turns`.
///
/// # Errors
/// [`OutputError`] when the writer fails, [`OutputError::NonFinite`] (before
/// the offending row is written) when a number is NaN or infinite.
pub fn write_turn_table(
    w: &mut impl Write,
    format: Format,
    table: &TurnTable,
    params: &RunParams,
) -> Result<(), OutputError> {
    match format {
        Format::Csv => {
            super::write_csv_header(w, table.model, params, &table.stop)?;
            let s = &table.summary;
            check_finite(s, None)?;
            writeln!(
                w,
                "# summary: {} turns; accelerations over G = g sin(alpha) = {} m/s^2",
                s.turns,
                super::format_number(s.g_along_m_s2)
            )?;
            writeln!(
                w,
                "# summary columns: turns_K, mean_a_turn_over_g (k < K), \
                 mean_a_with_collision_over_g (k < K), window_first_turn, \
                 window_mean_a_turn_over_g, window_mean_a_with_collision_over_g, \
                 window_min_a_over_g, window_max_a_over_g (window: K/10 <= k < K)"
            )?;
            for c in &s.checkpoints {
                writeln!(
                    w,
                    "# summary: {}, {}, {}, {}, {}, {}, {}, {}",
                    c.turns,
                    c.mean_a_turn_over_g,
                    c.mean_a_with_collision_over_g,
                    c.window_first_turn,
                    c.window_mean_a_turn_over_g,
                    c.window_mean_a_with_collision_over_g,
                    c.window_min_a_over_g,
                    c.window_max_a_over_g
                )?;
            }
            let mut csv = csv::Writer::from_writer(&mut *w);
            if table.rows.is_empty() {
                csv.write_record(COLUMNS)?;
            }
            for (k, row) in (1..).zip(&table.rows) {
                check_finite(row, Some(k))?;
                csv.serialize(row)?;
            }
            csv.flush()?;
        }
        Format::Json => {
            let doc = JsonTurnTable {
                snowroll_version: VERSION,
                model: ModelInfo {
                    id: table.model.id(),
                    equation: table.model.equation(),
                },
                params,
                stop: table.stop.into(),
                summary: &table.summary,
                turns: &table.rows,
            };
            // serde_json would write a non-finite number as `null`.
            check_finite(&doc, None)?;
            serde_json::to_writer_pretty(&mut *w, &doc)?;
            writeln!(w)?;
        }
    }
    Ok(())
}

/// The CSV columns of [`TurnRow`], for the header of an empty table.
const COLUMNS: [&str; 15] = [
    "turn",
    "t_start_s",
    "x_start_m",
    "v_start_m_s",
    "t_end_s",
    "v_end_m_s",
    "v_after_m_s",
    "collision_loss_j",
    "mean_a_turn_m_s2",
    "min_a_m_s2",
    "max_a_m_s2",
    "mean_a_with_collision_m_s2",
    "min_normal_n",
    "min_normal_over_mg",
    "max_friction_ratio",
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::{run_turns, ModelKind};
    use crate::scenario::Scenario;
    use crate::trajectory::SimOptions;

    fn table(turns: u64) -> (TurnTable, RunParams) {
        let opts = SimOptions {
            turns: Some(turns),
            t_end: 1e4,
            ..SimOptions::default()
        };
        let s = Scenario::default();
        (
            run_turns(ModelKind::Turns, &s, &opts).unwrap(),
            RunParams::new(&s, &opts),
        )
    }

    #[test]
    fn csv_header_then_one_row_per_turn_with_unit_columns() {
        let (t, params) = table(3);
        let mut out = Vec::new();
        write_turn_table(&mut out, Format::Csv, &t, &params).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("# snowroll "));
        assert!(text.contains("# model = turns (eqs. (73), (76), (89))"));
        assert!(text.contains("# turns = 3"));
        assert!(text.contains("# stop = turns"));
        let body: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
        assert_eq!(body[0], COLUMNS.join(","));
        assert_eq!(body.len(), 1 + 3);
    }

    #[test]
    fn empty_table_still_has_the_header_row() {
        let (mut t, params) = table(1);
        t.rows.clear();
        let mut out = Vec::new();
        write_turn_table(&mut out, Format::Csv, &t, &params).unwrap();
        let text = String::from_utf8(out).unwrap();
        let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
        assert_eq!(header, COLUMNS.join(","));
    }

    #[test]
    fn json_has_summary_and_turns() {
        let (t, params) = table(2);
        let mut out = Vec::new();
        write_turn_table(&mut out, Format::Json, &t, &params).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        for key in [
            "snowroll_version",
            "model",
            "params",
            "stop",
            "summary",
            "turns",
        ] {
            assert!(v.get(key).is_some(), "missing {key}");
        }
        assert_eq!(v["model"]["id"], "turns");
        assert_eq!(v["turns"].as_array().unwrap().len(), 2);
        assert_eq!(v["turns"][1]["turn"], 1);
    }
}
