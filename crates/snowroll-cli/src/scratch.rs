//! Temporary files and directories that become outputs, and the guarantee
//! that none is left behind.
//!
//! Every one is named `.snowroll-<pid>-<random>.tmp`, made in the directory
//! of the output it will replace, locked (`flock`) by its writer for as long
//! as it lives, and listed in one process-wide registry:
//!
//! - an error drops its [`Scratch`], which removes it;
//! - SIGINT, SIGTERM or SIGHUP run [`remove_all_and_exit`] (installed by
//!   [`crate::install_signal_handlers`]), which removes every listed one and
//!   exits with 128 + the signal's number;
//! - after SIGKILL, which no program can catch, the next run that writes
//!   into the same directory removes the leftovers it can prove are a
//!   snowroll's whose writer is gone ([`clean_stale`]).
//!
//! Creating, renaming into place and removing each hold the registry's
//! lock, and so does the signal handler: a signal never finds a temporary
//! file made but not yet listed, or renamed but still listed.

use std::collections::hash_map::RandomState;
use std::ffi::OsStr;
use std::fs::{self, DirBuilder, File, OpenOptions};
use std::hash::{BuildHasher, Hasher};
use std::io;
use std::os::unix::fs::{DirBuilderExt, MetadataExt, OpenOptionsExt};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

use rustix::fs::{flock, FlockOperation};

use crate::console::report;

/// Start of every temporary name.
const PREFIX: &str = ".snowroll-";
/// End of every temporary name.
const SUFFIX: &str = ".tmp";
/// Random characters in a temporary name.
const RANDOM_CHARS: usize = 8;
/// Names tried before giving up (each taken one is a collision of 8 random
/// characters, or someone squatting on our names).
const CREATE_ATTEMPTS: u32 = 100;

/// The temporary paths of this process that exist now.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic elsewhere must not stop the clean-up.
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Removes a file or a directory tree; a missing one is fine.
fn remove(path: &Path) -> io::Result<()> {
    let result = match fs::symlink_metadata(path) {
        Ok(m) if m.is_dir() => fs::remove_dir_all(path),
        Ok(_) => fs::remove_file(path),
        Err(e) => Err(e),
    };
    match result {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(()),
        other => other,
    }
}

/// Removes every temporary path of this process, then exits with `code`.
/// The registry stays locked, so no other thread makes or renames one
/// meanwhile.
pub fn remove_all_and_exit(code: i32) -> ! {
    let paths = live();
    for path in paths.iter() {
        // A writer may still be adding files to a directory: try again.
        for _ in 0..3 {
            if remove(path).is_ok() {
                break;
            }
        }
    }
    std::process::exit(code)
}

/// A temporary file or directory of this process: locked, listed, and
/// removed when dropped unless it was renamed into place.
#[derive(Debug)]
pub struct Scratch {
    path: PathBuf,
    /// Holds the `flock` that shows a live writer; released on close.
    _lock: File,
    /// Renamed into place: nothing is left to remove.
    renamed: bool,
}

impl Scratch {
    /// A new empty file in `dir`, opened for writing, created with `mode`
    /// less the umask.
    pub fn file_in(dir: &Path, mode: u32) -> io::Result<(Scratch, File)> {
        let mut registry = live();
        let (path, file) = create_unique(dir, |path| {
            OpenOptions::new()
                .write(true)
                .create_new(true)
                .mode(mode)
                .open(path)
        })?;
        let scratch = Scratch::listed(&mut registry, path, file.try_clone());
        Ok((scratch?, file))
    }

    /// A new empty directory in `dir`, created with `mode` less the umask.
    pub fn dir_in(dir: &Path, mode: u32) -> io::Result<Scratch> {
        let mut registry = live();
        let (path, ()) = create_unique(dir, |path| DirBuilder::new().mode(mode).create(path))?;
        let lock = File::open(&path);
        Scratch::listed(&mut registry, path, lock)
    }

    /// Lists `path` and takes its lock through `lock`, a handle to it; on
    /// an error, removes it again.
    fn listed(
        registry: &mut Vec<PathBuf>,
        path: PathBuf,
        lock: io::Result<File>,
    ) -> io::Result<Scratch> {
        let lock = match lock {
            Ok(lock) => lock,
            Err(e) => {
                let _ = remove(&path);
                return Err(plain(e));
            }
        };
        // Without the lock (a file system that has none), the process id in
        // the name still keeps other runs from removing it while we live.
        let _ = flock(&lock, FlockOperation::NonBlockingLockExclusive);
        registry.push(path.clone());
        Ok(Scratch {
            path,
            _lock: lock,
            renamed: false,
        })
    }

    /// Where it is.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Renames it to `dest`, replacing what is there, as one step that a
    /// signal cannot split.
    pub fn rename_to(mut self, dest: &Path) -> io::Result<()> {
        let mut registry = live();
        fs::rename(&self.path, dest).map_err(plain)?;
        registry.retain(|p| p != &self.path);
        self.renamed = true;
        Ok(())
    }

    /// Runs `f` while no signal handler can act: `f` may move what is at
    /// this path elsewhere and put something else here; whatever is here
    /// afterwards is removed when this scratch is dropped.
    pub fn while_locked<R>(&self, f: impl FnOnce() -> R) -> R {
        let _registry = live();
        f()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if self.renamed {
            return;
        }
        let mut registry = live();
        // Best effort: an error leaves it for the next run to clean up.
        let _ = remove(&self.path);
        registry.retain(|p| p != &self.path);
    }
}

/// Makes a new entry `.snowroll-<pid>-<random>.tmp` in `dir` with
/// `create`, which must fail with `AlreadyExists` if the name is taken.
///
/// Written here rather than with `tempfile`, whose errors name the
/// temporary path: messages must name only the destination.
fn create_unique<T>(
    dir: &Path,
    mut create: impl FnMut(&Path) -> io::Result<T>,
) -> io::Result<(PathBuf, T)> {
    let mut last = io::Error::from(io::ErrorKind::AlreadyExists);
    for attempt in 0..CREATE_ATTEMPTS {
        let name = format!(
            "{PREFIX}{}-{}{SUFFIX}",
            std::process::id(),
            random_chars(attempt)
        );
        let path = dir.join(name);
        match create(&path) {
            Ok(made) => return Ok((path, made)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = e,
            Err(e) => return Err(e),
        }
    }
    Err(last)
}

/// [`RANDOM_CHARS`] letters and digits, different at each call: std's
/// randomly keyed hasher over the time and `salt`.
fn random_chars(salt: u32) -> String {
    const ALPHABET: &[u8; 62] = b"0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    let mut hasher = RandomState::new().build_hasher();
    hasher.write_u128(nanos);
    hasher.write_u32(salt);
    let mut x = hasher.finish();
    (0..RANDOM_CHARS)
        .map(|_| {
            let c = ALPHABET[(x % 62) as usize];
            x /= 62;
            char::from(c)
        })
        .collect()
}

/// The process id in a temporary name of ours, `.snowroll-<pid>-<random>.tmp`.
fn owner_pid(name: &OsStr) -> Option<u32> {
    let rest = name.to_str()?.strip_prefix(PREFIX)?.strip_suffix(SUFFIX)?;
    let (pid, random) = rest.split_once('-')?;
    let ours = random.len() == RANDOM_CHARS && random.chars().all(|c| c.is_ascii_alphanumeric());
    ours.then(|| pid.parse().ok()).flatten()
}

/// Whether process `pid` exists (in this pid namespace).
fn alive(pid: u32) -> bool {
    let Some(pid) = i32::try_from(pid)
        .ok()
        .and_then(rustix::process::Pid::from_raw)
    else {
        return false;
    };
    // EPERM: it exists, but belongs to someone else.
    !matches!(
        rustix::process::test_kill_process(pid),
        Err(rustix::io::Errno::SRCH)
    )
}

/// Removes the temporary files and directories in `dir` that a killed
/// snowroll left: those with our name pattern whose process is gone, that
/// belong to this user, and whose `flock` no one holds (a live writer in
/// another pid namespace holds it). Says on stderr what it removed.
pub fn clean_stale(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let me = std::process::id();
    let uid = rustix::process::geteuid().as_raw();
    for entry in entries.flatten() {
        let Some(pid) = owner_pid(&entry.file_name()) else {
            continue;
        };
        if pid == me || alive(pid) {
            continue;
        }
        let path = entry.path();
        let Ok(meta) = fs::symlink_metadata(&path) else {
            continue;
        };
        if meta.uid() != uid || !(meta.is_file() || meta.is_dir()) {
            continue;
        }
        let Ok(lock) = File::open(&path) else {
            continue;
        };
        if flock(&lock, FlockOperation::NonBlockingLockExclusive).is_err() {
            continue;
        }
        if remove(&path).is_ok() {
            report!(
                "note: removed {}, left by an interrupted snowroll (process {pid}, no longer running)",
                path.display()
            );
        }
    }
}

/// `e` as the system's error alone, without any path a wrapper added:
/// error messages name the destination, never the temporary file.
pub fn plain(e: io::Error) -> io::Error {
    match e.raw_os_error() {
        Some(code) => io::Error::from_raw_os_error(code),
        None => e,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn owner_pid_reads_only_our_names() {
        assert_eq!(owner_pid(OsStr::new(".snowroll-42-abcdEF12.tmp")), Some(42));
        for other in [
            ".snowroll-42-abc.tmp",
            ".snowroll-x-abcdEF12.tmp",
            ".snowroll-abcdEF12.tmp",
            "snowroll-42-abcdEF12.tmp",
            ".snowroll-42-abcdEF12.tmp.bak",
            ".snowroll-42-abcd.F12.tmp",
        ] {
            assert_eq!(owner_pid(OsStr::new(other)), None, "{other}");
        }
    }

    #[test]
    fn a_scratch_is_listed_while_it_lives_and_removed_when_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let (scratch, _file) = Scratch::file_in(dir.path(), 0o600).unwrap();
        let path = scratch.path().to_path_buf();
        assert_eq!(
            owner_pid(path.file_name().unwrap()),
            Some(std::process::id())
        );
        assert!(live().contains(&path));
        // Locked and alive: never stale.
        clean_stale(dir.path());
        assert!(path.exists());
        drop(scratch);
        assert!(!path.exists());
        assert!(!live().contains(&path));
    }

    /// Open file descriptors of this process.
    fn open_descriptors() -> usize {
        fs::read_dir("/proc/self/fd").unwrap().count()
    }

    /// Regression of issue 7 (fuzzing): a scratch renamed into place kept
    /// its lock's descriptor open for ever, so that a program running many
    /// commands in one process (the fuzz harness: after 2.6·10^5 cases) ran
    /// out of descriptors.
    #[test]
    fn regression_7_a_renamed_scratch_closes_its_descriptor() {
        /// Rename cycles: each leaked descriptor would count once.
        const CYCLES: usize = 256;
        /// Descriptors other tests of this binary may hold meanwhile.
        const OTHERS: usize = 64;
        let dir = tempfile::tempdir().unwrap();
        let before = open_descriptors();
        for i in 0..CYCLES {
            let (scratch, file) = Scratch::file_in(dir.path(), 0o600).unwrap();
            drop(file);
            scratch
                .rename_to(&dir.path().join(format!("f{i}")))
                .unwrap();
        }
        assert!(open_descriptors() < before + OTHERS);
    }

    #[test]
    fn a_dead_writers_unlocked_leftover_is_removed_and_others_are_kept() {
        let dir = tempfile::tempdir().unwrap();
        // No process has pid 2^22 + 1 (above Linux's largest pid_max).
        let dead = dir.path().join(".snowroll-4194305-abcdEF12.tmp");
        let foreign = dir.path().join(".snowroll-abcdef.tmp");
        let mine = dir
            .path()
            .join(format!(".snowroll-{}-abcdEF12.tmp", std::process::id()));
        for p in [&dead, &foreign, &mine] {
            fs::write(p, "x").unwrap();
        }
        let dead_dir = dir.path().join(".snowroll-4194305-abcdEF13.tmp");
        fs::create_dir(&dead_dir).unwrap();
        fs::write(dead_dir.join("f"), "x").unwrap();
        clean_stale(dir.path());
        assert!(!dead.exists() && !dead_dir.exists());
        assert!(foreign.exists() && mine.exists());
    }
}
