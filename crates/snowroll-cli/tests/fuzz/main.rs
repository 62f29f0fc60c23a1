//! Fuzzing the command line and the config parser in-process, through
//! [`snowroll_cli::run_from`]: random argument vectors (real flags and
//! typos, valid, invalid and extreme numbers, odd paths, unicode) and random
//! TOML documents, each run in a scratch directory. Every case must
//!
//! - end with status 0, 1 (one `error:` line) or 2 (a usage error), never
//!   panic, and finish within [`CASE_BOUND`] (a watchdog ends the process
//!   otherwise, naming the case);
//! - leave no file but the outputs it named (`-o`, `--output`, the config's
//!   `output`, `paper --out`) and their parent folders, no temporary file
//!   anywhere, and every file it was given unchanged unless it named it as
//!   its output and succeeded;
//! - on failure, leave no new output file;
//! - never write a non-finite number into a CSV.
//!
//! A quarter of the cases ([`readback`], issue 20) give the readers of
//! outputs, grids and shards a corrupted, adversarial or endless file, with
//! outputs that clash with it.
//!
//! Runs are kept short by construction: end times at most
//! [`inputs::MAX_T_END`], grids no finer than [`inputs::MIN_DT`], at most
//! [`inputs::MAX_TURNS`]
//! turns (the row limits of huge requests are tested on their own).
//! `/dev/stdout` and `/proc/self/fd/N` are not generated: in-process they
//! would write to the harness's own stdout (they are tested on the binary in
//! `tests/output_files.rs`).
//!
//! `FUZZ_CASES` (default [`CI_CASES`], a few seconds) sets the number of
//! cases, `FUZZ_SEED` the seed, `FUZZ_SUMMARY` a file for the counts,
//! `FUZZ_FROM` the first case to run (to reproduce one of a campaign);
//! `scripts/fuzz.sh` runs the campaign of 10^6 and more.

mod checks;
mod inputs;
mod readback;
mod shards;

use std::fmt::Write as _;
use std::fs;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::thread;
use std::time::{Duration, Instant};

use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use crate::checks::{check, Tally};
use crate::inputs::case;

/// Cases run by `cargo test` (CI): a few seconds.
const CI_CASES: u32 = 2_000;
/// Descriptors the harness itself may hold at the end beyond those it held
/// at the start (the watchdog, buffers): far fewer than one per case.
const DESCRIPTOR_SLACK: usize = 64;
/// A file system in memory, if the machine has one.
const SCRATCH_IN_MEMORY: &str = "/dev/shm";
/// Seed of the CI run; the campaign uses others.
const CI_SEED: u64 = 7;
/// A case running longer than this is a hang: the watchdog reports it and
/// ends the process. The slowest valid case takes well under a second.
const CASE_BOUND: Duration = Duration::from_secs(30);
/// Ends the process when a case runs past [`CASE_BOUND`].
fn watchdog(
    started_ms: Arc<AtomicU64>,
    current: Arc<Mutex<String>>,
    done: Arc<AtomicBool>,
    epoch: Instant,
) {
    thread::spawn(move || {
        while !done.load(Ordering::Relaxed) {
            thread::sleep(Duration::from_millis(200));
            let start = started_ms.load(Ordering::Relaxed);
            let now = epoch.elapsed().as_millis() as u64;
            if start > 0 && now.saturating_sub(start) > CASE_BOUND.as_millis() as u64 {
                let case = current.lock().map(|c| c.clone()).unwrap_or_default();
                let mut err = std::io::stderr().lock();
                let _ = std::io::Write::write_fmt(
                    &mut err,
                    format_args!("FUZZ HANG (> {CASE_BOUND:?}): {case}\n"),
                );
                std::process::exit(3);
            }
        }
    });
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Open file descriptors of this process.
fn open_descriptors() -> usize {
    fs::read_dir("/proc/self/fd").map_or(0, Iterator::count)
}

#[test]
fn fuzz_the_command_line_and_the_config_file() {
    let cases = env_u64("FUZZ_CASES", u64::from(CI_CASES));
    let seed = env_u64("FUZZ_SEED", CI_SEED);
    // Relative to where the test started, before it changes directory.
    let summary_path =
        std::env::var_os("FUZZ_SUMMARY").map(|p| std::env::current_dir().unwrap().join(p));
    // In memory where there is such a file system: the fsync of every
    // output then costs nothing (on a disk it is most of a case's time).
    // `tests/output_files.rs` covers the file semantics on a disk.
    let scratch = tempfile::tempdir_in(SCRATCH_IN_MEMORY)
        .or_else(|_| tempfile::tempdir())
        .unwrap();
    // The real outputs the readers' cases corrupt, made before any case.
    let seed_dir = scratch.path().join("seeds");
    fs::create_dir(&seed_dir).unwrap();
    let seeds = readback::seeds(&seed_dir);
    let root = scratch.path().join("root");
    fs::create_dir(&root).unwrap();
    fs::create_dir(root.join("work")).unwrap();
    // Relative paths of the generated cases land in `root/work`; this is
    // the only test of this binary, so no other test minds.
    std::env::set_current_dir(root.join("work")).unwrap();

    let epoch = Instant::now();
    let started_ms = Arc::new(AtomicU64::new(0));
    let current = Arc::new(Mutex::new(String::new()));
    let done = Arc::new(AtomicBool::new(false));
    watchdog(started_ms.clone(), current.clone(), done.clone(), epoch);

    let mut seed_bytes = [0u8; 32];
    seed_bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let config = Config {
        cases: u32::try_from(cases).unwrap_or(u32::MAX),
        failure_persistence: None,
        max_shrink_iters: 2_000,
        ..Config::default()
    };
    let mut runner = TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &seed_bytes),
    );
    let descriptors_before = open_descriptors();
    let tally = Mutex::new(Tally::default());
    // FUZZ_FROM=N generates the first N cases without running them: case N
    // of a campaign is then the first one run.
    let skip = env_u64("FUZZ_FROM", 0);
    let index = std::cell::Cell::new(0u64);
    let result = runner.run(&case(seeds), |case| {
        index.set(index.get() + 1);
        if index.get() <= skip {
            return Ok(());
        }
        *current.lock().unwrap() = format!(
            "{:?} config {:?} files {:?}",
            case.args,
            case.config,
            // Small files whole (a hang names what it read), large ones by size.
            (case.files.iter())
                .map(|(n, b)| match b.len() {
                    len if len <= 16 << 10 => format!("{n}: {:?}", String::from_utf8_lossy(b)),
                    len => format!("{n}: {len} bytes"),
                })
                .collect::<Vec<_>>()
        );
        started_ms.store(epoch.elapsed().as_millis() as u64 + 1, Ordering::Relaxed);
        let outcome = check(&root, &case, &tally);
        started_ms.store(0, Ordering::Relaxed);
        outcome
    });
    done.store(true, Ordering::Relaxed);
    let t = tally.into_inner().unwrap();
    let mut summary = String::new();
    let _ = writeln!(summary, "seed {seed}");
    let _ = writeln!(summary, "cases {}", t.cases);
    for (status, n) in &t.by_status {
        let _ = writeln!(summary, "status {status} {n}");
    }
    for (command, n) in &t.by_command {
        let _ = writeln!(summary, "command {command} {n}");
    }
    let _ = writeln!(
        summary,
        "successful runs writing a file {}",
        t.successful_runs_with_output_file
    );
    let _ = writeln!(summary, "runs writing a non-finite number {}", t.non_finite);
    let _ = writeln!(
        summary,
        "merges copying a non-finite cell (until item 4) {}",
        t.merged_non_finite
    );
    let _ = writeln!(
        summary,
        "slowest case {:.3} s {}",
        t.slowest.as_secs_f64(),
        t.slowest_case
    );
    let _ = writeln!(summary, "findings {}", u8::from(result.is_err()));
    if let Some(path) = summary_path {
        fs::write(path, &summary).unwrap();
    }
    std::env::set_current_dir(scratch.path()).unwrap();
    if let Err(e) = result {
        panic!("fuzz finding (seed {seed}): {e}\n{summary}");
    }
    assert_eq!(t.cases + skip, cases, "every case ran");
    // Nothing a run opens outlives it (a leak once ended a campaign).
    assert!(open_descriptors() < descriptors_before + DESCRIPTOR_SLACK);
}
