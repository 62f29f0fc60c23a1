//! CSV text built in memory: the `#` comment header of a data file, and
//! the bytes as text (used by the figures' data and the animations').

use std::io::Write;
use std::path::{Path, PathBuf};

use super::error::{io_err, ReportError};

/// Writes `# key = value` comment lines: version, then parameters.
pub(super) fn comment_header(
    out: &mut Vec<u8>,
    software: &str,
    lines: &[(String, String)],
) -> Result<(), ReportError> {
    let io = io_err(Path::new("<memory>"));
    let mut text = format!("# {software}\n");
    for (k, v) in lines {
        text.push_str(&format!("# {k} = {}\n", v.replace('\n', " ")));
    }
    out.write_all(text.as_bytes()).map_err(io)
}

/// Converts CSV bytes to text.
pub(super) fn utf8(out: Vec<u8>) -> Result<String, ReportError> {
    String::from_utf8(out).map_err(|e| ReportError::Io {
        path: PathBuf::from("<memory>"),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e),
    })
}
