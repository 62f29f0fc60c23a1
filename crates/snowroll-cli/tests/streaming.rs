//! Issue 7, items 2 and 3: rows are written as they are computed, memory
//! does not grow with the number of rows or turns, row counts known to be
//! too large are refused before the run, and a run that stops on a limit
//! keeps its rows, records the stop and exits 0.

use std::fs;
use std::io::Read;
use std::process::{Command as Process, Stdio};
use std::thread;
use std::time::{Duration, Instant};

use assert_cmd::cargo::cargo_bin_cmd;
use assert_cmd::Command;
use serde_json::Value;
use snowroll::{ModelKind, Sampling, Scenario, SimOptions};

fn snowroll() -> Command {
    cargo_bin_cmd!("snowroll")
}

/// Interval between two readings of a child's peak RSS.
const POLL: Duration = Duration::from_millis(5);
/// Longest a whole-process test waits for its child: far above the seconds
/// the runs take, so a hang fails the test instead of stalling CI.
const WAIT_LIMIT: Duration = Duration::from_secs(300);

/// `VmHWM` (peak resident set) of process `pid` from `/proc`, bytes; `None`
/// once it has exited.
fn peak_rss(pid: u32) -> Option<u64> {
    let status = fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Runs snowroll with `args`, stdout discarded, and returns the largest
/// peak RSS read while it ran, in bytes, and whether it succeeded.
///
/// The kernel's `VmHWM` only grows, so the last reading before the exit is
/// the peak up to then; readings every 5 ms of a run that lasts seconds
/// miss at most the last 5 ms. (Neither std nor rustix offers `wait4` or
/// `getrusage(RUSAGE_CHILDREN)` without `unsafe`, which the workspace forbids.)
fn run_measuring_rss(args: &[&str]) -> (u64, bool) {
    let bin = assert_cmd::cargo::cargo_bin!("snowroll");
    let mut child = Process::new(bin)
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let (start, mut peak) = (Instant::now(), 0);
    loop {
        if let Some(bytes) = peak_rss(child.id()) {
            peak = peak.max(bytes);
        }
        if let Some(status) = child.try_wait().unwrap() {
            return (peak, status.success());
        }
        assert!(start.elapsed() < WAIT_LIMIT, "snowroll {args:?} hangs");
        thread::sleep(POLL);
    }
}

const MB: u64 = 1 << 20;

#[test]
fn regression_7_two_million_turns_to_a_file_stay_under_64_mb() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("f.csv");
    let (peak, ok) = run_measuring_rss(&[
        "turns",
        "--model",
        "turns",
        "--turns",
        "2000000",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(ok);
    // The bound. Before streaming the 2e6 rows of 96 bytes alone
    // took 192 MB (and the run 1 GB at 1e7 turns).
    assert!(peak < 64 * MB, "peak RSS {} MB", peak / MB);
    // The file is complete: its last lines are the summary, after the stop.
    let text = fs::read_to_string(&out).unwrap();
    let rows = text.lines().filter(|l| !l.starts_with('#')).count();
    assert_eq!(rows, 1 + 2_000_000);
    assert!(text
        .lines()
        .last()
        .unwrap()
        .starts_with("# summary: 2000000, "));
}

#[test]
fn regression_7_simulate_memory_does_not_grow_with_the_rows() {
    let dir = tempfile::tempdir().unwrap();
    let peak = |dt: &str| {
        let out = dir.path().join(format!("dt{dt}.csv"));
        let (peak, ok) = run_measuring_rss(&[
            "simulate",
            "--model",
            "eq4",
            "--dt",
            dt,
            "--t-end",
            "100",
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(ok);
        peak
    };
    let (small, large) = (peak("1e-2"), peak("1e-4"));
    // 10^4 and 10^6 rows. Held in memory, the 10^6 samples of 48 bytes
    // would add 48 MB; streamed, the peak differs by buffers and noise
    // (a few hundred kB): 8 MB separates the two cases by a factor 6.
    assert!(
        large < small + 8 * MB,
        "10^4 rows: {} kB, 10^6 rows: {} kB",
        small / 1024,
        large / 1024
    );
}

#[test]
fn regression_7_turns_piped_to_head_returns_at_once() {
    // 10^7 turns take minutes; `| head -1` must end as soon as head has
    // its line. The generous limit only keeps a hang from stalling CI.
    let bin = assert_cmd::cargo::cargo_bin!("snowroll");
    let mut child = Process::new(bin)
        .args(["turns", "--model", "turns", "--turns", "10000000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    stdout.read_exact(&mut first).unwrap();
    assert!(first.starts_with(b"# snowroll "));
    drop(stdout); // the reader goes away, as head does
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > WAIT_LIMIT {
            child.kill().unwrap();
            panic!("snowroll went on after its reader left");
        }
        thread::sleep(POLL);
    };
    // A reader that went away is not an error (console.rs).
    assert!(status.success(), "{status:?}");
}

#[test]
fn regression_7_step_limit_keeps_the_rows_records_the_stop_and_exits_0() {
    // `--model turns --t-end 1e9` uses up the default budget of 10^8 steps
    // in a minute; a budget of 5000 reaches the same stop in milliseconds.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("limit.csv");
    let assert = snowroll()
        .args(["simulate", "--model", "turns", "--t-end", "1e9"])
        .args(["--max-steps", "5000", "-o"])
        .arg(&out)
        .assert()
        .success();
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(stderr.contains("note: run stopped"), "{stderr}");
    assert!(stderr.contains("step budget"), "{stderr}");
    let text = fs::read_to_string(&out).unwrap();
    // A row per accepted step, plus the start: at most the budget + 1.
    let rows = text.lines().filter(|l| !l.starts_with('#')).count() - 1;
    assert!(rows > 2500 && rows <= 5001, "{rows} rows");
    // After the rows: the stop, then the note that says why it came early.
    let stop = text.lines().find(|l| l.starts_with("# stop = ")).unwrap();
    assert!(stop.starts_with("# stop = step-limit at t_s = "), "{stop}");
    assert!(text
        .lines()
        .last()
        .unwrap()
        .starts_with("# note = run stopped"));
    // The stop is the state of the last row.
    let last_row = text.lines().rev().find(|l| !l.starts_with('#')).unwrap();
    let t_last = last_row.split(',').next().unwrap();
    assert!(
        stop.contains(&format!("t_s = {t_last} ")),
        "{stop} / {last_row}"
    );
}

#[test]
fn regression_7_row_limit_stops_a_step_sampled_run_with_its_rows() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("limit.csv");
    let assert = snowroll()
        .args(["simulate", "--model", "turns", "--t-end", "1e9"])
        .args(["--max-rows", "2000", "-o"])
        .arg(&out)
        .assert()
        .success();
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(stderr.contains("--max-rows"), "{stderr}");
    let text = fs::read_to_string(&out).unwrap();
    let rows = text.lines().filter(|l| !l.starts_with('#')).count();
    assert_eq!(rows, 1 + 2000);
    let stop = text.lines().find(|l| l.starts_with("# stop = ")).unwrap();
    assert!(stop.starts_with("# stop = row-limit"), "{stop}");
}

#[test]
fn max_rows_refuses_a_known_count_before_the_run_naming_count_and_flag() {
    let cases: [(&[&str], &str); 4] = [
        (
            &["simulate", "--model", "eq4", "--dt", "1e-300"],
            "1.00e302 rows",
        ),
        (
            &[
                "simulate",
                "--model",
                "eq4",
                "--dt",
                "0.5",
                "--max-rows",
                "100",
            ],
            "201 rows",
        ),
        (
            &[
                "simulate",
                "--model",
                "eq4",
                "--times",
                "1,2,3",
                "--max-rows",
                "2",
            ],
            "3 rows",
        ),
        (
            &["turns", "--model", "turns", "--turns", "200000000"],
            "200000000 rows",
        ),
    ];
    for (args, count) in cases {
        let assert = snowroll().args(args).timeout(WAIT_LIMIT).assert().failure();
        let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(stderr.contains(count), "{args:?}: {stderr}");
        assert!(stderr.contains("--max-rows"), "{stderr}");
        assert!(assert.get_output().stdout.is_empty());
    }
}

/// The trajectory of `simulate` in the library, for comparison.
fn library_run(kind: ModelKind, opts: &SimOptions) -> snowroll::Trajectory {
    kind.build().simulate(&Scenario::default(), opts).unwrap()
}

#[test]
fn streamed_csv_and_json_give_back_the_numbers_of_simulate_to_the_bit() {
    for (kind, extra) in [
        (ModelKind::TorqueCm, vec!["--t-end", "5"]),
        (ModelKind::Loney, vec!["--t-end", "5"]),
        (
            ModelKind::TurnsExact,
            vec!["--turns", "3", "--t-end", "100"],
        ),
    ] {
        let opts = SimOptions {
            t_end: extra[extra.len() - 1].parse().unwrap(),
            turns: (!kind.is_circular()).then_some(3),
            sampling: Sampling::Steps,
            ..SimOptions::default()
        };
        let traj = library_run(kind, &opts);
        let want: Vec<[f64; 6]> = traj
            .samples
            .iter()
            .map(|s| [s.t_s, s.x_m, s.v_m_s, s.a_m_s2, s.r_m, s.mass_kg])
            .collect();
        let base = ["simulate", "--model", kind.id()];

        let csv = snowroll().args(base).args(&extra).assert().success();
        let text = String::from_utf8(csv.get_output().stdout.clone()).unwrap();
        let got: Vec<[f64; 6]> = text
            .lines()
            .filter(|l| !l.starts_with('#'))
            .skip(1)
            .map(|l| {
                let v: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
                [v[0], v[1], v[2], v[3], v[4], v[5]]
            })
            .collect();
        // Rust prints the shortest decimal that parses back to the same
        // f64, so equality of bits is the test.
        assert_eq!(bits(&got), bits(&want), "{kind} csv");

        let json = snowroll()
            .args(base)
            .args(&extra)
            .args(["--format", "json"])
            .assert()
            .success();
        let doc: Value = serde_json::from_slice(&json.get_output().stdout).unwrap();
        let got: Vec<[f64; 6]> = doc["samples"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| {
                ["t_s", "x_m", "v_m_s", "a_m_s2", "r_m", "mass_kg"].map(|k| s[k].as_f64().unwrap())
            })
            .collect();
        assert_eq!(bits(&got), bits(&want), "{kind} json");
        assert_eq!(
            doc["stop"]["t_s"].as_f64().unwrap().to_bits(),
            traj.stop.t_s.to_bits()
        );
        // The stop comes after the samples in the document (the key `"stop":`,
        // not the value `"stop"` of params.on_hop).
        let raw = String::from_utf8(json.get_output().stdout.clone()).unwrap();
        assert!(raw.find("\"stop\":").unwrap() > raw.find("\"samples\":").unwrap());
    }
}

fn bits(rows: &[[f64; 6]]) -> Vec<[u64; 6]> {
    rows.iter().map(|r| r.map(f64::to_bits)).collect()
}

#[test]
fn streamed_turn_table_gives_back_the_rows_and_summary_of_the_library() {
    let s = Scenario::default();
    let opts = SimOptions {
        turns: Some(25),
        t_end: 1e9,
        ..SimOptions::default()
    };
    let table = snowroll::run_turns(ModelKind::Turns, &s, &opts).unwrap();
    let out = snowroll()
        .args([
            "turns", "--model", "turns", "--turns", "25", "--format", "json",
        ])
        .assert()
        .success();
    let doc: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
    let rows: Vec<snowroll::TurnRow> = serde_json::from_value(doc["turns"].clone()).unwrap();
    assert_eq!(rows, table.rows);
    let summary: snowroll::TurnSummary = serde_json::from_value(doc["summary"].clone()).unwrap();
    assert_eq!(summary, table.summary);
}

#[test]
fn regression_7_paper_memory_does_not_grow_with_the_long_run_turns() {
    let dir = tempfile::tempdir().unwrap();
    let peak = |turns: &str| {
        let out = dir.path().join(format!("report-{turns}"));
        let (peak, ok) = run_measuring_rss(&[
            "paper",
            "--quiet",
            "--turns",
            turns,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(ok);
        peak
    };
    let (small, large) = (peak("20000"), peak("200000"));
    // Held whole, the 180 000 more rows of 96 bytes of each of the two long
    // runs would add 35 MB; kept as digests (10^4 first rows, the last, the
    // summary and 200 ledger points), nothing grows: 8 MB is 4 times short
    // of the old growth and far above noise.
    assert!(
        large < small + 8 * MB,
        "2e4 turns: {} kB, 2e5 turns: {} kB",
        small / 1024,
        large / 1024
    );
}

#[test]
fn the_limits_are_recorded_and_an_output_read_back_as_config_keeps_them() {
    let dir = tempfile::tempdir().unwrap();
    for format in ["csv", "json"] {
        let first = dir.path().join(format!("first.{format}"));
        snowroll()
            .args(["simulate", "--model", "turns", "--t-end", "1e9"])
            .args([
                "--max-rows",
                "40",
                "--max-steps",
                "5000",
                "--format",
                format,
                "-o",
            ])
            .arg(&first)
            .assert()
            .success();
        let again = snowroll()
            .args(["simulate", "--config"])
            .arg(&first)
            .args(["-o", "-"])
            .assert()
            .success();
        // The same limits give the same rows and the same row-limit stop.
        assert_eq!(
            again.get_output().stdout,
            fs::read(&first).unwrap(),
            "{format}"
        );
    }
}
