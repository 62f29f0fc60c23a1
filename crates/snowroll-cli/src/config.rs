//! The `--config FILE.toml` of `simulate` and `turns`, and its precedence:
//! command-line flags, then the file, then the library's defaults.
//!
//! The file has one key per long flag of the two commands (kebab-case, e.g.
//! `alpha-deg = 25`, `model = "eq4"`, `times = [1.0, 2.0]`, `turns = 10`);
//! unknown keys are an error, and so are keys of the other command
//! (`times`, `dt` for `turns`). The model is spelt as on the command line:
//! id or equation alias, in any case.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use serde::{Deserialize, Deserializer};
use snowroll::{Format, ModelKind};

use crate::args::{OutputArgs, ScenarioArgs, SimulateArgs, TurnsArgs};

/// The keys of a config file: every long flag of `simulate` and `turns`
/// except `--config` itself.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct ConfigFile {
    #[serde(default, deserialize_with = "model_any_case")]
    model: Option<ModelKind>,
    alpha_deg: Option<f64>,
    snow_depth: Option<f64>,
    r0: Option<f64>,
    g: Option<f64>,
    density: Option<f64>,
    length: Option<f64>,
    v0: Option<f64>,
    t_end: Option<f64>,
    x_end: Option<f64>,
    times: Option<Vec<f64>>,
    dt: Option<f64>,
    turns: Option<u64>,
    rtol: Option<f64>,
    atol: Option<f64>,
    format: Option<Format>,
    output: Option<PathBuf>,
}

/// A model id or alias in any case, as `--model` accepts it
/// ([`ModelKind`]'s `FromStr`).
fn model_any_case<'de, D: Deserializer<'de>>(d: D) -> Result<Option<ModelKind>, D::Error> {
    let name = String::deserialize(d)?;
    name.parse().map(Some).map_err(serde::de::Error::custom)
}

/// Reads and parses a config file. Every failure is one line naming the file.
pub fn load(path: &Path) -> Result<ConfigFile> {
    let text = fs::read_to_string(path)
        .with_context(|| format!("cannot read config file {}", path.display()))?;
    let file: ConfigFile = toml::from_str(&text).map_err(|e| {
        anyhow::anyhow!(
            "config file {}{}: {}",
            path.display(),
            e.span()
                .map(|s| {
                    let (line, column) = line_column(&text, s.start);
                    format!(", line {line}, column {column}")
                })
                .unwrap_or_default(),
            one_line(e.message())
        )
    })?;
    if file.times.is_some() && file.dt.is_some() {
        bail!(
            "config file {}: `times` and `dt` conflict, give one of them",
            path.display()
        );
    }
    Ok(file)
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
            t_end,
            x_end,
            rtol,
            atol,
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
            t_end: t_end.or(file.t_end),
            x_end: x_end.or(file.x_end),
            rtol: rtol.or(file.rtol),
            atol: atol.or(file.atol),
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
        let mut keys: Vec<String> = list
            .split(',')
            .map(|k| k.trim().trim_matches('`').to_string())
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
