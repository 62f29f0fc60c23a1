//! What each fuzz case must satisfy, checked on its exit status, its output
//! and the files around it.

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::fs;
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::{Component, Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

use crate::inputs::Case;

/// Where `paper` writes without `--out`.
const PAPER_OUT_DEFAULT: &str = "snowroll-report";

/// Whether a non-finite number in an output is tolerated (counted, not a
/// failure). Not since issue 7 item 6: derived quantities (the mass of
/// `--r0 1e154`) are checked at validation and the writers refuse NaN and
/// infinity.
pub(crate) const TOLERATE_NON_FINITE: bool = false;

/// Whether `merge` may copy a non-finite cell of a corrupted shard (counted,
/// not a failure): it checks only the index of each row until issue 20's
/// item 4 (rows parsed against the schema and their grid point), another
/// branch's work, is merged; then this is `false`. The first campaign of the
/// readers found it (`merge` of a shard whose `alpha_deg` was `nan`).
pub(crate) const TOLERATE_UNCHECKED_MERGE: bool = false;

/// A file's identity and contents, to see whether a run touched it.
#[derive(Debug, PartialEq)]
pub(crate) struct Snapshot {
    kind: &'static str,
    mode: u32,
    inode: u64,
    contents: Vec<u8>,
}

pub(crate) fn snapshot(path: &Path) -> Option<Snapshot> {
    let meta = fs::symlink_metadata(path).ok()?;
    let (kind, contents) = if meta.file_type().is_symlink() {
        (
            "link",
            fs::read_link(path)
                .ok()?
                .into_os_string()
                .into_encoded_bytes(),
        )
    } else if meta.is_dir() {
        ("dir", Vec::new())
    } else {
        ("file", fs::read(path).unwrap_or_default())
    };
    Some(Snapshot {
        kind,
        mode: meta.mode(),
        inode: meta.ino(),
        contents,
    })
}

/// `path` relative to the scratch `root`, with `.` and `..` resolved by
/// name (the folders involved are real ones, not links).
pub(crate) fn normalise(work: &Path, path: &str) -> PathBuf {
    let mut out = PathBuf::new();
    for c in work.join(path).components() {
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

/// Every path a case named as an output: `-o X`, `-oX`, `--output X`,
/// `--output=X`, `--out X`, `--plot X`, the config's `output`, and
/// `paper`'s default `snowroll-report`.
pub(crate) fn named_outputs(case: &Case) -> Vec<String> {
    let mut named = Vec::new();
    if case.args.first().is_some_and(|c| c == "paper") {
        named.push(PAPER_OUT_DEFAULT.to_string());
    }
    let mut args = case.args.iter().peekable();
    while let Some(a) = args.next() {
        if ["-o", "--output", "--out", "--plot"].contains(&a.as_str()) {
            if let Some(v) = args.peek() {
                named.push(v.to_string());
            }
        } else if let Some(v) = a
            .strip_prefix("--output=")
            .or_else(|| a.strip_prefix("--out="))
        {
            named.push(v.to_string());
        } else if let Some(v) = a.strip_prefix("-o") {
            named.push(v.trim_start_matches('=').to_string());
        }
    }
    // The config's `output`, however the document spells it.
    let config_output = case.config.as_deref().and_then(|doc| {
        match toml::from_str::<toml::Table>(doc) {
            Ok(table) => table.get("output")?.as_str().map(str::to_string),
            // A document the program reads but a generic table does not: an
            // integer past i64 (`max-steps = 18446744073709551615`, which
            // the program reads as a count). Its `output` line, if a basic
            // string (issue 33's campaign: the harness's own alarm).
            Err(_) => doc.lines().find_map(|line| {
                let (key, value) = line.split_once('=')?;
                let value = value.trim();
                (key.trim() == "output" && value.len() >= 2 && value.starts_with('"'))
                    .then(|| value.trim_matches('"').to_string())
            }),
        }
    });
    named.extend(config_output);
    // `link.csv` and `dangling.csv` write their targets.
    if named.iter().any(|n| n == "link.csv") {
        named.push("out.csv".to_string());
    }
    if named.iter().any(|n| n == "dangling.csv") {
        named.push("nowhere.csv".to_string());
    }
    named
}

/// Makes the files of `prepared` (and the config) in an empty `work`.
pub(crate) fn prepare(work: &Path, case: &Case) {
    let p = case.prepared;
    if let Some(doc) = &case.config {
        fs::write(work.join("c.toml"), doc).unwrap();
    }
    for (name, bytes) in &case.files {
        fs::write(work.join(name), bytes).unwrap();
    }
    if p.out_csv || p.link {
        fs::write(work.join("out.csv"), "previous\n").unwrap();
    }
    if p.dir {
        fs::create_dir(work.join("d")).unwrap();
    }
    if p.link {
        std::os::unix::fs::symlink("out.csv", work.join("link.csv")).unwrap();
    }
    if p.read_only {
        fs::write(work.join("ro.csv"), "read only\n").unwrap();
        fs::set_permissions(work.join("ro.csv"), fs::Permissions::from_mode(0o444)).unwrap();
    }
    if p.hard_link {
        fs::write(work.join("hard.csv"), "linked\n").unwrap();
        fs::hard_link(work.join("hard.csv"), work.join("hard2.csv")).unwrap();
    }
    if p.dangling {
        std::os::unix::fs::symlink("nowhere.csv", work.join("dangling.csv")).unwrap();
    }
}

/// Every path under `dir`, recursively (links not followed).
pub(crate) fn walk(dir: &Path, into: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let path = e.path();
        let is_dir = e.file_type().is_ok_and(|t| t.is_dir());
        into.push(path.clone());
        if is_dir {
            walk(&path, into);
        }
    }
}

/// Empties `dir` (making read-only things removable first).
pub(crate) fn clear(dir: &Path) -> std::io::Result<()> {
    for e in fs::read_dir(dir)? {
        let e = e?;
        let path = e.path();
        let removed = if e.file_type()?.is_dir() {
            fs::set_permissions(&path, fs::Permissions::from_mode(0o755))?;
            fs::remove_dir_all(&path)
        } else {
            fs::remove_file(&path)
        };
        removed
            .map_err(|err| std::io::Error::new(err.kind(), format!("{}: {err}", path.display())))?;
    }
    Ok(())
}

/// Non-finite numbers in the data rows of CSV text: none is allowed (the
/// friction ratio |F|/N where N <= 0 is undefined and written as an empty
/// cell, not as `inf`).
pub(crate) fn non_finite_csv(text: &str) -> Option<String> {
    let mut columns: Vec<&str> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        if columns.is_empty() {
            columns = line.split(',').collect();
            continue;
        }
        for (i, field) in line.split(',').enumerate() {
            let f = field.trim().to_ascii_lowercase();
            let column = columns.get(i).copied().unwrap_or("");
            if matches!(
                f.as_str(),
                "inf" | "-inf" | "+inf" | "nan" | "-nan" | "infinity" | "-infinity"
            ) {
                return Some(format!("{field} in column {column}"));
            }
        }
    }
    None
}

/// What the campaign saw.
#[derive(Debug, Default)]
pub(crate) struct Tally {
    pub(crate) cases: u64,
    pub(crate) by_status: BTreeMap<u8, u64>,
    pub(crate) by_command: BTreeMap<String, u64>,
    pub(crate) successful_runs_with_output_file: u64,
    /// Runs that wrote a non-finite number (tolerated while
    /// [`TOLERATE_NON_FINITE`]).
    pub(crate) non_finite: u64,
    /// Merges that copied a non-finite cell of a shard (tolerated while
    /// [`TOLERATE_UNCHECKED_MERGE`]).
    pub(crate) merged_non_finite: u64,
    pub(crate) slowest: Duration,
    pub(crate) slowest_case: String,
}

/// Runs one case in `root/work` and checks it.
pub(crate) fn check(root: &Path, case: &Case, tally: &Mutex<Tally>) -> Result<(), TestCaseError> {
    let work = root.join("work");
    if let Err(e) = clear(root) {
        prop_assert!(
            false,
            "the previous case left what cannot be removed: {}",
            e
        );
    }
    fs::create_dir(&work).unwrap();
    // The old working directory was removed with the rest.
    std::env::set_current_dir(&work).unwrap();
    prepare(&work, case);
    let mut before = Vec::new();
    walk(root, &mut before);
    let before: BTreeMap<PathBuf, Snapshot> = before
        .into_iter()
        .filter_map(|p| snapshot(&p).map(|s| (p, s)))
        .collect();

    let argv: Vec<OsString> = std::iter::once(OsString::from("snowroll"))
        .chain(case.args.iter().map(OsString::from))
        .collect();
    let started = Instant::now();
    let (status, captured) = snowroll_cli::console::capture(|| snowroll_cli::run_from(argv));
    let took = started.elapsed();

    let stderr = String::from_utf8_lossy(&captured.stderr);
    let stdout = String::from_utf8_lossy(&captured.stdout);
    prop_assert!(status <= 2, "status {}: {}", status, stderr);
    if status == 1 {
        let errors: Vec<&str> = stderr
            .lines()
            .filter(|l| l.starts_with("error: "))
            .collect();
        prop_assert_eq!(errors.len(), 1, "one error line: {}", stderr);
        prop_assert!(
            !stderr.contains(".snowroll-"),
            "names a temporary file: {}",
            stderr
        );
    }
    if status == 2 {
        prop_assert!(!stderr.is_empty(), "a usage error says why");
    }
    let mut non_finite = non_finite_csv(&stdout).map(|bad| format!("{bad} on stdout"));

    let named: Vec<PathBuf> = named_outputs(case)
        .iter()
        .map(|n| normalise(&work, n))
        .collect();
    let is_named = |p: &Path| named.iter().any(|n| p == n || p.starts_with(n));
    let is_parent_of_named = |p: &Path| named.iter().any(|n| n.starts_with(p));
    let mut after = Vec::new();
    walk(root, &mut after);
    for path in &after {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        prop_assert!(
            !name.starts_with(".snowroll-"),
            "temporary left: {}",
            path.display()
        );
        match before.get(path) {
            Some(old) => {
                let touched = snapshot(path).as_ref() != Some(old);
                if touched {
                    prop_assert!(status == 0 && is_named(path), "{} changed", path.display());
                }
            }
            None => {
                prop_assert!(
                    (status == 0 && is_named(path)) || is_parent_of_named(path),
                    "{} appeared (status {})",
                    path.display(),
                    status
                );
                if path.is_file() {
                    let text = fs::read_to_string(path).unwrap_or_default();
                    if let Some(bad) = non_finite_csv(&text) {
                        non_finite = Some(format!("{bad} in {}", path.display()));
                    }
                }
            }
        }
    }
    for path in before.keys() {
        prop_assert!(
            after.contains(path) || (status == 0 && is_named(path)),
            "{} disappeared",
            path.display()
        );
    }

    let merge = case.args.first().is_some_and(|c| c == "merge");
    if let (Some(_), true, true) = (&non_finite, merge, TOLERATE_UNCHECKED_MERGE) {
        tally.lock().unwrap().merged_non_finite += 1;
    } else if let Some(bad) = non_finite {
        prop_assert!(TOLERATE_NON_FINITE, "non-finite number written: {}", bad);
        tally.lock().unwrap().non_finite += 1;
    }
    if std::env::var("FUZZ_DEBUG").is_ok() {
        eprintln!(
            "DEBUG {status} {}",
            stderr
                .lines()
                .find(|l| l.starts_with("error"))
                .unwrap_or("")
        );
    }
    let mut t = tally.lock().unwrap();
    t.cases += 1;
    *t.by_status.entry(status).or_default() += 1;
    let command = case.args.first().cloned().unwrap_or_default();
    let command =
        if ["simulate", "turns", "models", "paper", "sweep", "merge"].contains(&command.as_str()) {
            command
        } else {
            "other".to_string()
        };
    *t.by_command.entry(command).or_default() += 1;
    if status == 0 && !named.is_empty() {
        t.successful_runs_with_output_file += 1;
    }
    if took > t.slowest {
        t.slowest = took;
        t.slowest_case = format!("{:?}", case.args);
    }
    Ok(())
}
