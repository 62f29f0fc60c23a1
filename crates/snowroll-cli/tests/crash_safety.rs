//! Crash safety of `-o` (issue 7): a long `turns` run writing over an
//! existing complete file is killed with SIGKILL, which no program can
//! catch, at many seeded random moments. After each kill the path must hold
//! the previous complete file or the complete new one, never a partial
//! file; the temporary file a kill leaves is removed by a later run.

use std::collections::BTreeSet;
use std::fs;
use std::path::Path;
use std::process::{Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

use rustix::process::{kill_process, Pid, Signal};

/// Kills at random moments, plus one at once and one after the end.
const RANDOM_KILLS: usize = 22;
/// Seed of the kill moments.
const SEED: u64 = 0x5eed_0007;
/// Turns of the file that is there before (complete).
const OLD_TURNS: &str = "10000";
/// Turns of the run that replaces it (a fraction of a second).
const NEW_TURNS: &str = "20000";
/// Kill moments are drawn up to this multiple of a full run's duration, so
/// that some fall after the run has ended.
const WINDOW_OVER_RUN: f64 = 1.2;

fn bin() -> &'static Path {
    assert_cmd::cargo::cargo_bin!("snowroll")
}

/// splitmix64: a seeded sequence of uniform numbers in [0, 1).
struct Moments(u64);

impl Moments {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// What `turns --turns N` writes to stdout.
fn table(turns: &str) -> Vec<u8> {
    let out = Command::new(bin())
        .args(["turns", "--model", "turns", "--turns", turns])
        .stderr(Stdio::null())
        .output()
        .unwrap();
    assert!(out.status.success());
    out.stdout
}

/// The run under test: `turns --turns NEW_TURNS -o path`.
fn writer(path: &Path) -> Command {
    let mut cmd = Command::new(bin());
    cmd.args(["turns", "--model", "turns", "--turns", NEW_TURNS, "-o"])
        .arg(path)
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    cmd
}

/// The process ids in the temporary names in `dir`.
fn temporaries(dir: &Path) -> Vec<u32> {
    fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| {
            let name = e.unwrap().file_name().to_string_lossy().into_owned();
            let rest = name.strip_prefix(".snowroll-")?;
            Some(rest.split('-').next()?.parse().unwrap())
        })
        .collect()
}

#[test]
fn sigkill_at_any_moment_leaves_the_old_file_or_the_complete_new_one() {
    let old = table(OLD_TURNS);
    let new = table(NEW_TURNS);
    assert_ne!(old, new);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.csv");

    // One full run: it writes exactly what stdout gets, and says how long
    // the kill window is.
    fs::write(&path, &old).unwrap();
    let start = Instant::now();
    assert!(writer(&path).status().unwrap().success());
    let full_run = start.elapsed();
    assert_eq!(fs::read(&path).unwrap(), new);

    let mut moments = Moments(SEED);
    let mut delays: Vec<Duration> = (0..RANDOM_KILLS)
        .map(|_| full_run.mul_f64(WINDOW_OVER_RUN * moments.next()))
        .collect();
    // At once (before any output can exist), and after the run has ended.
    delays.push(Duration::ZERO);
    delays.push(Duration::MAX);

    let mut killed = BTreeSet::new();
    let (mut kept_old, mut got_new) = (0, 0);
    for delay in delays {
        fs::write(&path, &old).unwrap();
        let mut child = writer(&path).spawn().unwrap();
        if delay == Duration::MAX {
            child.wait().unwrap();
        } else {
            thread::sleep(delay);
        }
        // ESRCH if it already ended: then it must have written the new file.
        let _ = kill_process(Pid::from_child(&child), Signal::KILL);
        child.wait().unwrap();
        killed.insert(child.id());

        let now = fs::read(&path).unwrap();
        if now == old {
            kept_old += 1;
        } else {
            assert!(
                now == new,
                "partial file after a kill at {delay:?}: {} bytes",
                now.len()
            );
            got_new += 1;
        }
        // Whatever is left is a killed run's, and no older kill's survives
        // a later run that got as far as opening its output.
        let left = temporaries(dir.path());
        assert!(left.iter().all(|pid| killed.contains(pid)), "{left:?}");
        assert!(left.len() <= 2, "stale temporaries pile up: {left:?}");
    }
    assert!(
        kept_old >= 1 && got_new >= 1,
        "old {kept_old}, new {got_new}"
    );

    // The next complete run cleans up after the last kill.
    assert!(writer(&path).status().unwrap().success());
    assert!(temporaries(dir.path()).is_empty());
    assert_eq!(fs::read(&path).unwrap(), new);
    eprintln!(
        "crash safety: {} kills, {kept_old} left the old file, {got_new} the new one",
        RANDOM_KILLS + 2
    );
}
