//! Flags of `snowroll fit`.

use std::path::PathBuf;

use clap::ValueEnum;

use super::{ModelList, ParamArgs};

/// How `snowroll fit` writes its result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum FitFormat {
    /// A table and, per model, its parameters, for people.
    #[default]
    Text,
    /// One JSON object: `fits` sorted by rank, with the data and settings.
    Json,
}

/// Flags of `snowroll fit`: the data, the models and free parameters, the
/// fixed parameters (every scenario flag of `simulate`, or `--config`), the
/// output.
#[derive(Debug, Clone, Default, PartialEq, clap::Args)]
pub struct FitArgs {
    /// The measured trajectory: a CSV file with a time column (t, t_s or time) and a distance column along the slope (x, x_m or distance), separated by commas, tabs, semicolons or spaces; or the table Tracker exports (its first line names the mass, then the header, then the numbers). Units s and m unless the header says (`t (ms)`, `x (cm)`, `x_mm`). `-` reads stdin
    #[arg(value_name = "DATA")]
    pub data: PathBuf,

    /// The models to fit, ID[,ID...] (`snowroll models` lists them) [default: every model that can run the scenario, the turn models included where they take it]
    #[arg(long, value_name = "ID[,ID...]", ignore_case = true)]
    pub model: Option<ModelList>,

    /// The parameters to fit, KEY[,KEY...]: any real parameter of the scenario or the losses (alpha_deg, snow_depth, r0, g, density, length, v0, drag_coefficient, ...; the long flag's name in snake case), and t0 (s, the time the body is let go, on the data's clock) and x0 (m, where it is then, on the data's ruler). Each starts from its flag's value (or the config's, or the default); the others stay fixed [default: snow_depth,t0,x0]
    #[arg(long, value_name = "KEY[,KEY...]", value_delimiter = ',')]
    pub free: Option<Vec<String>>,

    /// The time t0 at which the body is let go, in s on the data's clock: the start of the fit if t0 is free, else its value [default: fixed, the first data time; free, the release time of a constant acceleration through the middle and last points]
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub t0: Option<f64>,

    /// The position x0 of the body at t0, in m on the data's ruler: the start of the fit if x0 is free, else its value [default: the first data distance]
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub x0: Option<f64>,

    /// The names of the time and distance columns in DATA's header, TIME,DISTANCE (without the unit) [default: t, t_s or time; x, x_m or distance]
    #[arg(long, value_name = "TIME,DISTANCE")]
    pub columns: Option<String>,

    /// Levenberg-Marquardt iterations at most, per model (N >= 1); a fit that needs more is reported as not converged [default: 200]
    #[arg(long, value_name = "N")]
    pub max_iterations: Option<usize>,

    /// Output: text (a ranking table, then each model's parameters with standard errors) or json (`fits` sorted by rank: model, params {KEY: {value, stderr}}, rms_m, aic, bic, rank, converged, ...) [default: text]
    #[arg(long, value_enum, ignore_case = true, value_name = "FORMAT")]
    pub format: Option<FitFormat>,

    /// Also draw the data with each fitted model's x(t), and the residuals below, SVG or PNG by the name's ending. Written in full, then renamed into place
    #[arg(long, value_name = "FILE.svg|FILE.png")]
    pub plot: Option<PathBuf>,

    /// Read the fixed parameters (and the free ones' starts) from this TOML file or snowroll simulate output; flags on the command line override it (its model, format and output keys are not read)
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,

    /// The scenario, the integrator, the losses: one flag per parameter.
    #[command(flatten)]
    pub params: ParamArgs,
}
