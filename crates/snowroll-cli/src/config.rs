//! The `--config FILE.toml` of `simulate`, and its precedence:
//! command-line flags, then the file, then the library's defaults.
//!
//! The file has the same keys as the long flags (kebab-case, e.g.
//! `alpha-deg = 25`, `model = "eq4"`, `times = [1.0, 2.0]`); unknown keys are
//! an error.

use std::fs;
use std::path::Path;

use anyhow::{bail, Context, Result};

use crate::args::SimulateArgs;

/// Reads and parses a config file. Every failure is one line naming the file.
pub fn load(path: &Path) -> Result<SimulateArgs> {
    let text = fs::read_to_string(path)
        .with_context(|| format!("cannot read config file {}", path.display()))?;
    let file: SimulateArgs = toml::from_str(&text).map_err(|e| {
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

impl SimulateArgs {
    /// These flags, with every one that was not given taken from `file`.
    ///
    /// `times` and `dt` choose the sampling together: if either is on the
    /// command line, the file's sampling is ignored (the two conflict).
    pub fn over(self, file: SimulateArgs) -> SimulateArgs {
        // Destructured so that a new flag cannot be forgotten here.
        let SimulateArgs {
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
            times,
            dt,
            rtol,
            atol,
            format,
            output,
            config,
        } = self;
        let sampling_on_command_line = times.is_some() || dt.is_some();
        let (times, dt) = if sampling_on_command_line {
            (times, dt)
        } else {
            (file.times, file.dt)
        };
        SimulateArgs {
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
            times,
            dt,
            rtol: rtol.or(file.rtol),
            atol: atol.or(file.atol),
            format: format.or(file.format),
            output: output.or(file.output),
            config,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::args::Args;
    use clap::CommandFactory;
    use snowroll::ModelKind;

    #[test]
    fn file_fills_only_missing_flags() {
        let flags = SimulateArgs {
            alpha_deg: Some(40.0),
            dt: Some(0.5),
            ..Default::default()
        };
        let file = SimulateArgs {
            model: Some(ModelKind::Energy),
            alpha_deg: Some(25.0),
            snow_depth: Some(0.02),
            times: Some(vec![1.0, 2.0]),
            ..Default::default()
        };
        let merged = flags.over(file);
        assert_eq!(merged.model, Some(ModelKind::Energy));
        assert_eq!(merged.alpha_deg, Some(40.0));
        assert_eq!(merged.snow_depth, Some(0.02));
        // The command line's sampling replaces the file's.
        assert_eq!(merged.dt, Some(0.5));
        assert_eq!(merged.times, None);
    }

    #[test]
    fn config_keys_are_exactly_the_long_flags() {
        let err = toml::from_str::<SimulateArgs>("no-such-key = 1")
            .unwrap_err()
            .message()
            .to_string();
        let (_, list) = err.split_once("expected one of").unwrap();
        let mut keys: Vec<&str> = list
            .split(',')
            .map(|k| k.trim().trim_matches('`'))
            .collect();
        let command = Args::command();
        let simulate = command.find_subcommand("simulate").unwrap();
        let mut flags: Vec<&str> = simulate
            .get_arguments()
            .filter_map(|a| a.get_long())
            .filter(|l| !["config", "help"].contains(l))
            .collect();
        keys.sort_unstable();
        flags.sort_unstable();
        assert_eq!(keys, flags);
    }

    #[test]
    fn line_and_column_are_one_based() {
        let text = "a = 1\nbb = x\n";
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, 11), (2, 6));
    }
}
