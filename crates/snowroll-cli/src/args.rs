//! The command line: subcommands and their flags.
//!
//! Every value flag of `simulate` is an `Option`, so that a flag that was not
//! given can fall back to the `--config` file and then to the library's
//! defaults ([`ScenarioFile::default`], [`SimOptions::default`]); the defaults
//! shown in `--help` are read from those same values. The same struct is the
//! schema of the config file, so its keys are exactly the long flags.

use std::fmt::Display;
use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};
use serde::Deserialize;
use snowroll::{Format, ModelKind, ScenarioFile, SimOptions};

/// Simulate a log rolling down a snowy slope, picking up snow as it goes
/// (K. T. McDonald's note, every model). Units are SI; angles are in degrees.
#[derive(Debug, Parser)]
#[command(
    name = "snowroll",
    version,
    propagate_version = true,
    args_override_self = true
)]
pub struct Args {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Integrate one model for one scenario and write its trajectory (CSV or JSON).
    Simulate(Box<SimulateArgs>),
    /// List every model: id, alias, equation, terminal acceleration, stall slope.
    Models(ModelsArgs),
}

/// `help` text with the default value appended, as clap shows it.
fn with_default(text: &str, default: impl Display) -> String {
    format!("{text} [default: {default}]")
}

/// How a value of a clap enum is spelt on the command line.
fn value_name(v: impl ValueEnum) -> String {
    v.to_possible_value()
        .map_or_else(String::new, |p| p.get_name().to_string())
}

/// A number as a person would type it: `1e-10` rather than `0.0000000001`.
fn short(x: f64) -> String {
    if x != 0.0 && !(1e-3..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        x.to_string()
    }
}

/// Flags of `snowroll simulate`, also the keys of its `--config` file.
#[derive(Debug, Clone, Default, PartialEq, clap::Args, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct SimulateArgs {
    /// Model id or equation alias, e.g. torque-cm or eq4 (`snowroll models` describes them)
    #[arg(long, value_name = "ID", ignore_case = true)]
    pub model: Option<ModelKind>,

    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        help = with_default(
            "Slope angle alpha, in degrees (0 < alpha < 90)",
            ScenarioFile::default().slope_deg
        )
    )]
    pub alpha_deg: Option<f64>,

    #[arg(
        long,
        value_name = "M",
        allow_negative_numbers = true,
        help = with_default(
            "Snow depth b normal to the slope, in m (b >= 0; 0 = no snow)",
            ScenarioFile::default().snow_depth_m
        )
    )]
    pub snow_depth: Option<f64>,

    #[arg(
        long,
        value_name = "M",
        allow_negative_numbers = true,
        help = with_default(
            "Initial radius r0 of the log, in m (r0 > 0)",
            ScenarioFile::default().r0_m
        )
    )]
    pub r0: Option<f64>,

    #[arg(
        long,
        value_name = "M/S^2",
        allow_negative_numbers = true,
        help = with_default(
            "Gravitational acceleration g, in m/s^2 (g > 0)",
            ScenarioFile::default().g_m_s2
        )
    )]
    pub g: Option<f64>,

    #[arg(
        long,
        value_name = "KG/M^3",
        allow_negative_numbers = true,
        help = with_default(
            "Density rho of log and snow, in kg/m^3 (rho > 0)",
            ScenarioFile::default().density_kg_m3
        )
    )]
    pub density: Option<f64>,

    #[arg(
        long,
        value_name = "M",
        allow_negative_numbers = true,
        help = with_default(
            "Length l of the log, in m (l > 0)",
            ScenarioFile::default().length_m
        )
    )]
    pub length: Option<f64>,

    #[arg(
        long,
        value_name = "M/S",
        allow_negative_numbers = true,
        help = with_default(
            "Initial speed v0 down the slope, in m/s (v0 >= 0)",
            ScenarioFile::default().v0_m_s
        )
    )]
    pub v0: Option<f64>,

    #[arg(
        long,
        value_name = "S",
        allow_negative_numbers = true,
        help = with_default(
            "Stop at this time, in s (t_end > 0)",
            SimOptions::default().t_end
        )
    )]
    pub t_end: Option<f64>,

    #[arg(
        long,
        value_name = "M",
        allow_negative_numbers = true,
        help = "Also stop when the log has rolled this distance, in m (x_end > 0) [default: none]"
    )]
    pub x_end: Option<f64>,

    #[arg(
        long,
        value_name = "T1,T2,...",
        value_delimiter = ',',
        allow_negative_numbers = true,
        conflicts_with = "dt",
        help = "Write exactly these times, in s, ascending (from the dense output; none after a stop) [default: every accepted step]"
    )]
    pub times: Option<Vec<f64>>,

    #[arg(
        long,
        value_name = "S",
        allow_negative_numbers = true,
        help = "Write a regular grid 0, dt, 2 dt, ... up to the stop, in s (dt > 0) [default: every accepted step]"
    )]
    pub dt: Option<f64>,

    #[arg(
        long,
        value_name = "R",
        allow_negative_numbers = true,
        help = with_default(
            "Relative tolerance of the integrator (1e-15 <= rtol < 1)",
            short(SimOptions::default().tolerances.rtol)
        )
    )]
    pub rtol: Option<f64>,

    #[arg(
        long,
        value_name = "A",
        allow_negative_numbers = true,
        help = with_default(
            "Absolute tolerance of the integrator, in the units of x (m) and v (m/s) (atol > 0)",
            short(SimOptions::default().tolerances.atol)
        )
    )]
    pub atol: Option<f64>,

    #[arg(
        long,
        value_enum,
        value_name = "FORMAT",
        help = with_default(
            "Output format: csv (with # lines recording version and parameters) or json",
            value_name(Format::default())
        )
    )]
    pub format: Option<Format>,

    /// Write to this file instead of stdout (written in full, then renamed into place)
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Read any of the flags above from this TOML file, as `alpha-deg = 25`; flags on the command line override it
    #[arg(long, value_name = "FILE.toml")]
    #[serde(skip)]
    pub config: Option<PathBuf>,
}

/// Flags of `snowroll models`.
#[derive(Debug, Clone, clap::Args)]
pub struct ModelsArgs {
    /// Output format
    #[arg(long, value_enum, default_value_t = ModelsFormat::Table)]
    pub format: ModelsFormat,
}

/// How `snowroll models` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ModelsFormat {
    /// An aligned text table with notes.
    Table,
    /// One JSON object.
    Json,
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn clap_definition_is_consistent() {
        Args::command().debug_assert();
    }
}
