//! Helpers shared by the test modules of this binary: the program under
//! test and one run of it in a directory.

use std::path::Path;
use std::process::{Command, Output};

/// The `snowroll` binary cargo built for these tests.
pub fn bin() -> &'static Path {
    assert_cmd::cargo::cargo_bin!("snowroll")
}

/// `snowroll ARGS` run in `dir`, its status and output captured.
pub fn run_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(bin())
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}
