//! The command line: subcommands and their flags.
//!
//! The parameter flags of `simulate` and `turns` come from the one parameter
//! table ([`snowroll::params`]): a flag that was not given falls back to the
//! `--config` file and then to the library's defaults, which `--help` shows.
//! The flags the two share are one struct each ([`ScenarioArgs`],
//! [`OutputArgs`]); the config file ([`crate::config::ConfigFile`]) has one
//! key per long flag.

use std::fmt::Display;
use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};
use snowroll::sweep::Method;
use snowroll::{ModelKind, Param};

mod fit;
mod paper;
mod table;
pub use fit::{FitArgs, FitFormat};
pub use paper::PaperArgs;
use snowroll_io::Format;
pub use table::{sweep_axes, AxisArgs, BodyArgs, ParamArgs, SlopeArgs};

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
    /// Run a turn model (§3.4) and write one row per turn, with the long-run
    /// mean acceleration on stderr.
    ///
    /// Columns, SI units as suffixed: turn (k, from 0), t_start_s, x_start_m,
    /// v_start_m_s, t_end_s, v_end_m_s (before the collision), v_after_m_s
    /// (after it, eq. (89)), collision_loss_j (kinetic energy lost, J),
    /// mean_a_turn_m_s2, min_a_m_s2, max_a_m_s2 (within the turn, m/s^2),
    /// mean_a_with_collision_m_s2 (including the collision's jump in v).
    /// The summary gives the means as fractions of g sin(alpha), and how they
    /// converge with the number of turns K.
    Turns(Box<TurnsArgs>),
    /// List every model: id, alias, equation, terminal acceleration, stall slope.
    Models(ModelsArgs),
    /// Reproduce and judge every claim of the note; write the report
    /// (./snowroll-report/report.html)
    ///
    /// Runs the default scenario (alpha 30 degrees, b 0.01 m, r0 0.1 m, from
    /// rest) through every model, checks each claim of the note with a
    /// verdict (holds, holds after correction, refuted), and writes a
    /// self-contained HTML report with the claims table, plots and an
    /// animation, plus report.md, claims.json, figures/*.svg|png and data/*.csv.
    Paper(PaperArgs),
    /// Run many trajectories over a grid of parameters and models; write one
    /// summary row per trajectory (CSV, or Parquet when built with the
    /// `parquet` feature).
    ///
    /// Every scenario flag and --model takes one value, a list `a,b,c` or a
    /// range `start:end:count` (both ends included; angles in degrees), e.g.
    /// `--alpha-deg 5:60:12 --snow-depth 0.001,0.01,0.1 --model torque-cm,energy`.
    /// Rows come in grid order: model first, then the swept parameters in
    /// the order of the header's columns (the order of the flags below),
    /// the last varying fastest. Columns: index, the parameters, stop, t_s, x_m, v_m_s (at
    /// the end of the run), a_over_g_sin_alpha (the acceleration there over
    /// g sin(alpha)), turns (full turns completed), error.
    Sweep(Box<SweepArgs>),
    /// Fit the models to a measured trajectory x(t) (a CSV file, or Tracker's
    /// exported table) by least squares, and rank them.
    ///
    /// Levenberg-Marquardt, each model's own runs as the function fitted,
    /// finite-difference Jacobians, each free parameter kept in its range.
    /// Per model: the best values with standard errors and correlations from
    /// the covariance s^2 (J^T J)^-1, combinations of parameters the data
    /// cannot separate (named, not given huge errors), the residuals' RMS,
    /// AIC and BIC, whether it converged; models ranked by AIC.
    Fit(Box<FitArgs>),
    /// Join the CSV files of `snowroll sweep --shard i/N` into one, in grid
    /// order, checking that every shard is there exactly once.
    ///
    /// The result is the file the whole sweep run in one process writes to
    /// the same -o path, byte for byte: its `# command:` line is that
    /// sweep's (shard 0's command line without --shard, with this -o).
    Merge(MergeArgs),
    /// Serve the classroom explorer: a local web page with a slider for every
    /// parameter, live plots and a race of the models, and its JSON API
    /// (`/api/simulate`, `/api/turns`, `/api/models`, `/api/params`).
    #[cfg(feature = "serve")]
    Serve(ServeArgs),
    /// `snowroll serve` in a build without it: says which feature to enable.
    #[cfg(not(feature = "serve"))]
    #[command(hide = true, disable_help_flag = true)]
    Serve(ServeMissingArgs),
}

/// Whatever follows `snowroll serve` in a build without the `serve`
/// feature (never read: the command says how to get it).
#[cfg(not(feature = "serve"))]
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct ServeMissingArgs {
    /// Any flags.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<std::ffi::OsString>,
}

/// Default port of `snowroll serve`.
#[cfg(feature = "serve")]
pub const SERVE_PORT_DEFAULT: u16 = 8000;

/// Flags of `snowroll serve`.
#[cfg(feature = "serve")]
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct ServeArgs {
    /// Port to listen on (0: any free port; the URL printed names it).
    #[arg(long, value_name = "PORT", default_value_t = SERVE_PORT_DEFAULT)]
    pub port: u16,
    /// Address to listen on. Anything but a loopback address (127.0.0.1,
    /// ::1) serves other machines too, with a warning. Requests must name
    /// the server (`Host`) as localhost, 127.0.0.1, [::1] or this address;
    /// with 0.0.0.0 or :: any IP address.
    #[arg(long, value_name = "IP", default_value = "127.0.0.1")]
    pub host: String,
    /// A host name (or IPv4 address) requests may also name the server by,
    /// such as teacher.local with --host 0.0.0.0; repeatable. Requests for
    /// other names are refused (403), a guard against DNS rebinding.
    #[arg(long, value_name = "NAME")]
    pub allow_host: Vec<String>,
    /// Open the page in a browser (with xdg-open, where there is one).
    #[arg(long)]
    pub open: bool,
}

/// Turns run by `snowroll turns` when neither `--turns` nor the config
/// file says, and its end time, s: the library's defaults of a turn run.
pub use snowroll::models::{TURNS_DEFAULT, TURNS_T_END_S};

/// Model ids or equation aliases `a,b,c`, any case, as `--model` of
/// `sweep` reads them (the one parser of a model list).
///
/// # Errors
/// The first id that names no model, with the ids and aliases allowed.
pub fn parse_models(text: &str) -> Result<Vec<ModelKind>, snowroll::ParamError> {
    text.split(',').map(str::parse::<ModelKind>).collect()
}

/// The `--model` of `simulate` and `turns`: one model or several, each
/// once, in the order given.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ModelList(Vec<ModelKind>);

impl ModelList {
    /// A list of one model.
    pub fn one(model: ModelKind) -> Self {
        Self(vec![model])
    }

    /// The models, in the order given (never empty).
    pub fn models(&self) -> &[ModelKind] {
        &self.0
    }
}

impl std::str::FromStr for ModelList {
    type Err = String;

    /// [`parse_models`], then refuses a model given twice (by id or alias).
    fn from_str(text: &str) -> Result<Self, String> {
        let models = parse_models(text).map_err(|e| e.to_string())?;
        for (i, m) in models.iter().enumerate() {
            if models[..i].contains(m) {
                return Err(format!(
                    "model {} ({}) is given twice in {text:?}; give each model once",
                    m.id(),
                    m.alias()
                ));
            }
        }
        Ok(Self(models))
    }
}

/// `help` text with the default value appended, as clap shows it.
fn with_default(text: &str, default: impl Display) -> String {
    format!("{text} [default: {default}]")
}

/// How a value of a clap enum is spelt on the command line.
pub(crate) fn value_name(v: impl ValueEnum) -> String {
    v.to_possible_value()
        .map_or_else(String::new, |p| p.get_name().to_string())
}

/// Flags shared by `simulate` and `turns`: the model, then every
/// [`Scope::Shared`](snowroll::params::Scope::Shared) parameter of the table. Every one is also a key of the
/// `--config` file.
#[derive(Debug, Clone, Default, PartialEq, clap::Args)]
pub struct ScenarioArgs {
    /// Model id or equation alias, e.g. torque-cm or eq4, any case (`snowroll models` describes them); simulate takes a list ID,ID,... of circular models, each once, and writes one output, its rows led by a model column, and with --plot one figure, a curve per model [default: none, one is required]
    #[arg(long, value_name = "ID[,ID...]", ignore_case = true)]
    pub model: Option<ModelList>,

    /// The scenario, the integrator, the losses: one flag per parameter.
    #[command(flatten)]
    pub params: ParamArgs,
}

impl ScenarioArgs {
    /// Whether `--atol` was given (else each model takes its own default,
    /// scaled to the run: [`snowroll::default_atol`]).
    pub fn atol_given(&self) -> bool {
        Param::of_key("atol").is_some_and(|p| self.params.given.get(p).is_some())
    }
}

/// Where and how results are written, and the `--config` file; shared by
/// `simulate` and `turns`.
#[derive(Debug, Clone, Default, PartialEq, clap::Args)]
pub struct OutputArgs {
    #[arg(
        long,
        value_enum,
        ignore_case = true,
        value_name = "FORMAT",
        help = with_default(
            "Output format: csv (# lines with version and parameters, the rows as computed, the stop in a last # line) or json (one object, the stop after the rows)",
            value_name(Format::default())
        )
    )]
    pub format: Option<Format>,

    /// Write to this file instead of stdout, `-` for stdout (written in full, then renamed into place; a device or FIFO is written through)
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Read settings from this file (one --config only); flags on the command line override it. A TOML file with one key per long flag (`alpha-deg = 25` or `alpha_deg = 25`), or a JSON or CSV output of snowroll, which reproduces that run
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,

    /// Also draw the run as a figure (config key `plot`), SVG or PNG by the name's ending (.svg, .png): simulate: a/(g sin alpha), v and x against t, N and |F|/N, and the energy ledger as shares when the run records one (--ledger, or losses); turns: the per-turn means and extremes of a/(g sin alpha), the speed at each turn's start, the least N/(M g) of each turn. One curve per model. Written in full, then renamed into place
    #[arg(long, value_name = "FILE.svg|FILE.png")]
    pub plot: Option<PathBuf>,
}

/// Refuses a second `--config`: every other flag may be repeated (the last
/// one counts, `args_override_self`), but two config files would silently
/// replace one another, and merging them is not what anyone would guess.
/// clap keeps only the last occurrence of an overridable flag, so the
/// occurrences are counted here, in the arguments before any `--`
/// (`--config FILE` and `--config=FILE`; clap takes no abbreviations).
///
/// # Errors
/// A clap usage error (exit status 2) naming the repeated flag.
pub fn config_given_once(argv: &[std::ffi::OsString]) -> Result<(), clap::Error> {
    let count = argv
        .iter()
        .skip(1)
        .take_while(|a| a.as_encoded_bytes() != b"--")
        .filter(|a| {
            let a = a.as_encoded_bytes();
            a == b"--config" || a.starts_with(b"--config=")
        })
        .count();
    if count > 1 {
        use clap::CommandFactory;
        return Err(Args::command().error(
            clap::error::ErrorKind::ArgumentConflict,
            format!(
                "--config was given {count} times; give one config file (flags on the command \
                 line override its keys)"
            ),
        ));
    }
    Ok(())
}

/// Flags of `snowroll simulate`.
#[derive(Debug, Clone, Default, PartialEq, clap::Args)]
pub struct SimulateArgs {
    /// Model, scenario and integrator.
    #[command(flatten)]
    pub scenario: ScenarioArgs,

    #[arg(
        long,
        value_name = "T1,T2,...",
        value_delimiter = ',',
        allow_negative_numbers = true,
        conflicts_with = "dt",
        help = "Write exactly these times, in s, strictly ascending, each <= t_end (from the dense output; times after an early stop are noted, not written) [default: every accepted step]"
    )]
    pub times: Option<Vec<f64>>,

    #[arg(
        long,
        value_name = "S",
        allow_negative_numbers = true,
        help = "Write a regular grid 0, dt, 2 dt, ... up to the stop, in s (dt > 0) [default: every accepted step]"
    )]
    pub dt: Option<f64>,

    /// Stop after N full turns, N >= 1 (turn models only: turns, turns-exact) [default: none]
    #[arg(long, value_name = "N")]
    pub turns: Option<u64>,

    /// Format, destination, config file.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// The `--model` of `snowroll turns`: only the turn models are values (so
/// a typo is matched against them alone), by id or alias, in any case; one
/// model.
fn turn_model_parser() -> impl clap::builder::TypedValueParser<Value = ModelList> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    PossibleValuesParser::new(
        ModelKind::ALL
            .into_iter()
            .filter(|k| k.is_turn_model())
            .map(|k| PossibleValue::new(k.id()).alias(k.alias())),
    )
    .try_map(|name| name.parse::<ModelKind>().map(ModelList::one))
}

/// Flags of `snowroll turns`.
#[derive(Debug, Clone, Default, PartialEq, clap::Args)]
#[command(
    mut_arg("model", |a| a.value_name("ID").hide_possible_values(true).value_parser(turn_model_parser()).help(
        "Turn model: turns (eq73, the note's eqs. (73), (76)) or turns-exact (eq88, exact geometry), any case; one model [default: turns]"
    )),
    mut_arg("t_end", |a| a.help(with_default(
        "Stop at this time, in s (t_end > 0); long enough by default that --turns ends the run",
        snowroll::params::short(TURNS_T_END_S)
    ))),
)]
pub struct TurnsArgs {
    /// Model, scenario and integrator.
    #[command(flatten)]
    pub scenario: ScenarioArgs,

    #[arg(
        long,
        value_name = "N",
        help = with_default("Number of full turns to run, N >= 1 (one row each)", TURNS_DEFAULT)
    )]
    pub turns: Option<u64>,

    /// How the table is computed: closed (each turn from its energy integral: time by quadrature, stall, hop and slip angles by root finding; --rtol, --atol and --max-steps do not apply) or ode (DOP853 with events, the cross-check). closed falls back to ode for what it does not cover, --collision pivot and a start from rest where the log may not start, and says so on stderr (docs/turn-model.md, "The closed-form path") [default: closed]
    #[arg(long, value_name = "METHOD")]
    pub method: Option<snowroll::TurnMethod>,

    /// Format, destination, config file.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Flags of `snowroll sweep`: each scenario flag takes one value, a list
/// `a,b,c` or a range `start:end:count`.
#[derive(Debug, Clone, Default, PartialEq, clap::Args)]
pub struct SweepArgs {
    /// Models, by id or equation alias: ID[,ID...] (`snowroll models` lists them)
    #[arg(long, value_name = "IDS")]
    pub model: Option<String>,
    /// One flag per sweep axis of the parameter table.
    #[command(flatten)]
    pub axes: AxisArgs,

    /// Also draw a regime map of the rows as SVG: cells over two swept parameters coloured by outcome (never starts / stalls in turn k / rolls on / hops / slips / stuck) or by --plot-color, with the closed-form stall, hop and slip borders drawn over them. Needs --output FILE
    #[arg(long, value_name = "FILE.svg", requires = "output")]
    pub plot: Option<PathBuf>,
    /// What colours the map's cells: outcome, t_s, x_m, v_m_s, a_over_g_sin_alpha or turns [default: outcome]
    #[arg(long, value_name = "COLUMN", requires = "plot")]
    pub plot_color: Option<String>,
    /// The map's horizontal parameter, a swept axis in snake case (e.g. alpha_deg) [default: the first swept axis with two or more values]
    #[arg(long, value_name = "PARAM", requires = "plot")]
    pub plot_x: Option<String>,
    /// The map's vertical parameter (e.g. snow_depth, mu) [default: the next swept axis with two or more values]
    #[arg(long, value_name = "PARAM", requires = "plot")]
    pub plot_y: Option<String>,

    /// Read axes from this TOML file, one key per flag in snake case (`alpha_deg = "5:60:12"`, `snow_depth = [0.001, 0.01]`, `model = ["energy", "eq4"]`); flags override it
    #[arg(long, value_name = "FILE.toml")]
    pub grid: Option<PathBuf>,

    /// Run again the sweep whose output is FILE (a sweep CSV, or Parquet in a build with `--features parquet`): its models, axes, shard and method, read from its header; flags given here override them. Without such flags the output is the same bytes, header included
    #[arg(long, value_name = "FILE", conflicts_with = "grid")]
    pub config: Option<PathBuf>,

    /// Write to this file instead of stdout. Rows go to FILE.partial as they are computed; the finished file is renamed into place
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Output format: csv, or parquet (needs a build with `--features parquet`) [default: parquet for a FILE ending in .parquet, else csv]
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<SweepFormat>,

    /// Run only slice I of N equal, contiguous slices of the grid (0 <= I < N), e.g. --shard $SLURM_ARRAY_TASK_ID/$N
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,

    /// Continue an interrupted sweep from the rows in FILE.partial (same flags as the first run)
    #[arg(long, requires = "output")]
    pub resume: bool,

    /// Do not show the progress bar
    #[arg(long, short)]
    pub quiet: bool,

    /// auto: circular models (and loney) from the closed-form speed and one quadrature for the time where they do not come near a stall and rtol >= 1e-12 (accurate to about 1e-12), the ODE elsewhere; ode: always the model's own solver
    #[arg(long, value_enum, default_value_t = Method::Auto)]
    pub method: Method,

    /// Rows computed and written at a time (tests and tuning; the result does not depend on it)
    #[arg(long, value_name = "N", hide = true, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    pub chunk_rows: Option<u64>,
}

/// Output formats of `snowroll sweep`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    /// Comma-separated values with `#` lines recording version, command and axes.
    Csv,
    /// Apache Parquet, the same columns, the `#` lines as key-value metadata.
    Parquet,
}

/// Flags of `snowroll merge`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct MergeArgs {
    /// The shard files, in any order
    #[arg(required = true, value_name = "SHARD.csv")]
    pub inputs: Vec<PathBuf>,

    /// Write to this file instead of stdout; Parquet for a FILE ending in .parquet (in a build with `--features parquet`), as `sweep` writes
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// Flags of `snowroll models`.
#[derive(Debug, Clone, clap::Args)]
pub struct ModelsArgs {
    /// Output format
    #[arg(long, value_enum, ignore_case = true, default_value_t = ModelsFormat::Table)]
    pub format: ModelsFormat,

    /// The scenario and the losses the stall slopes and the ball's column
    /// are computed for (the flags of `simulate`).
    #[command(flatten)]
    pub body: BodyArgs,
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
