//! Issue 20, items 2, 4 and 7: `sweep --resume` and `merge` decide
//! sameness from the parsed grid and settings, check every row read back
//! against the schema and the grid, never destroy rows they did not write,
//! and a sweep's partial file fits any output name and does not outlive a
//! write error.
//!
//! A partial file is made without killing anything: the finished file of a
//! sweep is its partial file copied, so its header and first rows are what
//! a sweep killed after those rows leaves.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{bin, fails_in, ok_in};

/// 48 points: two models, four angles, three speeds, two depths.
const GRID: [&str; 11] = [
    "sweep",
    "--model",
    "eq4,energy",
    "--alpha-deg",
    "10:40:4",
    "--v0",
    "0,1,2",
    "--snow-depth",
    "0.01,0.02",
    "--t-end",
    "20",
];

fn with(base: &[&str], extra: &[&str]) -> Vec<String> {
    base.iter().chain(extra).map(|s| s.to_string()).collect()
}

fn argv(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// The header lines (with newlines) and the row lines of a sweep file.
fn split(text: &str) -> (String, Vec<String>) {
    let mut header = String::new();
    let mut rows = Vec::new();
    let mut in_header = true;
    for line in text.split_inclusive('\n') {
        if in_header {
            header.push_str(line);
            in_header = line.starts_with('#');
        } else {
            rows.push(line.to_string());
        }
    }
    (header, rows)
}

/// A finished sweep of [`GRID`] in `dir/full.csv`, and its text.
fn full_sweep(dir: &Path) -> String {
    ok_in(dir, &argv(&with(&GRID, &["-q", "-o", "full.csv"])));
    fs::read_to_string(dir.join("full.csv")).unwrap()
}

/// The partial file a sweep of [`GRID`] to `out.csv` killed after `rows`
/// rows leaves (its command line is the one for `-o out.csv`).
fn partial_after(dir: &Path, rows: usize) -> (PathBuf, String) {
    let full = full_sweep(dir);
    let (header, all) = split(&full);
    let header = header.replace("--output full.csv", "--output out.csv");
    let text = format!("{header}{}", all[..rows].concat());
    let path = dir.join("out.csv.partial");
    fs::write(&path, &text).unwrap();
    (path, text)
}

/// The example: a partial of `--t-end 20` resumed with
/// `--t-end 200` was silently discarded. Now refused, naming the setting
/// with both values, and the partial file keeps every byte.
#[test]
fn regression_20_resume_refuses_another_sweep_and_keeps_its_rows() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (partial, before) = partial_after(d, 20);
    let mut other = with(&GRID, &["-q", "-o", "out.csv", "--resume"]);
    other[10] = "200".to_string();
    let e = fails_in(d, &argv(&other));
    assert!(
        e.contains("t_end: 20 in") && e.contains("200 in this sweep"),
        "{e}"
    );
    // Two settings differ: both are named.
    let mut two = other.clone();
    two[2] = "eq4".to_string();
    let e = fails_in(d, &argv(&two));
    assert!(
        e.contains("model: torque-cm,energy in") && e.contains("t_end:"),
        "{e}"
    );
    let e = fails_in(
        d,
        &argv(&with(
            &GRID,
            &["-q", "-o", "out.csv", "--resume", "--method", "ode"],
        )),
    );
    assert!(
        e.contains("method: auto in") && e.contains("ode in this sweep"),
        "{e}"
    );
    assert_eq!(fs::read_to_string(&partial).unwrap(), before);
    assert!(!d.join("out.csv").exists());
}

/// The same sweep spelt differently (`./out.csv`, an absolute path,
/// `--t-end 20.0`, `--v0 0,1,2.0`) resumes: it continues the partial file
/// (whose header, with the first run's command line, it keeps) instead of
/// starting again, and the rows are the uninterrupted run's.
#[test]
fn regression_20_the_same_sweep_spelt_differently_resumes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let absolute = d.join("out.csv").display().to_string();
    for spelling in [
        with(&GRID, &["-o", "./out.csv"]),
        with(&GRID, &["-o", &absolute]),
        {
            let mut v = with(&GRID, &["-o", "out.csv"]);
            v[10] = "20.0".to_string();
            v[6] = "0,1,2.0".to_string();
            v
        },
    ] {
        let (partial, before) = partial_after(d, 17);
        let mut args = spelling.clone();
        args.extend(["--resume".to_string(), "-q".to_string()]);
        ok_in(d, &argv(&args));
        assert!(!partial.exists());
        let got = fs::read_to_string(d.join("out.csv")).unwrap();
        let (header, rows) = split(&got);
        let (first_header, _) = split(&before);
        assert_eq!(header, first_header, "{spelling:?} started again");
        let (_, whole) = split(&fs::read_to_string(d.join("full.csv")).unwrap());
        assert_eq!(rows, whole);
        fs::remove_file(d.join("out.csv")).unwrap();
    }
}

/// Rows already in a partial file are checked before anything is
/// appended: a gap, a repeat, a garbage row, a NaN, a row of another point
/// are refused with the line number, the file unchanged; a torn last line
/// is dropped and computed again.
#[test]
fn regression_20_resume_checks_the_rows_already_there() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = with(&GRID, &["-q", "-o", "out.csv", "--resume"]);
    let (partial, good) = partial_after(d, 12);
    let (header, rows) = split(&good);
    let header_lines = header.lines().count();
    // Line numbers of the file: row k is on line header_lines + 1 + k.
    let line = |k: usize| format!("line {}", header_lines + 1 + k);
    let cases: Vec<(String, String, &str)> = vec![
        (
            [&rows[..5], &rows[6..]].concat().concat(),
            line(5),
            "leaves a gap",
        ),
        (
            // A torn last line is not cut when an earlier row is refused.
            [&rows[..5], &rows[6..]].concat().concat() + &rows[0][..9],
            line(5),
            "leaves a gap",
        ),
        (
            [&rows[..6], &rows[5..]].concat().concat(),
            line(6),
            "repeats an earlier row",
        ),
        (
            [&rows[..7], &["7,GARBAGE\n".to_string()], &rows[8..]]
                .concat()
                .concat(),
            line(7),
            "cells where a row has",
        ),
        (
            {
                let mut r = rows.clone();
                let cells: Vec<&str> = r[3].split(',').collect();
                let mut cells: Vec<String> = cells.iter().map(|s| s.to_string()).collect();
                cells[column("t_s")] = "NaN".to_string();
                r[3] = cells.join(",");
                r.concat()
            },
            line(3),
            "t_s: NaN is not a finite number",
        ),
        (
            {
                let mut r = rows.clone();
                r[4] = r[4].replacen(",torque-cm,", ",energy,", 1);
                r.concat()
            },
            line(4),
            "model = energy where point 4 of the grid has torque-cm",
        ),
        (
            {
                let mut r = rows.clone();
                r[2] = r[2].replacen(",20.0,", ",21.0,", 1);
                r.concat()
            },
            line(2),
            "t_end = 21 where point 2 of the grid has 20",
        ),
    ];
    for (body, at, why) in cases {
        let text = format!("{header}{body}");
        fs::write(&partial, &text).unwrap();
        let e = fails_in(d, &argv(&args));
        assert!(e.contains(&at) && e.contains(why), "{at} {why}: {e}");
        assert_eq!(fs::read_to_string(&partial).unwrap(), text);
        assert!(!d.join("out.csv").exists());
    }
    // A torn last line: dropped, computed again, the rows the whole run's.
    let torn = format!("{header}{}{}", rows.concat(), &rows[0][..9]);
    fs::write(&partial, torn).unwrap();
    ok_in(d, &argv(&args));
    let (_, got) = split(&fs::read_to_string(d.join("out.csv")).unwrap());
    let (_, whole) = split(&fs::read_to_string(d.join("full.csv")).unwrap());
    assert_eq!(got, whole);
}

/// A file at `NAME.partial` that is no sweep's partial file (or has lost
/// its header) is refused with `--resume`, never truncated.
#[test]
fn regression_20_resume_never_truncates_a_file_it_cannot_read() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let partial = d.join("out.csv.partial");
    let args = with(&GRID, &["-q", "-o", "out.csv", "--resume"]);
    for text in [
        "precious notes\n",
        "# snowroll sweep, version 0\n# command: x\n",
    ] {
        fs::write(&partial, text).unwrap();
        let e = fails_in(d, &argv(&args));
        assert!(e.contains("cannot resume from"), "{e}");
        assert_eq!(fs::read_to_string(&partial).unwrap(), text);
    }
}

/// Shards of [`GRID`] (`--shard i/2`, with `extra` flags) in `dir`.
fn shards(dir: &Path, extra: [&[&str]; 2]) -> [PathBuf; 2] {
    [0, 1].map(|i| {
        let name = format!("s{i}.csv");
        let shard = format!("{i}/2");
        let mut args = with(&GRID, &["-q", "--shard", &shard, "-o", &name]);
        args.extend(extra[i].iter().map(|s| s.to_string()));
        ok_in(dir, &argv(&args));
        dir.join(name)
    })
}

/// The examples for `merge`: a row `N,GARBAGE`, a NaN cell, a
/// swapped model, a renamed column, a hand-edited shard of 10 of the 48
/// points, `--method ode` and `auto` shards: each refused with what is
/// wrong and where, no output written, the shards unchanged.
#[test]
fn regression_20_merge_refuses_garbage_shards() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let [s0, _] = shards(d, [&[], &[]]);
    let good0 = fs::read_to_string(&s0).unwrap();
    let (header, rows) = split(&good0);
    let header_lines = header.lines().count();
    let line = |k: usize| format!("line {}", header_lines + 1 + k);
    let merge = ["merge", "s0.csv", "s1.csv", "-o", "m.csv"];
    ok_in(d, &merge);
    let (_, merged) = split(&fs::read_to_string(d.join("m.csv")).unwrap());
    let (_, whole) = split(&full_sweep(d));
    assert_eq!(merged, whole);
    fs::remove_file(d.join("m.csv")).unwrap();

    let edit = |k: usize, f: &dyn Fn(&str) -> String| {
        let mut r = rows.clone();
        r[k] = f(&r[k]);
        format!("{header}{}", r.concat())
    };
    let cases: Vec<(String, String)> = vec![
        (
            edit(3, &|_| "3,GARBAGE\n".into()),
            format!(
                "{}: 2 cells where a row has {}",
                line(3),
                snowroll::sweep::SweepRow::COLUMNS.len()
            ),
        ),
        (
            edit(5, &|r| {
                let mut c: Vec<&str> = r.split(',').collect();
                c[column("x_m")] = "NaN";
                c.join(",")
            }),
            format!("{}: column x_m: NaN is not a finite number", line(5)),
        ),
        (
            edit(6, &|r| r.replacen(",torque-cm,", ",energy,", 1)),
            "model = energy where point 6 of the grid has torque-cm".into(),
        ),
        (
            // An error message on a row that has results: no run gives one.
            // Text in the error cell, the last but one (the warnings last).
            edit(7, &|r| {
                let (head, warnings) = r.trim_end().rsplit_once(',').unwrap();
                format!("{head}oops,{warnings}\n")
            }),
            format!("{}: an error cell with results", line(7)),
        ),
        (
            header.replace(",alpha_deg,", ",alpha,") + &rows.concat(),
            "column 3 is \"alpha\" where a sweep has \"alpha_deg\"".into(),
        ),
    ];
    for (text, want) in cases {
        fs::write(&s0, &text).unwrap();
        let e = fails_in(d, &merge);
        assert!(e.contains(&want), "{want}: {e}");
        assert_eq!(fs::read_to_string(&s0).unwrap(), text);
        assert!(!d.join("m.csv").exists());
    }
    fs::write(&s0, &good0).unwrap();

    // A shard edited by hand into a whole sweep of 10 of the 48 points.
    let ten = header.replace("# shard: 0/2, rows 0..24", "# shard: 0/1, rows 0..48")
        + &rows[..10].concat();
    fs::write(d.join("ten.csv"), &ten).unwrap();
    let e = fails_in(d, &["merge", "ten.csv", "-o", "m.csv"]);
    assert!(e.contains("rows 10..48 are missing"), "{e}");
    let ten = header.replace("# shard: 0/2, rows 0..24", "# shard: 0/1, rows 0..10")
        + &rows[..10].concat();
    fs::write(d.join("ten.csv"), &ten).unwrap();
    let e = fails_in(d, &["merge", "ten.csv", "-o", "m.csv"]);
    assert!(e.contains("shard 0/1 of 48 points is rows 0..48"), "{e}");
    let e = fails_in(d, &["merge", "s1.csv", "-o", "m.csv"]);
    assert!(e.contains("missing shards: 0/2 (rows 0..24)"), "{e}");

    // Shards of the same grid by two methods, or two end times.
    shards(d, [&["--method", "ode"], &[]]);
    let e = fails_in(d, &merge);
    assert!(
        e.contains("not shards of the same sweep: method: ode in s0.csv, auto in s1.csv"),
        "{e}"
    );
    let mut later = with(&GRID, &["-q", "--shard", "1/2", "-o", "s1.csv"]);
    later[10] = "30".to_string();
    shards(d, [&[], &[]]);
    ok_in(d, &argv(&later));
    let e = fails_in(d, &merge);
    assert!(e.contains("t_end: 20 in s0.csv, 30 in s1.csv"), "{e}");
    assert!(!d.join("m.csv").exists());
}

/// A 250-character output name works for `sweep` as for `simulate`: the
/// partial file's name is cut to fit NAME_MAX, and `--resume` finds it.
#[test]
fn regression_20_a_long_output_name_sweeps_and_resumes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let name = format!("{}.csv", "n".repeat(246));
    assert_eq!(name.len(), 250);
    ok_in(d, &argv(&with(&GRID, &["-q", "-o", &name])));
    let full = fs::read_to_string(d.join(&name)).unwrap();
    assert_eq!(fs::read_dir(d).unwrap().count(), 1);
    // A partial file of the first rows under the name the sweep uses: the
    // only file whose name ends in `.partial` once a sweep has started.
    let (header, rows) = split(&full);
    let mut killed = Command::new(bin())
        .current_dir(d)
        .args([
            "sweep",
            "--model",
            "turns",
            "--alpha-deg",
            "20:40:100000",
            "--t-end",
            "2",
            "-q",
            "-o",
            &name,
        ])
        .spawn()
        .unwrap();
    let partial = loop {
        let found = fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().path())
            .find(|p| p.to_string_lossy().ends_with(".partial"));
        if let Some(p) = found {
            break p;
        }
        assert!(
            killed.try_wait().unwrap().is_none(),
            "the sweep ended first"
        );
        std::thread::sleep(std::time::Duration::from_millis(2));
    };
    killed.kill().unwrap();
    killed.wait().unwrap();
    assert!(partial.file_name().unwrap().len() <= 255);
    fs::write(&partial, format!("{header}{}", rows[..9].concat())).unwrap();
    fs::remove_file(d.join(&name)).unwrap();
    ok_in(d, &argv(&with(&GRID, &["-q", "-o", &name, "--resume"])));
    assert!(!partial.exists());
    assert_eq!(fs::read_to_string(d.join(&name)).unwrap(), full);
}

/// Runs `snowroll ARGS` in `dir` with files limited to `blocks` of 512
/// bytes and SIGXFSZ ignored, so a write past the limit fails with EFBIG
/// as a full disk fails with ENOSPC.
fn with_file_limit(dir: &Path, blocks: u32, args: &[String]) -> Output {
    let mut script = format!(
        "trap '' XFSZ; ulimit -f {blocks}; exec '{}'",
        bin().display()
    );
    for a in args {
        script.push_str(&format!(" '{a}'"));
    }
    Command::new("sh")
        .current_dir(dir)
        .args(["-c", &script])
        .output()
        .unwrap()
}

/// On a write error (a file size limit standing in for a full disk) the
/// sweep reports the error and removes the partial file it created; a
/// partial file of an earlier run that it was resuming is kept.
#[test]
fn regression_20_a_write_error_removes_the_partial_file_the_run_made() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let big = with(&GRID, &["-q", "--alpha-deg", "10:40:400", "-o", "out.csv"]);
    let out = with_file_limit(d, 8, &big);
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{e}");
    assert!(
        e.contains("error: writing") && e.contains("too large"),
        "{e}"
    );
    let left: Vec<_> = fs::read_dir(d).unwrap().collect();
    assert!(left.is_empty(), "{left:?}");

    // Resuming: the earlier run's partial file (its header, no row yet)
    // stays for another try.
    ok_in(d, &argv(&with(&GRID, &["-q", "-o", "full.csv"])));
    let (header, _) = split(&fs::read_to_string(d.join("full.csv")).unwrap());
    let text = header
        .replace("# alpha_deg: 10:40:4\n", "# alpha_deg: 10:40:400\n")
        .replace("# points: 48", "# points: 4800")
        .replace("rows 0..48", "rows 0..4800");
    // The rows with warnings: 100 times as many in a grid 100 times as fine
    // in alpha alone (the warnings of these points do not depend on alpha).
    let warned: u64 = header
        .lines()
        .find_map(|l| l.strip_prefix("# warnings: ")?.strip_suffix(" rows"))
        .unwrap()
        .parse()
        .unwrap();
    let text = text.replace(
        &format!("# warnings: {warned} rows"),
        &format!("# warnings: {} rows", 100 * warned),
    );
    let partial = d.join("out.csv.partial");
    fs::write(&partial, &text).unwrap();
    let mut resume = big.clone();
    resume.push("--resume".to_string());
    let out = with_file_limit(d, 8, &resume);
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{e}");
    assert!(e.contains("too large"), "{e}");
    assert!(fs::read_to_string(&partial).unwrap().starts_with(&text));
    assert!(!d.join("out.csv").exists());
}

/// The place of the sweep column `name` in a row (the columns follow the
/// parameter table, so a new axis moves the results).
fn column(name: &str) -> usize {
    snowroll::sweep::SweepRow::COLUMNS
        .iter()
        .position(|c| *c == name)
        .unwrap()
}
