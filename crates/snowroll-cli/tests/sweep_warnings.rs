//! Issue 20, item 8: a sweep's rows are judged like single runs. Each row
//! carries, in its `warnings` column, the codes of the warnings `simulate`
//! prints for its point; the header counts the rows that have any, and so
//! does the end-of-run message; `merge` and `--resume` check the column and
//! the count.

use std::fs;
use std::path::Path;

use crate::support::{bin, run_in};

/// Thin-snow limit of every model here (b/r0 at most 0.1, `ModelKind::validity`).
const THIN_SNOW: f64 = 0.1;
/// The accuracy the claims need: looser tolerances warn (`CLAIMS_ACCURACY`).
const CLAIMS_ACCURACY: f64 = 1e-6;

/// 8 points: a circular model and the turn model; b = 0.01 m (b/r0 = 0.1,
/// in range) and 0.5 m (b/r0 = 5); rtol 1e-10 and 0.5.
const SWEEP: [&str; 11] = [
    "sweep",
    "--model",
    "eq4,turns",
    "--snow-depth",
    "0.01,0.5",
    "--rtol",
    "1e-10,0.5",
    "--t-end",
    "5",
    "--quiet",
    "--method=auto",
];

fn ok_in(dir: &Path, args: &[&str]) -> String {
    let out = run_in(dir, args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.success(), "{args:?}: {err}");
    err
}

fn fails_in(dir: &Path, args: &[&str]) -> String {
    let out = run_in(dir, args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(1), "{args:?}: {err}");
    err
}

fn sweep_to(dir: &Path, out: &str, extra: &[&str]) -> String {
    let mut args = SWEEP.to_vec();
    args.extend(extra);
    args.extend(["-o", out]);
    ok_in(dir, &args)
}

/// The rows of a sweep file as (header of column names, cells per row).
fn rows(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let names = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (names, rows)
}

/// What `simulate` warns about for a point, as codes: each `warning:` line
/// of its stderr, recognised by the words of its message.
fn simulate_warnings(model: &str, b: &str, rtol: &str) -> Vec<&'static str> {
    let out = std::process::Command::new(bin())
        .args([
            "simulate",
            "--model",
            model,
            "--snow-depth",
            b,
            "--rtol",
            rtol,
        ])
        .args(["--t-end", "5", "-o", "/dev/null"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    err.lines()
        .filter_map(|l| l.strip_prefix("warning: "))
        .map(|w| {
            if w.contains("is used beyond its range: b/r0") {
                "b-over-r0"
            } else if w.starts_with("tolerances looser than") {
                "loose-tolerance"
            } else {
                panic!("a warning this test does not know: {w}")
            }
        })
        .collect()
}

#[test]
fn regression_20_sweep_rows_carry_the_warnings_simulate_gives() {
    let dir = tempfile::tempdir().unwrap();
    let stderr = sweep_to(dir.path(), "s.csv", &[]);
    let text = fs::read_to_string(dir.path().join("s.csv")).unwrap();
    let (names, rows) = rows(&text);
    let col = |name: &str| names.iter().position(|n| n == name).unwrap();
    assert_eq!(names.last().map(String::as_str), Some("warnings"));
    let mut warned = 0;
    for row in &rows {
        let (b, r0): (f64, f64) = (
            row[col("snow_depth")].parse().unwrap(),
            row[col("r0")].parse().unwrap(),
        );
        let rtol: f64 = row[col("rtol")].parse().unwrap();
        // Independently of the program: b/r0 = 5 is past the thin-snow
        // limit, rtol = 0.5 looser than the claims' accuracy.
        let mut want = Vec::new();
        if b / r0 > THIN_SNOW * (1.0 + 1e-12) {
            want.push("b-over-r0");
        }
        if rtol > CLAIMS_ACCURACY {
            want.push("loose-tolerance");
        }
        let cell = &row[col("warnings")];
        let have: Vec<&str> = cell.split(';').filter(|c| !c.is_empty()).collect();
        assert_eq!(have, want, "{row:?}");
        // The same as simulate's, for the same point.
        let model = row[col("model")].as_str();
        assert_eq!(
            have,
            simulate_warnings(model, &row[col("snow_depth")], &row[col("rtol")]),
            "{row:?}"
        );
        warned += usize::from(!have.is_empty());
    }
    // Of the 8 points, only b = 0.01 m with rtol = 1e-10 (one per model) is clean.
    assert_eq!((rows.len(), warned), (8, 6));
    assert!(text.contains("\n# warnings: 6 rows\n"), "{text}");
    assert!(
        stderr.contains("warning: 6 of the 8 rows have warnings"),
        "{stderr}"
    );
    // The turn model's bogus stall at rtol = 0.5 is flagged: the same
    // scenario at rtol = 1e-10 rolls to the end time.
    let stalled = rows
        .iter()
        .find(|r| {
            r[col("model")] == "turns" && r[col("snow_depth")] == "0.01" && r[col("rtol")] == "0.5"
        })
        .unwrap();
    assert_eq!(
        (
            stalled[col("stop")].as_str(),
            stalled[col("warnings")].as_str()
        ),
        ("stalled", "loose-tolerance")
    );
    // A sweep without warnings says nothing on stderr and counts 0.
    let clean = ok_in(
        dir.path(),
        &[
            "sweep",
            "--model",
            "eq4",
            "--alpha-deg",
            "20,30",
            "-o",
            "c.csv",
        ],
    );
    assert_eq!(clean, "");
    let text = fs::read_to_string(dir.path().join("c.csv")).unwrap();
    assert!(
        text.contains("\n# warnings: 0 rows\n") && text.ends_with(",\n"),
        "{text}"
    );
}

#[test]
fn regression_20_merge_and_resume_check_the_warnings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    sweep_to(d, "full.csv", &[]);
    let full = fs::read_to_string(d.join("full.csv")).unwrap();
    for i in 0..3 {
        sweep_to(d, &format!("s{i}.csv"), &["--shard", &format!("{i}/3")]);
    }
    ok_in(d, &["merge", "s2.csv", "s0.csv", "s1.csv", "-o", "m.csv"]);
    let merged = fs::read_to_string(d.join("m.csv")).unwrap();
    // Byte for byte the one-process sweep but for the command line.
    let without_command = |t: &str| -> Vec<String> {
        t.lines()
            .filter(|l| !l.starts_with("# command:"))
            .map(String::from)
            .collect()
    };
    assert_eq!(without_command(&merged), without_command(&full));
    // The shards' counts add up to the whole sweep's.
    let count = |t: &str| -> u64 {
        let line = t
            .lines()
            .find_map(|l| l.strip_prefix("# warnings: "))
            .unwrap();
        line.strip_suffix(" rows").unwrap().parse().unwrap()
    };
    let shards: Vec<String> = (0..3)
        .map(|i| fs::read_to_string(d.join(format!("s{i}.csv"))).unwrap())
        .collect();
    assert_eq!(shards.iter().map(|s| count(s)).sum::<u64>(), 6);

    // A shard whose header count is not that of its rows.
    let s0 = &shards[0];
    let n0 = count(s0);
    let edited = s0.replace(
        &format!("# warnings: {n0} rows"),
        &format!("# warnings: {} rows", n0 + 1),
    );
    fs::write(d.join("bad.csv"), edited).unwrap();
    let e = fails_in(d, &["merge", "bad.csv", "s1.csv", "s2.csv", "-o", "m2.csv"]);
    assert!(
        e.contains("bad.csv: its header says") && e.contains("its rows have"),
        "{e}"
    );
    // A row whose warnings cell is not its point's.
    let s1 = &shards[1];
    let edited = s1.replacen(",b-over-r0;loose-tolerance\n", ",b-over-r0\n", 1);
    assert_ne!(&edited, s1);
    fs::write(d.join("bad.csv"), edited).unwrap();
    let e = fails_in(d, &["merge", "s0.csv", "bad.csv", "s2.csv", "-o", "m2.csv"]);
    assert!(e.contains("has warnings = b-over-r0 where point"), "{e}");
    assert!(!d.join("m2.csv").exists());
    // A file of an older snowroll (no warnings line, no column).
    let old: String = s0
        .lines()
        .filter(|l| !l.starts_with("# warnings:"))
        .map(|l| {
            if l.starts_with('#') {
                l.to_string()
            } else {
                l.rsplit_once(',').unwrap().0.to_string()
            }
        })
        .map(|l| l + "\n")
        .collect();
    fs::write(d.join("old.csv"), old).unwrap();
    let e = fails_in(d, &["merge", "old.csv", "s1.csv", "s2.csv"]);
    assert!(e.contains("old.csv: has no column warnings"), "{e}");

    // Resume: a partial file of the header and three rows finishes as the
    // whole sweep; one whose count was edited is refused and kept.
    let header_lines = full.lines().take_while(|l| l.starts_with('#')).count() + 1;
    let partial: String = full
        .lines()
        .take(header_lines + 3)
        .map(|l| format!("{l}\n"))
        .collect();
    fs::write(d.join("r.csv.partial"), &partial).unwrap();
    sweep_to(d, "r.csv", &["--resume"]);
    let resumed = fs::read_to_string(d.join("r.csv")).unwrap();
    assert_eq!(without_command(&resumed), without_command(&full));
    let edited = partial.replace("# warnings: 6 rows", "# warnings: 5 rows");
    fs::write(d.join("r.csv.partial"), &edited).unwrap();
    let mut args = SWEEP.to_vec();
    args.extend(["--resume", "-o", "r.csv"]);
    let e = fails_in(d, &args);
    assert!(
        e.contains("warnings: 5 rows in r.csv.partial, 6 rows in this sweep"),
        "{e}"
    );
    assert_eq!(fs::read_to_string(d.join("r.csv.partial")).unwrap(), edited);
}
