//! The rows file of a sweep that writes to `FILE`: `FILE.partial`, locked
//! while a sweep writes it, kept after a kill so that `--resume` can go on
//! from its rows.
//!
//! Resuming decides sameness from the parsed header (the grid and every
//! setting, [`Recorded::differences`]), not from the command line's bytes,
//! checks every row already there ([`check_rows`]), drops only a torn last
//! line, and refuses anything else with the line and the reason. A partial
//! file is never truncated or removed unless this run created it.

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufReader, Read, Seek, SeekFrom, Write};
use std::ops::Range;
use std::os::unix::ffi::{OsStrExt, OsStringExt};
use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use rustix::fs::{flock, FlockOperation};

use super::sweep_check::{check_rows, Recorded};

/// What is appended to the output's name for the rows of a running sweep.
const PARTIAL_SUFFIX: &str = ".partial";
/// Longest file name (bytes) of the usual file systems (`NAME_MAX`).
const NAME_MAX: usize = 255;

/// The partial file of output `target`: `NAME.partial` beside it, or, when
/// that name would pass [`NAME_MAX`], the name cut short with a hash of the
/// whole name (`NAME-CUT~0123456789abcdef.partial`), so that a resumed run
/// finds the same file.
pub fn partial_path(target: &Path) -> PathBuf {
    let name = target.file_name().unwrap_or(target.as_os_str());
    let bytes = name.as_bytes();
    let mut short = if bytes.len() + PARTIAL_SUFFIX.len() <= NAME_MAX {
        bytes.to_vec()
    } else {
        let tag = format!("~{:016x}", fnv1a(bytes));
        let keep = NAME_MAX - PARTIAL_SUFFIX.len() - tag.len();
        // Cut at a character boundary when the name is UTF-8.
        let mut cut = keep;
        if let Ok(text) = std::str::from_utf8(bytes) {
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
        }
        let mut v = bytes[..cut].to_vec();
        v.extend_from_slice(tag.as_bytes());
        v
    };
    short.extend_from_slice(PARTIAL_SUFFIX.as_bytes());
    target.with_file_name(OsString::from_vec(short))
}

/// The 64-bit FNV-1a hash: stable across versions and platforms, unlike
/// std's hasher.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The rows file of a running sweep, locked for as long as it is open.
pub struct Partial {
    pub file: File,
    path: PathBuf,
    /// Length of the header, bytes: the rows start there.
    pub header_len: u64,
    /// Lines of the header: the first row's line number is one more.
    header_lines: u64,
    /// Whether this run created the file (it may then remove it).
    created: bool,
}

impl Partial {
    /// Opens (or creates) `path` and locks it; writes `header` into a new or
    /// empty one. An existing one is refused unless `resume`, and then must
    /// record the same sweep as `run` (the differing settings are named).
    pub fn open(path: &Path, header: &str, run: &Recorded, resume: bool) -> Result<Partial> {
        let shown = path.display().to_string();
        refuse_unless_regular(path)?;
        let (file, created) = open_or_create(path)?;
        // Checked again on the open file: it may have been replaced since.
        let kind = file.metadata()?.file_type();
        if !kind.is_file() {
            bail!("{}", not_regular(path, &kind));
        }
        flock(&file, FlockOperation::NonBlockingLockExclusive)
            .map_err(|_| anyhow!("{shown} is being written by another sweep"))?;
        let mut partial = Partial {
            header_len: 0,
            header_lines: header.lines().count() as u64,
            file,
            path: path.to_path_buf(),
            created,
        };
        let len = partial.file.metadata()?.len();
        if len == 0 {
            let written = (&partial.file)
                .write_all(header.as_bytes())
                .with_context(|| format!("writing {shown}"));
            if let Err(e) = written {
                partial.remove_if_created();
                return Err(e);
            }
            partial.header_len = header.len() as u64;
            return Ok(partial);
        }
        if !resume {
            bail!(
                "{shown} holds the rows of an unfinished sweep: pass --resume (with the same \
                 flags) to continue it, or remove it to start again"
            );
        }
        let mut reader = BufReader::new(&partial.file);
        let on_disk = Recorded::read(&mut reader, &shown)
            .map_err(|e| anyhow!("cannot resume from {shown}: {e}"))?;
        let differs = on_disk.differences(run, true, (&shown, "this sweep"));
        if !differs.is_empty() {
            bail!(
                "{shown} was written by another sweep ({}): remove it, or resume with the \
                 settings that started it",
                differs.join("; ")
            );
        }
        partial.header_len = on_disk.len;
        partial.header_lines = on_disk.lines;
        Ok(partial)
    }

    /// How many rows of `run` are complete on disk: checks every row
    /// ([`check_rows`] against `run`'s grid), then cuts a torn last line
    /// off (the only change made to rows already there, and only when the
    /// rows before it passed) and leaves the file positioned at its end.
    pub fn rows_done(&mut self, run: &Recorded) -> Result<u64> {
        let shown = self.path.display().to_string();
        let range: &Range<u64> = &run.rows;
        let len = self.file.metadata()?.len();
        let end = last_newline(&mut self.file, self.header_len, len)?;
        self.file.seek(SeekFrom::Start(self.header_len))?;
        let mut reader = BufReader::new((&self.file).take(end - self.header_len));
        let next = check_rows(
            &mut reader,
            &run.grid,
            range,
            self.header_lines + 1,
            &shown,
            |_, _| Ok(()),
        )
        .map_err(|e| anyhow!("cannot resume: {e}"))?;
        // Only now, the rows before it being sound, is the torn line cut.
        if end < len {
            self.file.set_len(end)?;
        }
        self.file.seek(SeekFrom::End(0))?;
        Ok(next - range.start)
    }

    /// Removes the file if this run created it: a run that fails leaves no
    /// new file, but a partial file of an earlier run is kept for
    /// `--resume`.
    pub fn remove_if_created(&self) {
        if self.created {
            // Nothing more to do if it is gone already.
            let _ = fs::remove_file(&self.path);
        }
    }

    /// Its path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Removes the file of a finished sweep whose output was converted
    /// from it (Parquet); a CSV output is the file itself, renamed.
    #[cfg(feature = "parquet")]
    pub fn remove(self) -> Result<()> {
        fs::remove_file(&self.path).with_context(|| format!("removing {}", self.path.display()))
    }
}

/// Refuses a partial file that is there and is not a regular file: a
/// symbolic link (to `/dev/null`, whose rows would vanish, or to another
/// file, which the finished output would be renamed over), a device such
/// as `/dev/zero` (endless), a FIFO, a socket or a directory (issue 33,
/// item 2). Nothing is opened.
fn refuse_unless_regular(path: &Path) -> Result<()> {
    match fs::symlink_metadata(path) {
        Ok(meta) if !meta.file_type().is_file() => {
            bail!("{}", not_regular(path, &meta.file_type()))
        }
        _ => Ok(()),
    }
}

/// The message for a partial file of kind `kind`, not a regular file.
fn not_regular(path: &Path, kind: &fs::FileType) -> String {
    format!(
        "cannot use {} as the rows file of this sweep: it is {}, not a regular file (a \
         sweep's partial file holds its rows and becomes its output); remove it, or give \
         another -o",
        path.display(),
        kind_name(kind)
    )
}

/// What a file of kind `kind` is, for messages.
pub fn kind_name(kind: &fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if kind.is_symlink() {
        "a symbolic link"
    } else if kind.is_dir() {
        "a directory"
    } else if kind.is_char_device() {
        "a character device"
    } else if kind.is_block_device() {
        "a block device"
    } else if kind.is_fifo() {
        "a FIFO"
    } else if kind.is_socket() {
        "a socket"
    } else if kind.is_file() {
        "a regular file"
    } else {
        "of an unknown kind"
    }
}

/// Opens `path` read-write, creating it if it does not exist, never
/// through a symbolic link; says whether it was created.
fn open_or_create(path: &Path) -> Result<(File, bool)> {
    use std::os::unix::fs::OpenOptionsExt;
    let shown = path.display();
    let mut options = OpenOptions::new();
    options
        .read(true)
        .write(true)
        .custom_flags(rustix::fs::OFlags::NOFOLLOW.bits() as i32);
    match options.clone().create_new(true).open(path) {
        Ok(f) => Ok((f, true)),
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
            let f = options
                .open(path)
                .with_context(|| format!("cannot write {shown}"))?;
            Ok((f, false))
        }
        Err(e) => Err(e).with_context(|| format!("cannot write {shown}")),
    }
}

/// The position just after the last `\n` before `end` and at or after
/// `floor`, or `floor` when there is none.
fn last_newline(file: &mut File, floor: u64, end: u64) -> io::Result<u64> {
    const BLOCK: u64 = 64 * 1024;
    let mut hi = end;
    let mut buf = vec![0u8; BLOCK as usize];
    while hi > floor {
        let lo = hi.saturating_sub(BLOCK).max(floor);
        let n = (hi - lo) as usize;
        file.seek(SeekFrom::Start(lo))?;
        file.read_exact(&mut buf[..n])?;
        if let Some(k) = buf[..n].iter().rposition(|&c| c == b'\n') {
            return Ok(lo + k as u64 + 1);
        }
        hi = lo;
    }
    Ok(floor)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Names that fit keep the plain suffix (the name earlier versions
    /// used); longer ones are cut to NAME_MAX with a hash of the whole
    /// name, so two long names that differ only past the cut get two
    /// files, and the same name always the same file.
    #[test]
    fn partial_names_fit_name_max_and_tell_long_names_apart() {
        let dir = Path::new("/some/dir");
        assert_eq!(
            partial_path(&dir.join("out.csv")),
            dir.join("out.csv.partial")
        );
        let fits = "a".repeat(NAME_MAX - PARTIAL_SUFFIX.len());
        assert_eq!(
            partial_path(&dir.join(&fits)),
            dir.join(format!("{fits}.partial"))
        );
        let long_a = format!("{}a.csv", "x".repeat(250));
        let long_b = format!("{}b.csv", "x".repeat(250));
        let (pa, pb) = (
            partial_path(&dir.join(&long_a)),
            partial_path(&dir.join(&long_b)),
        );
        for p in [&pa, &pb] {
            let name = p.file_name().unwrap().as_bytes();
            assert!(name.len() <= NAME_MAX, "{}", name.len());
            assert!(name.ends_with(b".partial"));
            assert_eq!(p.parent(), Some(dir));
        }
        assert_ne!(pa, pb);
        assert_eq!(pa, partial_path(&dir.join(&long_a)));
        // A multi-byte character at the cut is not split.
        let wide = "é".repeat(200);
        let p = partial_path(&dir.join(&wide));
        assert!(p.file_name().unwrap().to_str().is_some());
        assert!(p.file_name().unwrap().len() <= NAME_MAX);
    }

    /// FNV-1a's published test vectors.
    #[test]
    fn fnv1a_matches_its_reference_values() {
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a(b"foobar"), 0x8594_4171_f739_67e8);
    }
}
