//! Where results go: stdout, or a file that appears only when complete.
//!
//! A file is written to a temporary file in the same directory and renamed
//! over the destination by [`Sink::commit`]; if anything fails first, the
//! temporary file is deleted when the [`Sink`] is dropped, and an existing
//! destination is left untouched.

use std::io::{self, BufWriter, StdoutLock, Write};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use tempfile::NamedTempFile;

/// An open destination for results.
pub enum Sink {
    /// Standard output.
    Stdout(BufWriter<PipeOut>),
    /// A temporary file, renamed to `path` on commit.
    File {
        /// The temporary file.
        tmp: BufWriter<NamedTempFile>,
        /// The destination.
        path: PathBuf,
    },
}

impl Sink {
    /// Opens stdout, or a temporary file next to `path`.
    pub fn open(path: Option<&Path>) -> Result<Self> {
        let Some(path) = path else {
            return Ok(Sink::Stdout(BufWriter::new(PipeOut {
                out: io::stdout().lock(),
                closed: false,
            })));
        };
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let mut builder = tempfile::Builder::new();
        builder.prefix(".snowroll-").suffix(".tmp");
        #[cfg(unix)]
        {
            // Read/write for all, less the umask: what a plain `File::create`
            // gives, rather than the 0600 of a temporary file.
            use std::os::unix::fs::PermissionsExt;
            builder.permissions(std::fs::Permissions::from_mode(0o666));
        }
        let tmp = builder
            .tempfile_in(dir)
            .with_context(|| format!("cannot write {}", path.display()))?;
        Ok(Sink::File {
            tmp: BufWriter::new(tmp),
            path: path.to_path_buf(),
        })
    }

    /// Flushes everything and, for a file, renames it into place.
    pub fn commit(self) -> io::Result<()> {
        match self {
            Sink::Stdout(mut out) => out.flush(),
            Sink::File { tmp, path } => {
                let tmp = tmp.into_inner().map_err(|e| e.into_error())?;
                tmp.as_file().sync_all()?;
                tmp.persist(&path).map_err(|e| e.error)?;
                Ok(())
            }
        }
    }

    /// A description for error messages.
    pub fn name(&self) -> String {
        match self {
            Sink::Stdout(_) => "stdout".to_string(),
            Sink::File { path, .. } => path.display().to_string(),
        }
    }
}

impl Write for Sink {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match self {
            Sink::Stdout(w) => w.write(buf),
            Sink::File { tmp, .. } => tmp.write(buf),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match self {
            Sink::Stdout(w) => w.flush(),
            Sink::File { tmp, .. } => tmp.flush(),
        }
    }
}

/// Standard output that discards everything once the reader has gone.
pub struct PipeOut {
    out: StdoutLock<'static>,
    /// The reader closed the pipe.
    closed: bool,
}

impl PipeOut {
    /// Passes `result` through, except that a closed pipe counts as
    /// success from now on.
    fn quiet<T>(&mut self, result: io::Result<T>, discarded: T) -> io::Result<T> {
        match result {
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                self.closed = true;
                Ok(discarded)
            }
            other => other,
        }
    }
}

impl Write for PipeOut {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.closed {
            return Ok(buf.len());
        }
        let result = self.out.write(buf);
        self.quiet(result, buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if self.closed {
            return Ok(());
        }
        let result = self.out.flush();
        self.quiet(result, ())
    }
}
