//! One run of the program itself, as a child process, for one request.
//!
//! The API answers with exactly the bytes of `snowroll simulate` (or
//! `turns`, `models`) because it runs that command: the same executable,
//! the same code path, its stdout as the body. A child process, rather than
//! a call in this process, is what bounds a request's work: a run whose
//! length is not known before it starts (every step sampled, or a coarse
//! grid over a long turn-by-turn run) is ended at [`Limits::seconds`] or at
//! [`Limits::answer_bytes`] of output, and its memory goes with it; it is
//! ended too when its client goes away or the server stops.

use std::io;
use std::path::Path;
use std::process::{ExitStatus, Stdio};
use std::time::Duration;

use tokio::io::{AsyncRead, AsyncReadExt};
use tokio::process::Command;
use tokio::sync::watch;

use super::wait::{race, stopped, Either};

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
    /// It was ended because the server is stopping.
    Stopped,
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

/// Runs `exe` with `args` within `limits`, ended early when `stop` turns
/// true. The child is killed and reaped before this returns, and killed
/// too if this future is dropped (its client went away).
///
/// # Errors
/// When the child cannot be started or its pipes read.
pub async fn run(
    exe: &Path,
    args: &[String],
    limits: Limits,
    stop: watch::Receiver<bool>,
) -> io::Result<Ran> {
    let mut child = Command::new(exe)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .kill_on_drop(true)
        .spawn()?;
    let out = child.stdout.take();
    let err = child.stderr.take();
    // The messages are read beside the answer, so that a child writing much
    // to stderr never blocks on a full pipe.
    let errors = tokio::spawn(async move {
        let mut kept = Vec::new();
        if let Some(mut err) = err {
            let _ = (&mut err).take(STDERR_KEPT).read_to_end(&mut kept).await;
            let _ = tokio::io::copy(&mut err, &mut tokio::io::sink()).await;
        }
        String::from_utf8_lossy(&kept).into_owned()
    });
    let mut stdout = Vec::new();
    let limit = limits.answer_bytes as u64 + 1;
    let read = async {
        match out {
            Some(out) => read_limited(out, limit, &mut stdout).await,
            None => Ok(()),
        }
    };
    let deadline = tokio::time::sleep(Duration::from_secs_f64(limits.seconds));
    let ended = match race(race(read, deadline), stopped(stop)).await {
        Either::Left(Either::Left(read)) => {
            read?;
            if stdout.len() > limits.answer_bytes {
                Some(Ended::TooLong)
            } else {
                None
            }
        }
        Either::Left(Either::Right(())) => Some(Ended::TimedOut),
        Either::Right(()) => Some(Ended::Stopped),
    };
    let ended = match ended {
        Some(ended) => {
            // Killed and reaped (an error: it had already exited).
            let _ = child.kill().await;
            ended
        }
        // Its output is closed: it is exiting. Bounded all the same.
        None => match tokio::time::timeout(Duration::from_secs(2), child.wait()).await {
            Ok(status) => Ended::Exited(status?),
            Err(_) => {
                let _ = child.kill().await;
                Ended::TimedOut
            }
        },
    };
    let stderr = errors.await.unwrap_or_default();
    Ok(Ran {
        ended,
        stdout,
        stderr,
    })
}

/// Reads `from` to its end or to `limit` bytes into `into`.
async fn read_limited(
    from: impl AsyncRead + Unpin,
    limit: u64,
    into: &mut Vec<u8>,
) -> io::Result<()> {
    from.take(limit).read_to_end(into).await.map(drop)
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
