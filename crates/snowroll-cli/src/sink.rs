//! Where results go: stdout, or the path of `-o`, treated by what is there.
//!
//! | at the path | what `-o` does |
//! |---|---|
//! | nothing | a new file, written in full to a temporary file beside it, then renamed into place |
//! | a regular file | replaced the same way, keeping its permission bits (and its owner where allowed) |
//! | a read-only file | refused, even for root: the shell's `>` would refuse it too |
//! | a file with several hard links | refused: replacing it would break the links, writing in place would not survive a crash |
//! | a symbolic link | followed; its target is treated as above (replaced atomically in the target's directory) |
//! | the file standard output writes to (`/dev/stdout`, `/proc/self/fd/1`, the file of `>`) | written through descriptor 1, at its position, like `-o -` |
//! | a device, FIFO, socket, or another handle in `/proc` (`/dev/fd/3`, `/proc/self/fd/N`) | appended in place, never truncated: no temporary file, no rename |
//! | a directory | refused: "is a directory" |
//! | `-` | stdout |
//!
//! A path that is one of the run's inputs, or another of its outputs, is
//! refused before this module is reached ([`crate::clash`]).
//!
//! The temporary file is a [`Scratch`]: removed on error and on SIGINT or
//! SIGTERM, and cleaned up by the next run after SIGKILL. Error messages
//! name the path given, never the temporary file. `docs/reliability.md`
//! gives the reasons.

use std::fs::{self, File, Metadata, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use rustix::fs::{accessat, Access, AtFlags, CWD};
use rustix::io::Errno;

use crate::args::OutputArgs;
use crate::console::{self, note_broken_pipe};
use crate::scratch::{clean_stale, plain, Scratch};
use crate::writeback::EarlyWriteback;

/// Symbolic links followed before giving up, as Linux's `ELOOP` limit.
const MAX_LINKS: usize = 40;
/// Permission bits of a new file, less the umask: what the shell's `>` gives.
const NEW_FILE_MODE: u32 = 0o666;
/// Permission bits of the temporary file that replaces an existing one,
/// until it is given the existing file's.
const PRIVATE_MODE: u32 = 0o600;
/// Any write permission bit.
const WRITE_BITS: u32 = 0o222;
/// Set-user-ID and set-group-ID bits.
const SET_ID_BITS: u32 = 0o6000;
/// The bits `chmod` sets.
const MODE_BITS: u32 = 0o7777;

/// An open destination for results.
#[derive(Debug)]
pub enum Sink {
    /// Standard output.
    Stdout(BufWriter<console::Stdout>),
    /// A path that is not a regular file, written in place.
    Through {
        /// The open device, FIFO or handle.
        file: BufWriter<Piped>,
        /// The path as given.
        path: PathBuf,
    },
    /// A temporary file, renamed over `target` on commit.
    Replace {
        /// The temporary file, open for writing, buffered in whole
        /// blocks and sent to disk as it grows.
        file: EarlyWriteback,
        /// Its name and lock; removes it unless renamed.
        scratch: Scratch,
        /// The regular file (or place for one) that it will replace.
        target: PathBuf,
        /// The path as given.
        path: PathBuf,
    },
}

/// What a path names, and so how it is written.
#[derive(Debug)]
enum Destination {
    Stdout,
    Through,
    /// A regular file or none: `target` is the file after symbolic links.
    Replace {
        target: PathBuf,
        existing: Option<Metadata>,
    },
}

impl Sink {
    /// Standard output.
    pub fn stdout() -> Sink {
        Sink::Stdout(BufWriter::new(console::Stdout))
    }

    /// Opens the destination of `-o` (stdout without one), refusing the
    /// paths the [module docs](self) list.
    pub fn open(args: &OutputArgs) -> Result<Sink> {
        let Some(path) = args.output.as_deref() else {
            return Ok(Sink::stdout());
        };
        let shown = path.display();
        match resolve(path).with_context(|| format!("cannot write {shown}"))? {
            Destination::Stdout => Ok(Sink::stdout()),
            Destination::Through => {
                // Appended, never truncated: a handle such as `/dev/fd/3`
                // or `/proc/self/fd/N` opens the file the shell opened, and
                // what it already wrote there stays (issue 20, item 1).
                let file = OpenOptions::new()
                    .append(true)
                    .open(path)
                    .with_context(|| format!("cannot write {shown}"))?;
                Ok(Sink::Through {
                    file: BufWriter::new(Piped(file)),
                    path: path.to_path_buf(),
                })
            }
            Destination::Replace { target, existing } => {
                let (scratch, file) = temporary_beside(&target, existing.as_ref())
                    .with_context(|| format!("cannot write {shown}"))?;
                Ok(Sink::Replace {
                    file: EarlyWriteback::new(file),
                    scratch,
                    target,
                    path: path.to_path_buf(),
                })
            }
        }
    }

    /// Flushes everything and, for a file, renames it into place.
    pub fn commit(self) -> io::Result<()> {
        match self {
            Sink::Stdout(mut out) => out.flush(),
            Sink::Through { mut file, .. } => file.flush(),
            Sink::Replace {
                file,
                scratch,
                target,
                ..
            } => {
                let file = file.finish().map_err(plain)?;
                file.sync_all().map_err(plain)?;
                scratch.rename_to(&target)?;
                // Make the rename itself durable; a failure here cannot undo it.
                if let Ok(dir) = File::open(parent_or_dot(&target)) {
                    let _ = dir.sync_all();
                }
                Ok(())
            }
        }
    }

    /// Puts the file `from` (open as `file`, in the target's directory)
    /// in place of the output instead of what was written here: it gets
    /// the permission bits and owner the temporary file was given (those
    /// of the file it replaces, or of a new file), is synced, and renamed
    /// over the target; the temporary file is removed. A rename needs no
    /// room on the disk, so a full disk cannot make the output fail here.
    /// Only for a [`Sink::Replace`]; any other sink is an error.
    ///
    /// # Errors
    /// The system's error, naming no temporary path.
    pub fn commit_by_rename(self, file: &File, from: &Path) -> io::Result<()> {
        let Sink::Replace {
            file: written,
            scratch,
            target,
            ..
        } = self
        else {
            return Err(io::Error::other("the output is not a file to replace"));
        };
        drop(written);
        let meta = fs::symlink_metadata(scratch.path()).map_err(plain)?;
        let mut mode = meta.mode() & MODE_BITS;
        if std::os::unix::fs::fchown(file, Some(meta.uid()), Some(meta.gid())).is_err() {
            mode &= !SET_ID_BITS;
        }
        file.set_permissions(fs::Permissions::from_mode(mode))
            .map_err(plain)?;
        file.sync_all().map_err(plain)?;
        fs::rename(from, &target).map_err(plain)?;
        drop(scratch);
        if let Ok(dir) = File::open(parent_or_dot(&target)) {
            let _ = dir.sync_all();
        }
        Ok(())
    }

    /// A description for error messages: the path as given, or stdout.
    pub fn name(&self) -> String {
        match self {
            Sink::Stdout(_) => "stdout".to_string(),
            Sink::Through { path, .. } | Sink::Replace { path, .. } => path.display().to_string(),
        }
    }
}

impl Write for Sink {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match self {
            Sink::Stdout(w) => w.write(buf),
            Sink::Through { file, .. } => file.write(buf),
            Sink::Replace { file, .. } => file.write(buf).map_err(plain),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match self {
            Sink::Stdout(w) => w.flush(),
            Sink::Through { file, .. } => file.flush(),
            Sink::Replace { file, .. } => file.flush().map_err(plain),
        }
    }
}

/// A file written in place whose reader may go away (a FIFO, a pipe behind
/// `/dev/stdout`): a broken pipe ends the run quietly, as on stdout.
#[derive(Debug)]
pub struct Piped(File);

impl Write for Piped {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.0.write(buf).map_err(note_broken_pipe)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.0.flush().map_err(note_broken_pipe)
    }
}

/// The directory part of `path`, `.` for a bare name.
pub fn parent_or_dot(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// The regular file (or place for one) that `-o path` would replace, after
/// symbolic links; `None` for stdout, a device, a FIFO, a handle, or a path
/// [`Sink::open`] refuses (it says why).
pub fn replaced_target(path: &Path) -> Option<PathBuf> {
    match resolve(path) {
        Ok(Destination::Replace { target, .. }) => Some(target),
        _ => None,
    }
}

/// Whether `dir` (an existing directory) lies in a pseudo-file system whose
/// entries are handles, not files: `/proc` and `/sys`.
fn is_pseudo(dir: &Path) -> bool {
    fs::canonicalize(dir)
        .map(|d| d.starts_with("/proc") || d.starts_with("/sys"))
        .unwrap_or(false)
}

/// Whether `path` (after links) is the file this process's standard output
/// writes to (same device and inode): `/dev/stdout`, `/proc/self/fd/1`, or
/// the very file the shell's `>` or `>>` opened. Such a path is written
/// through descriptor 1 itself, at its position, so that what the shell
/// writes before and after stays in order (issue 20, item 1: reopening it
/// with truncation lost `HEAD` and a `>>` log).
fn is_our_stdout(path: &Path) -> bool {
    let (Ok(target), Ok(out)) = (fs::metadata(path), rustix::fs::fstat(io::stdout())) else {
        return false;
    };
    target.dev() == out.st_dev && target.ino() == out.st_ino
}

/// What `path` names, following symbolic links one at a time so that a
/// link's target, not the link, is replaced.
fn resolve(path: &Path) -> Result<Destination> {
    if path.as_os_str() == "-" {
        return Ok(Destination::Stdout);
    }
    if path.as_os_str().is_empty() {
        bail!("the output path is empty");
    }
    if path.as_os_str().as_encoded_bytes().ends_with(b"/") {
        bail!("is a directory name (it ends with /), not a file name");
    }
    if is_our_stdout(path) {
        return Ok(Destination::Stdout);
    }
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        let meta = match fs::symlink_metadata(&p) {
            Ok(meta) => meta,
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                return Ok(Destination::Replace {
                    target: p,
                    existing: None,
                });
            }
            Err(e) => return Err(e.into()),
        };
        let kind = meta.file_type();
        let dir = parent_or_dot(&p);
        if kind.is_symlink() {
            // `/dev/stdout` leads to `/proc/self/fd/1`: a handle to whatever
            // stdout is, whose "target" may be `pipe:[1234]`.
            if is_pseudo(dir) {
                return Ok(Destination::Through);
            }
            let link = fs::read_link(&p)?;
            p = dir.join(link);
        } else if kind.is_dir() {
            bail!("is a directory");
        } else if kind.is_file() && !is_pseudo(dir) {
            check_replaceable(&p, &meta)?;
            return Ok(Destination::Replace {
                target: p,
                existing: Some(meta),
            });
        } else {
            return Ok(Destination::Through);
        }
    }
    bail!("too many levels of symbolic links")
}

/// Refuses an existing regular file that `>` would refuse (no write
/// permission for us, judged by the mode bits even for root, who passes
/// every permission check), and one with other hard links.
fn check_replaceable(path: &Path, meta: &Metadata) -> Result<()> {
    let mode = meta.mode() & MODE_BITS;
    if mode & WRITE_BITS == 0 {
        bail!("it is read-only (mode {mode:04o}); make it writable (chmod u+w) or remove it first");
    }
    // Owner, group, other bits and ACLs: the kernel's answer for our
    // effective ids is the one `>` would get.
    let access = accessat(CWD, path, Access::WRITE_OK, AtFlags::EACCESS);
    if access == Err(Errno::ACCESS) {
        bail!("it is not writable by you (mode {mode:04o}); make it writable or remove it first");
    }
    check_links(meta)
}

/// Refuses a file with more than one name.
fn check_links(meta: &Metadata) -> Result<()> {
    let links = meta.nlink();
    if links > 1 {
        bail!(
            "it has {links} hard links; replacing it would leave the other names with the old \
             contents and writing it in place would not survive a crash: remove it or choose \
             another name"
        );
    }
    Ok(())
}

/// A temporary file in `target`'s directory, with `existing`'s owner (where
/// allowed) and permission bits, or those of a new file.
fn temporary_beside(target: &Path, existing: Option<&Metadata>) -> io::Result<(Scratch, File)> {
    let dir = parent_or_dot(target);
    clean_stale(dir);
    let Some(meta) = existing else {
        return Scratch::file_in(dir, NEW_FILE_MODE);
    };
    let (scratch, file) = Scratch::file_in(dir, PRIVATE_MODE)?;
    let mut mode = meta.mode() & MODE_BITS;
    // Owner first: changing it clears the set-id bits.
    let owned = std::os::unix::fs::fchown(&file, Some(meta.uid()), Some(meta.gid())).is_ok();
    if !owned {
        // Our file must not carry someone else's set-id bits.
        mode &= !SET_ID_BITS;
    }
    file.set_permissions(fs::Permissions::from_mode(mode))
        .map_err(plain)?;
    Ok((scratch, file))
}
