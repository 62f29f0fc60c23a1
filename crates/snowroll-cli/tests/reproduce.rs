//! Issue 9, "one vocabulary, and runs that reproduce": an output of
//! snowroll given back as `--config` reproduces its run byte for byte, in
//! its own format, for each command; the parameter names are the same in
//! flags (kebab-case), config files, outputs and JSON (snake_case); the names
//! of earlier outputs still read.

use std::fs;
use std::path::Path;

use assert_cmd::cargo::cargo_bin_cmd;

fn run(dir: &Path, args: &[&str]) {
    let out = cargo_bin_cmd!("snowroll")
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn fails(dir: &Path, args: &[&str]) -> String {
    let out = cargo_bin_cmd!("snowroll")
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{args:?} should fail");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Runs `first`, writing `name`; then the same command with only
/// `--config name`, writing `again`; the two files must be identical.
fn reproduces(command: &str, first: &[&str], name: &str) {
    reproduces_with(command, first, &[], name);
}

/// [`reproduces`], with `flags` given again on the second run: flags that
/// outputs do not record (`turns --method`, which outputs leave out so that
/// an `--method ode` output stays byte for byte what it was before the
/// closed form existed).
fn reproduces_with(command: &str, first: &[&str], flags: &[&str], name: &str) {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec![command];
    args.extend_from_slice(first);
    args.extend_from_slice(flags);
    args.extend_from_slice(&["-o", name]);
    run(dir.path(), &args);
    let again = format!("again-{name}");
    let mut args = vec![command, "--config", name];
    args.extend_from_slice(flags);
    args.extend_from_slice(&["-o", &again]);
    run(dir.path(), &args);
    let (a, b) = (
        fs::read(dir.path().join(name)).unwrap(),
        fs::read(dir.path().join(&again)).unwrap(),
    );
    assert!(
        a == b,
        "{command} {first:?}: --config {name} wrote a different file:\n{}\n---\n{}",
        String::from_utf8_lossy(&a),
        String::from_utf8_lossy(&b)
    );
}

#[test]
fn a_simulate_json_output_reproduces_its_run() {
    // Every scenario parameter away from its default, and a grid of times.
    let run = [
        "--model",
        "eq14",
        "--alpha-deg",
        "25.5",
        "--snow-depth",
        "0.02",
        "--r0",
        "0.15",
        "--g",
        "9.8",
        "--density",
        "350",
        "--length",
        "2",
        "--v0",
        "0.3",
        "--t-end",
        "12",
        "--dt",
        "0.7",
        "--rtol",
        "1e-9",
        "--atol",
        "1e-11",
        "--format",
        "json",
    ];
    reproduces("simulate", &run, "run.json");
}

#[test]
fn a_simulate_csv_output_reproduces_its_run() {
    let run = [
        "--model",
        "turns",
        "--times",
        "0.1,0.3,2",
        "--x-end",
        "50",
        "--rtol",
        "1e-9",
    ];
    reproduces("simulate", &run, "run.csv");
    // Every accepted step, an odd angle (shortest round-trip numbers in the header).
    reproduces(
        "simulate",
        &[
            "--model",
            "eq4",
            "--alpha-deg",
            "0.1234567890123",
            "--t-end",
            "3",
        ],
        "steps.csv",
    );
    // A run outside a model's range: its warning is recorded, and comes back.
    reproduces(
        "simulate",
        &["--model", "energy", "--snow-depth", "0.03", "--t-end", "2"],
        "warned.csv",
    );
}

#[test]
fn a_turns_output_reproduces_its_run_in_either_format() {
    reproduces(
        "turns",
        &[
            "--model",
            "turns-exact",
            "--turns",
            "7",
            "--alpha-deg",
            "35",
        ],
        "t.csv",
    );
    reproduces(
        "turns",
        &["--model", "turns", "--turns", "4", "--format", "json"],
        "t.json",
    );
}

/// The contact settings of issue 10 (`--on-hop`, `--mu`, `--collision`)
/// are recorded and read back. At 80° a turn-model log hops in turn 1
/// (`docs/contact-forces.md` §4.4): with `--on-hop continue` the table goes
/// on to the 5 turns asked for, and a turn with a negative minimum of N shows
/// where contact was lost.
#[test]
fn contact_settings_reproduce_their_runs() {
    let steep = ["--model", "turns", "--alpha-deg", "80", "--turns", "5"];
    let continued = [&steep[..], &["--on-hop", "continue"]].concat();
    reproduces("turns", &continued, "hop.csv");
    reproduces(
        "turns",
        &[&continued[..], &["--format", "json"]].concat(),
        "hop.json",
    );
    reproduces(
        "simulate",
        &[
            &steep[..],
            &["--on-hop", "continue", "--mu", "0.7", "--dt", "0.1"],
        ]
        .concat(),
        "slip.csv",
    );
    reproduces(
        "turns",
        &[
            "--model",
            "turns-exact",
            "--turns",
            "6",
            "--collision",
            "pivot",
            "--mu",
            "2",
        ],
        "pivot.csv",
    );

    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &[&["turns"], &continued[..], &["-o", "c.csv"]].concat(),
    );
    run(
        dir.path(),
        &[&["turns"], &steep[..], &["-o", "s.csv"]].concat(),
    );
    let text = |name: &str| fs::read_to_string(dir.path().join(name)).unwrap();
    let (c, s) = (text("c.csv"), text("s.csv"));
    assert!(c.contains("# on_hop = continue"), "{c}");
    assert!(s.contains("# on_hop = stop"), "{s}");
    let rows = |t: &str| t.lines().filter(|l| !l.starts_with('#')).count() - 1;
    assert_eq!(rows(&c), 5, "{c}");
    assert_eq!(rows(&s), 1, "stops in turn 1: {s}");
}

/// The limits of issue 7 (`--max-rows`, `--max-steps`) are recorded and read
/// back: a run cut short by either reproduces its rows and its stop.
#[test]
fn limits_reproduce_their_runs() {
    // Every accepted step of eq. (4) for 30 s takes more than 10 rows (17
    // Taylor steps since issue 37; 40 rows were asked for before, when
    // DOP853 took more than 60).
    let rows = ["--model", "eq4", "--t-end", "30", "--max-rows", "10"];
    reproduces("simulate", &rows, "rows.csv");
    reproduces(
        "simulate",
        &[&rows[..], &["--format", "json"]].concat(),
        "rows.json",
    );
    // 25 integrator steps end a turn-model run within its first turns (the
    // integrator's: the closed form takes no steps).
    let steps = ["--model", "turns", "--turns", "50", "--max-steps", "25"];
    let ode = ["--method", "ode"];
    reproduces_with("turns", &steps, &ode, "steps.csv");
    reproduces_with(
        "turns",
        &[&steps[..], &["--format", "json"]].concat(),
        &ode,
        "steps.json",
    );

    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &[&["simulate"], &rows[..], &["-o", "r.csv"]].concat(),
    );
    run(
        dir.path(),
        &[&["turns"], &steps[..], &ode[..], &["-o", "s.csv"]].concat(),
    );
    let text = |name: &str| fs::read_to_string(dir.path().join(name)).unwrap();
    let (r, s) = (text("r.csv"), text("s.csv"));
    assert!(r.contains("# max_rows = 10\n"), "{r}");
    assert!(r.contains("# stop = row-limit"), "{r}");
    assert!(s.contains("# max_steps = 25\n"), "{s}");
    assert!(s.contains("# stop = step-limit"), "{s}");
    let data = |t: &str| t.lines().filter(|l| !l.starts_with('#')).count() - 1;
    assert_eq!(data(&r), 10, "{r}");
    assert!(data(&s) < 50, "{s}");
}

#[test]
fn an_output_of_the_other_command_is_refused_with_the_reason() {
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &["turns", "--model", "turns", "--turns", "2", "-o", "t.csv"],
    );
    let err = fails(dir.path(), &["simulate", "--config", "t.csv"]);
    assert!(err.contains("output of `snowroll turns`"), "{err}");
    run(
        dir.path(),
        &[
            "simulate", "--model", "turns", "--format", "json", "-o", "s.json",
        ],
    );
    let err = fails(dir.path(), &["turns", "--config", "s.json"]);
    assert!(err.contains("output of `snowroll simulate`"), "{err}");
}

#[test]
fn outputs_and_config_files_use_the_flag_names() {
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &[
            "simulate",
            "--model",
            "eq4",
            "--snow-depth",
            "0.02",
            "--format",
            "json",
            "-o",
            "a.json",
        ],
    );
    let doc: serde_json::Value =
        serde_json::from_slice(&fs::read(dir.path().join("a.json")).unwrap()).unwrap();
    let params = doc["params"].as_object().unwrap();
    for key in [
        "alpha_deg",
        "snow_depth",
        "r0",
        "g",
        "density",
        "length",
        "v0",
        "t_end",
        "x_end",
        "turns",
        "rtol",
        "atol",
    ] {
        assert!(params.contains_key(key), "params lack `{key}`: {params:?}");
    }
    // The same run from a TOML file with the flags' own spelling, with
    // snake_case, and with the names of earlier outputs: the same bytes.
    for (name, text) in [
        (
            "kebab.toml",
            "model = \"eq4\"\nsnow-depth = 0.02\nformat = \"json\"\n",
        ),
        (
            "snake.toml",
            "model = \"eq4\"\nsnow_depth = 0.02\nformat = \"JSON\"\n",
        ),
        (
            "old.toml",
            "model = \"eq4\"\nsnow_depth_m = 0.02\nslope_deg = 30\nformat = \"json\"\n",
        ),
    ] {
        fs::write(dir.path().join(name), text).unwrap();
        let out = format!("{name}.json");
        run(dir.path(), &["simulate", "--config", name, "-o", &out]);
        assert_eq!(
            fs::read(dir.path().join("a.json")).unwrap(),
            fs::read(dir.path().join(&out)).unwrap(),
            "{name}"
        );
    }
}

#[test]
fn flags_override_an_output_read_as_config() {
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &["simulate", "--model", "eq4", "--t-end", "2", "-o", "a.csv"],
    );
    run(
        dir.path(),
        &[
            "simulate",
            "--config",
            "a.csv",
            "--alpha-deg",
            "40",
            "-o",
            "b.csv",
        ],
    );
    let text = fs::read_to_string(dir.path().join("b.csv")).unwrap();
    assert!(
        text.contains("# alpha_deg = 40\n") && text.contains("# t_end = 2\n"),
        "{text}"
    );
    // G = g sin 40°, a(0) = (2/3) G for eq. (4) from rest (no snow term at v = 0).
    let row = text.lines().find(|l| l.starts_with("0.0,")).unwrap();
    let a0: f64 = row.split(',').nth(3).unwrap().parse().unwrap();
    let want = 2.0 / 3.0 * 9.81 * 40f64.to_radians().sin();
    assert!((a0 - want).abs() < 1e-12 * want, "{a0} vs {want}");
}

#[test]
fn a_snowball_run_reproduces_its_run_in_either_format() {
    // issue 11: `shape` and `swath_width` are recorded and read back, in
    // CSV and JSON, from an output and from TOML in either spelling.
    for format in ["csv", "json"] {
        reproduces(
            "simulate",
            &[
                "--model",
                "energy",
                "--shape",
                "sphere",
                "--swath-width",
                "0.07",
                "--t-end",
                "3",
                "--format",
                format,
            ],
            &format!("ball.{format}"),
        );
        reproduces(
            "simulate",
            &[
                "--model", "loney", "--shape", "SPHERE", "--t-end", "2", "--format", format,
            ],
            &format!("natural.{format}"),
        );
        // issue 21: the contact chord is recorded as the word and read back.
        reproduces(
            "simulate",
            &[
                "--model",
                "torque-cm",
                "--shape",
                "sphere",
                "--swath-width",
                "CHORD",
                "--t-end",
                "3",
                "--format",
                format,
            ],
            &format!("chord.{format}"),
        );
    }
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &[
            "simulate",
            "--model",
            "eq4",
            "--shape",
            "sphere",
            "--swath-width",
            "0.05",
            "--t-end",
            "2",
            "-o",
            "a.csv",
        ],
    );
    let text = fs::read_to_string(dir.path().join("a.csv")).unwrap();
    assert!(text.contains("# shape = sphere\n") && text.contains("# swath_width = 0.05\n"));
    fs::write(
        dir.path().join("b.toml"),
        "model = \"eq4\"\nshape = \"Sphere\"\nswath-width = 0.05\nt_end = 2\n",
    )
    .unwrap();
    run(
        dir.path(),
        &["simulate", "--config", "b.toml", "-o", "b.csv"],
    );
    assert_eq!(text, fs::read_to_string(dir.path().join("b.csv")).unwrap());
    // The chord from TOML, as the word, gives the run of the flag.
    let flags = [
        "--shape",
        "sphere",
        "--swath-width",
        "chord",
        "--t-end",
        "2",
    ];
    run(
        dir.path(),
        &[&["simulate", "--model", "eq4", "-o", "c.csv"][..], &flags].concat(),
    );
    let chord = fs::read_to_string(dir.path().join("c.csv")).unwrap();
    assert!(chord.contains("# swath_width = chord\n"), "{chord}");
    fs::write(
        dir.path().join("d.toml"),
        "model = \"eq4\"\nshape = \"sphere\"\nswath_width = \"chord\"\nt_end = 2\n",
    )
    .unwrap();
    run(
        dir.path(),
        &["simulate", "--config", "d.toml", "-o", "d.csv"],
    );
    assert_eq!(chord, fs::read_to_string(dir.path().join("d.csv")).unwrap());
}

#[test]
fn a_shape_a_model_cannot_take_is_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let err = fails(
        dir.path(),
        &[
            "simulate", "--model", "turns", "--shape", "sphere", "--turns", "2",
        ],
    );
    assert!(
        err.contains("model turns does not support shape = sphere"),
        "{err}"
    );
    let err = fails(
        dir.path(),
        &["turns", "--model", "turns-exact", "--shape", "sphere"],
    );
    assert!(
        err.contains("turns-exact does not support shape = sphere"),
        "{err}"
    );
    let err = fails(
        dir.path(),
        &["simulate", "--model", "eq4", "--swath-width", "0.1"],
    );
    assert!(
        err.contains("swath width") && err.contains("--shape sphere"),
        "{err}"
    );
    let err = fails(
        dir.path(),
        &[
            "simulate",
            "--model",
            "loney",
            "--shape",
            "sphere",
            "--swath-width",
            "0.1",
        ],
    );
    assert!(err.contains("model loney does not support"), "{err}");
    // Nor the chord (its closed form needs eq. (8)); and a word other than
    // chord is refused by the flag.
    let err = fails(
        dir.path(),
        &[
            "simulate",
            "--model",
            "loney",
            "--shape",
            "sphere",
            "--swath-width",
            "chord",
        ],
    );
    assert!(
        err.contains("model loney does not support") && err.contains("chord"),
        "{err}"
    );
    let out = cargo_bin_cmd!("snowroll")
        .current_dir(dir.path())
        .args(["simulate", "--model", "torque-cm", "--shape", "sphere"])
        .args(["--swath-width", "cord"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("expected a number or chord"), "{err}");
}

/// Issue 21: a fixed swath wider than the ball's diameter 2 r0 at the start
/// is a run warning, shown by simulate and recorded in its output; a width
/// of 2 r0 is not.
#[test]
fn a_swath_wider_than_the_ball_is_warned_and_recorded() {
    let dir = tempfile::tempdir().unwrap();
    for (width, warned) in [("0.25", true), ("0.2", false)] {
        let out = cargo_bin_cmd!("snowroll")
            .current_dir(dir.path())
            .args(["simulate", "--model", "torque-cm", "--shape", "sphere"])
            .args(["--swath-width", width])
            .args(["--t-end", "1", "--format", "json", "-o", "w.json"])
            .output()
            .unwrap();
        assert!(out.status.success());
        let err = String::from_utf8_lossy(&out.stderr);
        let json = fs::read_to_string(dir.path().join("w.json")).unwrap();
        let says = "wider than the ball's diameter 2 r0 = 0.2 m";
        assert_eq!(err.contains(says), warned, "{width}: {err}");
        assert_eq!(json.contains(says), warned, "{width}");
    }
}

/// Issue 11: the losses, the ledger and the terminal stop are settings an
/// output records and a `--config` of it reads back, in either format.
#[test]
fn a_run_with_losses_reproduces_its_run() {
    let lossy = [
        "--model",
        "energy",
        "--drag-coefficient",
        "0.8",
        "--air-density",
        "1.1",
        "--rolling-resistance",
        "0.02",
        "--compaction-energy",
        "2.5",
        "--terminal-tol",
        "1e-6",
        "--t-end",
        "20",
        "--dt",
        "0.5",
    ];
    reproduces("simulate", &lossy, "lossy.json");
    reproduces("simulate", &lossy, "lossy.csv");
    let terminal = [
        "--model",
        "snowless",
        "--drag-coefficient",
        "1",
        "--terminal-tol",
        "1e-8",
    ];
    reproduces("simulate", &terminal, "terminal.csv");
    reproduces("simulate", &terminal, "terminal.json");
    let ledger_only = ["--model", "torque-cm", "--ledger", "--t-end", "5"];
    reproduces("simulate", &ledger_only, "ledger.csv");
    reproduces("simulate", &ledger_only, "ledger.json");
    // The ball's losses, on both growth laws.
    let ball = [
        "--model",
        "torque-cm",
        "--shape",
        "sphere",
        "--drag-coefficient",
        "0.5",
        "--rolling-resistance",
        "0.03",
        "--compaction-energy",
        "1.5",
        "--t-end",
        "5",
    ];
    reproduces("simulate", &ball, "ball.csv");
    let fixed = [&ball[..], &["--swath-width", "0.05", "--format", "json"]].concat();
    reproduces("simulate", &fixed, "fixed.json");
    // The turn models' ledger, per sample and per turn.
    let turns = ["--model", "turns", "--turns", "4", "--ledger"];
    reproduces("simulate", &turns, "turns.csv");
    reproduces("turns", &turns, "table.csv");
    let pivot = [
        "--model",
        "turns-exact",
        "--turns",
        "3",
        "--collision",
        "pivot",
        "--on-hop",
        "continue",
        "--ledger",
        "--format",
        "json",
    ];
    reproduces("turns", &pivot, "pivot.json");
}

/// A loss the model does not carry is refused with the flag's name; a
/// value out of range names the value and its range.
#[test]
fn losses_the_model_does_not_carry_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let err = fails(
        dir.path(),
        &[
            "simulate",
            "--model",
            "turns",
            "--rolling-resistance",
            "0.1",
        ],
    );
    assert!(
        err.contains("--rolling-resistance") && err.contains("turns"),
        "{err}"
    );
    let err = fails(
        dir.path(),
        &[
            "simulate",
            "--model",
            "torque-cm",
            "--drag-coefficient",
            "-1",
        ],
    );
    assert!(
        err.contains("drag_coefficient") && err.contains("-1"),
        "{err}"
    );
}

/// A sweep's output read back with `--config` runs the same grid, shard and
/// method: the same bytes, header (command line included) and rows.
#[test]
fn a_sweep_output_reproduces_its_sweep() {
    // List and range axes, several models (by alias and id), an end
    // distance, the second of three shards.
    let sweep = [
        "--model",
        "eq4,energy,turns",
        "--alpha-deg",
        "10,25",
        "--r0",
        "0.1:0.3:3",
        "--x-end",
        "5",
        "--on-hop",
        "stop,continue",
        "--shard",
        "1/3",
    ];
    reproduces("sweep", &sweep, "map.csv");
    let mut ode = sweep.to_vec();
    ode.extend(["--method", "ode"]);
    reproduces("sweep", &ode, "map-ode.csv");
}

#[cfg(feature = "parquet")]
#[test]
fn a_sweep_parquet_output_reproduces_its_sweep() {
    let sweep = [
        "--model",
        "eq4,energy",
        "--snow-depth",
        "0:0.02:3",
        "--t-end",
        "2,4",
        "--shard",
        "0/2",
    ];
    reproduces("sweep", &sweep, "map.parquet");
}

/// A sweep made from a `--grid` file is read back from its output alone:
/// the axes are in its header.
#[test]
fn a_sweep_from_a_grid_file_reproduces_without_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let grid = dir.path().join("axes.toml");
    fs::write(
        &grid,
        "model = [\"eq4\", \"energy\"]\nalpha_deg = \"5:60:4\"\nv0 = [0, 1.5]\n",
    )
    .unwrap();
    run(dir.path(), &["sweep", "--grid", "axes.toml", "-o", "a.csv"]);
    fs::remove_file(&grid).unwrap();
    run(dir.path(), &["sweep", "--config", "a.csv", "-o", "b.csv"]);
    assert_eq!(
        fs::read(dir.path().join("a.csv")).unwrap(),
        fs::read(dir.path().join("b.csv")).unwrap()
    );
    // Given to --grid by mistake, a sweep output is pointed to --config.
    let e = fails(dir.path(), &["sweep", "--grid", "a.csv"]);
    assert!(e.contains("--config a.csv"), "{e}");
}

/// Flags given with `--config` replace the file's axes; the others stay,
/// and the header's command line is then the run's own.
#[test]
fn flags_override_a_sweep_output_read_as_config() {
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &[
            "sweep",
            "--model",
            "eq4",
            "--alpha-deg",
            "10,20",
            "--r0",
            "0.1,0.2",
            "--shard",
            "1/2",
            "-o",
            "a.csv",
        ],
    );
    run(
        dir.path(),
        &[
            "sweep",
            "--config",
            "a.csv",
            "--alpha-deg",
            "30",
            "-o",
            "b.csv",
        ],
    );
    let b = fs::read_to_string(dir.path().join("b.csv")).unwrap();
    assert!(
        b.contains(
            "# command: snowroll sweep --model torque-cm --alpha-deg 30 --r0 0.1,0.2 \
             --collision note --on-hop stop --output b.csv --shard 1/2\n"
        ),
        "{b}"
    );
    assert!(b.contains("# alpha_deg: 30\n# r0: 0.1,0.2\n"), "{b}");
    // The file's shard 1/2 of the new two-point grid: its second point.
    let rows: Vec<&str> = b.lines().filter(|l| !l.starts_with('#')).skip(1).collect();
    assert_eq!(rows.len(), 1, "{b}");
    assert!(rows[0].starts_with("1,torque-cm,30.0,0.01,0.2,"), "{b}");
    let e = fails(dir.path(), &["sweep", "--config", "missing.csv"]);
    assert!(e.contains("missing.csv"), "{e}");
}
