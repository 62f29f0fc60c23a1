//! The program's standard output and standard error, written so that no I/O
//! error can panic, and captured per thread when [`capture`] asks (the fuzz
//! harness and in-process tests run commands this way).
//!
//! - Everything for people on stderr goes through `report!`: a failed write
//!   (`2>/dev/full`, a closed stderr) is dropped, as there is nowhere left to
//!   say so.
//! - Results on stdout go through [`Stdout`]: an error is returned to the
//!   command, except that a reader who went away (`| head -1`, EPIPE) is
//!   remembered ([`reader_gone`]) so that the run ends quietly with success
//!   instead of an error message.
//! - A standard output that cannot take results (open for reading only) is
//!   an error at the first write, never results silently lost
//!   ([`stdout_unusable`]).

use std::cell::RefCell;
use std::fmt;
use std::io::{self, IsTerminal, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::OnceLock;

use rustix::fs::OFlags;

/// Bytes written to stdout and stderr while [`capture`] ran.
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct Captured {
    /// What went to standard output.
    pub stdout: Vec<u8>,
    /// What went to standard error.
    pub stderr: Vec<u8>,
}

thread_local! {
    /// The buffers of this thread's [`capture`], if one is running.
    static CAPTURE: RefCell<Option<Captured>> = const { RefCell::new(None) };
}

/// Set when a write to stdout (or to a pipe named by `-o`) found that its
/// reader had gone.
static READER_GONE: AtomicBool = AtomicBool::new(false);

/// Runs `f` with this thread's stdout and stderr going to memory, and
/// returns its result with what it wrote.
pub fn capture<R>(f: impl FnOnce() -> R) -> (R, Captured) {
    let previous = CAPTURE.with(|c| c.replace(Some(Captured::default())));
    let result = f();
    let captured = CAPTURE.with(|c| c.replace(previous)).unwrap_or_default();
    (result, captured)
}

/// Whether this thread's output is being captured.
pub(crate) fn capturing() -> bool {
    CAPTURE.with(|c| c.borrow().is_some())
}

/// Whether stderr is a terminal (never while captured): progress bars only
/// go there.
pub fn stderr_is_terminal() -> bool {
    !capturing() && io::stderr().is_terminal()
}

/// Writes `args` and a newline to stderr; an error is dropped. Use
/// `report!`, which calls this.
pub fn report_line(args: fmt::Arguments<'_>) {
    let text = format!("{args}\n");
    let captured = CAPTURE.with(|c| match c.borrow_mut().as_mut() {
        Some(buf) => {
            buf.stderr.extend_from_slice(text.as_bytes());
            true
        }
        None => false,
    });
    if !captured {
        // Nowhere left to report a failure to report.
        let _ = io::stderr().lock().write_all(text.as_bytes());
    }
}

/// `eprintln!` that never panics: one message to stderr, a write error
/// dropped.
macro_rules! report {
    ($($arg:tt)*) => {
        $crate::console::report_line(format_args!($($arg)*))
    };
}
pub(crate) use report;

/// Marks the reader as gone if `e` says so (EPIPE); returns `e`.
pub fn note_broken_pipe(e: io::Error) -> io::Error {
    if e.kind() == io::ErrorKind::BrokenPipe {
        READER_GONE.store(true, Ordering::Relaxed);
    }
    e
}

/// Whether a reader of stdout (or of a pipe named by `-o`) went away; the
/// run then ends quietly with success.
pub fn reader_gone() -> bool {
    READER_GONE.load(Ordering::Relaxed)
}

/// Forgets an earlier [`reader_gone`] (each in-process run starts clean).
pub(crate) fn reset_reader_gone() {
    READER_GONE.store(false, Ordering::Relaxed);
}

/// Standard output, or this thread's capture.
#[derive(Debug, Default)]
pub struct Stdout;

impl Write for Stdout {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let captured = CAPTURE.with(|c| match c.borrow_mut().as_mut() {
            Some(b) => {
                b.stdout.extend_from_slice(buf);
                true
            }
            None => false,
        });
        if captured {
            return Ok(buf.len());
        }
        check_stdout()?;
        io::stdout().lock().write(buf).map_err(note_broken_pipe)
    }

    fn flush(&mut self) -> io::Result<()> {
        if capturing() {
            return Ok(());
        }
        io::stdout().lock().flush().map_err(note_broken_pipe)
    }
}

/// An error when results written to standard output would be lost
/// ([`stdout_unusable`]); never while captured. A command whose results
/// reach stdout only after a long computation checks it first.
///
/// # Errors
/// When stdout is closed or open for reading only.
pub fn check_stdout() -> io::Result<()> {
    match stdout_unusable() {
        Some(why) if !capturing() => Err(io::Error::other(why)),
        _ => Ok(()),
    }
}

/// Why results written to standard output would be lost, or `None` when it
/// can take them; judged once per process, at the first write.
///
/// A descriptor open for reading only (`1<&0`, `1</dev/null`) takes no
/// results, yet Rust's stdout reports a write to it as done: refused.
///
/// A stdout that was closed when the program started (`>&-`) is refused
/// too. Rust's runtime puts `/dev/null`, open for reading and writing, in
/// place of a closed descriptor 0 to 2 before `main`, so from `main` on it
/// looks like the read-write `/dev/null` of Python's `subprocess.DEVNULL`
/// or a daemon's stdio, which ask for exactly what they get and must work
/// (issue 33, item 4). A constructor in C (`csrc/closed_stdout.c`, linked by
/// `build.rs`) sees descriptor 1 before the runtime does and leaves a mark
/// in the environment, which [`note_start`] takes.
pub fn stdout_unusable() -> Option<&'static str> {
    static WHY: OnceLock<Option<&'static str>> = OnceLock::new();
    *WHY.get_or_init(|| {
        if closed_at_start() {
            return Some(
                "standard output is closed: nothing written to it would arrive; \
                 redirect it to a file, or to /dev/null to discard the results, or give -o FILE",
            );
        }
        let out = io::stdout();
        let flags = rustix::fs::fcntl_getfl(&out).ok()?;
        let mode = flags & (OFlags::RDONLY | OFlags::WRONLY | OFlags::RDWR);
        (mode == OFlags::RDONLY).then_some(
            "standard output is open for reading only: nothing written to it would arrive; \
             redirect it to a file, or to /dev/null to discard the results, or give -o FILE",
        )
    })
}

/// The environment variable by which `csrc/closed_stdout.c` says that
/// stdout was closed when the program started.
const CLOSED_MARK: &str = "SNOWROLL_STDOUT_CLOSED_AT_START";

/// Whether stdout was closed when the program started, as [`note_start`]
/// found it.
fn closed_at_start() -> bool {
    *STARTED_CLOSED.get_or_init(|| std::env::var_os(CLOSED_MARK).is_some())
}

static STARTED_CLOSED: OnceLock<bool> = OnceLock::new();

/// Takes the mark of a stdout closed at start out of the environment (first
/// thing in `main`), so that no child process (`snowroll serve`'s runs)
/// inherits it, and keeps it for [`stdout_unusable`].
pub fn note_start() {
    let closed = closed_at_start();
    if closed {
        // Safe in edition 2021; `main` calls this before any thread starts.
        std::env::remove_var(CLOSED_MARK);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capture_collects_both_streams_and_nests() {
        let ((), outer) = capture(|| {
            report!("to stderr {}", 1);
            Stdout.write_all(b"to stdout").unwrap();
            let ((), inner) = capture(|| report!("inner"));
            assert_eq!(inner.stderr, b"inner\n");
        });
        assert_eq!(outer.stdout, b"to stdout");
        assert_eq!(outer.stderr, b"to stderr 1\n");
    }
}
