//! Fuzzing `merge` and `sweep --resume` (issue 20) with damaged files:
//! the shards and the partial file of one small sweep, each case damaged by
//! one to three random edits (truncation, a flipped or inserted byte, a
//! line deleted, repeated, swapped or inserted, a cell or a header value
//! replaced by an adversarial token, a renamed column, a swapped model, a
//! torn tail, a cell spelt otherwise with its value or quoted), and shards
//! given in any order, twice, missing, or with `/dev/zero`, a directory or
//! a missing path among them; the partial file is now and then a symbolic
//! link to a device or a FIFO (issue 33). Every case must
//!
//! - end with status 0 or 1 (one `error:` line), never panic;
//! - on failure, leave no output, and every input byte for byte as it was
//!   (a partial file included: a torn tail is cut only on success);
//! - on success, give all 48 rows, in order, each with the parameters of
//!   the uninterrupted sweep's row (index, model, choices and every
//!   parameter, by value), every number finite, the sweep's header and
//!   every cell of the sweep's value in the sweep's spelling (issue 33),
//!   and an output that `merge` reads back. A result cell may differ from the sweep's (an edit of a
//!   digit there cannot be told from a result without running the point
//!   again); such cases are counted.
//!
//! `FUZZ_SHARD_CASES` (default [`CI_CASES`]) sets the number of cases,
//! `FUZZ_SEED` the seed, `FUZZ_SUMMARY` the summary file (the counts go to
//! that name with `.shards` appended).

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};

/// Cases run by `cargo test`.
const CI_CASES: u64 = 300;
/// The sweep: 3 models × 4 angles × 2 speeds × 2 depths = 48 points, every
/// kind of row (fast path, ODE, turn model) in a few milliseconds.
const GRID: [&str; 12] = [
    "sweep",
    "--model",
    "eq4,energy,turns",
    "--alpha-deg",
    "10:40:4",
    "--v0",
    "0,1",
    "--snow-depth",
    "0.01,0.02",
    "--t-end",
    "2",
    "-q",
];
const POINTS: usize = 48;
const SHARDS: usize = 3;
/// Columns up to and including these are the row's grid point.
const POINT_COLUMNS: usize = 16;
/// Cells a damaged file may get.
const TOKENS: [&str; 24] = [
    "NaN",
    "nan",
    "inf",
    "-inf",
    "1e309",
    "-1e309",
    "1e-400",
    "GARBAGE",
    "",
    "-0",
    "0x10",
    "١٢",
    "\"a,b\"",
    "\"",
    " 5",
    "18446744073709551616",
    "-1",
    "torque-cm",
    "energy",
    "turns",
    "stop",
    "continue",
    "end-time",
    "4.9e-324",
];

/// SplitMix64: a seeded, reproducible stream.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Runs `snowroll ARGS` in-process: its status and stderr.
fn run(args: &[String]) -> (u8, String) {
    let argv: Vec<OsString> = std::iter::once(OsString::from("snowroll"))
        .chain(args.iter().map(OsString::from))
        .collect();
    let (status, captured) = snowroll_cli::console::capture(|| snowroll_cli::run_from(argv));
    (
        status,
        String::from_utf8_lossy(&captured.stderr).into_owned(),
    )
}

fn strings(items: &[&str]) -> Vec<String> {
    items.iter().map(|s| s.to_string()).collect()
}

/// The lines of `text` after its header.
fn rows(text: &str) -> Vec<&str> {
    let mut lines = text.lines().skip_while(|l| l.starts_with('#'));
    lines.next();
    lines.collect()
}

/// One random edit of `bytes`, named for the tally.
fn damage(bytes: &mut Vec<u8>, rng: &mut Rng) -> &'static str {
    let lines = |b: &[u8]| -> Vec<Vec<u8>> {
        b.split_inclusive(|&c| c == b'\n')
            .map(<[u8]>::to_vec)
            .collect()
    };
    let mut ls = lines(bytes);
    let n = ls.len();
    let kind = rng.below(14);
    let name = match kind {
        0 => {
            bytes.truncate(rng.below(bytes.len() + 1));
            return "truncated";
        }
        1 => {
            let i = rng.below(bytes.len());
            if let Some(b) = bytes.get_mut(i) {
                *b = (rng.next() & 0xff) as u8;
            }
            return "byte changed";
        }
        2 => {
            let i = rng.below(bytes.len() + 1);
            bytes.insert(i, (rng.next() & 0xff) as u8);
            return "byte inserted";
        }
        3 if n > 0 => {
            ls.remove(rng.below(n));
            "line deleted"
        }
        4 if n > 0 => {
            let i = rng.below(n);
            let l = ls[i].clone();
            ls.insert(i, l);
            "line repeated"
        }
        5 if n > 1 => {
            let i = rng.below(n - 1);
            ls.swap(i, i + 1);
            "lines swapped"
        }
        6 | 7 if n > 0 => {
            // A cell (row or header value) replaced by an adversarial token.
            let i = rng.below(n);
            let text = String::from_utf8_lossy(&ls[i]).into_owned();
            let token = TOKENS[rng.below(TOKENS.len())];
            let edited =
                if let Some((key, _)) = text.strip_prefix("# ").and_then(|t| t.split_once(": ")) {
                    format!("# {key}: {token}\n")
                } else {
                    let mut cells: Vec<&str> = text.trim_end_matches('\n').split(',').collect();
                    let k = rng.below(cells.len());
                    cells[k] = token;
                    cells.join(",") + "\n"
                };
            ls[i] = edited.into_bytes();
            if kind == 6 {
                "cell replaced"
            } else {
                "cell or header value replaced"
            }
        }
        8 if n > 0 => {
            let i = rng.below(n);
            let junk: Vec<u8> = (0..rng.below(40))
                .map(|_| (rng.next() & 0xff) as u8)
                .collect();
            ls.insert(i, [junk, b"\n".to_vec()].concat());
            "line inserted"
        }
        9 => {
            bytes.extend((0..rng.below(30)).map(|_| b"0123456789,.e-"[rng.below(14)]));
            return "torn tail appended";
        }
        10 if n > 0 => {
            let i = rng.below(n);
            let text = String::from_utf8_lossy(&ls[i]).into_owned();
            let swaps = [
                ("torque-cm", "energy"),
                ("energy", "turns"),
                ("turns", "torque-cm"),
                ("alpha_deg", "alpha"),
                ("stop", "continue"),
                ("note", "pivot"),
            ];
            let (a, b) = swaps[rng.below(swaps.len())];
            ls[i] = text.replacen(a, b, 1).into_bytes();
            "word swapped"
        }
        12 | 13 if n > 0 => {
            // Issue 33, item 5: a cell spelt otherwise with the same value
            // (`5.0` as `5.00`, `1e-10` as `1.0e-10`) or quoted.
            let i = rng.below(n);
            let text = String::from_utf8_lossy(&ls[i]).into_owned();
            let mut cells: Vec<String> = text
                .trim_end_matches('\n')
                .split(',')
                .map(str::to_string)
                .collect();
            let k = rng.below(cells.len());
            let c = &cells[k];
            cells[k] = if kind == 13 {
                format!("\"{c}\"")
            } else if let Some((m, e)) = c.split_once('e') {
                format!("{m}.0e{e}")
            } else if c.contains('.') {
                format!("{c}0")
            } else {
                format!("{c}.0")
            };
            ls[i] = (cells.join(",") + "\n").into_bytes();
            if kind == 13 {
                "cell quoted"
            } else {
                "cell respelt"
            }
        }
        _ if n > 0 => {
            let i = rng.below(n);
            let mut l = ls[i].clone();
            if l.last() == Some(&b'\n') {
                l.pop();
            }
            l.extend_from_slice(b",x\n");
            ls[i] = l;
            "cell added"
        }
        _ => return "nothing",
    };
    *bytes = ls.concat();
    name
}

/// What the fuzz found, by outcome.
#[derive(Default)]
struct Tally {
    cases: u64,
    outcomes: BTreeMap<String, u64>,
    edits: BTreeMap<&'static str, u64>,
}

impl Tally {
    fn count(&mut self, outcome: String) {
        *self.outcomes.entry(outcome).or_default() += 1;
    }
}

/// The cells of one CSV line (an error message may be quoted).
fn cells(line: &str) -> Vec<String> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(line.as_bytes());
    let mut record = csv::StringRecord::new();
    assert!(reader.read_record(&mut record).unwrap(), "{line:?}");
    record.iter().map(str::to_string).collect()
}

/// The header lines of a sweep file, the column names included, without
/// its `# command:` line: that is provenance, which `--resume` does not
/// compare by design (`-o ./out.csv` resumes `-o out.csv`) and keeps from
/// the partial file, and which `merge` writes from shard 0's.
fn header_of(text: &str) -> String {
    let mut header = String::new();
    for line in text.split_inclusive('\n') {
        if !line.starts_with("# command: ") {
            header.push_str(line);
        }
        if !line.starts_with('#') {
            break;
        }
    }
    header
}

/// Checks a successful run's output against the uninterrupted sweep's
/// header (`full`'s) and rows; true when a result cell differs. A cell
/// whose value is the sweep's must be spelt as the sweep spells it, and
/// the header must be the sweep's byte for byte (issue 33, item 5: an
/// edited spelling or header line passed into the output).
fn check_output(out: &Path, full: &str, reference: &[&str], context: &str) -> bool {
    let text = fs::read_to_string(out).unwrap_or_else(|e| panic!("{context}: {e}"));
    assert_eq!(
        header_of(&text),
        header_of(full),
        "{context}: the header is not the sweep's"
    );
    let got = rows(&text);
    assert_eq!(got.len(), POINTS, "{context}: rows");
    let mut results_differ = false;
    for (line, want) in got.iter().zip(reference) {
        let (g, w) = (cells(line), cells(want));
        // The same cells in another spelling (a quoted cell): refused.
        assert!(
            g != w || line == want,
            "{context}: a row spelt otherwise passed: {line} for {want}"
        );
        assert_eq!(g.len(), w.len(), "{context}: {g:?}");
        for k in 0..g.len() {
            let same = g[k] == w[k];
            let same_value = matches!((g[k].parse::<f64>(), w[k].parse::<f64>()), (Ok(a), Ok(b)) if a.to_bits() == b.to_bits());
            assert!(
                same || !same_value,
                "{context}: a cell spelt otherwise passed: {} for {}",
                g[k],
                w[k]
            );
            // The warnings, last, depend on the point alone, like its parameters.
            if k < POINT_COLUMNS || k + 1 == g.len() {
                assert!(
                    same,
                    "{context}: accepted a row of another point: {g:?} for {w:?}"
                );
            } else if !same {
                results_differ = true;
            }
            if let Ok(x) = g[k].parse::<f64>() {
                assert!(x.is_finite(), "{context}: accepted {}", g[k]);
            }
        }
    }
    // The output is a sweep file that merge reads back.
    let again = out.with_extension("again.csv");
    let (status, e) = run(&strings(&[
        "merge",
        &out.display().to_string(),
        "-o",
        &again.display().to_string(),
    ]));
    assert_eq!(status, 0, "{context}: its output does not read back: {e}");
    fs::remove_file(again).unwrap();
    results_differ
}

/// The files of a directory, by name, with their bytes.
fn contents(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file())
        .map(|p| {
            let b = fs::read(&p).unwrap();
            (p, b)
        })
        .collect()
}

fn one_error_line(status: u8, stderr: &str, context: &str) {
    assert!(status <= 1, "{context}: status {status}: {stderr}");
    assert!(!stderr.contains("panicked"), "{context}: {stderr}");
    if status == 1 {
        let n = stderr.lines().filter(|l| l.starts_with("error: ")).count();
        assert_eq!(n, 1, "{context}: {stderr}");
    }
}

/// One `merge` case: damaged shards, in a random order, perhaps with one
/// missing, repeated or replaced by an endless or odd path.
fn merge_case(
    dir: &Path,
    good: &[Vec<u8>],
    (full, reference): (&str, &[&str]),
    rng: &mut Rng,
    t: &mut Tally,
) {
    let mut files = good.to_vec();
    for _ in 0..1 + rng.below(3) {
        let k = rng.below(files.len());
        let edit = damage(&mut files[k], rng);
        *t.edits.entry(edit).or_default() += 1;
    }
    let paths: Vec<PathBuf> = (0..files.len())
        .map(|k| dir.join(format!("c{k}.csv")))
        .collect();
    for (p, b) in paths.iter().zip(&files) {
        fs::write(p, b).unwrap();
    }
    let mut args: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    for i in (1..args.len()).rev() {
        args.swap(i, rng.below(i + 1));
    }
    match rng.below(10) {
        0 => drop(args.pop()),
        1 => args.push(args[0].clone()),
        2 => args.push(["/dev/zero", "/", "/nonexistent/x.csv"][rng.below(3)].to_string()),
        _ => {}
    }
    let out = dir.join("out.csv");
    let before = contents(dir);
    let mut argv = vec!["merge".to_string()];
    argv.extend(args);
    argv.extend(["-o".to_string(), out.display().to_string()]);
    let (status, e) = run(&argv);
    let context = format!("{argv:?}");
    one_error_line(status, &e, &context);
    if status == 0 {
        let differ = check_output(&out, full, reference, &context);
        fs::remove_file(&out).unwrap();
        t.count(format!(
            "merge accepted{}",
            if differ {
                ", a result cell edited"
            } else {
                ", rows identical"
            }
        ));
    } else {
        assert!(!out.exists(), "{context}: an output after a failure");
        t.count("merge refused".to_string());
    }
    assert_eq!(contents(dir), before, "{context}: an input changed");
    for p in paths {
        fs::remove_file(p).unwrap();
    }
}

/// One `sweep --resume` case: the header and first rows of the sweep,
/// perhaps a torn tail, then random damage.
fn resume_case(dir: &Path, full: &str, reference: &[&str], rng: &mut Rng, t: &mut Tally) {
    let out = dir.join("out.csv");
    let mut header = String::new();
    for line in full.split_inclusive('\n') {
        header.push_str(line);
        if !line.starts_with('#') {
            break;
        }
    }
    let k = rng.below(POINTS + 1);
    let mut text = header.into_bytes();
    for r in &reference[..k] {
        text.extend_from_slice(r.as_bytes());
        text.push(b'\n');
    }
    if rng.below(3) == 0 && k < POINTS {
        let r = reference[k].as_bytes();
        text.extend_from_slice(&r[..rng.below(r.len())]);
    }
    for _ in 0..rng.below(3) {
        let edit = damage(&mut text, rng);
        *t.edits.entry(edit).or_default() += 1;
    }
    let partial = dir.join("out.csv.partial");
    if rng.below(16) == 0 {
        not_regular_partial(dir, &partial, rng, t);
        return;
    }
    fs::write(&partial, &text).unwrap();
    let mut argv = strings(&GRID);
    argv.extend([
        "-o".to_string(),
        out.display().to_string(),
        "--resume".to_string(),
    ]);
    let (status, e) = run(&argv);
    let context = format!("resume of {:?}", String::from_utf8_lossy(&text));
    one_error_line(status, &e, &context);
    if status == 0 {
        assert!(!partial.exists(), "{context}: the partial file is left");
        let differ = check_output(&out, full, reference, &context);
        fs::remove_file(&out).unwrap();
        t.count(format!(
            "resume accepted{}",
            if differ {
                ", a result cell edited"
            } else {
                ", rows identical"
            }
        ));
    } else {
        assert!(!out.exists(), "{context}: an output after a failure");
        assert_eq!(
            fs::read(&partial).unwrap(),
            text,
            "{context}: the partial file changed"
        );
        fs::remove_file(&partial).unwrap();
        t.count("resume refused".to_string());
    }
}

/// Issue 33, item 2: a partial file that is a symbolic link (to
/// `/dev/null`, `/dev/zero`, `/dev/urandom` or a file) or a FIFO is refused,
/// with or without `--resume`, and left as it was; no output is made.
fn not_regular_partial(dir: &Path, partial: &Path, rng: &mut Rng, t: &mut Tally) {
    let kind = ["/dev/null", "/dev/zero", "/dev/urandom", "full.csv", "fifo"][rng.below(5)];
    if kind == "fifo" {
        let made = std::process::Command::new("mkfifo")
            .arg(partial)
            .status()
            .is_ok_and(|s| s.success());
        if !made {
            return;
        }
    } else {
        std::os::unix::fs::symlink(kind, partial).unwrap();
    }
    let out = dir.join("out.csv");
    let mut argv = strings(&GRID);
    argv.extend(["-o".to_string(), out.display().to_string()]);
    if rng.below(2) == 0 {
        argv.push("--resume".to_string());
    }
    let (status, e) = run(&argv);
    let context = format!("{argv:?} with the partial file {kind}");
    one_error_line(status, &e, &context);
    assert_eq!(status, 1, "{context}: accepted");
    assert!(e.contains("not a regular file"), "{context}: {e}");
    assert!(!out.exists(), "{context}: an output");
    assert!(
        !fs::symlink_metadata(partial).unwrap().is_file(),
        "{context}: the partial file was replaced"
    );
    fs::remove_file(partial).unwrap();
    t.count("resume refused a partial file that is not a regular file".to_string());
}

#[test]
fn fuzz_merge_and_resume_with_damaged_files() {
    let env = |name: &str, default: u64| {
        std::env::var(name)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let cases = env("FUZZ_SHARD_CASES", CI_CASES);
    let seed = env("FUZZ_SEED", 7);
    // The other test of this binary may have left its working directory
    // removed: a relative name is taken from where the process started.
    let summary = std::env::var_os("FUZZ_SUMMARY").map(|p| {
        let mut p = match PathBuf::from(&p) {
            p if p.is_absolute() => p.into_os_string(),
            p => std::env::current_dir()
                .unwrap_or_default()
                .join(p)
                .into_os_string(),
        };
        p.push(".shards");
        PathBuf::from(p)
    });
    let scratch = tempfile::tempdir_in("/dev/shm")
        .or_else(|_| tempfile::tempdir())
        .unwrap();
    let dir = scratch.path();
    let full_path = dir.join("full.csv");
    let mut whole = strings(&GRID);
    whole.extend(["-o".to_string(), full_path.display().to_string()]);
    assert_eq!(run(&whole).0, 0);
    let full = fs::read_to_string(&full_path).unwrap();
    fs::remove_file(&full_path).unwrap();
    let reference: Vec<&str> = rows(&full);
    assert_eq!(reference.len(), POINTS);
    let good: Vec<Vec<u8>> = (0..SHARDS)
        .map(|i| {
            let p = dir.join(format!("s{i}.csv"));
            let mut a = strings(&GRID);
            a.extend([
                "--shard".to_string(),
                format!("{i}/{SHARDS}"),
                "-o".to_string(),
                p.display().to_string(),
            ]);
            assert_eq!(run(&a).0, 0);
            let b = fs::read(&p).unwrap();
            fs::remove_file(p).unwrap();
            b
        })
        .collect();
    // The resumed output's header names this -o, as the partial's does.
    let full = full.replace(
        &full_path.display().to_string(),
        &dir.join("out.csv").display().to_string(),
    );

    let mut rng = Rng(seed ^ 0x5eed_0020);
    let mut t = Tally::default();
    let started = std::time::Instant::now();
    for _ in 0..cases {
        if rng.below(5) < 3 {
            merge_case(dir, &good, (&full, &reference), &mut rng, &mut t);
        } else {
            resume_case(dir, &full, &reference, &mut rng, &mut t);
        }
        t.cases += 1;
        let left: Vec<_> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        assert!(left.is_empty(), "left behind: {left:?}");
    }
    let mut text = format!("seed {seed}\nshard cases {}\n", t.cases);
    for (o, n) in &t.outcomes {
        text.push_str(&format!("outcome {o}: {n}\n"));
    }
    for (e, n) in &t.edits {
        text.push_str(&format!("edit {e}: {n}\n"));
    }
    text.push_str(&format!(
        "shard wall time {:.1} s\n",
        started.elapsed().as_secs_f64()
    ));
    if let Some(path) = summary {
        fs::write(path, &text).unwrap();
    }
    eprint!("{text}");
}
