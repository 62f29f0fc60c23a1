//! Writing trajectories as CSV or JSON. Both come from the same serde
//! records ([`Sample`], [`TurnState`]); there is no hand-written CSV.

use std::io::Write;

use serde::{Deserialize, Serialize};

use crate::error::OutputError;
use crate::scenario::{Scenario, ScenarioFile};
use crate::trajectory::{Sample, Sampling, SimOptions, Stop, Trajectory, TurnState};

mod finite;
mod ledger;
mod turns;
pub use finite::{check_finite, NonFinite};
pub use turns::write_turn_table;

/// A number as people read it and programs parse it back exactly: the
/// shortest decimal digits that round-trip to the same `f64` (Rust's `{}`
/// and `{:e}` both give those), plain for ordinary magnitudes and in
/// exponent form for very small or very large ones (`1e-300`, `1e150`, not
/// hundreds of zeros).
///
/// ```
/// use snowroll::format_number;
/// assert_eq!(format_number(0.01), "0.01");
/// assert_eq!(format_number(1e308), "1e308");
/// assert_eq!(format_number(1.5e-7), "1.5e-7");
/// assert_eq!(format_number(0.1 + 0.2).parse::<f64>(), Ok(0.1 + 0.2));
/// ```
pub fn format_number(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e9).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        x.to_string()
    }
}

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
    /// Sampling, in words.
    pub sampling: String,
    /// The spacing of a regular sampling grid, s (`--dt`), when one was asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// The requested sample times, s (`--times`), when they were given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub times: Option<Vec<f64>>,
    /// Coefficient of static friction of the slip check; none = no check.
    pub mu: Option<f64>,
    /// How the turn models climb each new layer.
    pub collision: crate::models::CollisionModel,
    /// What the run does where the normal force reaches zero.
    pub on_hop: crate::trajectory::OnHop,
    /// The losses, the ledger and the terminal stop, when any differs from
    /// its default (outputs of lossless runs are unchanged).
    #[serde(flatten)]
    pub losses: Option<crate::losses::Losses>,
    /// Validity warnings of the run ([`crate::validity_warnings`]); empty when in range.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// Requests the run could not honour (times after an early stop, turns
    /// short of those asked for), one sentence each; empty when none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
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
            sampling: match &opts.sampling {
                Sampling::Steps => "every accepted step".to_string(),
                Sampling::Times(ts) => format!("{} requested times", ts.len()),
                Sampling::Every(dt) => format!("every {} s", format_number(*dt)),
                Sampling::Ends => "start and end".to_string(),
            },
            dt,
            times,
            mu: opts.mu,
            collision: opts.collision,
            on_hop: opts.on_hop,
            losses: (opts.losses != crate::losses::Losses::default()).then_some(opts.losses),
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
            ("sampling".into(), self.sampling.clone()),
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
        lines.extend(self.notes.iter().map(|m| ("note".into(), m.clone())));
        lines
    }
}

/// A sample of a turn model: [`Sample`] plus [`TurnState`] in one CSV row.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
struct TurnRow {
    t_s: f64,
    x_m: f64,
    v_m_s: f64,
    a_m_s2: f64,
    r_m: f64,
    mass_kg: f64,
    normal_n: f64,
    friction_n: f64,
    friction_ratio: Option<f64>,
    turn: u64,
    theta_rad: f64,
    omega_rad_s: f64,
}

impl TurnRow {
    fn new(s: &Sample, k: &TurnState) -> Self {
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
            turn: k.turn,
            theta_rad: k.theta_rad,
            omega_rad_s: k.omega_rad_s,
        }
    }
}

#[derive(Serialize)]
struct ModelInfo {
    id: &'static str,
    equation: &'static str,
}

#[derive(Serialize)]
struct JsonStop {
    reason: crate::trajectory::StopReason,
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

#[derive(Serialize)]
struct JsonTrajectory<'a> {
    snowroll_version: &'static str,
    model: ModelInfo,
    params: &'a RunParams,
    stop: JsonStop,
    samples: JsonSamples<'a>,
}

#[derive(Serialize)]
#[serde(untagged)]
enum JsonSamples<'a> {
    Plain(&'a [Sample]),
    Turns(Vec<TurnRow>),
    Ledger(Vec<ledger::LedgerSample>),
}

/// The `#` comment lines that open every CSV: version, model, every
/// parameter in a fixed order, and how the run stopped.
pub(crate) fn write_csv_header(
    w: &mut impl Write,
    model: crate::models::ModelKind,
    params: &RunParams,
    stop: &Stop,
) -> Result<(), OutputError> {
    check_finite(params, None)?;
    check_finite(stop, None)?;
    writeln!(w, "# snowroll {VERSION}")?;
    writeln!(w, "# model = {} ({})", model.id(), model.equation())?;
    for (k, v) in params.lines() {
        writeln!(w, "# {k} = {v}")?;
    }
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
    Ok(())
}

/// Writes `traj` in `format`, recording the version, the model and `params`.
///
/// # Errors
/// [`OutputError`] when the writer fails, [`OutputError::NonFinite`] (before
/// the offending row is written) when a number is NaN or infinite.
pub fn write_trajectory(
    w: &mut impl Write,
    format: Format,
    traj: &Trajectory,
    params: &RunParams,
) -> Result<(), OutputError> {
    let has_turns = !traj.turn_states.is_empty() && traj.turn_states.len() == traj.samples.len();
    let has_ledger = !traj.ledger.is_empty() && traj.ledger.len() == traj.samples.len();
    let v_terminal = ledger::closed_form_terminal_velocity(traj.model, params);
    match format {
        Format::Csv => {
            write_csv_header(w, traj.model, params, &traj.stop)?;
            if let Some(vt) = v_terminal {
                writeln!(
                    w,
                    "# terminal velocity: closed form v_t = {} m/s (docs/snowball-and-losses.md §2.2); \
                     measured: v_m_s at the stop `terminal`",
                    format_number(vt)
                )?;
            }
            let mut csv = csv::Writer::from_writer(&mut *w);
            if has_turns {
                for (row, (s, k)) in (1..).zip(traj.samples.iter().zip(&traj.turn_states)) {
                    let record = TurnRow::new(s, k);
                    check_finite(&record, Some(row))?;
                    csv.serialize(record)?;
                }
            } else if has_ledger {
                for (row, (s, l)) in (1..).zip(traj.samples.iter().zip(&traj.ledger)) {
                    let record = ledger::LedgerSample::new(s, l);
                    check_finite(&record, Some(row))?;
                    csv.serialize(record)?;
                }
            } else if traj.samples.is_empty() {
                csv.write_record([
                    "t_s",
                    "x_m",
                    "v_m_s",
                    "a_m_s2",
                    "r_m",
                    "mass_kg",
                    "normal_n",
                    "friction_n",
                    "friction_ratio",
                ])?;
            } else {
                for (row, s) in (1..).zip(&traj.samples) {
                    check_finite(s, Some(row))?;
                    csv.serialize(s)?;
                }
            }
            csv.flush()?;
        }
        Format::Json => {
            let doc = JsonTrajectory {
                snowroll_version: VERSION,
                model: ModelInfo {
                    id: traj.model.id(),
                    equation: traj.model.equation(),
                },
                params,
                stop: JsonStop {
                    v_terminal_m_s: v_terminal,
                    ..traj.stop.into()
                },
                samples: if has_turns {
                    JsonSamples::Turns(
                        traj.samples
                            .iter()
                            .zip(&traj.turn_states)
                            .map(|(s, k)| TurnRow::new(s, k))
                            .collect(),
                    )
                } else if has_ledger {
                    JsonSamples::Ledger(
                        traj.samples
                            .iter()
                            .zip(&traj.ledger)
                            .map(|(s, l)| ledger::LedgerSample::new(s, l))
                            .collect(),
                    )
                } else {
                    JsonSamples::Plain(&traj.samples)
                },
            };
            // serde_json would write a non-finite number as `null`.
            check_finite(&doc, None)?;
            serde_json::to_writer_pretty(&mut *w, &doc)?;
            writeln!(w)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::ModelKind;
    use crate::trajectory::StopReason;

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
    fn csv_has_comment_header_then_unit_columns() {
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
    fn regression_7_6_a_non_finite_number_is_refused_naming_column_and_row() {
        let params = RunParams::new(&Scenario::default(), &SimOptions::default());
        let mut traj = tiny();
        traj.samples.push(Sample {
            mass_kg: f64::INFINITY,
            ..traj.samples[0]
        });
        let mut out = Vec::new();
        let err = write_trajectory(&mut out, Format::Csv, &traj, &params).unwrap_err();
        let text = err.to_string();
        assert!(
            text.contains("mass_kg = inf") && text.contains("row 2"),
            "{text}"
        );
        // The first row went out, the bad one did not.
        let written = String::from_utf8(out).unwrap();
        assert_eq!(written.lines().filter(|l| !l.starts_with('#')).count(), 2);
        // JSON is checked whole before anything is written (serde_json
        // would write `null`).
        traj.samples[1].mass_kg = f64::NAN;
        let mut out = Vec::new();
        let err = write_trajectory(&mut out, Format::Json, &traj, &params).unwrap_err();
        assert!(
            err.to_string().contains("samples[1].mass_kg = NaN"),
            "{err}"
        );
        assert!(out.is_empty());
    }
}
