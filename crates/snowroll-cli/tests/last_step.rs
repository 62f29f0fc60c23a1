//! Issue 33, items 1, 2 and 5: the last step of a sweep never throws its
//! rows away (every output checked before the first row, a complete
//! partial file kept on any error, the output put in place by rename, so
//! a full disk cannot cost the rows); a partial file that is not a regular
//! file is refused; `merge` reads its shards one after another and refuses
//! a shard spelt otherwise than snowroll writes it.
//!
//! The full-disk tests mount a small tmpfs, which needs root: elsewhere
//! they print why they are skipped and pass.

use std::fs;
use std::os::unix::fs::symlink;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::support::{bin, fails_in, ok_in, run_in};

/// A sweep of 4000 closed-form rows (about 670 kB of CSV, a map of about
/// 360 kB): large enough that a tmpfs's 4 kB pages do not blur the sizes.
const BIG: [&str; 7] = [
    "sweep",
    "--model",
    "eq4",
    "--alpha-deg",
    "5:60:2000",
    "--r0",
    "0.1,0.2",
];

fn args(base: &[&str], extra: &[&str]) -> Vec<String> {
    base.iter().chain(extra).map(|s| s.to_string()).collect()
}

fn argv(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// The entries of `dir`, sorted.
fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Pages of 4 kB that `bytes` take on a tmpfs.
fn pages(bytes: u64) -> u64 {
    bytes.div_ceil(4096)
}

/// A tmpfs of a given size mounted on a temporary directory, unmounted
/// when dropped; `None` (with the reason printed) where mounting is not
/// allowed.
struct Tmpfs {
    dir: tempfile::TempDir,
}

impl Tmpfs {
    fn mount(pages: u64, options: &str) -> Option<Tmpfs> {
        let dir = tempfile::tempdir().unwrap();
        let out = Command::new("mount")
            .args(["-t", "tmpfs", "-o"])
            .arg(format!("size={}k{options}", pages * 4))
            .arg("tmpfs")
            .arg(dir.path())
            .output();
        match out {
            Ok(o) if o.status.success() => Some(Tmpfs { dir }),
            Ok(o) => {
                eprintln!(
                    "skipped: cannot mount a tmpfs (not root?): {}",
                    String::from_utf8_lossy(&o.stderr).trim()
                );
                None
            }
            Err(e) => {
                eprintln!("skipped: no mount command: {e}");
                None
            }
        }
    }

    fn path(&self) -> &Path {
        self.dir.path()
    }

    /// Gives it `pages` pages.
    fn resize(&self, pages: u64) {
        let ok = Command::new("mount")
            .args(["-o"])
            .arg(format!("remount,size={}k", pages * 4))
            .arg(self.path())
            .status()
            .unwrap()
            .success();
        assert!(ok, "remount");
    }
}

impl Drop for Tmpfs {
    fn drop(&mut self) {
        let _ = Command::new("umount").arg(self.dir.path()).status();
    }
}

/// The finished sweep [`BIG`] (with `--plot map.svg` when `plot`) run in a
/// directory of its own: its CSV and map bytes.
fn reference(plot: bool) -> (Vec<u8>, Vec<u8>) {
    let dir = tempfile::tempdir().unwrap();
    let mut a = args(&BIG, &["-q", "-o", "out.csv"]);
    if plot {
        a.extend(["--plot".to_string(), "map.svg".to_string()]);
    }
    ok_in(dir.path(), &argv(&a));
    let svg = fs::read(dir.path().join("map.svg")).unwrap_or_default();
    (fs::read(dir.path().join("out.csv")).unwrap(), svg)
}

/// `dir/out.csv.partial` as a sweep of [`BIG`] to `out.csv` killed after 10
/// rows leaves it: its path and text.
fn partial_of_ten_rows(dir: &Path) -> (PathBuf, String) {
    let (full, _) = reference(false);
    let text = String::from_utf8(full).unwrap();
    let columns = text.find("\nindex,").unwrap() + 1;
    let mut cut = columns + text[columns..].find('\n').unwrap() + 1;
    for _ in 0..10 {
        cut += text[cut..].find('\n').unwrap() + 1;
    }
    let partial = dir.join("out.csv.partial");
    fs::write(&partial, &text[..cut]).unwrap();
    (partial, text[..cut].to_string())
}

/// The example, `--plot nodir/map.svg`, computed every row and then
/// failed on the map. Now every output is opened before the first row: a
/// resumed sweep whose map cannot be written is refused with its partial
/// file byte for byte as it was (before, its missing rows were computed
/// and appended, then the run failed).
#[test]
fn regression_33_a_plot_that_cannot_be_written_is_refused_before_any_row() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (partial, text) = partial_of_ten_rows(d);
    let e = fails_in(
        d,
        &argv(&args(
            &BIG,
            &["-q", "-o", "out.csv", "--resume", "--plot", "nodir/map.svg"],
        )),
    );
    assert!(e.contains("cannot write nodir/map.svg"), "{e}");
    assert_eq!(fs::read_to_string(&partial).unwrap(), text);
    assert_eq!(entries(d), ["out.csv.partial"]);
    // Without a partial file: refused the same, nothing made.
    fs::remove_file(&partial).unwrap();
    let e = fails_in(
        d,
        &argv(&args(
            &BIG,
            &["-q", "-o", "out.csv", "--plot", "nodir/map.svg"],
        )),
    );
    assert!(e.contains("cannot write nodir/map.svg"), "{e}");
    assert!(entries(d).is_empty(), "{:?}", entries(d));
}

/// A map in a read-only directory: refused before any row (a read-only
/// mount for root, whom directory modes do not stop). As above, a resumed
/// sweep's partial file is left byte for byte as it was.
#[test]
fn regression_33_a_plot_in_a_read_only_directory_is_refused_before_any_row() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let ro = if rustix::process::geteuid().is_root() {
        match Tmpfs::mount(16, ",ro") {
            Some(t) => t,
            None => return,
        }
    } else {
        use std::os::unix::fs::PermissionsExt;
        let t = Tmpfs {
            dir: tempfile::tempdir().unwrap(),
        };
        fs::set_permissions(t.path(), fs::Permissions::from_mode(0o555)).unwrap();
        t
    };
    let (partial, text) = partial_of_ten_rows(d);
    let plot = ro.path().join("map.svg");
    let a = args(
        &BIG,
        &[
            "-q",
            "-o",
            "out.csv",
            "--resume",
            "--plot",
            plot.to_str().unwrap(),
        ],
    );
    let e = fails_in(d, &argv(&a));
    assert!(
        e.contains("map.svg") && (e.contains("Read-only") || e.contains("Permission denied")),
        "{e}"
    );
    assert_eq!(fs::read_to_string(&partial).unwrap(), text);
    assert_eq!(entries(d), ["out.csv.partial"]);
}

/// On a disk with room for the rows once but not twice, the last step
/// copied the finished partial file and, the copy failing, deleted it:
/// every row lost. It is now renamed into place: the sweep succeeds with
/// the same bytes as on a roomy disk.
#[test]
fn regression_33_a_disk_with_room_for_the_rows_once_finishes_the_sweep() {
    let (full, _) = reference(false);
    // The rows and half as much again: not room for a copy.
    let size = pages(full.len() as u64) * 3 / 2;
    let Some(fs) = Tmpfs::mount(size, "") else {
        return;
    };
    ok_in(fs.path(), &argv(&args(&BIG, &["-q", "-o", "out.csv"])));
    assert!(fs::read(fs.path().join("out.csv")).unwrap() == full);
    assert_eq!(entries(fs.path()), ["out.csv"]);
}

/// A disk with room for the rows but not for the map: the run fails on
/// the map, and the complete partial file is kept (it was removed) with a
/// note saying so; once there is room, `--resume` computes nothing again
/// and writes the map and the output, the bytes of a run on a roomy disk.
#[test]
fn regression_33_a_complete_partial_file_is_kept_on_an_error_and_resume_finishes() {
    let (full, svg) = reference(true);
    assert!(svg.len() > 64 * 1024, "{}", svg.len());
    // Room for the rows and a page: not for the map.
    let Some(fs) = Tmpfs::mount(pages(full.len() as u64) + 1, "") else {
        return;
    };
    let d = fs.path();
    let a = args(&BIG, &["-q", "-o", "out.csv", "--plot", "map.svg"]);
    let e = fails_in(d, &argv(&a));
    assert!(e.contains("No space left on device"), "{e}");
    assert!(
        e.contains("note: the 4000 rows are complete in out.csv.partial, which is kept"),
        "{e}"
    );
    assert_eq!(entries(d), ["out.csv.partial"]);
    assert!(fs::read(d.join("out.csv.partial")).unwrap() == full);
    // Room again: resume writes the outputs.
    fs.resize(pages(full.len() as u64) + pages(svg.len() as u64) + 4);
    let mut resume = a.clone();
    resume.push("--resume".into());
    ok_in(d, &argv(&resume));
    assert_eq!(entries(d), ["map.svg", "out.csv"]);
    assert!(fs::read(d.join("out.csv")).unwrap() == full);
    assert!(fs::read(d.join("map.svg")).unwrap() == svg);
}

/// `cmd` in `dir`, killed after `limit`: its output, or `None` if it had
/// to be killed.
fn run_for(dir: &Path, cmd: &[&str], limit: Duration) -> Option<Output> {
    let mut child = Command::new(bin())
        .current_dir(dir)
        .args(cmd)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    while started.elapsed() < limit {
        if child.try_wait().unwrap().is_some() {
            return Some(child.wait_with_output().unwrap());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = child.kill();
    let _ = child.wait();
    None
}

/// Issue 33, item 2: `FILE.partial` a link to `/dev/null` made a sweep
/// exit 0 with an empty `FILE`; linked to `/dev/zero` or `/dev/urandom`
/// (with `--resume`) it never ended. Each such partial file (and a FIFO,
/// a directory) is refused at once by name, and left as it was.
#[test]
fn regression_33_a_partial_file_that_is_not_a_regular_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let small = ["sweep", "--model", "eq4", "--alpha-deg", "5:60:8", "-q"];
    for (target, kind) in [
        ("/dev/null", "a symbolic link"),
        ("/dev/zero", "a symbolic link"),
        ("/dev/urandom", "a symbolic link"),
        ("real.csv", "a symbolic link"),
        ("fifo", "a FIFO"),
        ("dir", "a directory"),
    ] {
        let partial = d.join("out.csv.partial");
        match target {
            "fifo" => {
                let ok = Command::new("mkfifo").arg(&partial).status().unwrap();
                assert!(ok.success());
            }
            "dir" => fs::create_dir(&partial).unwrap(),
            t => symlink(t, &partial).unwrap(),
        }
        for resume in [false, true] {
            let mut cmd = args(&small, &["-o", "out.csv"]);
            if resume {
                cmd.push("--resume".into());
            }
            let out = run_for(d, &argv(&cmd), Duration::from_secs(20))
                .unwrap_or_else(|| panic!("{target}: still running after 20 s"));
            let e = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{target}: {e}");
            assert!(
                e.contains(&format!(
                    "cannot use out.csv.partial as the rows file of this sweep: it is {kind}"
                )),
                "{target}: {e}"
            );
            assert!(!d.join("out.csv").exists(), "{target}");
        }
        let kept = fs::symlink_metadata(&partial).unwrap().file_type();
        assert!(!kept.is_file(), "{target}");
        if kept.is_dir() {
            fs::remove_dir(&partial).unwrap();
        } else {
            fs::remove_file(&partial).unwrap();
        }
    }
    assert!(!d.join("real.csv").exists());
}

/// A grid of 44 points in `n` shards in `dir`: their paths, and the bytes
/// of the same sweep run in one process to `m.csv`.
fn many_shards(dir: &Path, n: usize) -> (Vec<PathBuf>, Vec<u8>) {
    let grid = ["sweep", "--model", "eq4,energy", "--alpha-deg", "5:60:22"];
    let mut paths = Vec::new();
    for i in 0..n {
        let name = format!("s{i:03}.csv");
        let shard = format!("{i}/{n}");
        ok_in(
            dir,
            &argv(&args(&grid, &["-q", "--shard", &shard, "-o", &name])),
        );
        paths.push(dir.join(name));
    }
    ok_in(dir, &argv(&args(&grid, &["-q", "-o", "m.csv"])));
    let whole = fs::read(dir.join("m.csv")).unwrap();
    fs::remove_file(dir.join("m.csv")).unwrap();
    (paths, whole)
}

/// Issue 33, item 5: `merge` opened every shard at once, so more shards
/// than the open-file limit (1,100 under `ulimit -n 1024`) failed with
/// "Too many open files". 40 shards under a limit of 24 descriptors: the
/// merge succeeds, the bytes of the one-process sweep.
#[test]
fn regression_33_merge_reads_more_shards_than_the_open_file_limit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (paths, whole) = many_shards(d, 40);
    let mut script = format!("ulimit -n 24 && exec '{}' merge", bin().display());
    for p in &paths {
        script.push_str(&format!(" '{}'", p.file_name().unwrap().to_string_lossy()));
    }
    script.push_str(" -o m.csv");
    let out = Command::new("sh")
        .current_dir(d)
        .args(["-c", &script])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(fs::read(d.join("m.csv")).unwrap() == whole);
}

/// Issue 33, item 5: hand-edited spellings of the same values (`5.00` for
/// `5.0`, a quoted cell, two header lines swapped) passed through `merge`
/// and changed its bytes. Each is refused, with the line, by `merge` and
/// by `--resume`; nothing is written and the files keep their bytes.
#[test]
fn regression_33_merge_and_resume_refuse_edited_spellings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (paths, _) = many_shards(d, 2);
    let good = fs::read_to_string(&paths[0]).unwrap();
    let lines: Vec<&str> = good.lines().collect();
    let first_row = lines.iter().position(|l| l.starts_with("0,")).unwrap();
    let row = lines[first_row];
    // The row's alpha (5 degrees, column 3, written `5.0`) spelt `5.00`,
    // and its model quoted.
    let cells: Vec<&str> = row.split(',').collect();
    assert_eq!(cells[2], "5.0", "{row}");
    let with_cell = |k: usize, text: &str| {
        let mut c = cells.clone();
        c[k] = text;
        c.join(",")
    };
    let collision = lines
        .iter()
        .position(|l| l.starts_with("# collision:"))
        .unwrap();
    let cases: Vec<(usize, String)> = vec![
        (first_row, with_cell(2, "5.00")),
        (first_row, with_cell(1, &format!("\"{}\"", cells[1]))),
        (collision, lines[collision + 1].to_string()),
    ];
    for (at, replacement) in cases {
        let mut edited: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        if at == collision {
            edited.swap(collision, collision + 1);
        } else {
            edited[at] = replacement.clone();
        }
        let text = format!("{}\n", edited.join("\n"));
        fs::write(&paths[0], &text).unwrap();
        let e = fails_in(d, &["merge", "s000.csv", "s001.csv", "-o", "m.csv"]);
        assert!(
            e.contains(&format!("s000.csv: line {}", at + 1)) && e.contains("snowroll writes"),
            "{replacement}: {e}"
        );
        assert!(!d.join("m.csv").exists());
        assert_eq!(fs::read_to_string(&paths[0]).unwrap(), text);
        // The same file as the partial file of a resumed shard.
        let partial = d.join("s000.csv.partial");
        fs::write(&partial, &text).unwrap();
        let out = run_in(
            d,
            &[
                "sweep",
                "--model",
                "eq4,energy",
                "--alpha-deg",
                "5:60:22",
                "-q",
                "--shard",
                "0/2",
                "-o",
                "s000.csv",
                "--resume",
            ],
        );
        let e = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{replacement}: {e}");
        assert!(e.contains("snowroll writes"), "{replacement}: {e}");
        assert_eq!(fs::read_to_string(&partial).unwrap(), text);
        fs::remove_file(&partial).unwrap();
    }
    fs::write(&paths[0], &good).unwrap();
    ok_in(d, &["merge", "s000.csv", "s001.csv", "-o", "m.csv"]);
}

/// Issue 33, item 5 (with item 2): a shard that is not a regular file
/// (`/dev/zero`, a FIFO) is refused by name, at once.
#[test]
fn regression_33_merge_refuses_a_shard_that_is_not_a_regular_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (paths, _) = many_shards(d, 2);
    let name = paths[1].file_name().unwrap().to_str().unwrap().to_string();
    for other in ["/dev/zero", "/dev/null"] {
        let out = run_for(
            d,
            &["merge", "s000.csv", other, &name, "-o", "m.csv"],
            Duration::from_secs(20),
        )
        .expect("ended");
        let e = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{e}");
        assert!(
            e.contains(&format!("cannot merge {other}: it is a character device")),
            "{e}"
        );
        assert!(!d.join("m.csv").exists());
    }
}

/// Issue 33's campaign: a partial file whose `# command:` line was not a
/// sweep's (`# command: end-time`) was resumed into a file that `merge`
/// then refused. The command line is provenance and not compared, but it
/// must be a `snowroll sweep` command, in a partial file and in every
/// shard (merge checked shard 0's only).
#[test]
fn regression_33_a_command_line_that_is_not_a_sweep_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (paths, _) = many_shards(d, 2);
    let good: Vec<String> = paths
        .iter()
        .map(|p| fs::read_to_string(p).unwrap())
        .collect();
    let edit = |text: &str| {
        let line = text.lines().nth(1).unwrap().to_string();
        assert!(line.starts_with("# command: snowroll sweep"), "{line}");
        text.replacen(&line, "# command: end-time", 1)
    };
    // Shard 1 edited: merge refuses it, naming it.
    fs::write(&paths[1], edit(&good[1])).unwrap();
    let e = fails_in(d, &["merge", "s000.csv", "s001.csv", "-o", "m.csv"]);
    assert!(
        e.contains("s001.csv: its command line `end-time` does not parse"),
        "{e}"
    );
    assert!(!d.join("m.csv").exists());
    fs::write(&paths[1], &good[1]).unwrap();
    // Shard 0 as a partial file to resume: refused, kept.
    let partial = d.join("s000.csv.partial");
    let text = edit(&good[0]);
    fs::write(&partial, &text).unwrap();
    let e = fails_in(
        d,
        &[
            "sweep",
            "--model",
            "eq4,energy",
            "--alpha-deg",
            "5:60:22",
            "-q",
            "--shard",
            "0/2",
            "-o",
            "s000.csv",
            "--resume",
        ],
    );
    assert!(
        e.contains("its command line `end-time` does not parse"),
        "{e}"
    );
    assert_eq!(fs::read_to_string(&partial).unwrap(), text);
}
