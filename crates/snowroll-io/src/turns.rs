//! Writing the per-turn table of §3.4 as it is computed:
//! [`TurnTableWriter`] is a [`TurnSink`], so a run of any number of turns
//! needs memory for one row.
//!
//! Layout, as for trajectories ([`TrajectoryWriter`](super::TrajectoryWriter)):
//! * CSV: `#` lines with version, model and parameters; the column header;
//!   one row per turn as it ends; then `#` lines with the stop and the
//!   long-run statistics ([`TurnSummary`], one line per checkpoint).
//! * JSON: one object, `snowroll_version`, `model`, `params`, then `turns`
//!   (one object per line), then `stop` and `summary`.

use std::io::Write;

use super::row::TableRow;
use super::{
    check_finite, format_number, write_csv_header, write_csv_stop, write_json_array_end,
    write_json_end, write_json_field, write_json_opening, Body, Format, JsonStop, RunParams,
};
use crate::OutputError;
use snowroll::models::{ModelKind, TurnRow, TurnRunEnd, TurnSink, TurnSummary, TurnTable};
use snowroll::trajectory::{LedgerRow, Stop};
use snowroll::SinkError;

/// Writes a turn table row by row in a [`Format`]; use it as the sink of
/// [`TurnModel::run_table_into`](snowroll::TurnModel::run_table_into), then
/// call [`finish`](Self::finish) with the run's end.
pub struct TurnTableWriter<W: Write> {
    body: Body<W>,
    rows: u64,
    /// Whether the rows carry the ledger at each turn end (`--ledger`,
    /// `docs/snowball-and-losses.md` §3.2).
    ledger: bool,
    /// The ledger of the row that comes next ([`TurnSink::ledger`]).
    pending_ledger: Option<LedgerRow>,
}

impl<W: Write> TurnTableWriter<W> {
    /// Writes the opening (version, `model`, `params`, and for CSV the
    /// column header) to `w`.
    ///
    /// # Errors
    /// [`OutputError`] when the writer fails.
    pub fn new(
        mut w: W,
        format: Format,
        model: ModelKind,
        params: &RunParams,
    ) -> Result<Self, OutputError> {
        let ledger = params.losses().is_some_and(|l| l.records_ledger());
        let body = match format {
            Format::Csv => {
                write_csv_header(&mut w, model, params)?;
                Body::csv(w, TableRow::columns(ledger))?
            }
            Format::Json => {
                write_json_opening(&mut w, model, params, "turns")?;
                Body::Json(w)
            }
        };
        Ok(Self {
            body,
            rows: 0,
            ledger,
            pending_ledger: None,
        })
    }

    /// Rows written so far.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// Writes one row; a row with a non-finite number is refused before any
    /// of it is written ([`OutputError::NonFinite`]).
    fn row(&mut self, turn: &TurnRow) -> Result<(), OutputError> {
        let k = self.rows + 1;
        let ledger = match self.ledger {
            true => Some(
                self.pending_ledger
                    .take()
                    .ok_or(OutputError::MissingLedger { row: k })?,
            ),
            false => None,
        };
        let row = &TableRow {
            turn,
            ledger: ledger.as_ref(),
        };
        self.body.put(k, row)?;
        self.rows += 1;
        Ok(())
    }

    /// Writes the stop, `notes` (requests the run could not honour,
    /// [`RunParams::notes`]) and the long-run statistics, and returns the
    /// writer, flushed.
    ///
    /// # Errors
    /// [`OutputError`] when the writer fails.
    pub fn finish(self, end: &TurnRunEnd, notes: &[String]) -> Result<W, OutputError> {
        self.finish_with(&end.stop, &end.summary, notes)
    }

    fn finish_with(
        self,
        stop: &Stop,
        summary: &TurnSummary,
        notes: &[String],
    ) -> Result<W, OutputError> {
        let mut w = match self.body {
            Body::Csv(csv) => {
                let mut w = (*csv).into_inner().map_err(|e| e.into_error())?;
                write_csv_stop(&mut w, stop, notes)?;
                write_csv_summary(&mut w, summary)?;
                w
            }
            Body::Json(mut w) => {
                write_json_array_end(&mut w, self.rows == 0)?;
                write_json_field(&mut w, "stop", &JsonStop::from(*stop))?;
                if !notes.is_empty() {
                    write_json_field(&mut w, "notes", &notes)?;
                }
                write_json_field(&mut w, "summary", summary)?;
                write_json_end(&mut w)?;
                w
            }
        };
        w.flush()?;
        Ok(w)
    }
}

impl<W: Write> TurnSink for TurnTableWriter<W> {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        Ok(self.row(row)?)
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.pending_ledger = Some(*row);
        Ok(())
    }
}

/// The `#` lines of the long-run statistics: one per checkpoint.
fn write_csv_summary(w: &mut impl Write, s: &TurnSummary) -> Result<(), OutputError> {
    check_finite(s, None)?;
    writeln!(
        w,
        "# summary: {} turns; accelerations over G = g sin(alpha) = {} m/s^2",
        s.turns,
        format_number(s.g_along_m_s2)
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
    Ok(())
}

/// Writes a whole `table` in `format`, recording the version, the model
/// and `params` (the layout of [`TurnTableWriter`]).
///
/// # Errors
/// [`OutputError`] when the writer fails.
pub fn write_turn_table(
    w: &mut impl Write,
    format: Format,
    table: &TurnTable,
    params: &RunParams,
) -> Result<(), OutputError> {
    let mut writer = TurnTableWriter::new(w, format, table.model, params)?;
    let has_ledger = table.ledger.len() == table.rows.len();
    for (i, row) in table.rows.iter().enumerate() {
        if let Some(l) = table.ledger.get(i).filter(|_| has_ledger) {
            writer.pending_ledger = Some(*l);
        }
        writer.row(row)?;
    }
    writer.finish_with(&table.stop, &table.summary, &params.notes)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use snowroll::models::{run_turns, ModelKind};
    use snowroll::scenario::Scenario;
    use snowroll::trajectory::SimOptions;

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
        // Streamed: the stop and the summary close the file.
        let lines: Vec<&str> = text.lines().collect();
        let stop = lines.iter().position(|l| l.starts_with("# stop = turns"));
        let last_row = lines.iter().rposition(|l| !l.starts_with('#'));
        assert!(stop > last_row);
        let body: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
        assert_eq!(body[0], TableRow::columns(false).join(","));
        assert_eq!(body.len(), 1 + 3);
    }

    /// With `ledger` each row carries the ledger at its turn end, after the
    /// turn's columns, and a row whose ledger is missing is an error.
    #[test]
    fn a_ledger_run_writes_the_ledger_columns_last() {
        let opts = SimOptions {
            turns: Some(3),
            t_end: 1e4,
            losses: snowroll::Losses {
                ledger: true,
                ..snowroll::Losses::default()
            },
            ..SimOptions::default()
        };
        let s = Scenario::default();
        let t = run_turns(ModelKind::Turns, &s, &opts).unwrap();
        let params = RunParams::new(&s, &opts);
        let mut out = Vec::new();
        write_turn_table(&mut out, Format::Csv, &t, &params).unwrap();
        let text = String::from_utf8(out).unwrap();
        let body: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
        assert_eq!(body[0], TableRow::columns(true).join(","));
        assert!(body[0].ends_with(",collision_j,created_j,residual_j"));
        let width = body[0].split(',').count();
        assert!(body[1..].iter().all(|r| r.split(',').count() == width));
        assert_eq!(body.len(), 1 + 3);
        let mut writer = TurnTableWriter::new(Vec::new(), Format::Csv, t.model, &params).unwrap();
        assert!(matches!(
            writer.row(&t.rows[0]),
            Err(OutputError::MissingLedger { row: 1 })
        ));
    }

    #[test]
    fn empty_table_still_has_the_header_row() {
        let (mut t, params) = table(1);
        t.rows.clear();
        let mut out = Vec::new();
        write_turn_table(&mut out, Format::Csv, &t, &params).unwrap();
        let text = String::from_utf8(out).unwrap();
        let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
        assert_eq!(header, TableRow::columns(false).join(","));
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
