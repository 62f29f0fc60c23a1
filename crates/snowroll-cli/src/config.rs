//! The `--config FILE` of `simulate` and `turns`, and its precedence:
//! command-line flags, then the file, then the library's defaults.
//!
//! A config file is one of three things, told apart by its content:
//! - a TOML file with one key per long flag of the two commands, spelt as
//!   the flag (`alpha-deg = 25`) or in snake_case (`alpha_deg = 25`), e.g.
//!   `model = "eq4"`, `times = [1.0, 2.0]`, `turns = 10`;
//! - a JSON output of snowroll (`--format json`): its `model` and `params`;
//! - a CSV output of snowroll: its `# key = value` header lines.
//!
//! The keys are the project's one parameter vocabulary ([`snowroll::ScenarioFile`],
//! [`snowroll::RunParams`]), so an output read back reproduces its run byte for
//! byte, in its own format. Unknown keys are an error, and so are keys of the
//! other command (`times`, `dt` for `turns`). The model is spelt as on the
//! command line: id or equation alias, in any case.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use serde::{Deserialize, Deserializer};
use serde_json::{Map, Value};
use snowroll::{CollisionModel, ModelKind, OnHop, Shape};
use snowroll_io::{Format, RecordedSampling};

use crate::args::{OutputArgs, ScenarioArgs, SimulateArgs, TurnsArgs};

/// The keys of a config file: every long flag of `simulate` and `turns`
/// except `--config` itself, in snake_case; the flag's own spelling and the
/// parameter names of earlier outputs are aliases.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConfigFile {
    #[serde(default, deserialize_with = "model_any_case")]
    model: Option<ModelKind>,
    #[serde(alias = "alpha-deg", alias = "slope_deg")]
    alpha_deg: Option<f64>,
    #[serde(alias = "snow-depth", alias = "snow_depth_m")]
    snow_depth: Option<f64>,
    #[serde(alias = "r0_m")]
    r0: Option<f64>,
    #[serde(alias = "g_m_s2")]
    g: Option<f64>,
    #[serde(alias = "density_kg_m3")]
    density: Option<f64>,
    #[serde(alias = "length_m")]
    length: Option<f64>,
    #[serde(alias = "v0_m_s")]
    v0: Option<f64>,
    #[serde(default, deserialize_with = "shape_any_case")]
    shape: Option<Shape>,
    #[serde(alias = "swath-width")]
    swath_width: Option<f64>,
    #[serde(alias = "t-end", alias = "t_end_s")]
    t_end: Option<f64>,
    #[serde(alias = "x-end", alias = "x_end_m")]
    x_end: Option<f64>,
    times: Option<Vec<f64>>,
    dt: Option<f64>,
    turns: Option<u64>,
    rtol: Option<f64>,
    atol: Option<f64>,
    mu: Option<f64>,
    collision: Option<CollisionModel>,
    #[serde(alias = "on-hop")]
    on_hop: Option<OnHop>,
    max_rows: Option<u64>,
    max_steps: Option<u64>,
    #[serde(alias = "drag-coefficient")]
    drag_coefficient: Option<f64>,
    #[serde(alias = "air-density")]
    air_density: Option<f64>,
    #[serde(alias = "rolling-resistance")]
    rolling_resistance: Option<f64>,
    #[serde(alias = "compaction-energy")]
    compaction_energy: Option<f64>,
    ledger: Option<bool>,
    #[serde(alias = "terminal-tol")]
    terminal_tol: Option<f64>,
    #[serde(default, deserialize_with = "format_any_case")]
    format: Option<Format>,
    output: Option<PathBuf>,
}

/// A model id or alias in any case, as `--model` accepts it
/// ([`ModelKind`]'s `FromStr`).
fn model_any_case<'de, D: Deserializer<'de>>(d: D) -> Result<Option<ModelKind>, D::Error> {
    let name = String::deserialize(d)?;
    name.parse().map(Some).map_err(serde::de::Error::custom)
}

/// `cylinder` or `sphere`, in any case, as `--shape` accepts it.
fn shape_any_case<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Shape>, D::Error> {
    let name = String::deserialize(d)?;
    name.parse().map(Some).map_err(serde::de::Error::custom)
}

/// `csv` or `json`, in any case, as `--format` accepts it.
fn format_any_case<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Format>, D::Error> {
    let name = String::deserialize(d)?;
    match name.to_ascii_lowercase().as_str() {
        "csv" => Ok(Some(Format::Csv)),
        "json" => Ok(Some(Format::Json)),
        _ => Err(serde::de::Error::custom(format!(
            "unknown format `{name}`, expected `csv` or `json`"
        ))),
    }
}

/// Which command wrote an output that is read back as a config file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// A TOML file written by hand.
    Toml,
    /// An output of `snowroll simulate`.
    Simulate,
    /// An output of `snowroll turns` (one row per turn).
    Turns,
}

/// The keys an output records that are not settings of a run: they are
/// read back as the output's provenance, not as config keys.
const RECORD_ONLY: [&str; 5] = ["sampling", "warnings", "warning", "notes", "note"];

/// Whether a recorded `sampling` is that of a turn table (`snowroll turns`).
fn is_turn_table(sampling: &str) -> bool {
    sampling.parse() == Ok(RecordedSampling::PerTurn)
}

/// Reads and parses a config file for command `command` (`simulate` or
/// `turns`). Every failure is one line naming the file; an output of the
/// other command is refused (its settings would not reproduce it).
pub fn load(path: &Path, command: Origin) -> Result<ConfigFile> {
    let (file, origin) = load_with_origin(path)?;
    let name = |o: Origin| match o {
        Origin::Turns => "turns",
        _ => "simulate",
    };
    if origin != Origin::Toml && origin != command {
        bail!(
            "config file {} is an output of `snowroll {}`; read it back with that command",
            path.display(),
            name(origin)
        );
    }
    Ok(file)
}

/// Reads and parses a config file and says what wrote it.
fn load_with_origin(path: &Path) -> Result<(ConfigFile, Origin)> {
    let text = fs::read_to_string(path)
        .with_context(|| format!("cannot read config file {}", path.display()))?;
    let trimmed = text.trim_start();
    let (file, origin) = if trimmed.starts_with('{') {
        from_json_output(&text).map_err(|e| anyhow!("config file {}: {e}", path.display()))?
    } else if trimmed.starts_with("# snowroll") {
        from_csv_output(&text).map_err(|e| anyhow!("config file {}: {e}", path.display()))?
    } else {
        (from_toml(&text, path)?, Origin::Toml)
    };
    if file.times.is_some() && file.dt.is_some() {
        bail!(
            "config file {}: `times` and `dt` conflict, give one of them",
            path.display()
        );
    }
    Ok((file, origin))
}

fn from_toml(text: &str, path: &Path) -> Result<ConfigFile> {
    toml::from_str(text).map_err(|e| {
        anyhow!(
            "config file {}{}: {}",
            path.display(),
            e.span()
                .map(|s| {
                    let (line, column) = line_column(text, s.start);
                    format!(", line {line}, column {column}")
                })
                .unwrap_or_default(),
            one_line(e.message())
        )
    })
}

/// The settings of a JSON output of snowroll (`simulate` or `turns`).
fn from_json_output(text: &str) -> Result<(ConfigFile, Origin)> {
    let doc: Value = serde_json::from_str(text).map_err(|e| anyhow!("not valid JSON: {e}"))?;
    let Some(params) = doc.get("params").and_then(Value::as_object) else {
        bail!("a JSON config file must be an output of snowroll (with `params` and `model`)");
    };
    let mut keys = Map::new();
    if let Some(id) = doc.pointer("/model/id").and_then(Value::as_str) {
        keys.insert("model".into(), Value::String(id.to_string()));
    }
    let sampling = params.get("sampling").and_then(Value::as_str);
    let origin = if sampling.is_some_and(is_turn_table) {
        Origin::Turns
    } else {
        Origin::Simulate
    };
    for (k, v) in params {
        if !RECORD_ONLY.contains(&k.as_str()) && !v.is_null() {
            keys.insert(k.clone(), v.clone());
        }
    }
    keys.insert("format".into(), Value::String("json".into()));
    let file = serde_json::from_value(Value::Object(keys)).map_err(|e| anyhow!("{e}"))?;
    Ok((file, origin))
}

/// The settings of a CSV output of snowroll: its `# key = value` lines
/// before the column header. `# model = torque-cm (eq. (4))` gives the id;
/// `none` means not set; `times` is a comma-separated list.
fn from_csv_output(text: &str) -> Result<(ConfigFile, Origin)> {
    let mut keys = Map::new();
    let mut origin = Origin::Simulate;
    for line in text.lines() {
        let Some(comment) = line.strip_prefix('#') else {
            break;
        };
        let Some((key, value)) = comment.split_once(" = ") else {
            continue;
        };
        let (key, value) = (key.trim(), value.trim());
        if !key
            .bytes()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_')
        {
            continue; // a sentence (the turn table's summary), not a setting
        }
        let value = match key {
            "model" | "collision" | "on_hop" | "shape" => {
                Value::String(value.split_whitespace().next().unwrap_or("").into())
            }
            "ledger" => Value::Bool(
                value
                    .parse::<bool>()
                    .map_err(|_| anyhow!("`ledger = {value}` is not true or false"))?,
            ),
            "sampling" => {
                if is_turn_table(value) {
                    origin = Origin::Turns;
                }
                continue;
            }
            k if RECORD_ONLY.contains(&k) || k == "stop" => continue,
            _ if value == "none" => continue,
            "turns" | "max_rows" | "max_steps" => Value::from(
                value
                    .parse::<u64>()
                    .map_err(|_| anyhow!("`{key} = {value}` is not a whole number"))?,
            ),
            "times" => Value::Array(
                value
                    .split(',')
                    .map(|t| number(key, t.trim()))
                    .collect::<Result<_>>()?,
            ),
            _ => number(key, value)?,
        };
        keys.insert(key.to_string(), value);
    }
    if !keys.contains_key("model") {
        bail!(
            "a CSV config file must be an output of snowroll (its `# model = ...` line is missing)"
        );
    }
    keys.insert("format".into(), Value::String("csv".into()));
    let file = serde_json::from_value(Value::Object(keys)).map_err(|e| anyhow!("{e}"))?;
    Ok((file, origin))
}

/// A number of a CSV header line, as JSON.
fn number(key: &str, value: &str) -> Result<Value> {
    let x: f64 = value
        .parse()
        .map_err(|_| anyhow!("`{key} = {value}` is not a number"))?;
    serde_json::Number::from_f64(x)
        .map(Value::Number)
        .ok_or_else(|| anyhow!("`{key} = {value}` is not a finite number"))
}

/// A possibly multi-line message on one line.
fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}

/// 1-based line and column of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

impl ScenarioArgs {
    /// These flags, with every one that was not given taken from `file`.
    fn over(self, file: &ConfigFile) -> ScenarioArgs {
        // Destructured so that a new flag cannot be forgotten here.
        let ScenarioArgs {
            model,
            alpha_deg,
            snow_depth,
            r0,
            g,
            density,
            length,
            v0,
            shape,
            swath_width,
            t_end,
            x_end,
            rtol,
            atol,
            mu,
            collision,
            on_hop,
            max_rows,
            max_steps,
            drag_coefficient,
            air_density,
            rolling_resistance,
            compaction_energy,
            ledger,
            terminal_tol,
        } = self;
        ScenarioArgs {
            model: model.or(file.model),
            alpha_deg: alpha_deg.or(file.alpha_deg),
            snow_depth: snow_depth.or(file.snow_depth),
            r0: r0.or(file.r0),
            g: g.or(file.g),
            density: density.or(file.density),
            length: length.or(file.length),
            v0: v0.or(file.v0),
            shape: shape.or(file.shape),
            swath_width: swath_width.or(file.swath_width),
            t_end: t_end.or(file.t_end),
            x_end: x_end.or(file.x_end),
            rtol: rtol.or(file.rtol),
            atol: atol.or(file.atol),
            mu: mu.or(file.mu),
            collision: collision.or(file.collision),
            on_hop: on_hop.or(file.on_hop),
            max_rows: max_rows.or(file.max_rows),
            max_steps: max_steps.or(file.max_steps),
            drag_coefficient: drag_coefficient.or(file.drag_coefficient),
            air_density: air_density.or(file.air_density),
            rolling_resistance: rolling_resistance.or(file.rolling_resistance),
            compaction_energy: compaction_energy.or(file.compaction_energy),
            ledger: ledger || file.ledger.unwrap_or(false),
            terminal_tol: terminal_tol.or(file.terminal_tol),
        }
    }
}

impl OutputArgs {
    /// These flags, with every one that was not given taken from `file`.
    fn over(self, file: &ConfigFile) -> OutputArgs {
        let OutputArgs {
            format,
            output,
            config,
        } = self;
        OutputArgs {
            format: format.or(file.format),
            output: output.or_else(|| file.output.clone()),
            config,
        }
    }
}

impl SimulateArgs {
    /// These flags, with every one that was not given taken from `file`.
    ///
    /// `times` and `dt` choose the sampling together: if either is on the
    /// command line, the file's sampling is ignored (the two conflict).
    pub fn over(self, file: ConfigFile) -> SimulateArgs {
        let SimulateArgs {
            scenario,
            times,
            dt,
            turns,
            output,
        } = self;
        let sampling_on_command_line = times.is_some() || dt.is_some();
        let (times, dt) = if sampling_on_command_line {
            (times, dt)
        } else {
            (file.times.clone(), file.dt)
        };
        SimulateArgs {
            scenario: scenario.over(&file),
            times,
            dt,
            turns: turns.or(file.turns),
            output: output.over(&file),
        }
    }
}

impl TurnsArgs {
    /// These flags, with every one that was not given taken from `file`,
    /// which was read from `path`.
    ///
    /// # Errors
    /// When the file sets `times` or `dt`, keys of `simulate` only: the turn
    /// table has one row per turn.
    pub fn over(self, file: ConfigFile, path: &Path) -> Result<TurnsArgs> {
        let TurnsArgs {
            scenario,
            turns,
            output,
        } = self;
        for (key, set) in [("times", file.times.is_some()), ("dt", file.dt.is_some())] {
            if set {
                bail!(
                    "config file {}: `{key}` is a key of `snowroll simulate` only; \
                     `snowroll turns` writes one row per turn",
                    path.display()
                );
            }
        }
        Ok(TurnsArgs {
            scenario: scenario.over(&file),
            turns: turns.or(file.turns),
            output: output.over(&file),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::args::Args;
    use clap::CommandFactory;

    #[test]
    fn file_fills_only_missing_flags() {
        let flags = SimulateArgs {
            scenario: ScenarioArgs {
                alpha_deg: Some(40.0),
                ..Default::default()
            },
            dt: Some(0.5),
            ..Default::default()
        };
        let file = ConfigFile {
            model: Some(ModelKind::Energy),
            alpha_deg: Some(25.0),
            snow_depth: Some(0.02),
            times: Some(vec![1.0, 2.0]),
            turns: Some(7),
            format: Some(Format::Json),
            ..Default::default()
        };
        let merged = flags.over(file);
        assert_eq!(merged.scenario.model, Some(ModelKind::Energy));
        assert_eq!(merged.scenario.alpha_deg, Some(40.0));
        assert_eq!(merged.scenario.snow_depth, Some(0.02));
        assert_eq!(merged.turns, Some(7));
        assert_eq!(merged.output.format, Some(Format::Json));
        // The command line's sampling replaces the file's.
        assert_eq!(merged.dt, Some(0.5));
        assert_eq!(merged.times, None);
    }

    #[test]
    fn turns_takes_the_shared_keys_and_refuses_the_sampling_keys() {
        let path = Path::new("run.toml");
        let flags = TurnsArgs {
            turns: Some(5),
            ..Default::default()
        };
        let file = ConfigFile {
            model: Some(ModelKind::TurnsExact),
            r0: Some(0.2),
            turns: Some(50),
            ..Default::default()
        };
        let merged = flags.clone().over(file, path).unwrap();
        assert_eq!(merged.scenario.model, Some(ModelKind::TurnsExact));
        assert_eq!(merged.scenario.r0, Some(0.2));
        assert_eq!(merged.turns, Some(5));
        let file = ConfigFile {
            dt: Some(0.1),
            ..Default::default()
        };
        let err = flags.over(file, path).unwrap_err().to_string();
        assert!(err.contains("run.toml") && err.contains("`dt`"), "{err}");
    }

    #[test]
    fn config_model_is_spelt_as_on_the_command_line() {
        for (text, want) in [
            ("turns", ModelKind::Turns),
            ("EQ73", ModelKind::Turns),
            ("Turns-Exact", ModelKind::TurnsExact),
            ("eq4", ModelKind::TorqueCm),
            ("Torque-CM", ModelKind::TorqueCm),
        ] {
            let file: ConfigFile = toml::from_str(&format!("model = \"{text}\"")).unwrap();
            assert_eq!(file.model, Some(want), "{text}");
        }
        assert!(toml::from_str::<ConfigFile>("model = \"eq99\"").is_err());
    }

    /// The long flags of subcommand `name`, less `--config` and `--help`.
    fn long_flags(name: &str) -> Vec<String> {
        let command = Args::command();
        let mut flags: Vec<String> = command
            .find_subcommand(name)
            .unwrap()
            .get_arguments()
            .filter_map(|a| a.get_long())
            .filter(|l| !["config", "help"].contains(l))
            .map(str::to_string)
            .collect();
        flags.sort_unstable();
        flags
    }

    #[test]
    fn config_keys_are_exactly_the_long_flags() {
        let err = toml::from_str::<ConfigFile>("no-such-key = 1")
            .unwrap_err()
            .message()
            .to_string();
        let (_, list) = err.split_once("expected one of").unwrap();
        // serde lists the aliases too: the flags' own kebab-case spelling
        // and the names of earlier outputs. Leave those out; the rest, in
        // kebab-case, must be exactly the long flags.
        const EARLIER_OUTPUT_NAMES: [&str; 9] = [
            "slope_deg",
            "snow_depth_m",
            "r0_m",
            "g_m_s2",
            "density_kg_m3",
            "length_m",
            "v0_m_s",
            "t_end_s",
            "x_end_m",
        ];
        let mut keys: Vec<String> = list
            .split(',')
            .map(|k| k.trim().trim_matches('`').to_string())
            .filter(|k| !k.contains('-') && !EARLIER_OUTPUT_NAMES.contains(&k.as_str()))
            .map(|k| k.replace('_', "-"))
            .collect();
        keys.sort_unstable();
        let mut flags = long_flags("simulate");
        flags.extend(long_flags("turns"));
        flags.sort_unstable();
        flags.dedup();
        assert_eq!(keys, flags);
        // `turns` has every flag of `simulate` but the sampling.
        let mut sampling_free = long_flags("simulate");
        sampling_free.retain(|f| f != "times" && f != "dt");
        assert_eq!(long_flags("turns"), sampling_free);
    }

    #[test]
    fn line_and_column_are_one_based() {
        let text = "a = 1\nbb = x\n";
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, 11), (2, 6));
    }
}
