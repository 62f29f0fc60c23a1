//! Issue 24: `snowroll merge` writes the file the whole sweep run in one
//! process writes to the same path, byte for byte, its `# command:` line
//! included (that process's command line), whatever the split and the
//! threads each shard ran with; shards of another sweep, or a shard whose
//! command line is not a sweep's, are refused.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{bin, fails_in, run_in};

/// 48 points: two models, four angles, three speeds, two depths; the
/// flags in an order other than the one a sweep records them in.
const GRID: [&str; 11] = [
    "sweep",
    "--t-end",
    "20",
    "--snow-depth",
    "0.01,0.02",
    "--model",
    "eq4,energy",
    "--v0",
    "0,1,2",
    "--alpha-deg",
    "10:40:4",
];

/// An output name a shell must quote (a space and a quote).
const NAME: &str = "it's a map.csv";

/// `snowroll ARGS` run in `dir` with `threads` threads; must succeed.
fn ok_with(dir: &Path, args: &[String], threads: usize) {
    let out: Output = Command::new(bin())
        .current_dir(dir)
        .args(args)
        .env("RAYON_NUM_THREADS", threads.to_string())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// [`GRID`] followed by `extra`.
fn grid(extra: &[&str]) -> Vec<String> {
    GRID.iter().chain(extra).map(|s| s.to_string()).collect()
}

/// A new directory `name` under `root`.
fn subdir(root: &Path, name: &str) -> PathBuf {
    let dir = root.join(name);
    fs::create_dir(&dir).unwrap();
    dir
}

/// Shards `part I.csv` of [`GRID`] (with `extra`) in 3 in `dir`, shard I
/// run with I + 1 threads.
fn three_shards(dir: &Path, extra: &[&str]) {
    for i in 0..3 {
        let (shard, out) = (format!("{i}/3"), format!("part {i}.csv"));
        let args = grid(&[extra, &["-q", "--shard", &shard, "-o", &out]].concat());
        ok_with(dir, &args, i + 1);
    }
}

/// Runs `line` (a `# command:` line) with `sh -c` in `dir`, its leading
/// `snowroll` replaced by the program under test: a shell splits and
/// unquotes its words, not this program.
fn run_as_shell(dir: &Path, line: &str) {
    let rest = line.strip_prefix("snowroll ").expect(line);
    let program = bin().to_str().unwrap();
    let out = Command::new("sh")
        .current_dir(dir)
        .arg("-c")
        .arg(format!("'{program}' {rest} --quiet"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{line}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Three shards (1, 2 and 3 threads) merged in directory `a` are the bytes
/// of the whole sweep run in one process in directory `b`, to the same
/// path; the merged file's command line, run by a shell in directory `c`,
/// writes them again, so it is that process's command line and not merge's.
#[test]
fn merged_shards_are_the_bytes_of_one_process() {
    let root = tempfile::tempdir().unwrap();
    let [a, b, c] = ["a", "b", "c"].map(|n| subdir(root.path(), n));
    three_shards(&a, &[]);
    let merge = [
        "merge",
        "part 2.csv",
        "part 0.csv",
        "part 1.csv",
        "-o",
        NAME,
    ];
    ok_with(&a, &merge.map(String::from), 1);
    ok_with(&b, &grid(&["-q", "-o", NAME]), 2);
    let merged = fs::read(a.join(NAME)).unwrap();
    let whole = fs::read(b.join(NAME)).unwrap();
    assert!(merged == whole, "merged and one-process files differ");

    let text = String::from_utf8(merged.clone()).unwrap();
    let line = text
        .lines()
        .find_map(|l| l.strip_prefix("# command: "))
        .unwrap();
    assert!(!line.contains("--shard"), "{line}");
    run_as_shell(&c, line);
    assert!(fs::read(c.join(NAME)).unwrap() == merged, "{line}");

    // To stdout the one process has no --output either.
    let out = run_in(&a, &["merge", "part 0.csv", "part 1.csv", "part 2.csv"]);
    assert!(out.status.success());
    let to_stdout = run_in(&b, &GRID.iter().chain(&["-q"]).copied().collect::<Vec<_>>());
    assert!(
        out.stdout == to_stdout.stdout,
        "merge and sweep to stdout differ"
    );
}

/// The wrong inputs: shard 2 of another grid (five angles, not four), and a
/// shard 0 whose command line is not a sweep's: each refused, named, and
/// nothing written.
#[test]
fn merge_refuses_shards_of_another_grid_and_foreign_command_lines() {
    let root = tempfile::tempdir().unwrap();
    let a = subdir(root.path(), "a");
    three_shards(&a, &[]);
    let merge = [
        "merge",
        "part 0.csv",
        "part 1.csv",
        "part 2.csv",
        "-o",
        NAME,
    ];
    let part2 = fs::read(a.join("part 2.csv")).unwrap();
    let mut other = grid(&["-q", "--shard", "2/3", "-o", "part 2.csv"]);
    other[10] = "10:40:5".to_string();
    ok_with(&a, &other, 2);
    let e = fails_in(&a, &merge);
    assert!(e.contains("are not shards of the same sweep"), "{e}");
    assert!(e.contains("alpha_deg"), "{e}");
    assert!(!a.join(NAME).exists());
    fs::write(a.join("part 2.csv"), part2).unwrap();

    let part0 = fs::read_to_string(a.join("part 0.csv")).unwrap();
    let recorded = part0
        .lines()
        .find(|l| l.starts_with("# command: "))
        .unwrap();
    for (line, says) in [
        (
            "# command: snowroll merge x.csv y.csv",
            "is not a `snowroll sweep` command",
        ),
        (
            "# command: snowroll sweep --model eq4 --output 'part 0.csv",
            "cannot be split into words: unterminated '",
        ),
        (
            "# command: snowroll sweep --no-such-flag 3",
            "does not parse",
        ),
    ] {
        fs::write(a.join("part 0.csv"), part0.replace(recorded, line)).unwrap();
        let e = fails_in(&a, &merge);
        assert!(e.contains("part 0.csv: its command line"), "{e}");
        assert!(e.contains(says), "{says}: {e}");
        assert!(!a.join(NAME).exists());
    }
}

/// Parquet (feature `parquet`): CSV shards merged to a `.parquet` path are
/// the bytes (rows and key-value metadata) the whole sweep writes there.
#[cfg(feature = "parquet")]
#[test]
fn shards_merged_to_parquet_are_the_bytes_of_one_process() {
    let root = tempfile::tempdir().unwrap();
    let [a, b] = ["a", "b"].map(|n| subdir(root.path(), n));
    three_shards(&a, &[]);
    let merge = [
        "merge",
        "part 0.csv",
        "part 1.csv",
        "part 2.csv",
        "-o",
        "m.parquet",
    ];
    ok_with(&a, &merge.map(String::from), 1);
    ok_with(&b, &grid(&["-q", "-o", "m.parquet"]), 2);
    let merged = fs::read(a.join("m.parquet")).unwrap();
    assert!(merged.starts_with(b"PAR1"));
    assert!(merged == fs::read(b.join("m.parquet")).unwrap());
}

/// Without the feature, a merge to a `.parquet` path is refused as a sweep
/// to it is, not written as CSV under that name.
#[cfg(not(feature = "parquet"))]
#[test]
fn merge_to_parquet_without_the_feature_is_refused() {
    let root = tempfile::tempdir().unwrap();
    let a = subdir(root.path(), "a");
    three_shards(&a, &[]);
    let e = fails_in(
        &a,
        &[
            "merge",
            "part 0.csv",
            "part 1.csv",
            "part 2.csv",
            "-o",
            "m.parquet",
        ],
    );
    assert!(e.contains("built without Parquet"), "{e}");
    assert!(!a.join("m.parquet").exists());
}
