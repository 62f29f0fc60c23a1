//! One regression test for each finding of the fuzz harness
//! (`tests/fuzz/`, `scripts/fuzz.sh`), run on the binary.

use assert_cmd::cargo::cargo_bin_cmd;

/// Runs `snowroll ARGS` to its end; returns the exit code, after checking
/// that it did not panic.
fn ends(args: &[&str]) -> i32 {
    let out = cargo_bin_cmd!("snowroll").args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    let code = out.status.code().unwrap();
    assert!(code == 0 || code == 1, "{args:?}: exit {code}: {stderr}");
    code
}

/// Loney's closed form with v0 = 1e308 m/s (or 1e200) overflowed inside
/// the quadrature of t(x); the bisection then never met its tolerance and
/// ran through 2^40 intervals (hours). Now each integral has a budget.
#[test]
fn regression_7_loney_with_an_overflowing_speed_ends() {
    for v0 in ["1e308", "1e200"] {
        ends(&["simulate", "--model", "loney", "--v0", v0]);
        ends(&["simulate", "--model", "loney", "--v0", v0, "--dt", "1"]);
    }
}

/// Not a defect of the program but of the harness, kept so that the
/// behaviour it checked stays pinned: a config's `output` spelt as a TOML
/// literal string (`output = '''x'''`) is the output path like any other.
#[test]
fn regression_7_a_config_output_in_any_toml_string_form_is_the_output() {
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join("c.toml");
    std::fs::write(&config, "model = 'eq4'\nt-end = 1\noutput = '''x.csv'''\n").unwrap();
    cargo_bin_cmd!("snowroll")
        .current_dir(dir.path())
        .args(["simulate", "--config", "c.toml"])
        .assert()
        .success();
    assert!(dir.path().join("x.csv").is_file());
}

/// The config reader looked for the first byte that is not white space by
/// rescanning everything read so far at each 8 KiB chunk: a JSON output
/// after 9 MiB of blanks took minutes (the fuzzing of the readers, issue
/// 20). Each chunk is now scanned once: blanks just under the 8 MiB limit
/// and a JSON output read back at once (the same run again), blanks past
/// it refused with the limit.
#[test]
fn regression_20_a_config_after_megabytes_of_blanks_is_read_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    cargo_bin_cmd!("snowroll")
        .current_dir(d)
        .args([
            "simulate", "--model", "eq4", "--t-end", "1", "--format", "json", "-o", "a.json",
        ])
        .assert()
        .success();
    let json = std::fs::read(d.join("a.json")).unwrap();
    for (blanks, works) in [((8 << 20) - 1024, true), ((8 << 20) + (64 << 10), false)] {
        let mut text = vec![b'\n'; blanks];
        text.extend_from_slice(&json);
        std::fs::write(d.join("b.json"), text).unwrap();
        let started = std::time::Instant::now();
        let out = cargo_bin_cmd!("snowroll")
            .current_dir(d)
            .args(["simulate", "--config", "b.json", "-o", "again.json"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.success(), works, "{blanks} blanks: {stderr}");
        if works {
            assert_eq!(std::fs::read(d.join("again.json")).unwrap(), json);
        } else {
            assert!(stderr.contains("8 MiB"), "{stderr}");
        }
        // A linear scan of 8 MiB takes milliseconds; the quadratic one took
        // seconds even optimised.
        assert!(
            started.elapsed() < std::time::Duration::from_secs(20),
            "{blanks}"
        );
    }
}
