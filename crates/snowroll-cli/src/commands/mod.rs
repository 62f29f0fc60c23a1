//! One module per subcommand; [`run`] dispatches. Later subcommands
//! (`turns`, `paper`) add a variant to [`Command`] and an arm here.

mod models;
mod simulate;

use anyhow::Result;

use crate::args::{Args, Command};

/// Runs the subcommand the user asked for.
pub fn run(args: Args) -> Result<()> {
    match args.command {
        Command::Simulate(a) => simulate::run(*a),
        Command::Models(a) => models::run(&a),
    }
}
