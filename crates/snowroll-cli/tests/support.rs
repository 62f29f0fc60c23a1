//! Helpers shared by the test modules of this binary: the program under
//! test, one run of it in a directory, and the checks of a run that must
//! succeed or fail.

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

/// A run in `dir` that must succeed (its stderr shown when it does not).
pub fn ok_in(dir: &Path, args: &[&str]) {
    let out = run_in(dir, args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The one `error:` line of a run in `dir` that must fail with status 1,
/// never a panic.
pub fn fails_in(dir: &Path, args: &[&str]) -> String {
    let out = run_in(dir, args);
    let e = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(1), "{args:?}: {e}");
    assert!(!e.contains("panicked"), "{e}");
    e
}
