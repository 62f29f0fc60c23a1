//! One module per subcommand; [`run`] dispatches. `inputs` turns the flags
//! that `simulate` and `turns` share into library types.

mod figure;
mod fit;
mod fit_text;
mod inputs;
mod merge;
mod models;
mod paper;
mod simulate;
mod stack;
mod sweep;
mod sweep_check;
mod sweep_grid;
mod sweep_partial;
mod sweep_plot;
mod turns;

use anyhow::Result;

use crate::args::{Args, Command};

/// Runs the subcommand the user asked for.
pub fn run(args: Args) -> Result<()> {
    match args.command {
        Command::Simulate(a) => simulate::run(*a),
        Command::Turns(a) => turns::run(*a),
        Command::Models(a) => models::run(&a),
        Command::Paper(a) => paper::run(&a),
        Command::Sweep(a) => sweep::run(&a),
        Command::Merge(a) => merge::run(&a),
        Command::Fit(a) => fit::run(*a),
        #[cfg(feature = "serve")]
        Command::Serve(a) => crate::serve::run(&a),
        #[cfg(not(feature = "serve"))]
        Command::Serve(_) => anyhow::bail!(
            "this snowroll was built without `snowroll serve`: rebuild it with the `serve` \
             feature (cargo install --path crates/snowroll-cli --features serve; it is in the \
             default features)"
        ),
    }
}
