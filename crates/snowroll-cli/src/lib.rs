//! `snowroll`: the command-line front end of the snowroll library.
//!
//! A thin layer: each subcommand turns its arguments into library types
//! ([`snowroll::Scenario`], [`snowroll::SimOptions`], [`snowroll::ModelKind`]),
//! calls the library, and writes the results. There is no physics here.
//!
//! The binary (`src/main.rs`) installs the signal handlers and calls
//! [`run_from`]; tests and the fuzz harness call [`run_from`] in-process,
//! with [`console::capture`] collecting what it prints. Nothing here panics
//! on an I/O error: messages go through [`console`], outputs through
//! `sink::Sink` (the file semantics of `-o`), temporary files through
//! `scratch` (removed on error and on SIGINT/SIGTERM/SIGHUP).

#![deny(clippy::print_stdout, clippy::print_stderr)]

#[cfg(not(unix))]
compile_error!(
    "the snowroll command-line program needs Unix file semantics (flock, signals, modes); \
     the snowroll library itself builds everywhere"
);

mod args;
mod bounded;
mod clash;
mod commands;
mod config;
pub mod console;
mod outdir;
mod scratch;
#[cfg(feature = "serve")]
mod serve;
mod shell;
mod sink;
mod writeback;

use std::ffi::OsString;

use clap::Parser;

use crate::args::Args;
use crate::console::report;

/// Exit status of a run that succeeded (or whose reader went away).
pub const EXIT_SUCCESS: u8 = 0;
/// Exit status of a run that failed: bad input, or a failed write.
pub const EXIT_FAILURE: u8 = 1;
/// Exit status of a command line that clap could not parse.
pub const EXIT_USAGE: u8 = 2;

/// Parses `args` (the program name first, as `std::env::args_os`) and runs
/// the command; returns the exit status. Errors are one `error: ...` line on
/// stderr. When the reader of stdout goes away (`| head -1`), the run stops
/// at its next write and ends quietly with success.
pub fn run_from<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    console::reset_reader_gone();
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    if let Err(e) = args::config_given_once(&args) {
        return usage(&e);
    }
    let args = match Args::try_parse_from(args) {
        Ok(args) => args,
        Err(e) => return usage(&e),
    };
    match commands::run(args) {
        Ok(()) => EXIT_SUCCESS,
        Err(_) if console::reader_gone() => EXIT_SUCCESS,
        Err(e) => {
            report!("error: {}", clip_long_words(&message(&e)));
            EXIT_FAILURE
        }
    }
}

/// A parameter that a library message names (by its key in the parameter
/// table, with the word given with it), as the command line spells it:
/// `--snow-depth`, `--shape sphere`.
pub fn flag_name(key: &str, word: Option<&str>) -> String {
    let flag = format!("--{}", key.replace('_', "-"));
    match word {
        Some(w) => format!("{flag} {w}"),
        None => flag,
    }
}

/// The error chain as anyhow's `{:#}` writes it (each cause after `: `),
/// with the library's errors in the command line's words ([`flag_name`]):
/// the library names parameters by key and leaves their spelling to each
/// front end.
pub fn message(e: &anyhow::Error) -> String {
    e.chain()
        .map(|c| {
            if let Some(p) = c.downcast_ref::<snowroll::ParamError>() {
                p.render(&flag_name)
            } else if let Some(s) = c.downcast_ref::<snowroll::SimError>() {
                s.render(&flag_name)
            } else if let Some(g) = c.downcast_ref::<snowroll::sweep::GridError>() {
                g.render(&flag_name)
            } else if let Some(f) = c.downcast_ref::<snowroll::fit::FitError>() {
                f.render(&flag_name)
            } else {
                c.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join(": ")
}

/// Prints clap's message (help, version, or a usage error) where clap
/// would, in colour on a terminal, without panicking; returns clap's exit
/// status.
fn usage(e: &clap::Error) -> u8 {
    let plain = e.render().to_string();
    let text = clip_long_words(&plain);
    if console::capturing() || text != plain {
        if e.use_stderr() {
            report!("{}", text.trim_end());
        } else {
            use std::io::Write;
            let _ = console::Stdout.write_all(text.as_bytes());
        }
    } else {
        // clap returns a failed write (a closed stdout) rather than panic.
        let _ = e.print();
    }
    u8::try_from(e.exit_code()).unwrap_or(EXIT_FAILURE)
}

/// The longest word (a run without white space: a value, a path) echoed
/// whole in a message; a longer one (a 10 MB bad model name) is cut.
const MAX_ECHOED_WORD: usize = 200;

/// `text` with every word longer than [`MAX_ECHOED_WORD`] characters cut to
/// its first 100 characters, followed by how long it was.
fn clip_long_words(text: &str) -> String {
    let mut out = String::with_capacity(text.len().min(4 * MAX_ECHOED_WORD));
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| !c.is_whitespace()) {
        out.push_str(&rest[..start]);
        rest = &rest[start..];
        let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let word = &rest[..end];
        let chars = word.chars().count();
        if chars > MAX_ECHOED_WORD {
            out.extend(word.chars().take(MAX_ECHOED_WORD / 2));
            out.push_str(&format!("... ({chars} characters in all)"));
        } else {
            out.push_str(word);
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// Most worker threads per CPU that this process may use: the work is
/// CPU-bound, so more threads than CPUs only cost memory (each has its own
/// stack).
const THREADS_PER_CPU: usize = 4;
/// Fewest threads always allowed, whatever the CPU count.
const MIN_THREAD_CAP: usize = 16;

/// Starts the global worker pool before any command runs (issue 33, item
/// 4). `RAYON_NUM_THREADS` (set, e.g., from a Slurm task's
/// `SLURM_CPUS_PER_TASK`) is honoured up to 4 (`THREADS_PER_CPU`) times the
/// CPUs this process may use (at least 16, `MIN_THREAD_CAP`); more are
/// pointless for CPU-bound work and could not all start under a memory cap
/// (`ulimit -v`): rayon then panicked at the first parallel loop with a
/// backtrace. Returns a note to print when the request was cut; an error
/// when even that many threads cannot start.
///
/// # Errors
/// The pool cannot start (the system refuses the threads): the message
/// says how many and what to change.
pub fn start_threads() -> Result<Option<String>, String> {
    let cpus = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
    let cap = (THREADS_PER_CPU * cpus).max(MIN_THREAD_CAP);
    let asked = std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0);
    let (threads, note) = match asked {
        Some(n) if n > cap => (
            cap,
            Some(format!(
                "note: RAYON_NUM_THREADS={n} is more than {THREADS_PER_CPU} threads for each of \
                 the {cpus} CPUs this process may use: {cap} threads are used"
            )),
        ),
        Some(n) => (n, None),
        None => (cpus, None),
    };
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build_global()
        .map_err(|e| {
            format!(
                "cannot start {threads} worker threads ({e}): lower RAYON_NUM_THREADS (e.g. \
                 RAYON_NUM_THREADS=1) or raise the memory limit (ulimit -v)"
            )
        })?;
    Ok(note)
}

/// Removes the run's temporary files on SIGINT, SIGTERM and SIGHUP, then
/// exits with 128 + the signal's number (130, 143, 129), as a shell reports
/// a process killed by it. A second signal while that clean-up runs (stuck
/// on a slow file system) ends the program at once, with the same status.
///
/// # Errors
/// When the handlers cannot be installed.
pub fn install_signal_handlers() -> std::io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    use std::sync::atomic::AtomicBool;
    use std::sync::Arc;

    const SIGNALS: [i32; 3] = [SIGINT, SIGTERM, SIGHUP];
    // Armed by the first signal; the shutdown must be registered first.
    let armed = Arc::new(AtomicBool::new(false));
    for signal in SIGNALS {
        signal_hook::flag::register_conditional_shutdown(signal, 128 + signal, Arc::clone(&armed))?;
        signal_hook::flag::register(signal, Arc::clone(&armed))?;
    }
    let mut signals = signal_hook::iterator::Signals::new(SIGNALS)?;
    std::thread::Builder::new()
        .name("signals".to_string())
        .spawn(move || {
            for signal in signals.forever() {
                if serve_stops_on_signal() {
                    continue;
                }
                scratch::remove_all_and_exit(128 + signal);
            }
        })?;
    Ok(())
}

/// Whether a running `snowroll serve` takes this signal: it stops its
/// workers and ends with success; a second signal ends it at once
/// (registered in [`install_signal_handlers`]).
#[cfg(feature = "serve")]
fn serve_stops_on_signal() -> bool {
    serve::stop_on_signal()
}

/// Without the `serve` feature no server takes a signal.
#[cfg(not(feature = "serve"))]
fn serve_stops_on_signal() -> bool {
    false
}
