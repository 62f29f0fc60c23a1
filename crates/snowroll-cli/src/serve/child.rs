//! One run of the program itself, as a child process, for one request.
//!
//! The API answers with exactly the bytes of `snowroll simulate` (or
//! `turns`, `models`) because it runs that command: the same executable,
//! the same code path, its stdout as the body. A child process, rather than
//! a call in this process, is what bounds a request's work: a run whose
//! length is not known before it starts (every step sampled, or a coarse
//! grid over a long turn-by-turn run) is ended at [`Limits::seconds`] or at
//! [`Limits::answer_bytes`] of output, and its memory goes with it.

use std::io::{self, Read};
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread;
use std::time::{Duration, Instant};

/// The most of a child's stderr kept (its messages are a few lines).
const STDERR_KEPT: u64 = 64 * 1024;

/// How a run ended.
#[derive(Debug)]
pub enum Ended {
    /// It exited by itself with this status.
    Exited(ExitStatus),
    /// It was ended after `seconds`.
    TimedOut,
    /// It was ended when its output passed `answer_bytes`.
    TooLong,
}

/// What one run gave.
#[derive(Debug)]
pub struct Ran {
    /// How it ended.
    pub ended: Ended,
    /// Its standard output (the answer).
    pub stdout: Vec<u8>,
    /// Its standard error (the messages), at most [`STDERR_KEPT`] bytes.
    pub stderr: String,
}

/// The bounds of one run.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// Wall-clock time, s.
    pub seconds: f64,
    /// Bytes of output.
    pub answer_bytes: usize,
}

/// Runs `exe` with `args` within `limits`.
///
/// # Errors
/// When the child cannot be started or its pipes read.
pub fn run(exe: &Path, args: &[String], limits: Limits) -> io::Result<Ran> {
    let mut child = Command::new(exe)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()?;
    let out = child.stdout.take();
    let err = child.stderr.take();
    let errors = thread::spawn(move || {
        let mut kept = Vec::new();
        if let Some(mut err) = err {
            let _ = (&mut err).take(STDERR_KEPT).read_to_end(&mut kept);
            let _ = io::copy(&mut err, &mut io::sink());
        }
        String::from_utf8_lossy(&kept).into_owned()
    });
    let child = Arc::new(Mutex::new(child));
    let timed_out = Arc::new(AtomicBool::new(false));
    let done = Arc::new(AtomicBool::new(false));
    let watchdog = {
        let (child, timed_out, done) = (
            Arc::clone(&child),
            Arc::clone(&timed_out),
            Arc::clone(&done),
        );
        let deadline = Instant::now() + Duration::from_secs_f64(limits.seconds);
        thread::spawn(move || watch(&child, deadline, &timed_out, &done))
    };
    let mut stdout = Vec::new();
    let read = match out {
        Some(out) => out
            .take(limits.answer_bytes as u64 + 1)
            .read_to_end(&mut stdout)
            .map(drop),
        None => Ok(()),
    };
    let too_long = stdout.len() > limits.answer_bytes;
    let status = {
        let mut c = child.lock().unwrap_or_else(PoisonError::into_inner);
        if too_long || read.is_err() {
            let _ = c.kill();
        }
        c.wait()
    };
    done.store(true, Ordering::SeqCst);
    watchdog.thread().unpark();
    let _ = watchdog.join();
    let stderr = errors.join().unwrap_or_default();
    read?;
    let ended = if timed_out.load(Ordering::SeqCst) {
        Ended::TimedOut
    } else if too_long {
        Ended::TooLong
    } else {
        Ended::Exited(status?)
    };
    Ok(Ran {
        ended,
        stdout,
        stderr,
    })
}

/// Ends the child at `deadline` unless `done` is set first.
fn watch(child: &Mutex<Child>, deadline: Instant, timed_out: &AtomicBool, done: &AtomicBool) {
    loop {
        if done.load(Ordering::SeqCst) {
            return;
        }
        let now = Instant::now();
        if now >= deadline {
            let mut c = child.lock().unwrap_or_else(PoisonError::into_inner);
            // Still running (not yet reaped): end it.
            if matches!(c.try_wait(), Ok(None)) {
                timed_out.store(true, Ordering::SeqCst);
                let _ = c.kill();
            }
            return;
        }
        thread::park_timeout(deadline - now);
    }
}

/// The message of a failed run: from its first `error: ` line to the first
/// blank line (clap's usage hint after it is left out), without the prefix.
pub fn error_message(stderr: &str) -> String {
    let Some(start) = stderr.find("error: ") else {
        return stderr.trim().to_string();
    };
    let text = &stderr[start + "error: ".len()..];
    let end = text.find("\n\n").unwrap_or(text.len());
    text[..end].trim().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_message_is_the_error_line_without_clap_hint() {
        let clap = "error: invalid value 'x' for '--alpha-deg <DEG>': invalid float literal\n\n\
                    For more information, try '--help'.\n";
        assert_eq!(
            error_message(clap),
            "invalid value 'x' for '--alpha-deg <DEG>': invalid float literal"
        );
        let run = "warning: something\nerror: alpha_deg = 95 is out of range\n";
        assert_eq!(error_message(run), "alpha_deg = 95 is out of range");
    }
}
