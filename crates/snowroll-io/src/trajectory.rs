//! A trajectory written as it is computed: [`TrajectoryWriter`] is a
//! [`SampleSink`], so a run of any length needs memory for one row.
//!
//! Layout (the parameters first, each row as it comes, the stop last):
//! * CSV: `#` lines with the version, the model and every parameter; the
//!   column header; one row per sample; a last `# stop = …` line.
//! * JSON: one object, `snowroll_version`, `model`, `params`, then
//!   `samples` (one object per line), then `stop`.
//!
//! A turn model's rows carry its [`TurnState`] columns (`turn`,
//! `theta_rad`, `omega_rad_s`) after those of [`Sample`]; a run that records
//! the energy ledger carries the [`LedgerRow`] columns last
//! (`docs/snowball-and-losses.md` §3).

use std::io::Write;

use super::ledger::closed_form_terminal_velocity;
use super::row::{Extra, Row, RowKind};
use super::{
    format_number, write_csv_header, write_csv_stop, write_json_array_end, write_json_end,
    write_json_field, write_json_opening, Body, Format, JsonStop, RunParams,
};
use crate::OutputError;
use snowroll::models::ModelKind;
use snowroll::trajectory::{LedgerRow, RunEnd, Sample, SampleSink, Stop, Trajectory, TurnState};
use snowroll::SinkError;

/// Writes a trajectory row by row in a [`Format`]; use it as the sink of
/// [`Model::simulate_into`](snowroll::Model::simulate_into), then call
/// [`finish`](Self::finish) with the run's end. Nothing is held but the
/// last turn state.
///
/// ```
/// use snowroll::{Model, ModelKind, Scenario, SimOptions};
/// use snowroll_io::{Format, RunParams, TrajectoryWriter};
/// let (s, opts) = (Scenario::default(), SimOptions::default());
/// let mut out = Vec::new();
/// let params = RunParams::new(&s, &opts);
/// let mut writer = TrajectoryWriter::new(&mut out, Format::Csv, ModelKind::TorqueCm, &params)?;
/// let end = ModelKind::TorqueCm.build().simulate_into(&s, &opts, &mut writer)?;
/// writer.finish(&end, &[])?;
/// let text = String::from_utf8(out).unwrap();
/// assert!(text.lines().last().unwrap().starts_with("# stop = end-time"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct TrajectoryWriter<W: Write> {
    body: Body<W>,
    /// Whether the rows carry the turn columns.
    turns: bool,
    /// Whether the rows carry the ledger columns.
    ledger: bool,
    /// The ledger row of the sample that comes next ([`SampleSink::ledger`]).
    pending_ledger: Option<LedgerRow>,
    /// The closed-form terminal velocity, m/s, where one exists (§2.2).
    v_terminal: Option<f64>,
    rows: u64,
    last_turn: Option<TurnState>,
}

impl<W: Write> TrajectoryWriter<W> {
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
        let turns = !model.is_circular();
        let ledger = params.losses().is_some_and(|l| l.records_ledger());
        let v_terminal = closed_form_terminal_velocity(model, params);
        let body = match format {
            Format::Csv => {
                write_csv_header(&mut w, model, params)?;
                if let Some(vt) = v_terminal {
                    writeln!(
                        w,
                        "# terminal velocity: closed form v_t = {} m/s (docs/snowball-and-losses.md §2.2); \
                         measured: v_m_s at the stop `terminal`",
                        format_number(vt)
                    )?;
                }
                let kind = if turns && ledger {
                    RowKind::TurnLedger
                } else if turns {
                    RowKind::Turn
                } else if ledger {
                    RowKind::Ledger
                } else {
                    RowKind::Plain
                };
                Body::csv(w, Row::columns(kind))?
            }
            Format::Json => {
                write_json_opening(&mut w, model, params, "samples")?;
                Body::Json(w)
            }
        };
        Ok(Self {
            body,
            turns,
            ledger,
            pending_ledger: None,
            v_terminal,
            rows: 0,
            last_turn: None,
        })
    }

    /// Rows written so far.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// The turn state of the last row, for the turn models.
    pub fn last_turn(&self) -> Option<TurnState> {
        self.last_turn
    }

    /// Writes one row; a row with a non-finite number is refused before any
    /// of it is written ([`OutputError::NonFinite`]).
    fn row(&mut self, s: &Sample, turn: Option<&TurnState>) -> Result<(), OutputError> {
        let row = self.rows + 1;
        // A ledger run sends a ledger row before each sample; one without
        // is a model that keeps no ledger: zeros would lie.
        let ledger = match self.ledger {
            true => Some(
                self.pending_ledger
                    .take()
                    .ok_or(OutputError::MissingLedger { row })?,
            ),
            false => None,
        };
        let extra = match (turn.filter(|_| self.turns), &ledger) {
            (Some(k), Some(l)) => Extra::TurnLedger(k, l),
            (Some(k), None) => Extra::Turn(k),
            (None, Some(l)) => Extra::Ledger(l),
            (None, None) => Extra::None,
        };
        self.body.put(row, &Row { sample: s, extra })?;
        self.rows += 1;
        self.last_turn = turn.copied();
        Ok(())
    }

    /// Writes how the run ended, and `notes` (requests the run could not
    /// honour, [`RunParams::notes`]), and returns the writer, flushed.
    ///
    /// # Errors
    /// [`OutputError`] when the writer fails.
    pub fn finish(self, end: &RunEnd, notes: &[String]) -> Result<W, OutputError> {
        self.finish_stop(&end.stop, notes)
    }

    fn finish_stop(self, stop: &Stop, notes: &[String]) -> Result<W, OutputError> {
        let mut w = match self.body {
            Body::Csv(csv) => {
                let mut w = (*csv).into_inner().map_err(|e| e.into_error())?;
                write_csv_stop(&mut w, stop, notes)?;
                w
            }
            Body::Json(mut w) => {
                write_json_array_end(&mut w, self.rows == 0)?;
                let stop = JsonStop {
                    v_terminal_m_s: self.v_terminal,
                    ..JsonStop::from(*stop)
                };
                write_json_field(&mut w, "stop", &stop)?;
                if !notes.is_empty() {
                    write_json_field(&mut w, "notes", &notes)?;
                }
                write_json_end(&mut w)?;
                w
            }
        };
        w.flush()?;
        Ok(w)
    }
}

impl<W: Write> SampleSink for TrajectoryWriter<W> {
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError> {
        Ok(self.row(sample, turn)?)
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.pending_ledger = Some(*row);
        Ok(())
    }
}

/// Writes a whole `traj` in `format`, recording the version, the model and
/// `params` (the layout of [`TrajectoryWriter`]).
///
/// # Errors
/// [`OutputError`] when the writer fails.
pub fn write_trajectory(
    w: &mut impl Write,
    format: Format,
    traj: &Trajectory,
    params: &RunParams,
) -> Result<(), OutputError> {
    let mut writer = TrajectoryWriter::new(w, format, traj.model, params)?;
    let has_turns = traj.turn_states.len() == traj.samples.len();
    let has_ledger = traj.ledger.len() == traj.samples.len();
    for (i, s) in traj.samples.iter().enumerate() {
        let turn = traj.turn_states.get(i).filter(|_| has_turns);
        if let Some(l) = traj.ledger.get(i).filter(|_| has_ledger) {
            writer.pending_ledger = Some(*l);
        }
        writer.row(s, turn)?;
    }
    writer.finish_stop(&traj.stop, &params.notes)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use snowroll::scenario::Scenario;
    use snowroll::trajectory::{SimOptions, StopReason};

    fn tiny() -> Trajectory {
        Trajectory {
            model: ModelKind::TorqueCm,
            samples: vec![Sample {
                t_s: 0.0,
                x_m: 0.0,
                v_m_s: 0.0,
                a_m_s2: 3.27,
                r_m: 0.1,
                mass_kg: 12.566,
                normal_n: 106.8,
                friction_n: 20.5,
                friction_ratio: Some(20.5 / 106.8),
            }],
            turn_states: vec![],
            stop: Stop {
                reason: StopReason::EndTime,
                t_s: 0.0,
                x_m: 0.0,
                v_m_s: 0.0,
                turn: None,
            },
            stats: Default::default(),
            ledger: Vec::new(),
        }
    }

    #[test]
    fn csv_has_comment_header_then_unit_columns_then_the_stop() {
        let params = RunParams::new(&Scenario::default(), &SimOptions::default());
        let mut out = Vec::new();
        write_trajectory(&mut out, Format::Csv, &tiny(), &params).unwrap();
        let text = String::from_utf8(out).unwrap();
        let mut lines = text.lines();
        assert!(lines.next().unwrap().starts_with("# snowroll "));
        assert!(text.contains("# model = torque-cm (eq. (4))"));
        assert!(text.contains("# alpha_deg = 30"));
        let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
        assert_eq!(
            header,
            "t_s,x_m,v_m_s,a_m_s2,r_m,mass_kg,normal_n,friction_n,friction_ratio"
        );
        // Streamed: the stop is known only at the end, so it closes the file.
        assert!(text
            .lines()
            .last()
            .unwrap()
            .starts_with("# stop = end-time"));
    }

    #[test]
    fn json_has_the_documented_shape() {
        let params = RunParams::new(&Scenario::default(), &SimOptions::default());
        let mut out = Vec::new();
        write_trajectory(&mut out, Format::Json, &tiny(), &params).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        for key in ["snowroll_version", "model", "params", "stop", "samples"] {
            assert!(v.get(key).is_some(), "missing {key}");
        }
        assert_eq!(v["model"]["id"], "torque-cm");
        assert_eq!(v["stop"]["reason"], "end-time");
        assert_eq!(v["params"]["snow_depth"], 0.01);
        assert_eq!(v["samples"][0]["a_m_s2"], 3.27);
    }

    #[test]
    fn json_without_samples_is_still_one_valid_object() {
        let params = RunParams::new(&Scenario::default(), &SimOptions::default());
        let mut traj = tiny();
        traj.samples.clear();
        let mut out = Vec::new();
        write_trajectory(&mut out, Format::Json, &traj, &params).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(v["samples"].as_array().unwrap().len(), 0);
    }

    #[test]
    fn regression_7_6_a_non_finite_number_is_refused_naming_column_and_row() {
        let params = RunParams::new(&Scenario::default(), &SimOptions::default());
        let mut traj = tiny();
        traj.samples.push(Sample {
            mass_kg: f64::INFINITY,
            ..traj.samples[0]
        });
        for format in [Format::Csv, Format::Json] {
            let mut out = Vec::new();
            let err = write_trajectory(&mut out, format, &traj, &params).unwrap_err();
            let text = err.to_string();
            assert!(
                text.contains("mass_kg = inf") && text.contains("row 2"),
                "{text}"
            );
            // Rows are streamed: the first went out, nothing of the bad one
            // did (the program then drops the whole output, sink.rs).
            let written = String::from_utf8(out).unwrap();
            // (Both rows have a = 3.27; only the first may appear.)
            assert_eq!(written.matches("3.27").count(), 1, "{written}");
        }
    }
}
