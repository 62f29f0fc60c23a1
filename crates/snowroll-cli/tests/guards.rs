//! Issue 7, items 6 to 9: no silent garbage. Derived quantities that
//! overflow are refused at validation, loose tolerances are bounded or
//! warned about, requests that cannot be honoured are noted (stderr and the
//! output's metadata) or refused, and messages stay short and exact. Each
//! test is named after the item it pins: `regression_7_<item>_<what>`.

use std::fs;
use std::path::Path;

use assert_cmd::cargo::cargo_bin_cmd;
use assert_cmd::Command;

fn snowroll() -> Command {
    cargo_bin_cmd!("snowroll")
}

/// Runs a command that must fail with exit 1; its stderr.
fn fails(args: &[&str]) -> String {
    let out = snowroll().args(args).assert().code(1);
    String::from_utf8(out.get_output().stderr.clone()).unwrap()
}

/// Runs a command that must succeed; (stdout, stderr).
fn succeeds(args: &[&str]) -> (String, String) {
    let out = snowroll().args(args).assert().success();
    let o = out.get_output();
    (
        String::from_utf8(o.stdout.clone()).unwrap(),
        String::from_utf8(o.stderr.clone()).unwrap(),
    )
}

/// One `error:` line holding every needle.
fn assert_error(stderr: &str, needles: &[&str]) {
    assert_eq!(stderr.lines().count(), 1, "not one line: {stderr:?}");
    assert!(stderr.starts_with("error: "), "{stderr:?}");
    for n in needles {
        assert!(stderr.contains(n), "{stderr:?} lacks {n:?}");
    }
}

/// Files in `dir`, sorted.
fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn regression_7_6_overflowing_derived_quantities_are_refused_by_name() {
    // Each case: arguments, then what the error must name (the quantity and
    // the allowed range, 1e150 being the largest magnitude allowed).
    let cases: [(&[&str], &[&str]); 6] = [
        (
            &["simulate", "--model", "eq4", "--r0", "1e308"],
            &["r0", "1e308", "1e150"],
        ),
        (
            &["simulate", "--model", "eq4", "--density", "1e308"],
            &["density", "1e150"],
        ),
        (
            &["simulate", "--model", "eq4", "--length", "1e308"],
            &["length", "1e150"],
        ),
        // Each parameter in range, their product not: r0 = 1e40 m gives
        // I_C = 3 m0 r0^2/2 = 1.9e163 kg m^2.
        (
            &["simulate", "--model", "eq4", "--r0", "1e40"],
            &["moment of inertia", "eq. (56)", "1e150"],
        ),
        (
            &["turns", "--model", "turns", "--density", "1e308"],
            &["density", "1e150"],
        ),
        // The turn model's mass grows with the turns: after 100 turns with
        // b = 1e60 m the radius is 1e62 m and I_C = 3 m r^2/2 ~ 1e252.
        (
            &["turns", "--model", "turns", "--snow-depth", "1e60"],
            &["after the turns asked for", "1e150", "--turns"],
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.csv");
    for (args, needles) in cases {
        for format in ["csv", "json"] {
            let mut all = args.to_vec();
            all.extend(["--format", format, "-o", out.to_str().unwrap()]);
            assert_error(&fails(&all), needles);
            assert!(entries(dir.path()).is_empty(), "{args:?} left a file");
        }
    }
}

#[test]
fn regression_7_6_valid_extremes_write_only_finite_numbers() {
    // The largest and smallest scales the validation allows still give
    // finite numbers (or a clear error), never inf, NaN or a JSON null.
    let cases: [&[&str]; 4] = [
        &["simulate", "--model", "eq4", "--r0", "1e30", "--x-end", "1"],
        &[
            "simulate",
            "--model",
            "eq14",
            "--density",
            "1e100",
            "--t-end",
            "1",
        ],
        &[
            "simulate", "--model", "loney", "--v0", "1e50", "--t-end", "1",
        ],
        &[
            "turns",
            "--model",
            "turns",
            "--density",
            "1e100",
            "--turns",
            "3",
        ],
    ];
    for args in cases {
        for format in ["csv", "json"] {
            let mut all = args.to_vec();
            all.extend(["--format", format]);
            let out = snowroll().args(&all).output().unwrap();
            let stdout = String::from_utf8(out.stdout).unwrap();
            let stderr = String::from_utf8(out.stderr).unwrap();
            assert!(
                matches!(out.status.code(), Some(0 | 1)),
                "{all:?}: {stderr}"
            );
            // No `inf` or `nan` anywhere: the friction ratio |F|/N of a log
            // off the ground (N <= 0) is undefined and left empty.
            let mut columns: Vec<&str> = Vec::new();
            for line in stdout
                .lines()
                .filter(|l| format == "csv" && !l.starts_with('#') && !l.is_empty())
            {
                if columns.is_empty() {
                    columns = line.split(',').collect();
                    continue;
                }
                for (field, column) in line.split(',').zip(&columns) {
                    let f = field.to_ascii_lowercase();
                    assert!(
                        !(f.contains("inf") || f.contains("nan")),
                        "{all:?} wrote {field} in {column}"
                    );
                    assert!(
                        !f.is_empty() || column.ends_with("friction_ratio"),
                        "{all:?}: empty cell in {column}"
                    );
                }
            }
            if format == "json" && !stdout.is_empty() {
                let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
                assert_no_null_number(&doc, "", &all);
            }
        }
    }
}

/// serde_json writes NaN and infinity as `null`: the only nulls allowed
/// are the options that were not set (the parameters whose default is none
/// in the table, e.g. `x_end`, `turns`, `mu`, `dt`, `times`; and `x_end_m`)
/// and the friction ratio of a log off the ground (undefined where N <= 0).
fn assert_no_null_number(v: &serde_json::Value, path: &str, args: &[&str]) {
    match v {
        serde_json::Value::Null => assert!(
            snowroll::PARAMS
                .iter()
                .filter(|p| p.default_value() == snowroll::Value::None)
                .map(|p| p.key)
                .chain(["x_end_m", "friction_ratio"])
                .any(|k| path.ends_with(&format!(".{k}"))),
            "{args:?}: null at {path}"
        ),
        serde_json::Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                assert_no_null_number(item, &format!("{path}[{i}]"), args);
            }
        }
        serde_json::Value::Object(map) => {
            for (k, item) in map {
                assert_no_null_number(item, &format!("{path}.{k}"), args);
            }
        }
        _ => {}
    }
}

#[test]
fn regression_7_9_header_numbers_are_shortest_round_trip_not_hundreds_of_digits() {
    let (stdout, _) = succeeds(&[
        "simulate",
        "--model",
        "eq4",
        "--density",
        "1e100",
        "--snow-depth",
        "0.30000000000000004",
        "--t-end",
        "1",
        "--dt",
        "1e-5",
    ]);
    for line in [
        "# density = 1e100",
        "# snow_depth = 0.30000000000000004",
        "# sampling = every 1e-5 s",
    ] {
        assert!(
            stdout.lines().any(|l| l == line),
            "no {line:?} in\n{stdout}"
        );
    }
    // Shortest round-trip digits of an f64 are at most 17.
    let longest_digits = stdout
        .lines()
        .filter(|l| l.starts_with('#'))
        .flat_map(|l| l.split(|c: char| !c.is_ascii_digit()))
        .map(str::len)
        .max();
    assert!(
        longest_digits <= Some(17),
        "{longest_digits:?} digits in a row"
    );
}

#[test]
fn regression_7_7_atol_is_bounded_by_the_scale_of_the_state() {
    // Default scenario, eq. (4): r0 = 0.1 m < sqrt(g r0) = 0.99 m/s, so the
    // bound is 1e-3 r0 = 1e-4.
    for atol in ["1e308", "1e6", "0.001"] {
        let err = fails(&["simulate", "--model", "eq4", "--atol", atol]);
        assert_error(&err, &["atol", "atol <= 0.0001", "scale of the state"]);
    }
    // Turn models: the state is theta (rad), omega (rad/s); the scale is
    // min(1, sqrt(g/r0)) = 1, the bound 1e-3.
    let err = fails(&["turns", "--model", "turns", "--atol", "0.01"]);
    assert_error(&err, &["atol <= 0.001"]);
    // At the bound the run goes through, with a warning on stderr and in
    // the output's metadata.
    let (stdout, stderr) = succeeds(&[
        "simulate", "--model", "eq4", "--atol", "1e-4", "--t-end", "1",
    ]);
    assert!(stderr.starts_with("warning: tolerances looser"), "{stderr}");
    assert!(stdout.contains("# warning = tolerances looser"), "{stdout}");
}

#[test]
fn regression_7_7_loose_tolerances_are_warned_about_and_tight_ones_are_not() {
    let (stdout, stderr) = succeeds(&[
        "simulate", "--model", "eq4", "--rtol", "1e-3", "--t-end", "1", "--format", "json",
    ]);
    assert!(stderr.contains("rtol = 1e-3"), "{stderr}");
    let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let warnings = doc["params"]["warnings"].as_array().unwrap();
    assert!(warnings
        .iter()
        .any(|w| w.as_str().unwrap().contains("looser")));
    // The defaults (rtol 1e-10, atol 1e-12) and the claims' accuracy
    // (1e-6 relative) give no warning.
    for args in [
        &["simulate", "--model", "eq4", "--t-end", "1"][..],
        &[
            "simulate", "--model", "eq4", "--t-end", "1", "--rtol", "1e-6", "--atol", "1e-7",
        ],
        &["turns", "--model", "turns", "--turns", "2"],
    ] {
        let (_, stderr) = succeeds(args);
        assert!(!stderr.contains("warning"), "{args:?}: {stderr}");
    }
}

#[test]
fn regression_7_7_a_turn_model_of_huge_radius_works_or_is_refused_clearly() {
    // r0 = 1e155 m is beyond the magnitudes the program computes in.
    let err = fails(&["turns", "--model", "turns", "--r0", "1e155"]);
    assert_error(&err, &["r0", "1e155", "1e150"]);
    // r0 = 1e20 m: sqrt(g/r0) = 3e-10 rad/s; the default atol shrinks with
    // the scale, so the log moves as eq. (4)'s start does: from rest, with
    // a(0) = (2/3) g sin(alpha) for a thin layer, x(t) = g sin(alpha) t^2/3.
    let (stdout, _) = succeeds(&[
        "simulate", "--model", "turns", "--r0", "1e20", "--t-end", "1000",
    ]);
    // The last data row (rows are streamed; the stop line follows them).
    let last = stdout.lines().rev().find(|l| !l.starts_with('#')).unwrap();
    let x: f64 = last.split(',').nth(1).unwrap().parse().unwrap();
    let expected = 9.81 * 0.5 * 1000.0f64.powi(2) / 3.0;
    // b/r0 = 1e-22: the layer changes a by O(b/r0); the integrator's 1e-10.
    assert!(
        (x / expected - 1.0).abs() < 1e-8,
        "x = {x}, expected {expected}"
    );
}

#[test]
fn regression_7_8_times_after_t_end_are_refused_with_their_count() {
    // Known before the run: an error is clearer than a silent drop.
    let err = fails(&["simulate", "--model", "eq4", "--times", "50,100,150,200"]);
    assert_error(&err, &["2 of the 4", "t_end = 100 s", "150 s", "--t-end"]);
    let err = fails(&["simulate", "--model", "eq4", "--times", "150"]);
    assert_error(&err, &["1 of the 1", "t_end = 100 s"]);
}

#[test]
fn regression_7_8_times_after_an_early_stop_are_noted_on_stderr_and_in_the_output() {
    // x_end = 1 m stops eq. (4) well before t = 5 s (x ~ g sin(alpha) t^2/3 = 1 m at t ~ 0.8 s).
    let (stdout, stderr) = succeeds(&[
        "simulate", "--model", "eq4", "--x-end", "1", "--times", "0.5,5,10", "--t-end", "10",
    ]);
    let note = "2 of the 3 requested times are after the stop";
    assert!(stderr.contains(note), "{stderr}");
    assert!(
        stdout
            .lines()
            .any(|l| l.starts_with("# note = ") && l.contains(note)),
        "{stdout}"
    );
    let rows = stdout.lines().filter(|l| !l.starts_with('#')).count();
    assert_eq!(rows, 1 + 1, "header and the one time before the stop");
    let (stdout, _) = succeeds(&[
        "simulate", "--model", "eq4", "--x-end", "1", "--times", "0.5,5", "--format", "json",
    ]);
    let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    // Notes are known only when the run has ended: they follow the rows.
    let notes = doc["notes"].as_array().unwrap();
    assert!(
        notes
            .iter()
            .any(|n| n.as_str().unwrap().contains("1 of the 2")),
        "{notes:?}"
    );
}

#[test]
fn regression_7_8_repeated_times_are_refused() {
    let err = fails(&["simulate", "--model", "eq4", "--times", "1,1"]);
    assert_error(&err, &["repeated"]);
    let err = fails(&["simulate", "--model", "eq4", "--times", "1,2,2,3"]);
    assert_error(&err, &["repeated"]);
}

#[test]
fn regression_7_8_a_second_config_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.toml"), dir.path().join("b.toml"));
    fs::write(&a, "model = 'eq4'\nt-end = 1\n").unwrap();
    fs::write(&b, "model = 'eq14'\nt-end = 2\n").unwrap();
    let joined = format!("--config={}", b.display());
    for second in [vec!["--config", b.to_str().unwrap()], vec![joined.as_str()]] {
        let mut args = vec!["simulate", "--config", a.to_str().unwrap()];
        args.extend(second);
        let out = snowroll().args(&args).assert().code(2);
        let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
        assert!(err.contains("--config was given 2 times"), "{err}");
    }
    // One config is fine.
    succeeds(&["simulate", "--config", a.to_str().unwrap()]);
}

#[test]
fn regression_7_8_a_turn_run_that_stalls_records_the_stop_and_notes_it() {
    // alpha = 1 degree is below the first turn's stall slope of the
    // default scenario: the log stops within its first turn.
    for format in ["csv", "json"] {
        let (stdout, stderr) = succeeds(&[
            "turns",
            "--model",
            "turns",
            "--alpha-deg",
            "1",
            "--format",
            format,
        ]);
        let note = "after 0 of the 100 turns asked for";
        assert!(
            stderr.contains(note) && stderr.contains("stall"),
            "{stderr}"
        );
        if format == "csv" {
            assert!(stdout.contains("# stop = stalled"), "{stdout}");
            assert!(
                stdout
                    .lines()
                    .any(|l| l.starts_with("# note = ") && l.contains(note)),
                "{stdout}"
            );
        } else {
            let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
            assert_eq!(doc["stop"]["reason"], "stalled");
            // Notes follow the rows and the stop (known only at the end).
            assert!(doc["notes"][0].as_str().unwrap().contains(note));
        }
    }
}

#[test]
fn regression_7_9_values_are_case_insensitive_everywhere() {
    let (json, _) = succeeds(&[
        "simulate", "--model", "EQ4", "--format", "JSON", "--t-end", "0.1",
    ]);
    assert!(json.trim_start().starts_with('{'), "{json}");
    let (csv, _) = succeeds(&[
        "turns",
        "--model",
        "Turns-Exact",
        "--format",
        "Csv",
        "--turns",
        "1",
    ]);
    assert!(csv.starts_with("# snowroll"), "{csv}");
    let (table, _) = succeeds(&["models", "--format", "JSON"]);
    assert!(table.trim_start().starts_with('{') || table.trim_start().starts_with('['));
}

#[test]
fn regression_7_9_turns_suggests_only_turn_models() {
    let out = snowroll()
        .args(["turns", "--model", "turnz"])
        .assert()
        .code(2);
    let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        err.contains("[possible values: turns, turns-exact]"),
        "{err}"
    );
    assert!(err.contains("a similar value exists: 'turns'"), "{err}");
    assert!(!err.contains("torque-cm"), "{err}");
}

#[test]
fn regression_7_9_long_bad_values_are_cut_in_messages() {
    // On the command line (one argument may hold up to 128 KiB on Linux)...
    let long = "x".repeat(100_000);
    let out = snowroll()
        .args(["simulate", "--model", &long])
        .assert()
        .code(2);
    let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(err.len() < 2_000, "{} bytes of message", err.len());
    assert!(err.contains("100002 characters in all"), "{err}");
    // ... and in a config file (10 MB).
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join("c.toml");
    fs::write(&config, format!("model = \"{}\"\n", "y".repeat(10_000_000))).unwrap();
    let err = fails(&["simulate", "--config", config.to_str().unwrap()]);
    assert!(err.len() < 2_000, "{} bytes of message", err.len());
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn regression_7_9_paths_that_cannot_be_outputs_are_named_once() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("afile");
    fs::write(&file, "mine\n").unwrap();
    let err = fails(&[
        "paper",
        "--out",
        file.to_str().unwrap(),
        "--turns",
        "10",
        "--quiet",
    ]);
    assert_error(&err, &["not a directory"]);
    assert_eq!(err.matches("exists").count(), 1, "{err}");
    let err = fails(&[
        "simulate",
        "--model",
        "eq4",
        "-o",
        dir.path().to_str().unwrap(),
    ]);
    assert_error(&err, &["is a directory"]);
    assert!(!err.contains("busy"), "{err}");
    // `-o` never overwrites the run's own config file.
    let config = dir.path().join("c.toml");
    fs::write(&config, "model = 'eq4'\nt-end = 1\n").unwrap();
    let c = config.to_str().unwrap();
    let err = fails(&["simulate", "--config", c, "-o", c]);
    assert_error(&err, &["--config"]);
    assert_eq!(
        fs::read_to_string(&config).unwrap(),
        "model = 'eq4'\nt-end = 1\n"
    );
    assert_eq!(fs::read_to_string(&file).unwrap(), "mine\n");
}
