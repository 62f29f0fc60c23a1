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
use snowroll::trajectory::{Sampling, SimOptions, Stop, StopReason};

mod error;
mod finite;
mod ledger;
mod row;
mod sampling;
mod trajectory;
mod turns;
pub use finite::{check_finite, NonFinite};
pub use sampling::{RecordedSampling, UnknownSampling};
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

/// Every parameter of a run, as recorded in outputs, in the one parameter
/// vocabulary of [`ScenarioFile`] (the command line's long flags in
/// snake_case). A config file may be an output of snowroll: reading these
/// keys back reproduces the run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunParams {
    /// The scenario.
    #[serde(flatten)]
    pub scenario: ScenarioFile,
    /// End time, s.
    pub t_end: f64,
    /// End distance, m.
    pub x_end: Option<f64>,
    /// Number of turns (turn models).
    pub turns: Option<u64>,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// How the rows were chosen; written in words (`sampling = every 0.5 s`).
    pub sampling: RecordedSampling,
    /// Most rows of the run ([`SimOptions::max_rows`]).
    pub max_rows: u64,
    /// Most integrator steps of the run ([`Tolerances::max_steps`](snowroll::integrate::Tolerances::max_steps)).
    pub max_steps: u64,
    /// The spacing of a regular sampling grid, s (`--dt`), when one was asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// The requested sample times, s (`--times`), when they were given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub times: Option<Vec<f64>>,
    /// Coefficient of static friction of the slip check; none = no check.
    pub mu: Option<f64>,
    /// How the turn models climb each new layer.
    pub collision: snowroll::models::CollisionModel,
    /// What the run does where the normal force reaches zero.
    pub on_hop: snowroll::trajectory::OnHop,
    /// The losses, the ledger and the terminal stop, when any differs from
    /// its default (outputs of lossless runs are unchanged).
    #[serde(flatten)]
    pub losses: Option<snowroll::losses::Losses>,
    /// Validity warnings of the run ([`snowroll::validity_warnings`]); empty when in range.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// Requests the run could not honour (times after an early stop, turns
    /// short of those asked for), one sentence each; empty when none. Known
    /// only once the run ended, so the writers put them at the end, after the
    /// stop, not among the parameters.
    #[serde(skip)]
    pub notes: Vec<String>,
}

impl RunParams {
    /// Collects the parameters of a run.
    pub fn new(scenario: &Scenario, opts: &SimOptions) -> Self {
        let (dt, times) = match &opts.sampling {
            Sampling::Every(dt) => (Some(*dt), None),
            Sampling::Times(ts) => (None, Some(ts.clone())),
            Sampling::Steps | Sampling::Ends => (None, None),
        };
        Self {
            scenario: ScenarioFile::from(*scenario),
            t_end: opts.t_end,
            x_end: opts.x_end,
            turns: opts.turns,
            rtol: opts.tolerances.rtol,
            atol: opts.tolerances.atol,
            sampling: RecordedSampling::from(&opts.sampling),
            max_rows: opts.max_rows,
            max_steps: opts.tolerances.max_steps,
            dt,
            times,
            mu: opts.mu,
            collision: opts.collision,
            on_hop: opts.on_hop,
            losses: (opts.losses != snowroll::losses::Losses::default()).then_some(opts.losses),
            warnings: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// `key = value` lines, in a fixed order, keys as in [`ScenarioFile`].
    /// Numbers are written in Rust's shortest form that reads back to the
    /// same `f64`, so a CSV header reproduces the run exactly.
    fn lines(&self) -> Vec<(String, String)> {
        let opt = |v: Option<f64>| v.map_or("none".to_string(), format_number);
        let n = format_number;
        let s = &self.scenario;
        let mut lines: Vec<(String, String)> = vec![
            ("alpha_deg".into(), n(s.alpha_deg)),
            ("snow_depth".into(), n(s.snow_depth)),
            ("r0".into(), n(s.r0)),
            ("g".into(), n(s.g)),
            ("density".into(), n(s.density)),
            ("length".into(), n(s.length)),
            ("v0".into(), n(s.v0)),
            ("shape".into(), s.shape.to_string()),
            ("t_end".into(), n(self.t_end)),
            ("x_end".into(), opt(self.x_end)),
            (
                "turns".into(),
                self.turns.map_or("none".to_string(), |n| n.to_string()),
            ),
            ("rtol".into(), format!("{:e}", self.rtol)),
            ("atol".into(), format!("{:e}", self.atol)),
            ("sampling".into(), self.sampling.to_string()),
            ("max_rows".into(), self.max_rows.to_string()),
            ("max_steps".into(), self.max_steps.to_string()),
            ("collision".into(), self.collision.to_string()),
            ("on_hop".into(), self.on_hop.to_string()),
        ];
        if let Some(w) = s.swath_width {
            lines.push(("swath_width".into(), n(w)));
        }
        if let Some(mu) = self.mu {
            lines.push(("mu".into(), n(mu)));
        }
        if let Some(l) = &self.losses {
            lines.extend([
                ("drag_coefficient".into(), n(l.drag_coefficient)),
                ("air_density".into(), n(l.air_density)),
                ("rolling_resistance".into(), n(l.rolling_resistance)),
                ("compaction_energy".into(), n(l.compaction_energy)),
                ("ledger".into(), l.ledger.to_string()),
                ("terminal_tol".into(), format!("{:e}", l.terminal_tol)),
            ]);
        }
        if let Some(dt) = self.dt {
            lines.push(("dt".into(), n(dt)));
        }
        if let Some(times) = &self.times {
            let list: Vec<String> = times.iter().map(|t| n(*t)).collect();
            lines.push(("times".into(), list.join(",")));
        }
        lines.extend(self.warnings.iter().map(|w| ("warning".into(), w.clone())));
        lines
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
