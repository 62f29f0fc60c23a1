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

/// A sweep whose grid held the subnormal `alpha_deg = 4.9e-324` wrote
/// `a_over_g_sin_alpha = -inf` (the energy model) and `NaN` (eq. (4)): the
/// angle became 0 rad, and the acceleration was divided by g sin 0 = 0 (the
/// fuzzing of the readers, seed 2027). Such a slope is now refused before
/// anything is written, in a grid file as on the command line and in
/// `simulate`, naming the angle and the range; the smallest slope allowed
/// (1e-150 rad, here 1e-100 degrees) sweeps to finite numbers only,
/// a_over_g_sin_alpha included (about -1.9e100 for the energy model, which
/// does not start there: a(0) is about -2b/(pi r0) g cos alpha, eq. (14)).
#[test]
fn regression_20_a_subnormal_slope_is_refused_and_no_sweep_writes_a_non_finite_number() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("g.toml"), "alpha_deg = \"4.9e-324:30:3\"\n").unwrap();
    let refused = [
        &[
            "sweep",
            "--model",
            "eq4,energy,turns",
            "--grid",
            "g.toml",
            "-o",
            "s.csv",
        ][..],
        &[
            "sweep",
            "--model",
            "energy",
            "--alpha-deg",
            "4.9e-324:30:3",
            "-o",
            "s.csv",
        ],
        &["simulate", "--model", "energy", "--alpha-deg", "4.9e-324"],
    ];
    for args in refused {
        let out = cargo_bin_cmd!("snowroll")
            .current_dir(dir.path())
            .args(args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {err}");
        assert!(
            err.contains("slope angle alpha (rad)")
                && err.contains("1e-150")
                && err.contains("--alpha-deg"),
            "{args:?}: {err}"
        );
        assert!(
            out.stdout.is_empty() && !dir.path().join("s.csv").exists(),
            "{args:?}"
        );
    }
    let out = cargo_bin_cmd!("snowroll")
        .args([
            "sweep",
            "--model",
            "eq4,energy,turns",
            "--alpha-deg",
            "1e-100,1e-50,30",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<&str> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .collect();
    assert_eq!(rows.len(), 9, "{text}");
    for row in rows {
        for cell in row.split(',') {
            let lower = cell.to_ascii_lowercase();
            assert!(!lower.contains("nan") && !lower.contains("inf"), "{row}");
        }
    }
}
