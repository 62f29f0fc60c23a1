//! Reading inputs with bounded sizes (issue 20, item 5): a config file, a
//! grid file, the header of an output read back, a line of a sweep file.
//! An endless input (`/dev/zero`, `/dev/urandom`, a FIFO that never ends) or
//! a huge one ends the run with an error naming the limit, instead of
//! growing until an allocation fails. Rows of an output read back as a
//! config are never read: only its header is needed.
//!
//! The limits, and why:
//! - [`MAX_SETTINGS_FILE`], 8 MiB: a TOML config or grid file. The longest
//!   legitimate settings are lists (`times`, a list axis): 8 MiB holds
//!   3·10^5 values at their longest spelling (24 characters and a comma),
//!   more than anyone types or a script needs for one run.
//! - [`MAX_HEADER`], 32 MiB: the `#` lines of a CSV output, or a JSON output
//!   up to its `params`. A header records the settings of its run, which
//!   came from a settings file (at most 8 MiB; a number is written back at
//!   most about three times as long as its shortest spelling, `1e5` as
//!   `100000`) and a command line (at most a few MiB, `ARG_MAX`).
//! - [`MAX_ROW_LINE`], 1 MiB: one row of a sweep file. A row has 30-odd
//!   columns of at most 24 characters, under 1 KiB; a longer line is not a
//!   row.
//!
//! Memory is then bounded by a small multiple of the limit whatever the
//! input, and refusing an endless input costs reading the limit (about 10 ms
//! for 32 MiB of `/dev/zero`).

use std::fmt;
use std::fs::File;
use std::io::{self, BufRead, Read};
use std::path::Path;

use anyhow::{Context, Result};

/// Most bytes of a config file (`--config` TOML) or a `--grid` file.
pub const MAX_SETTINGS_FILE: u64 = 8 << 20;
/// Most bytes of the header of an output read back (its `#` lines, or a
/// JSON output up to its `params`).
pub const MAX_HEADER: u64 = 32 << 20;
/// Most bytes of one row of a sweep file, its newline included.
pub const MAX_ROW_LINE: u64 = 1 << 20;

/// The error of an input longer than a limit: carried inside an
/// [`io::Error`] so that readers built on [`Read`] (serde_json, csv) pass it
/// on unchanged.
#[derive(Debug)]
pub struct TooLong {
    /// The limit, bytes.
    pub limit: u64,
    /// What was too long (`a config file`, `the header of an output`).
    pub what: &'static str,
}

impl fmt::Display for TooLong {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "longer than {}, the most snowroll reads of {} (an endless file such as /dev/zero, \
             or not the file meant?)",
            size(self.limit),
            self.what
        )
    }
}

impl std::error::Error for TooLong {}

/// The [`io::Error`] of an input longer than `limit`.
pub fn too_long(limit: u64, what: &'static str) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, TooLong { limit, what })
}

/// `n` bytes in MiB (or KiB, or bytes) when whole, as the limits are.
fn size(n: u64) -> String {
    match n {
        n if n >= 1 << 20 && n % (1 << 20) == 0 => format!("{} MiB", n >> 20),
        n if n >= 1 << 10 && n % (1 << 10) == 0 => format!("{} KiB", n >> 10),
        n => format!("{n} bytes"),
    }
}

/// A reader that fails with [`TooLong`] when its input goes on past
/// `limit` bytes (an input of exactly `limit` bytes reads whole).
#[derive(Debug)]
pub struct Bounded<R> {
    inner: R,
    left: u64,
    limit: u64,
    what: &'static str,
}

impl<R: Read> Bounded<R> {
    /// `inner`, cut at `limit` bytes; `what` names the input in the error.
    pub fn new(inner: R, limit: u64, what: &'static str) -> Self {
        Bounded {
            inner,
            left: limit,
            limit,
            what,
        }
    }
}

impl<R: Read> Read for Bounded<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        if buf.is_empty() {
            return Ok(0);
        }
        if self.left == 0 {
            // At the limit: the input must end here.
            let mut probe = [0u8; 1];
            return match self.inner.read(&mut probe)? {
                0 => Ok(0),
                _ => Err(too_long(self.limit, self.what)),
            };
        }
        let max = buf
            .len()
            .min(usize::try_from(self.left).unwrap_or(usize::MAX));
        let n = self.inner.read(&mut buf[..max])?;
        self.left -= n as u64;
        Ok(n)
    }
}

/// The whole of the file at `path`, at most `limit` bytes, as UTF-8 text.
/// `role` names the file in the messages (`--grid file`), `what` in the
/// one of the limit (`a --grid file`).
///
/// # Errors
/// When the file cannot be read, is longer than `limit`, or is not UTF-8.
pub fn read_text(
    path: &Path,
    limit: u64,
    role: &'static str,
    what: &'static str,
) -> Result<String> {
    let shown = path.display();
    let context = || format!("cannot read {role} {shown}");
    let file = File::open(path).with_context(context)?;
    let mut bytes = Vec::new();
    Bounded::new(file, limit, what)
        .read_to_end(&mut bytes)
        .with_context(context)?;
    String::from_utf8(bytes).map_err(|e| {
        anyhow::anyhow!(
            "{role} {shown} is not UTF-8 text (byte {} is not)",
            e.utf8_error().valid_up_to()
        )
    })
}

/// Reads one line (up to and with its `\n`) of at most `limit` bytes into
/// `buf`; returns its length, 0 at the end of the input.
///
/// # Errors
/// [`TooLong`] for a longer line, `InvalidData` for a line that is not
/// UTF-8, and the reader's own.
pub fn read_line(
    reader: &mut impl BufRead,
    buf: &mut String,
    limit: u64,
    what: &'static str,
) -> io::Result<usize> {
    let mut bytes = Vec::new();
    let n = reader.take(limit + 1).read_until(b'\n', &mut bytes)?;
    if n as u64 > limit {
        return Err(too_long(limit, what));
    }
    let text = std::str::from_utf8(&bytes).map_err(|e| {
        io::Error::new(
            io::ErrorKind::InvalidData,
            format!(
                "a line that is not UTF-8 text (at its byte {})",
                e.valid_up_to()
            ),
        )
    })?;
    buf.push_str(text);
    Ok(n)
}

/// The header of a CSV output: its `#` lines and the line after them (the
/// column names), each with its newline, at most [`MAX_HEADER`] bytes in
/// all. Fewer lines at the end of the input: the caller judges.
///
/// # Errors
/// [`TooLong`] past [`MAX_HEADER`], a line that is not UTF-8, the reader's.
pub fn read_header(reader: &mut impl BufRead) -> io::Result<Vec<String>> {
    let mut lines = Vec::new();
    let mut left = MAX_HEADER;
    loop {
        let mut line = String::new();
        let n =
            read_line(reader, &mut line, left, "the header of an output").map_err(|e| {
                match e.get_ref().and_then(|e| e.downcast_ref::<TooLong>()) {
                    Some(_) => too_long(MAX_HEADER, "the header of an output"),
                    None => e,
                }
            })?;
        if n == 0 {
            return Ok(lines);
        }
        left -= n as u64;
        let columns = !line.starts_with('#');
        lines.push(line);
        if columns {
            return Ok(lines);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::BufReader;

    fn is_too_long(e: &io::Error) -> bool {
        e.get_ref().is_some_and(|e| e.is::<TooLong>())
    }

    #[test]
    fn a_bounded_reader_reads_up_to_its_limit_and_refuses_more() {
        let mut out = Vec::new();
        Bounded::new(&b"12345"[..], 5, "x")
            .read_to_end(&mut out)
            .unwrap();
        assert_eq!(out, b"12345");
        let e = Bounded::new(&b"123456"[..], 5, "x")
            .read_to_end(&mut Vec::new())
            .unwrap_err();
        assert!(is_too_long(&e), "{e}");
        // Endless input: refused after the limit, not read for ever.
        let e = Bounded::new(io::repeat(0), 1 << 20, "a config file")
            .read_to_end(&mut Vec::new())
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "longer than 1 MiB, the most snowroll reads of a config file (an endless file such \
             as /dev/zero, or not the file meant?)"
        );
    }

    #[test]
    fn lines_and_headers_are_bounded() {
        let mut r = BufReader::new(&b"abc\ndefgh\n"[..]);
        let mut line = String::new();
        assert_eq!(read_line(&mut r, &mut line, 4, "a sweep row").unwrap(), 4);
        assert_eq!(line, "abc\n");
        assert!(is_too_long(
            &read_line(&mut r, &mut line, 4, "a sweep row").unwrap_err()
        ));
        // A line without a newline at the end of the input is a line.
        let mut r = BufReader::new(&b"xy"[..]);
        let mut line = String::new();
        assert_eq!(read_line(&mut r, &mut line, 4, "a sweep row").unwrap(), 2);

        let mut r = BufReader::new(&b"# a\n# b\ncols\n1,2\n"[..]);
        assert_eq!(read_header(&mut r).unwrap(), ["# a\n", "# b\n", "cols\n"]);
        // An endless header: short `#` lines past the limit, or one endless
        // line after a first one.
        let many = b"#\n".repeat(MAX_HEADER as usize / 2 + 1);
        let e = read_header(&mut BufReader::new(&many[..])).unwrap_err();
        assert!(is_too_long(&e) && e.to_string().contains("32 MiB"), "{e}");
        let endless = Read::chain(&b"#\n"[..], io::repeat(b'#'));
        let e = read_header(&mut BufReader::new(endless)).unwrap_err();
        assert!(is_too_long(&e) && e.to_string().contains("32 MiB"), "{e}");
    }
}
