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
use crate::float_text::push_float;
use crate::OutputError;
use snowroll::models::{ModelKind, TurnRow, TurnRunEnd, TurnSink, TurnSummary, TurnTable};
use snowroll::trajectory::{LedgerRow, Stop};
use snowroll::SinkError;

/// Writes a turn table row by row in a [`Format`]; use it as the sink of
/// [`TurnModel::run_table_into`](snowroll::TurnModel::run_table_into), then
/// call [`finish`](Self::finish) with the run's end.
pub struct TurnTableWriter<W: Write> {
    out: Out<W>,
    rows: u64,
    /// The ledger of the row that comes next ([`TurnSink::ledger`]).
    pending_ledger: Option<LedgerRow>,
}

/// Where the rows go.
enum Out<W: Write> {
    /// Serialised: JSON, and CSV rows that carry the ledger at each turn
    /// end (`--ledger`, `docs/snowball-and-losses.md` §3.2).
    Body { body: Body<W>, ledger: bool },
    /// CSV rows without the ledger, formatted here ([`LineFormatter`]) and
    /// written in blocks of about [`LINES_BLOCK`] bytes.
    Lines {
        w: W,
        lines: Vec<u8>,
        format: LineFormatter,
    },
}

/// Bytes of formatted CSV rows written at a time.
const LINES_BLOCK: usize = 1 << 20;

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
        let out = match format {
            Format::Csv if !ledger => {
                write_csv_header(&mut w, model, params)?;
                // The column header as `csv` writes it.
                let mut header = csv::WriterBuilder::new()
                    .has_headers(false)
                    .from_writer(Vec::new());
                header.write_record(TableRow::columns(false))?;
                w.write_all(&header.into_inner().map_err(|e| e.into_error())?)?;
                Out::Lines {
                    w,
                    lines: Vec::with_capacity(LINES_BLOCK + 1024),
                    format: LineFormatter::default(),
                }
            }
            Format::Csv => {
                write_csv_header(&mut w, model, params)?;
                Out::Body {
                    body: Body::csv(w, TableRow::columns(ledger))?,
                    ledger,
                }
            }
            Format::Json => {
                write_json_opening(&mut w, model, params, "turns")?;
                Out::Body {
                    body: Body::Json(w),
                    ledger,
                }
            }
        };
        Ok(Self {
            out,
            rows: 0,
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
        match &mut self.out {
            Out::Lines { w, lines, format } => {
                if !format.line(turn, lines) {
                    // A number not finite: the error names the row and the column.
                    let row = TableRow { turn, ledger: None };
                    check_finite(&row, Some(k))?;
                    // (Not reached: both refuse the same numbers.)
                    let mut by_csv = csv::WriterBuilder::new()
                        .has_headers(false)
                        .from_writer(std::mem::take(lines));
                    by_csv.serialize(row)?;
                    *lines = by_csv.into_inner().map_err(|e| e.into_error())?;
                }
                if lines.len() >= LINES_BLOCK {
                    w.write_all(lines)?;
                    lines.clear();
                }
            }
            Out::Body { body, ledger } => {
                let ledger = match ledger {
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
                body.put(k, row)?;
            }
        }
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
        let body = match self.out {
            Out::Lines { mut w, lines, .. } => {
                w.write_all(&lines)?;
                Body::Csv(Box::new(
                    csv::WriterBuilder::new().has_headers(false).from_writer(w),
                ))
            }
            Out::Body { body, .. } => body,
        };
        let mut w = match body {
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

/// The CSV rows of a turn table without the ledger, formatted by hand in
/// the bytes the `csv` writer gives the serialised [`TableRow`] (floats as
/// `ryu` writes them, the turn by `itoa`, an undefined ratio as an empty
/// field; a test holds the two to the byte). By hand because this is the
/// hot path of a long table: serde and `csv` took four times as long per
/// row. A turn starts when and as fast as the one before ended (`t_start =
/// t_end`, `v_start = v_after`, the same numbers), so those two are
/// formatted once. The floats by `zmij` ([`push_float`]), a quarter faster
/// than `ryu` on these numbers.
#[derive(Debug, Clone, Default)]
struct LineFormatter {
    /// The bits and text of the last `t_end_s` and `v_after_m_s`.
    carried: [(Option<u64>, Vec<u8>); 2],
}

impl LineFormatter {
    /// Appends the row of `turn` to `out`; false, with nothing appended,
    /// when a number is not finite.
    fn line(&mut self, turn: &TurnRow, out: &mut Vec<u8>) -> bool {
        let t = turn;
        let floats = [
            t.t_start_s,
            t.x_start_m,
            t.v_start_m_s,
            t.t_end_s,
            t.v_end_m_s,
            t.v_after_m_s,
            t.collision_loss_j,
            t.mean_a_turn_m_s2,
            t.min_a_m_s2,
            t.max_a_m_s2,
            t.mean_a_with_collision_m_s2,
            t.min_normal_n,
            t.min_normal_over_mg,
        ];
        let ratio_finite = t.max_friction_ratio.is_none_or(f64::is_finite);
        if !floats.iter().all(|x| x.is_finite()) || !ratio_finite {
            return false;
        }
        out.extend_from_slice(itoa::Buffer::new().format(t.turn).as_bytes());
        let mut number = zmij::Buffer::new();
        // Columns 0 and 2 (t_start, v_start) may be the carried 3 and 5
        // (t_end, v_after) of the row before.
        for (column, x) in floats.into_iter().enumerate() {
            out.push(b',');
            let slot = match column {
                0 | 3 => 0,
                2 | 5 => 1,
                _ => {
                    push_float(out, &mut number, x);
                    continue;
                }
            };
            let (bits, text) = &mut self.carried[slot];
            if column < 3 && *bits == Some(x.to_bits()) {
                out.extend_from_slice(text);
                continue;
            }
            let start = out.len();
            push_float(out, &mut number, x);
            if column >= 3 {
                text.clear();
                text.extend_from_slice(&out[start..]);
                *bits = Some(x.to_bits());
            }
        }
        out.push(b',');
        if let Some(ratio) = t.max_friction_ratio {
            push_float(out, &mut number, ratio);
        }
        out.push(b'\n');
        true
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

    /// The hand-formatted rows are the bytes the `csv` writer gives the
    /// serialised row, for awkward numbers (exponents, integers, negative
    /// zero, subnormals, extremes) and an undefined ratio; a non-finite
    /// number is refused. Checked once against a formatter that put the
    /// columns in another order, which this test failed.
    #[test]
    fn hand_formatted_rows_are_the_csv_writers_bytes() {
        let (t, _) = table(3);
        let mut row = t.rows[1];
        let awkward = [
            1e-7,
            1e21,
            -0.0,
            5e-324,
            f64::MAX / 8.0,
            123456.0,
            0.1 + 0.2,
        ];
        // One formatter for all rows, as for a table: each row starts where
        // the one before ended (the carried text), or not.
        let mut format = LineFormatter::default();
        for (n, x) in awkward.into_iter().enumerate() {
            row.turn = n as u64 * 1_000_003;
            if n % 3 == 0 {
                (row.t_start_s, row.v_start_m_s) = (row.t_end_s, row.v_after_m_s);
            } else {
                row.t_start_s = x;
            }
            row.t_end_s = x * 3.0 + 1.0;
            row.v_after_m_s = -x;
            row.min_a_m_s2 = -x;
            row.min_normal_over_mg = x / 3.0;
            row.max_friction_ratio = (n % 2 == 0).then_some(x * 7.0);
            let mut by_csv = csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(Vec::new());
            by_csv
                .serialize(TableRow {
                    turn: &row,
                    ledger: None,
                })
                .unwrap();
            let mut by_hand = Vec::new();
            assert!(format.line(&row, &mut by_hand));
            assert_eq!(
                String::from_utf8_lossy(&by_hand),
                String::from_utf8_lossy(&by_csv.into_inner().unwrap())
            );
        }
        row.v_end_m_s = f64::NAN;
        assert!(!format.line(&row, &mut Vec::new()));
        row.v_end_m_s = 1.0;
        row.max_friction_ratio = Some(f64::INFINITY);
        assert!(!format.line(&row, &mut Vec::new()));
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
