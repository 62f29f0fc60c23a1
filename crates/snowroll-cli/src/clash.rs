//! Refuses a run that would write over one of its own files (issue 20,
//! item 3): an output that is one of the run's inputs (`sweep --config a.csv
//! -o a.csv`, `--grid g.toml -o g.toml`), or another of its outputs
//! (`--plot` equal to `-o` or to `FILE.partial`). Every command that reads or
//! writes files lists them, each with its role, and calls [`refuse_clashes`]
//! before it writes anything.
//!
//! Two paths are the same file however they are spelt:
//! - an existing file is known by its device and inode after every symbolic
//!   link (so `..`, `./`, absolute and relative paths, links and hard links
//!   all compare equal);
//! - a file that does not exist yet is known by the canonical path of its
//!   directory and its name, after following a dangling link as `-o` does
//!   (the link's target is what gets created).
//!
//! Only regular files and directories can clash: writing to a device, a FIFO
//! or a socket destroys nothing (two outputs to `/dev/null`, or `--config
//! /dev/stdin` with `-o /dev/stdout` on a terminal, are fine), and `-o -`
//! (stdout) is never a clash.

use std::fs;
use std::io;
use std::path::{Component, Path, PathBuf};

use anyhow::{bail, Result};
use std::os::unix::fs::MetadataExt;

use crate::sink::parent_or_dot;

/// Symbolic links followed before giving up, as Linux's `ELOOP` limit (and
/// the sink's).
const MAX_LINKS: usize = 40;

/// Whether the run reads a file or writes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Use {
    /// The run reads it (a config, a grid, a shard).
    Input,
    /// The run writes it (an output, a map, a partial file, a report).
    Output,
}

/// One file of a run, with its role for the message (`--config file`).
#[derive(Debug, Clone)]
pub struct RunFile<'a> {
    /// The path as given (or as the run derives it, for `FILE.partial`).
    pub path: &'a Path,
    /// What the file is to the run, as the message names it.
    pub role: &'static str,
    /// Read or written.
    pub used: Use,
}

impl<'a> RunFile<'a> {
    /// A file the run reads.
    pub fn input(path: &'a Path, role: &'static str) -> Self {
        RunFile {
            path,
            role,
            used: Use::Input,
        }
    }

    /// A file the run writes.
    pub fn output(path: &'a Path, role: &'static str) -> Self {
        RunFile {
            path,
            role,
            used: Use::Output,
        }
    }
}

/// What makes two paths the same file.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Identity {
    /// An existing regular file or directory: device and inode.
    Inode(u64, u64),
    /// A file still to be made: its directory's canonical path and its name.
    Name(PathBuf),
}

/// Refuses `files` when an output is the same file as an input or as
/// another output. The message names both paths and the role of each.
///
/// # Errors
/// The first clash, in the order of `files`.
pub fn refuse_clashes(files: &[RunFile<'_>]) -> Result<()> {
    let ids: Vec<Option<Identity>> = files.iter().map(|f| identity(f.path)).collect();
    for (i, out) in files.iter().enumerate() {
        if out.used != Use::Output {
            continue;
        }
        let Some(id) = &ids[i] else { continue };
        for (j, other) in files.iter().enumerate() {
            if j == i || ids[j].as_ref() != Some(id) {
                continue;
            }
            // Each pair of outputs once.
            if other.used == Use::Output && j < i {
                continue;
            }
            let (o, p) = (out.path.display(), other.path.display());
            match other.used {
                Use::Input => bail!(
                    "cannot write {o} (the {}): it is the same file as {p} (the {}), which this \
                     run reads; writing it would destroy that input: give another output name",
                    out.role,
                    other.role
                ),
                Use::Output => bail!(
                    "{o} (the {}) and {p} (the {}) are the same file: one would overwrite the \
                     other; give them different names",
                    out.role,
                    other.role
                ),
            }
        }
    }
    Ok(())
}

/// The identity of the file at `path`, or `None` when writing it cannot
/// destroy a file (stdout, a device, a FIFO, a socket) or when it cannot be
/// told (an unreadable directory: the run's own open reports that).
fn identity(path: &Path) -> Option<Identity> {
    if path.as_os_str() == "-" || path.as_os_str().is_empty() {
        return None;
    }
    match fs::metadata(path) {
        Ok(meta) if meta.is_file() || meta.is_dir() => {
            Some(Identity::Inode(meta.dev(), meta.ino()))
        }
        Ok(_) => None,
        Err(e) if e.kind() == io::ErrorKind::NotFound => to_be_made(path).map(Identity::Name),
        Err(_) => None,
    }
}

/// The absolute name of the file that writing `path` would create: a
/// dangling link is followed to its target, the directory is canonicalised
/// where it exists, and the rest is resolved by name.
fn to_be_made(path: &Path) -> Option<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::symlink_metadata(&p) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let link = fs::read_link(&p).ok()?;
                p = parent_or_dot(&p).join(link);
            }
            Ok(_) => return None, // it appeared meanwhile, or is not a plain name
            Err(_) => {
                let name = p.file_name()?;
                let dir = parent_or_dot(&p);
                let dir = fs::canonicalize(dir).unwrap_or_else(|_| lexical_absolute(dir));
                return Some(dir.join(name));
            }
        }
    }
    None
}

/// `path` made absolute against the current directory, with `.` and `..`
/// resolved by name (for a directory that does not exist yet).
fn lexical_absolute(path: &Path) -> PathBuf {
    let base = std::env::current_dir().unwrap_or_default();
    let mut out = PathBuf::new();
    for c in base.join(path).components() {
        match c {
            Component::ParentDir => {
                out.pop();
            }
            Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clash(files: &[RunFile<'_>]) -> Option<String> {
        refuse_clashes(files).err().map(|e| e.to_string())
    }

    /// Every spelling of one file is one identity; different files differ.
    #[test]
    fn one_file_however_spelt() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        fs::create_dir(d.join("sub")).unwrap();
        fs::write(d.join("a.csv"), "x").unwrap();
        fs::write(d.join("b.csv"), "x").unwrap();
        fs::hard_link(d.join("a.csv"), d.join("hard.csv")).unwrap();
        std::os::unix::fs::symlink("a.csv", d.join("link.csv")).unwrap();
        std::os::unix::fs::symlink("new.csv", d.join("dangling.csv")).unwrap();
        let a = d.join("a.csv");
        for same in [
            d.join("sub/../a.csv"),
            d.join("./a.csv"),
            d.join("hard.csv"),
            d.join("link.csv"),
        ] {
            assert_eq!(identity(&same), identity(&a), "{}", same.display());
        }
        assert_ne!(identity(&d.join("b.csv")), identity(&a));
        // Not yet made: by directory and name, after a dangling link.
        let new = identity(&d.join("new.csv"));
        assert!(matches!(new, Some(Identity::Name(_))));
        assert_eq!(identity(&d.join("sub/../new.csv")), new);
        assert_eq!(identity(&d.join("dangling.csv")), new);
        assert_ne!(identity(&d.join("new2.csv")), new);
        // Stdout and devices cannot be destroyed.
        assert_eq!(identity(Path::new("-")), None);
        assert_eq!(identity(Path::new("/dev/null")), None);
    }

    #[test]
    fn an_output_over_an_input_or_another_output_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        fs::write(d.join("a.csv"), "x").unwrap();
        let (a, dotted, map) = (d.join("a.csv"), d.join("./a.csv"), d.join("map.svg"));
        let err = clash(&[
            RunFile::input(&a, "--config file"),
            RunFile::output(&dotted, "-o output"),
        ])
        .unwrap();
        assert!(
            err.contains(&format!("cannot write {}", dotted.display())),
            "{err}"
        );
        assert!(
            err.contains("(the -o output)") && err.contains("(the --config file)"),
            "{err}"
        );
        let err = clash(&[
            RunFile::output(&map, "-o output"),
            RunFile::output(&map, "--plot map"),
        ])
        .unwrap();
        assert!(
            err.contains("(the -o output) and") && err.contains("(the --plot map)"),
            "{err}"
        );
        // Two inputs may be one file; distinct files, stdout and devices pass.
        assert_eq!(
            clash(&[
                RunFile::input(&a, "input shard"),
                RunFile::input(&dotted, "input shard"),
                RunFile::output(&map, "-o output"),
                RunFile::output(Path::new("-"), "--plot map"),
                RunFile::output(Path::new("/dev/null"), "a"),
                RunFile::output(Path::new("/dev/null"), "b"),
            ]),
            None
        );
    }
}
