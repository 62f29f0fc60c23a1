//! Determinism (issue 7): the same command gives the same bytes, run after
//! run and whatever the thread count (RAYON_NUM_THREADS 1 and 2; a long
//! turn table, whose turns are prepared ahead on the other threads in
//! blocks, also with 3).

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use assert_cmd::cargo::cargo_bin_cmd;
use serde_json::Value;

/// Thread counts each command is run with.
const THREADS: [&str; 2] = ["1", "2"];

/// stdout of `snowroll ARGS` with `threads` worker threads.
fn run(args: &[&str], threads: &str) -> Vec<u8> {
    let out = cargo_bin_cmd!("snowroll")
        .args(args)
        .env("RAYON_NUM_THREADS", threads)
        .assert()
        .success();
    out.get_output().stdout.clone()
}

/// Every model id, from `snowroll models`.
fn model_ids() -> Vec<String> {
    let listing: Value =
        serde_json::from_slice(&run(&["models", "--format", "json"], "1")).unwrap();
    listing["models"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["id"].as_str().unwrap().to_string())
        .collect()
}

/// The same bytes from each of two runs with each thread count.
fn assert_deterministic(args: &[&str]) {
    let first = run(args, THREADS[0]);
    assert!(!first.is_empty(), "{args:?}");
    for threads in THREADS {
        for _ in 0..2 {
            assert!(
                run(args, threads) == first,
                "{args:?} differs with {threads} threads"
            );
        }
    }
}

#[test]
fn simulate_and_turns_give_the_same_bytes_every_run() {
    for id in model_ids() {
        let turn_model = id.starts_with("turns");
        let mut args = vec!["simulate", "--model", id.as_str(), "--t-end", "20"];
        if turn_model {
            args.extend(["--turns", "20"]);
        }
        assert_deterministic(&args);
        args.extend(["--format", "json", "--dt", "0.5"]);
        assert_deterministic(&args);
    }
    assert_deterministic(&["turns", "--model", "turns", "--turns", "500"]);
    // Past the first blocks of turns prepared ahead (8192 turns each), with
    // as many threads as blocks in the pipeline: which thread prepares which
    // run of turns must not show in the bytes.
    let long = ["turns", "--model", "turns", "--turns", "30000"];
    let first = run(&long, "1");
    for threads in ["2", "3", "4"] {
        assert!(
            run(&long, threads) == first,
            "30000 turns differ with {threads} threads"
        );
    }
    assert_deterministic(&[
        "turns",
        "--model",
        "turns-exact",
        "--turns",
        "200",
        "--format",
        "json",
    ]);
}

/// Every file under `dir`, by path relative to it.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in fs::read_dir(&d).unwrap() {
            let path = e.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                out.insert(
                    path.strip_prefix(dir).unwrap().to_path_buf(),
                    fs::read(&path).unwrap(),
                );
            }
        }
    }
    out
}

#[test]
fn paper_writes_the_same_report_every_run() {
    let dir = tempfile::tempdir().unwrap();
    let mut reports = Vec::new();
    for (i, threads) in THREADS.iter().enumerate() {
        let out = dir.path().join(format!("report-{i}"));
        let stdout = run(
            &[
                "paper",
                "--quiet",
                "--turns",
                "10",
                "--out",
                out.to_str().unwrap(),
            ],
            threads,
        );
        // The last line names the directory, which differs by design.
        let table: Vec<u8> = stdout
            .split(|&b| b == b'\n')
            .take_while(|l| !l.starts_with(b"Report:"))
            .flatten()
            .copied()
            .collect();
        reports.push((table, files(&out)));
    }
    let (first_table, first_files) = &reports[0];
    assert!(first_files.contains_key(Path::new("report.html")));
    for (table, files) in &reports[1..] {
        assert!(table == first_table, "the claims table differs");
        assert_eq!(
            files.keys().collect::<Vec<_>>(),
            first_files.keys().collect::<Vec<_>>()
        );
        for (name, bytes) in files {
            assert!(bytes == &first_files[name], "{} differs", name.display());
        }
    }
}
