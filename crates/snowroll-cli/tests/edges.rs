//! Issue 33, items 4 and 5: edges of the command line (the row limit, steps
//! and ends that cannot make progress, a huge thread count under a memory
//! cap) and of config files (keys given twice, a byte order mark) and the
//! grid-size message.

use std::fs;
use std::process::Command;
use std::time::{Duration, Instant};

use crate::support::{bin, fails_in, ok_in, run_in};

/// The rows (lines not starting with `#`) and the `# stop` line of a CSV.
fn rows_and_stop(csv: &str) -> (Vec<&str>, Option<&str>) {
    let rows = csv.lines().filter(|l| !l.starts_with('#')).collect();
    let stop = csv.lines().find(|l| l.starts_with("# stop = "));
    (rows, stop)
}

/// `simulate --times 0.5,1,2 --max-rows 3` stopped at the row limit having
/// written its three rows (off by one). It now ends as the run without the
/// limit does, with the same rows and stop; a limit of 2 still stops at 2.
#[test]
fn regression_33_a_row_limit_equal_to_the_times_asked_is_not_reached() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let base = ["simulate", "--model", "eq4", "--times", "0.5,1,2"];
    ok_in(d, &[&base[..], &["-o", "free.csv"]].concat());
    ok_in(
        d,
        &[&base[..], &["--max-rows", "3", "-o", "three.csv"]].concat(),
    );
    let out = run_in(
        d,
        &[&base[..], &["--max-rows", "3", "-o", "x.csv"]].concat(),
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("max_rows"), "{err}");
    let free = fs::read_to_string(d.join("free.csv")).unwrap();
    let three = fs::read_to_string(d.join("three.csv")).unwrap();
    let (free_rows, free_stop) = rows_and_stop(&free);
    let (rows, stop) = rows_and_stop(&three);
    assert_eq!(rows, free_rows);
    assert_eq!(rows.len(), 4, "the column line and three rows");
    assert_eq!(stop, free_stop);
    assert!(!stop.unwrap().contains("row-limit"), "{stop:?}");
    // One row fewer than asked for is refused before the run, as before.
    let e = fails_in(
        d,
        &[&base[..], &["--max-rows", "2", "-o", "two.csv"]].concat(),
    );
    assert!(e.contains("3 rows, more than --max-rows 2"), "{e}");
}

/// A run that must end within `limit`: its status and stderr.
fn bounded(args: &[&str], limit: Duration) -> (Option<i32>, String) {
    let mut child = Command::new(bin())
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if started.elapsed() > limit {
            let _ = child.kill();
            panic!("{args:?}: still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `--dt 5e-324 --t-end 1e-308` ran for ever (counting its grid). Steps
/// and ends that are subnormal are refused up front, by the library's
/// checks (so Python and the server refuse them too), naming the value
/// and the smallest allowed; the smallest normal values still run.
#[test]
fn regression_33_subnormal_steps_and_ends_are_refused_up_front() {
    let limit = Duration::from_secs(30);
    for (flags, says) in [
        (
            &["--dt", "5e-324", "--t-end", "1e-308"][..],
            "invalid dt (s) = 5e-324",
        ),
        (
            &["--dt", "1e-310", "--t-end", "1e-300"][..],
            "invalid dt (s) = 1e-310",
        ),
        (&["--t-end", "1e-308"][..], "invalid t_end (s) = 1e-308"),
        (&["--x-end", "1e-310"][..], "invalid x_end (m) = 1e-310"),
    ] {
        let args = [&["simulate", "--model", "eq4"][..], flags].concat();
        let (code, err) = bounded(&args, limit);
        assert_eq!(code, Some(1), "{flags:?}: {err}");
        assert!(
            err.contains(says) && err.contains("2.2250738585072014e-308"),
            "{flags:?}: {err}"
        );
    }
    let (code, err) = bounded(
        &[
            "simulate",
            "--model",
            "eq4",
            "--t-end",
            "2.2250738585072014e-308",
        ],
        limit,
    );
    assert_eq!(code, Some(0), "{err}");
}

/// `--x-end 1e-100` stopped at x = 1.6e-8 m and reported the end distance
/// reached. Positions are computed to within atol, so an end distance below
/// it is refused, naming both; one above it is reached where it is: the
/// stop's x is x_end to within atol, the precision positions have.
#[test]
fn regression_33_an_end_distance_below_atol_is_refused_and_one_above_is_reached() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let e = fails_in(d, &["simulate", "--model", "eq4", "--x-end", "1e-100"]);
    assert!(
        e.contains("invalid x_end (m) = 1e-100: expected x_end >= atol = 1e-12"),
        "{e}"
    );
    for (x_end, atol) in [("1e-11", "1e-12"), ("1e-28", "1e-30"), ("0.5", "1e-12")] {
        ok_in(
            d,
            &[
                "simulate", "--model", "eq4", "--x-end", x_end, "--atol", atol, "-o", "x.csv",
            ],
        );
        let text = fs::read_to_string(d.join("x.csv")).unwrap();
        let stop = text.lines().find(|l| l.starts_with("# stop = ")).unwrap();
        assert!(stop.starts_with("# stop = distance"), "{stop}");
        let x: f64 = stop
            .split("x_m = ")
            .nth(1)
            .unwrap()
            .split_whitespace()
            .next()
            .unwrap()
            .parse()
            .unwrap();
        let (want, atol): (f64, f64) = (x_end.parse().unwrap(), atol.parse().unwrap());
        assert!((x - want).abs() <= atol, "{x_end}: stopped at {x}");
    }
}

/// `RAYON_NUM_THREADS=5000` under a memory cap panicked with a backtrace
/// (the thread pool could not start). The request is cut to four threads a
/// CPU (at least 16) with a note, and the sweep runs; a cap too small for
/// even that is one clear error.
#[test]
fn regression_33_a_huge_thread_count_under_a_memory_cap_runs_with_fewer_threads() {
    let dir = tempfile::tempdir().unwrap();
    let script = format!(
        "ulimit -v 2000000 && RAYON_NUM_THREADS=5000 exec '{}' sweep --model eq4 \
         --alpha-deg 5:60:40 -q -o out.csv",
        bin().display()
    );
    let out = Command::new("sh")
        .current_dir(dir.path())
        .args(["-c", &script])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(
        err.contains("note: RAYON_NUM_THREADS=5000 is more than 4 threads for each of"),
        "{err}"
    );
    assert!(dir.path().join("out.csv").exists());
}

/// A JSON config with a key given twice (even `model`) took the last; a
/// CSV config with a `# key =` line twice likewise. Both are refused,
/// naming the key, as TOML refuses it.
#[test]
fn regression_33_a_config_key_given_twice_is_refused_in_every_format() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    ok_in(
        d,
        &[
            "simulate", "--model", "eq4", "--t-end", "1", "--format", "json", "-o", "a.json",
        ],
    );
    ok_in(
        d,
        &["simulate", "--model", "eq4", "--t-end", "1", "-o", "a.csv"],
    );
    let json = fs::read_to_string(d.join("a.json")).unwrap();
    let model_twice = json.replacen(
        "\"model\": {",
        "\"model\": {\"id\":\"energy\"},\n  \"model\": {",
        1,
    );
    let t_end_twice = json.replacen("\"t_end\":1.0,", "\"t_end\":1.0,\"t_end\":5.0,", 1);
    let id_twice = json.replacen(
        "{\"id\":\"torque-cm\",",
        "{\"id\":\"torque-cm\",\"id\":\"energy\",",
        1,
    );
    let csv = fs::read_to_string(d.join("a.csv")).unwrap();
    let csv_twice = csv.replacen("# t_end = 1\n", "# t_end = 1\n# t_end = 5\n", 1);
    for (name, text, key) in [
        ("m.json", &model_twice, "model"),
        ("t.json", &t_end_twice, "t_end"),
        ("i.json", &id_twice, "id"),
        ("t.csv", &csv_twice, "t_end"),
    ] {
        assert_ne!(text, &json, "{name}: the edit applies");
        fs::write(d.join(name), text).unwrap();
        // The output in the config's own format, which a read-back keeps.
        let out = if name.ends_with(".json") {
            "out.json"
        } else {
            "out.csv"
        };
        let e = fails_in(d, &["simulate", "--config", name, "-o", out]);
        assert!(
            e.contains(name) && e.contains(&format!("`{key}`")) && e.contains("twice"),
            "{name}: {e}"
        );
        assert!(!d.join(out).exists());
    }
}

/// A byte order mark before a JSON or CSV config gave a TOML parse error.
/// It is skipped: the file reads back to the run it records, the output
/// the same bytes as the original's.
#[test]
fn regression_33_a_config_after_a_byte_order_mark_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (format, name) in [("json", "a.json"), ("csv", "a.csv")] {
        ok_in(
            d,
            &[
                "simulate", "--model", "eq4", "--t-end", "1", "--format", format, "-o", name,
            ],
        );
        let original = fs::read(d.join(name)).unwrap();
        let bom = format!("bom.{format}");
        fs::write(d.join(&bom), [&b"\xEF\xBB\xBF"[..], &original].concat()).unwrap();
        let again = format!("again.{format}");
        ok_in(d, &["simulate", "--config", &bom, "-o", &again]);
        assert!(fs::read(d.join(&again)).unwrap() == original, "{format}");
    }
    // A TOML file after a mark reads as before.
    fs::write(d.join("c.toml"), "\u{FEFF}model = \"eq4\"\nt_end = 1\n").unwrap();
    ok_in(d, &["simulate", "--config", "c.toml", "-o", "t.csv"]);
}

/// The grid-size error printed `1000000000000000000000000 points`; it now
/// writes the count as the outputs write numbers.
#[test]
fn regression_33_the_grid_size_error_writes_the_count_as_a_number() {
    let dir = tempfile::tempdir().unwrap();
    let e = fails_in(
        dir.path(),
        &[
            "sweep",
            "--model",
            "eq4",
            "--alpha-deg",
            "5:60:1000000000000",
            "--r0",
            "1:2:1000000000000",
        ],
    );
    assert!(
        e.contains("the grid has 1e24 points, more than the limit"),
        "{e}"
    );
}
