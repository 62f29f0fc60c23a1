//! Writing trajectories and turn tables as CSV or JSON, row by row as a run
//! computes them ([`TrajectoryWriter`], [`TurnTableWriter`]). Both formats
//! come from the same serde records ([`Sample`](snowroll::Sample),
//! [`TurnState`](snowroll::TurnState), [`LedgerRow`](snowroll::LedgerRow),
//! [`TurnRow`](snowroll::TurnRow)), and every CSV header from their serde field
//! names (`row.rs`); there is no hand-written CSV and no hand-typed header.

use std::io::Write;

use serde::{Deserialize, Serialize};

pub use error::OutputError;
use snowroll::format_number;
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, ScenarioFile};
use snowroll::trajectory::{SimOptions, Stop, StopReason};
use snowroll::{Losses, Settings, TurnMethod};

mod error;
mod finite;
pub mod fit_record;
mod float_text;
mod json;
mod ledger;
pub mod measured;
pub mod notes;
pub mod page_table;
#[cfg(feature = "parquet")]
pub mod parquet;
mod row;
pub mod sweep;
mod table;
mod trajectory;
mod turns;
pub use finite::{check_finite, NonFinite};
pub use json::json_document;
pub use snowroll::params::{RecordedSampling, UnknownSampling};
pub use table::CsvTable;
pub use trajectory::{write_trajectory, TrajectoryWriter};
pub use turns::{write_turn_table, TurnTableWriter};

/// The program version written into every output.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// Output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Format {
    /// Comma-separated values with `#` comment lines recording version and parameters.
    #[default]
    Csv,
    /// One JSON object.
    Json,
}

/// Every parameter of a run, as recorded in outputs: the settings, in the
/// order and form of the one parameter table ([`snowroll::params`]), then
/// the run's validity warnings. A config file may be an output of snowroll:
/// reading these keys back reproduces the run.
#[derive(Debug, Clone, PartialEq)]
pub struct RunParams {
    /// The run's settings (scenario and options).
    pub settings: Settings,
    /// Validity warnings of the run ([`snowroll::validity_warnings`]); empty when in range.
    pub warnings: Vec<String>,
    /// Requests the run could not honour (times after an early stop, turns
    /// short of those asked for), one sentence each; empty when none. Known
    /// only once the run ended, so the writers put them at the end, after the
    /// stop, not among the parameters.
    pub notes: Vec<String>,
    /// How a turn table was computed (`snowroll turns --method`), recorded
    /// after the parameters as `method`; `None` for other outputs.
    pub method: Option<TurnMethod>,
}

impl RunParams {
    /// Collects the parameters of a run.
    pub fn new(scenario: &Scenario, opts: &SimOptions) -> Self {
        Self {
            settings: Settings {
                scenario: ScenarioFile::from(*scenario),
                options: opts.clone(),
                per_turn: false,
            },
            warnings: Vec::new(),
            notes: Vec::new(),
            method: None,
        }
    }

    /// The parameters of a turn table (`snowroll turns`): one row per turn,
    /// so recorded.
    pub fn per_turn(mut self) -> Self {
        self.settings.per_turn = true;
        self
    }

    /// The losses, when any setting of theirs differs from its default
    /// (outputs record them only then).
    pub fn losses(&self) -> Option<Losses> {
        let l = self.settings.options.losses;
        (l != Losses::default()).then_some(l)
    }

    /// `key = value` lines, in the table's CSV order
    /// ([`Settings::csv_lines`]), then one `warning` line per warning.
    fn lines(&self) -> Vec<(String, String)> {
        let mut lines: Vec<(String, String)> = self
            .settings
            .csv_lines()
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect();
        lines.extend(self.method.map(|m| ("method".into(), m.id().into())));
        lines.extend(self.warnings.iter().map(|w| ("warning".into(), w.clone())));
        lines
    }
}

impl Serialize for RunParams {
    /// The table's JSON entries ([`Settings::json_entries`]), then
    /// `warnings` when there are any.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = serializer.serialize_map(None)?;
        self.settings.serialize_record(&mut map)?;
        if let Some(m) = self.method {
            map.serialize_entry("method", m.id())?;
        }
        if !self.warnings.is_empty() {
            map.serialize_entry("warnings", &self.warnings)?;
        }
        map.end()
    }
}

/// The `model` object of a JSON output: the id and equation of
/// [`ModelKind`] (the full description is the public
/// [`ModelInfo`](snowroll::models::ModelInfo)).
#[derive(Serialize)]
struct JsonModel {
    id: &'static str,
    equation: &'static str,
}

impl JsonModel {
    fn of(model: ModelKind) -> Self {
        Self {
            id: model.id(),
            equation: model.equation(),
        }
    }
}

#[derive(Serialize)]
struct JsonStop {
    reason: StopReason,
    description: &'static str,
    t_s: f64,
    x_m: f64,
    v_m_s: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    turn: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    theta_rad: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    omega_rad_s: Option<f64>,
    /// The closed-form terminal velocity, m/s, where one exists (§2.2).
    #[serde(skip_serializing_if = "Option::is_none")]
    v_terminal_m_s: Option<f64>,
}

impl From<Stop> for JsonStop {
    fn from(s: Stop) -> Self {
        Self {
            reason: s.reason,
            description: s.reason.describe(),
            t_s: s.t_s,
            x_m: s.x_m,
            v_m_s: s.v_m_s,
            turn: s.turn.map(|k| k.turn),
            theta_rad: s.turn.map(|k| k.theta_rad),
            omega_rad_s: s.turn.map(|k| k.omega_rad_s),
            v_terminal_m_s: None,
        }
    }
}

/// The `#` comment lines that open every CSV: version, model and every
/// parameter in a fixed order.
pub(crate) fn write_csv_header(
    w: &mut impl Write,
    model: ModelKind,
    params: &RunParams,
) -> Result<(), OutputError> {
    check_finite(params, None)?;
    writeln!(w, "# snowroll {VERSION}")?;
    writeln!(w, "# model = {} ({})", model.id(), model.equation())?;
    for (k, v) in params.lines() {
        writeln!(w, "# {k} = {v}")?;
    }
    Ok(())
}

/// The `#` comment lines that close every CSV: how the run stopped, then
/// one `# note = ...` line per request the run could not honour.
pub(crate) fn write_csv_stop(
    w: &mut impl Write,
    stop: &Stop,
    notes: &[String],
) -> Result<(), OutputError> {
    check_finite(stop, None)?;
    let turn = stop.turn.map_or(String::new(), |k| {
        format!(
            " turn = {} theta_rad = {} omega_rad_s = {}",
            k.turn, k.theta_rad, k.omega_rad_s
        )
    });
    writeln!(
        w,
        "# stop = {} at t_s = {} x_m = {} v_m_s = {}{}: {}",
        serde_json::to_value(stop.reason)?
            .as_str()
            .unwrap_or_default(),
        format_number(stop.t_s),
        format_number(stop.x_m),
        format_number(stop.v_m_s),
        turn,
        stop.reason.describe()
    )?;
    for note in notes {
        writeln!(w, "# note = {note}")?;
    }
    Ok(())
}

/// The opening of a streamed JSON object: version, model and parameters,
/// then the key of the array that follows, `"key": [`.
pub(crate) fn write_json_opening(
    w: &mut impl Write,
    model: ModelKind,
    params: &RunParams,
    array_key: &str,
) -> Result<(), OutputError> {
    write!(w, "{{\n  \"snowroll_version\": ")?;
    serde_json::to_writer(&mut *w, VERSION)?;
    write!(w, ",\n  \"model\": ")?;
    serde_json::to_writer(&mut *w, &JsonModel::of(model))?;
    write!(w, ",\n  \"params\": ")?;
    serde_json::to_writer(&mut *w, params)?;
    write!(w, ",\n  \"{array_key}\": [")?;
    Ok(())
}

/// The body of a streamed output, after its opening: the rows go to a CSV
/// writer or into the JSON array.
pub(crate) enum Body<W: Write> {
    /// Boxed: the CSV writer carries its own buffer.
    Csv(Box<csv::Writer<W>>),
    /// The JSON array, one element per line.
    Json(W),
}

impl<W: Write> Body<W> {
    /// A CSV body whose first record is the column header `columns`.
    pub(crate) fn csv<'c>(
        w: W,
        columns: impl IntoIterator<Item = &'c str>,
    ) -> Result<Self, OutputError> {
        let mut csv = csv::WriterBuilder::new().has_headers(false).from_writer(w);
        csv.write_record(columns)?;
        Ok(Body::Csv(Box::new(csv)))
    }

    /// Writes `record` as row `row` (from 1), refused before any of it is
    /// written if a number is not finite ([`OutputError::NonFinite`]).
    pub(crate) fn put(&mut self, row: u64, record: &impl Serialize) -> Result<(), OutputError> {
        match self {
            Body::Csv(csv) => {
                check_finite(record, Some(row))?;
                csv.serialize(record)?;
            }
            Body::Json(w) => write_json_element(w, row, record)?,
        }
        Ok(())
    }
}

/// Element `row` (from 1) of a streamed JSON array, on its own line;
/// refused, before anything of it is written, if a number is not finite.
pub(crate) fn write_json_element(
    w: &mut impl Write,
    row: u64,
    value: &impl Serialize,
) -> Result<(), OutputError> {
    // serde_json would write a non-finite number as `null`.
    check_finite(value, Some(row))?;
    let first = row == 1;
    w.write_all(if first { b"\n    " } else { b",\n    " })?;
    serde_json::to_writer(&mut *w, value)?;
    Ok(())
}

/// Closes the array of a streamed JSON object.
pub(crate) fn write_json_array_end(w: &mut impl Write, empty: bool) -> Result<(), OutputError> {
    w.write_all(if empty { b"]" } else { b"\n  ]" })?;
    Ok(())
}

/// One more `"key": value` pair of a streamed JSON object.
pub(crate) fn write_json_field(
    w: &mut impl Write,
    key: &str,
    value: &impl Serialize,
) -> Result<(), OutputError> {
    check_finite(value, None)?;
    write!(w, ",\n  \"{key}\": ")?;
    serde_json::to_writer(&mut *w, value)?;
    Ok(())
}

/// Closes a streamed JSON object.
pub(crate) fn write_json_end(w: &mut impl Write) -> Result<(), OutputError> {
    writeln!(w, "\n}}")?;
    Ok(())
}
