//! `snowroll`: the command-line front end of the snowroll library.
//!
//! A thin layer: each subcommand turns its arguments into library types
//! ([`snowroll::Scenario`], [`snowroll::SimOptions`], [`snowroll::ModelKind`]),
//! calls the library, and writes the results. There is no physics here.

mod args;
mod commands;
mod config;
mod sink;

use std::process::ExitCode;

use clap::Parser;

use crate::args::Args;

fn main() -> ExitCode {
    match commands::run(Args::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
