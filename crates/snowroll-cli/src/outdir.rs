//! Where `snowroll paper` writes: a directory built in full beside its
//! destination and then moved into place, so that a reader sees the old
//! report or the new one, never half of one.
//!
//! - `--out DIR` missing: its parents are made, the report is built in a
//!   temporary directory in DIR's parent ([`Scratch`]) and renamed to DIR.
//! - `--out DIR` an existing report: the new one is swapped in with one
//!   `renameat2(RENAME_EXCHANGE)` (Linux), and the old one, now at the
//!   temporary name, is removed. Where the file system cannot exchange, the
//!   old one is renamed aside and the new one renamed in: for that moment DIR
//!   is missing, but never partial.
//! - `--out DIR` anything else is refused, so that no one's files are
//!   deleted: a directory holding files no report has, the current directory
//!   or one containing it, a path that is not a directory.
//!
//! An interrupted run (SIGINT, SIGTERM) removes the temporary directory; a
//! killed one leaves it for the next run to clean up, as for `-o`.

use std::fs;
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use rustix::fs::{renameat_with, RenameFlags, CWD};
use rustix::io::Errno;

use crate::scratch::{clean_stale, plain, Scratch};
use crate::sink::parent_or_dot;

/// Permission bits of a new directory, less the umask.
const NEW_DIR_MODE: u32 = 0o777;
/// The bits `chmod` sets.
const MODE_BITS: u32 = 0o7777;
/// The files at the top of a report.
const REPORT_FILES: [&str; 3] = ["report.html", "report.md", "claims.json"];
/// The folders of a report, which hold only files.
const REPORT_DIRS: [&str; 2] = ["figures", "data"];

/// A report directory being built.
#[derive(Debug)]
pub struct StagedDir {
    /// The directory the report is built in.
    scratch: Scratch,
    /// The directory it will become (after symbolic links).
    target: PathBuf,
    /// `--out` as given, for messages.
    shown: PathBuf,
}

impl StagedDir {
    /// Checks `out` and makes the temporary directory beside it.
    pub fn open(out: &Path) -> Result<StagedDir> {
        let shown = out.display();
        let context = || format!("cannot write the report to {shown}");
        if out.as_os_str().is_empty() {
            bail!("cannot write the report: the --out path is empty");
        }
        let (target, mode) = match fs::metadata(out) {
            Ok(meta) if !meta.is_dir() => {
                bail!("cannot write the report to {shown}: it exists and is not a directory")
            }
            Ok(meta) => {
                let target = fs::canonicalize(out).with_context(context)?;
                check_replaceable(&target).with_context(context)?;
                (target, meta.mode() & MODE_BITS)
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                if fs::symlink_metadata(out).is_ok() {
                    bail!("cannot write the report to {shown}: it is a symbolic link to nothing");
                }
                let parent = parent_or_dot(out);
                fs::create_dir_all(parent).with_context(context)?;
                (out.to_path_buf(), NEW_DIR_MODE)
            }
            Err(e) => return Err(e).with_context(context),
        };
        let dir = parent_or_dot(&target);
        clean_stale(dir);
        let scratch = Scratch::dir_in(dir, mode).with_context(context)?;
        if mode != NEW_DIR_MODE {
            fs::set_permissions(scratch.path(), fs::Permissions::from_mode(mode))
                .map_err(plain)
                .with_context(context)?;
        }
        Ok(StagedDir {
            scratch,
            target,
            shown: out.to_path_buf(),
        })
    }

    /// Where to write the report now.
    pub fn path(&self) -> &Path {
        self.scratch.path()
    }

    /// `path` inside [`Self::path`] as it will be named once in place, for
    /// messages: they never name the temporary directory.
    pub fn shown(&self, path: &Path) -> PathBuf {
        match path.strip_prefix(self.scratch.path()) {
            Ok(rest) => self.shown.join(rest),
            Err(_) => path.to_path_buf(),
        }
    }

    /// Moves the finished report into place, replacing an old one.
    pub fn commit(self) -> Result<()> {
        let context = || format!("cannot move the report into {}", self.shown.display());
        let StagedDir {
            scratch, target, ..
        } = self;
        if fs::symlink_metadata(&target).is_err() {
            scratch.rename_to(&target).with_context(context)?;
        } else {
            let exchanged = scratch.while_locked(|| {
                renameat_with(CWD, scratch.path(), CWD, &target, RenameFlags::EXCHANGE)
            });
            match exchanged {
                // The old report is now at the temporary name: dropping
                // `scratch` removes it.
                Ok(()) => {}
                Err(Errno::INVAL | Errno::NOSYS | Errno::OPNOTSUPP) => {
                    set_aside_and_rename(scratch, &target).with_context(context)?;
                }
                Err(e) => return Err(std::io::Error::from(e)).with_context(context),
            }
        }
        // Make the renames durable; a failure here cannot undo them.
        if let Ok(dir) = fs::File::open(parent_or_dot(&target)) {
            let _ = dir.sync_all();
        }
        Ok(())
    }
}

/// Where the file system cannot exchange two names: renames the old report
/// onto an empty temporary directory, then the new one into place, both
/// while no signal handler can act.
fn set_aside_and_rename(new: Scratch, target: &Path) -> std::io::Result<()> {
    let aside = Scratch::dir_in(parent_or_dot(target), NEW_DIR_MODE)?;
    new.while_locked(|| {
        fs::rename(target, aside.path())?;
        fs::rename(new.path(), target)
    })
    .map_err(plain)
    // Dropping `new` (now nothing) and `aside` (the old report) cleans up.
}

/// Refuses to replace a directory that holds anything a report does not,
/// or that holds the current directory.
fn check_replaceable(target: &Path) -> Result<()> {
    if let Ok(cwd) = std::env::current_dir().and_then(fs::canonicalize) {
        if cwd.starts_with(target) {
            bail!(
                "it is the current directory or contains it; name a new directory for the report"
            );
        }
    }
    if let Some(foreign) = foreign_entry(target)? {
        bail!(
            "it holds {}, which is not part of a snowroll report; choose another directory \
             or remove it first",
            foreign.display()
        );
    }
    Ok(())
}

/// The first entry of `dir` that a report does not have, if any.
fn foreign_entry(dir: &Path) -> Result<Option<PathBuf>> {
    for entry in fs::read_dir(dir)? {
        let entry = entry?;
        let name = entry.file_name();
        let kind = entry.file_type()?;
        let name_str = name.to_string_lossy();
        let ours = if REPORT_DIRS.contains(&name_str.as_ref()) && kind.is_dir() {
            match only_files(&entry.path())? {
                Some(foreign) => return Ok(Some(foreign)),
                None => true,
            }
        } else {
            (kind.is_file() && REPORT_FILES.contains(&name_str.as_ref()))
                || is_old_temporary(&name_str)
        };
        if !ours {
            return Ok(Some(entry.path()));
        }
    }
    Ok(None)
}

/// The first entry of `dir` that is not a regular file, if any.
fn only_files(dir: &Path) -> Result<Option<PathBuf>> {
    for entry in fs::read_dir(dir)? {
        let entry = entry?;
        if !entry.file_type()?.is_file() {
            return Ok(Some(entry.path()));
        }
    }
    Ok(None)
}

/// A temporary file that earlier versions left in a report when
/// interrupted: `.NAME.tmpPID`.
fn is_old_temporary(name: &str) -> bool {
    name.starts_with('.')
        && name
            .rsplit_once(".tmp")
            .is_some_and(|(_, pid)| !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The path taken where the file system cannot exchange two names.
    #[test]
    fn set_aside_and_rename_puts_the_new_report_in_place_and_removes_the_old() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("report");
        fs::create_dir(&target).unwrap();
        fs::write(target.join("old.txt"), "old").unwrap();
        let new = Scratch::dir_in(dir.path(), NEW_DIR_MODE).unwrap();
        fs::write(new.path().join("new.txt"), "new").unwrap();
        set_aside_and_rename(new, &target).unwrap();
        assert_eq!(fs::read_to_string(target.join("new.txt")).unwrap(), "new");
        assert!(!target.join("old.txt").exists());
        let left: Vec<_> = fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(left.len(), 1, "only the report is left");
    }

    #[test]
    fn old_temporary_names_are_recognised() {
        assert!(is_old_temporary(".report.html.tmp1234"));
        assert!(!is_old_temporary("report.html.tmp1234"));
        assert!(!is_old_temporary(".report.html.tmp"));
        assert!(!is_old_temporary(".notes.txt"));
    }
}
