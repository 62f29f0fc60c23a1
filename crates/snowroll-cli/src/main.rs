//! The `snowroll` program: signal handlers, the worker threads, then
//! [`snowroll_cli::run_from`].

use std::process::ExitCode;

fn main() -> ExitCode {
    snowroll_cli::console::note_start();
    if let Err(e) = snowroll_cli::install_signal_handlers() {
        // Runs still work; only the clean-up on SIGINT/SIGTERM is lost.
        use std::io::Write;
        let _ = writeln!(
            std::io::stderr(),
            "warning: temporary files will not be removed on SIGINT or SIGTERM: {e}"
        );
    }
    match snowroll_cli::start_threads() {
        Ok(None) => {}
        Ok(Some(note)) => {
            use std::io::Write;
            let _ = writeln!(std::io::stderr(), "{note}");
        }
        Err(e) => {
            use std::io::Write;
            let _ = writeln!(std::io::stderr(), "error: {e}");
            return ExitCode::from(1);
        }
    }
    ExitCode::from(snowroll_cli::run_from(std::env::args_os()))
}
