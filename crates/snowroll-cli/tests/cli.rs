//! The `snowroll` binary end to end: every flag has the effect the physics
//! predicts, outputs record what produced them, and bad input is one clear
//! line on stderr with a non-zero exit.

use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::fs;
use std::path::Path;

use assert_cmd::cargo::cargo_bin_cmd;
use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;
use snowroll::ModelKind;

/// a(0), m(0), r(0) are closed-form expressions the program evaluates in its
/// own order and prints in full (shortest round-trip) precision: only
/// rounding can differ.
const CLOSED_FORM_TOL: f64 = 1e-12;
/// Requested and grid times are set, not integrated: only rounding of k·dt.
const TIME_TOL: f64 = 1e-12;
/// Events are located on the dense output to near machine precision; at
/// rtol 1e-10 the located x or v is off by far less than this (m, m/s).
const EVENT_TOL: f64 = 1e-8;
/// Eq. (8) along an integrated trajectory: x carries the integrator's
/// relative error (rtol 1e-10 by default), r is computed from x.
const EQ8_TOL: f64 = 1e-9;

/// Default slope angle and g, as documented in `--help`.
const ALPHA_DEG: f64 = 30.0;
const G: f64 = 9.81;

fn snowroll() -> Command {
    cargo_bin_cmd!("snowroll")
}

/// Runs `snowroll simulate ARGS`, expecting success; returns stdout.
fn simulate(args: &[&str]) -> String {
    let out = snowroll().arg("simulate").args(args).assert().success();
    String::from_utf8(out.get_output().stdout.clone()).unwrap()
}

/// A config file `name` with `contents` in a fresh temporary directory (kept
/// while the returned guard lives).
fn config_file(name: &str, contents: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    fs::write(&path, contents).unwrap();
    (dir, path)
}

/// Runs `snowroll ARGS`, expecting failure; returns stderr.
fn fails(args: &[&str]) -> String {
    let out = snowroll().args(args).assert().failure();
    String::from_utf8(out.get_output().stderr.clone()).unwrap()
}

/// A parsed CSV output: `# key = value` comments, header, numeric rows.
struct Csv {
    comments: BTreeMap<String, String>,
    first_line: String,
    header: String,
    rows: Vec<Vec<f64>>,
}

impl Csv {
    fn parse(text: &str) -> Csv {
        let mut lines = text.lines();
        let first_line = text.lines().next().unwrap().to_string();
        let mut comments = BTreeMap::new();
        let mut header = String::new();
        for line in lines.by_ref() {
            match line.strip_prefix("# ") {
                Some(c) => {
                    if let Some((k, v)) = c.split_once(" = ") {
                        comments.insert(k.to_string(), v.to_string());
                    }
                }
                None => {
                    header = line.to_string();
                    break;
                }
            }
        }
        // Rows are written as they are computed, so the lines known only at
        // the end (`# stop = ...`, the turn summary) follow them.
        let mut rows = Vec::new();
        for line in lines {
            match line.strip_prefix("# ") {
                Some(c) => {
                    if let Some((k, v)) = c.split_once(" = ") {
                        comments.insert(k.to_string(), v.to_string());
                    }
                }
                // An empty cell is an undefined value (|F|/N where N <= 0): NaN here.
                None => rows.push(
                    line.split(',')
                        .map(|c| {
                            if c.is_empty() {
                                f64::NAN
                            } else {
                                c.parse().unwrap()
                            }
                        })
                        .collect(),
                ),
            }
        }
        Csv {
            comments,
            first_line,
            header,
            rows,
        }
    }

    fn param(&self, key: &str) -> f64 {
        self.comments[key].parse().unwrap()
    }

    /// Column `name` of row `i`.
    fn get(&self, i: usize, name: &str) -> f64 {
        let col = self.header.split(',').position(|h| h == name).unwrap();
        self.rows[i][col]
    }

    fn column(&self, name: &str) -> Vec<f64> {
        (0..self.rows.len()).map(|i| self.get(i, name)).collect()
    }
}

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap()
}

fn close(got: f64, want: f64, tol: f64) -> bool {
    (got - want).abs() <= tol * want.abs().max(1.0)
}

fn assert_close(got: f64, want: f64, tol: f64) {
    assert!(close(got, want, tol), "got {got}, want {want} (tol {tol})");
}

/// App. A / eq. (4) at rest: a(0) = (2/3) g sin alpha.
fn two_thirds_g_sin(alpha_deg: f64, g: f64) -> f64 {
    2.0 / 3.0 * g * alpha_deg.to_radians().sin()
}

// ---------------------------------------------------------------- flags

#[test]
fn alpha_deg_sets_initial_acceleration_to_two_thirds_g_sin_alpha() {
    for alpha in [10.0, 45.0, 70.0] {
        let a = alpha.to_string();
        let csv = Csv::parse(&simulate(&[
            "--model",
            "torque-cm",
            "--alpha-deg",
            &a,
            "--t-end",
            "1",
        ]));
        assert_close(
            csv.get(0, "a_m_s2"),
            two_thirds_g_sin(alpha, G),
            CLOSED_FORM_TOL,
        );
        assert_close(csv.param("alpha_deg"), alpha, CLOSED_FORM_TOL);
    }
}

#[test]
fn g_scales_initial_acceleration() {
    let csv = Csv::parse(&simulate(&[
        "--model", "eq4", "--g", "1.62", "--t-end", "1",
    ]));
    assert_close(
        csv.get(0, "a_m_s2"),
        two_thirds_g_sin(ALPHA_DEG, 1.62),
        CLOSED_FORM_TOL,
    );
}

#[test]
fn v0_enters_the_drag_term_of_eq4() {
    // eq. (4) at x = 0: a = (2/3) g sin alpha - 7 b v0^2 / (6 pi r0^2).
    let (b, r0, v0) = (0.02, 0.15, 3.0);
    let csv = Csv::parse(&simulate(&[
        "--model",
        "torque-cm",
        "--snow-depth",
        "0.02",
        "--r0",
        "0.15",
        "--v0",
        "3",
        "--t-end",
        "1",
    ]));
    let want = two_thirds_g_sin(ALPHA_DEG, G) - 7.0 * b * v0 * v0 / (6.0 * PI * r0 * r0);
    assert_close(csv.get(0, "v_m_s"), v0, CLOSED_FORM_TOL);
    assert_close(csv.get(0, "a_m_s2"), want, CLOSED_FORM_TOL);
}

#[test]
fn r0_density_and_length_set_the_initial_mass() {
    // m0 = pi rho l r0^2 (eq. (37)).
    let csv = Csv::parse(&simulate(&[
        "--model",
        "torque-cm",
        "--r0",
        "0.2",
        "--density",
        "917",
        "--length",
        "2.5",
        "--t-end",
        "1",
    ]));
    assert_close(csv.get(0, "r_m"), 0.2, CLOSED_FORM_TOL);
    assert_close(
        csv.get(0, "mass_kg"),
        PI * 917.0 * 2.5 * 0.2 * 0.2,
        CLOSED_FORM_TOL,
    );
}

#[test]
fn snow_depth_sets_the_growth_of_eq8_and_zero_depth_is_the_snowless_limit() {
    // pi r^2 = pi r0^2 + b x along the run (eq. (8)).
    let csv = Csv::parse(&simulate(&[
        "--model",
        "energy",
        "--snow-depth",
        "0.05",
        "--times",
        "1,2,5,10",
    ]));
    assert_eq!(csv.rows.len(), 4);
    for i in 0..4 {
        let (x, r) = (csv.get(i, "x_m"), csv.get(i, "r_m"));
        assert!(x > 0.0);
        assert_close(PI * r * r, PI * 0.1 * 0.1 + 0.05 * x, EQ8_TOL);
    }
    // b = 0: a = (2/3) g sin alpha throughout (App. A), r stays r0.
    let csv = Csv::parse(&simulate(&[
        "--model",
        "torque-contact",
        "--snow-depth",
        "0",
        "--t-end",
        "5",
    ]));
    for i in 0..csv.rows.len() {
        assert_close(
            csv.get(i, "a_m_s2"),
            two_thirds_g_sin(ALPHA_DEG, G),
            CLOSED_FORM_TOL,
        );
        assert_close(csv.get(i, "r_m"), 0.1, CLOSED_FORM_TOL);
    }
}

#[test]
fn t_end_ends_the_run_there() {
    let csv = Csv::parse(&simulate(&["--model", "torque-cm", "--t-end", "3.5"]));
    let t = csv.column("t_s");
    assert_close(*t.last().unwrap(), 3.5, TIME_TOL);
    assert!(t.windows(2).all(|w| w[1] > w[0]), "times must increase");
    assert!(csv.comments["stop"].starts_with("end-time"));
}

#[test]
fn x_end_stops_at_that_distance_with_a_note() {
    let out = snowroll()
        .args(["simulate", "--model", "torque-cm", "--x-end", "7.5"])
        .args(["--format", "json"])
        .assert()
        .success()
        .stderr(predicate::str::contains("end distance"));
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert_eq!(doc["stop"]["reason"], "distance");
    let x_stop = doc["stop"]["x_m"].as_f64().unwrap();
    assert!((x_stop - 7.5).abs() < EVENT_TOL, "stopped at x = {x_stop}");
    let last = doc["samples"].as_array().unwrap().last().unwrap();
    assert!((last["x_m"].as_f64().unwrap() - 7.5).abs() < EVENT_TOL);
    assert!(doc["stop"]["t_s"].as_f64().unwrap() < 100.0);
}

#[test]
fn times_give_exactly_one_row_per_requested_time() {
    let requested = [0.0, 0.25, 1.0, 2.0, 17.5, 60.0];
    let csv = Csv::parse(&simulate(&[
        "--model",
        "eq6",
        "--times",
        "0,0.25,1,2,17.5,60",
    ]));
    let t = csv.column("t_s");
    assert_eq!(t.len(), requested.len());
    for (got, want) in t.iter().zip(requested) {
        assert_close(*got, want, TIME_TOL);
    }
    assert_eq!(csv.comments["sampling"], "6 requested times");
}

#[test]
fn times_past_the_stop_are_not_written() {
    // The run stops at x = 1 m well before t = 50 s.
    let csv = Csv::parse(&simulate(&[
        "--model",
        "torque-cm",
        "--x-end",
        "1",
        "--times",
        "0.1,0.2,50",
    ]));
    assert_eq!(csv.column("t_s").len(), 2);
}

#[test]
fn dt_gives_a_regular_grid() {
    let csv = Csv::parse(&simulate(&[
        "--model",
        "quasi-circular",
        "--dt",
        "0.5",
        "--t-end",
        "4",
    ]));
    let t = csv.column("t_s");
    assert_eq!(t.len(), 9, "0, 0.5, ..., 4");
    for (k, got) in t.iter().enumerate() {
        assert_close(*got, 0.5 * k as f64, TIME_TOL);
    }
}

#[test]
fn looser_tolerances_take_fewer_steps() {
    // Every accepted step is a row: an adaptive method takes fewer steps
    // when the error it may commit per step is larger. With rolling
    // resistance eq. (4) takes DOP853 steps; without losses it takes
    // Taylor steps (issue 37), whose length depends on the tolerance only
    // through the absolute part of the scale (`taylor.rs`: a looser rtol
    // lowers the order, order 15 at 1e-4 against 28 at 1e-12, and keeps
    // the steps), so there a looser rtol takes no more steps.
    let rows = |losses: &[&str], extra: &[&str]| {
        let mut args = vec!["--model", "torque-cm", "--t-end", "20"];
        args.extend_from_slice(losses);
        args.extend_from_slice(extra);
        Csv::parse(&simulate(&args))
    };
    for losses in [&["--rolling-resistance", "0.01"][..], &[]] {
        let tight = rows(losses, &["--rtol", "1e-12", "--atol", "1e-12"]);
        let loose_rtol = rows(losses, &["--rtol", "1e-4", "--atol", "1e-12"]);
        // The loosest atol allowed here: 1e-3 of r0 = 0.1 m.
        let loose_atol = rows(losses, &["--rtol", "1e-12", "--atol", "1e-4"]);
        if losses.is_empty() {
            assert!(loose_rtol.rows.len() <= tight.rows.len());
        } else {
            assert!(loose_rtol.rows.len() < tight.rows.len());
        }
        assert!(loose_atol.rows.len() < tight.rows.len(), "{losses:?}");
        assert_close(loose_rtol.param("rtol"), 1e-4, CLOSED_FORM_TOL);
        assert_close(loose_atol.param("atol"), 1e-4, CLOSED_FORM_TOL);
    }
}

#[test]
fn csv_records_version_model_and_every_parameter_before_the_header() {
    let csv = Csv::parse(&simulate(&[
        "--model",
        "energy-thin",
        "--snow-depth",
        "0.02",
        "--r0",
        "0.3",
        "--g",
        "9.8",
        "--density",
        "300",
        "--length",
        "2",
        "--v0",
        "0.5",
        "--t-end",
        "2",
        "--x-end",
        "1000",
        "--rtol",
        "1e-9",
        "--atol",
        "1e-11",
    ]));
    assert_eq!(
        csv.first_line,
        format!("# snowroll {}", env!("CARGO_PKG_VERSION"))
    );
    assert_eq!(csv.comments["model"], "energy-thin (eq. (15))");
    for (key, want) in [
        ("alpha_deg", ALPHA_DEG),
        ("snow_depth", 0.02),
        ("r0", 0.3),
        ("g", 9.8),
        ("density", 300.0),
        ("length", 2.0),
        ("v0", 0.5),
        ("t_end", 2.0),
        ("x_end", 1000.0),
        ("rtol", 1e-9),
        ("atol", 1e-11),
    ] {
        assert_close(csv.param(key), want, CLOSED_FORM_TOL);
    }
    assert_eq!(
        csv.header,
        "t_s,x_m,v_m_s,a_m_s2,r_m,mass_kg,normal_n,friction_n,friction_ratio"
    );
}

#[test]
fn json_has_the_documented_keys() {
    let doc = json(&simulate(&[
        "--model",
        "torque-cm",
        "--format",
        "json",
        "--times",
        "0,1",
    ]));
    assert_eq!(doc["snowroll_version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(doc["model"]["id"], "torque-cm");
    assert_eq!(doc["model"]["equation"], "eq. (4)");
    assert_close(
        doc["params"]["snow_depth"].as_f64().unwrap(),
        0.01,
        CLOSED_FORM_TOL,
    );
    assert_eq!(doc["stop"]["reason"], "end-time");
    assert!(doc["stop"]["t_s"].is_number() && doc["stop"]["x_m"].is_number());
    let samples = doc["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 2);
    for key in [
        "t_s",
        "x_m",
        "v_m_s",
        "a_m_s2",
        "r_m",
        "mass_kg",
        "normal_n",
        "friction_n",
        "friction_ratio",
    ] {
        assert!(samples[1][key].is_number(), "sample lacks {key}");
    }
    assert_close(
        samples[0]["a_m_s2"].as_f64().unwrap(),
        two_thirds_g_sin(ALPHA_DEG, G),
        CLOSED_FORM_TOL,
    );
}

#[test]
fn output_writes_the_file_and_nothing_to_stdout() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("run.json");
    snowroll()
        .args(["simulate", "--model", "loney", "--format", "json"])
        .args(["--times", "1,2", "--output"])
        .arg(&path)
        .assert()
        .success()
        .stdout(predicate::str::is_empty());
    let doc = json(&fs::read_to_string(&path).unwrap());
    assert_eq!(doc["model"]["id"], "loney");
    assert_eq!(doc["samples"].as_array().unwrap().len(), 2);
    assert_eq!(entries(dir.path()), vec!["run.json".to_string()]);
}

/// File names in `dir`, sorted.
fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn config_values_are_used_and_flags_override_them() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("run.toml");
    fs::write(
        &path,
        "model = \"eq4\"\nalpha-deg = 45\ng = 9.0\ntimes = [0.0, 1.0, 2.0]\n",
    )
    .unwrap();
    let from_file = Csv::parse(&simulate(&["--config", path.to_str().unwrap()]));
    assert_eq!(from_file.comments["model"], "torque-cm (eq. (4))");
    assert_eq!(from_file.rows.len(), 3);
    assert_close(
        from_file.get(0, "a_m_s2"),
        two_thirds_g_sin(45.0, 9.0),
        CLOSED_FORM_TOL,
    );

    let overridden = Csv::parse(&simulate(&[
        "--config",
        path.to_str().unwrap(),
        "--alpha-deg",
        "20",
        "--model",
        "snowless",
        "--dt",
        "0.5",
        "--t-end",
        "1",
    ]));
    assert_eq!(overridden.comments["model"], "snowless (eq. (95))");
    // g still from the file, alpha from the flag, sampling from the flag.
    assert_close(
        overridden.get(0, "a_m_s2"),
        two_thirds_g_sin(20.0, 9.0),
        CLOSED_FORM_TOL,
    );
    assert_eq!(overridden.rows.len(), 3, "t = 0, 0.5, 1");
}

#[test]
fn model_aliases_are_accepted() {
    for (given, id) in [
        ("eq4", "torque-cm"),
        ("EQ4", "torque-cm"),
        ("eq32+36", "quasi-circular-lift"),
        ("fn4", "loney"),
        ("eq95", "snowless"),
        ("eq73", "turns"),
        ("Turns-Exact", "turns-exact"),
        ("EQ88", "turns-exact"),
    ] {
        let doc = json(&simulate(&[
            "--model", given, "--format", "json", "--times", "0",
        ]));
        assert_eq!(doc["model"]["id"], id, "--model {given}");
    }
}

/// The slope the note of a run that does not start asks for is the run's
/// own (issue 21): the ball's, tan α* = 2b/(π r0) + 3b²/(4π r0²) = 49.4503°
/// at b = 0.05 m, r0 = 0.04 m, not the log's 40.2149°; with rolling
/// resistance c_rr the log's tan α* grows by c_rr (eq. (14):
/// (3 b r0 + b²)/(2π r0²) + 0.5 at the defaults, 28.7817°). Values typed
/// from those closed forms, to the 4 decimals the note prints.
#[test]
fn does_not_start_names_the_run_s_own_threshold() {
    let note = |args: &[&str]| {
        let out = snowroll()
            .args(["simulate", "--model", "energy", "-o", "/dev/null"])
            .args(args)
            .assert()
            .success();
        String::from_utf8_lossy(&out.get_output().stderr).to_string()
    };
    let ball = note(&[
        "--shape",
        "sphere",
        "--snow-depth",
        "0.05",
        "--r0",
        "0.04",
        "--alpha-deg",
        "45",
    ]);
    assert!(ball.contains("needs alpha > 49.4503 degrees"), "{ball}");
    let log = note(&["--snow-depth", "0.05", "--r0", "0.04", "--alpha-deg", "30"]);
    assert!(log.contains("needs alpha > 40.2149 degrees"), "{log}");
    let rolling = note(&["--rolling-resistance", "0.5", "--alpha-deg", "20"]);
    assert!(
        rolling.contains("needs alpha > 28.7817 degrees"),
        "{rolling}"
    );
}

#[test]
fn does_not_start_and_stall_are_reported_on_stderr_with_exit_zero() {
    // Below the stall slope of eq. (14) (fn. 7) the log cannot start from rest.
    let out = snowroll()
        .args(["simulate", "--model", "energy", "--alpha-deg", "1"])
        .assert()
        .success()
        .stderr(predicate::str::contains("does not start"));
    let csv = Csv::parse(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert!(csv.comments["stop"].starts_with("does-not-start"));
    // Pushed, it decelerates (a < 0 there) until v = 0.
    let out = snowroll()
        .args(["simulate", "--model", "energy", "--alpha-deg", "1"])
        .args(["--v0", "0.5", "--format", "json"])
        .assert()
        .success()
        .stderr(predicate::str::contains("stall"));
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert_eq!(doc["stop"]["reason"], "stalled");
    let last = doc["samples"].as_array().unwrap().last().unwrap();
    assert!(last["v_m_s"].as_f64().unwrap().abs() < EVENT_TOL);
    assert!(doc["stop"]["x_m"].as_f64().unwrap() > 0.0);
}

// ---------------------------------------------------------------- turn models

/// v_after / v_end of eq. (89) and r_k = r0 + k b: one product and one
/// quotient of printed (round-trip) numbers, so only rounding can differ.
const COLLISION_TOL: f64 = 1e-12;
/// The collision loss against T_end − T_after: two kinetic energies that
/// agree to O(b/r_k), so cancellation magnifies rounding by about r_k/b.
const LOSS_TOL: f64 = 1e-10;
/// X_k of eq. (74) against the printed x_start (relative).
const EQ74_TOL: f64 = 1e-9;
/// The stderr summary prints fractions of G with 6 decimals.
const SUMMARY_PRINT_TOL: f64 = 1e-6;

/// Runs `snowroll turns ARGS`, expecting success; returns stdout and stderr.
fn turns(args: &[&str]) -> (String, String) {
    let out = snowroll().arg("turns").args(args).assert().success();
    let o = out.get_output();
    (
        String::from_utf8(o.stdout.clone()).unwrap(),
        String::from_utf8(o.stderr.clone()).unwrap(),
    )
}

/// The header of the per-turn table.
const TURN_COLUMNS: &str = "turn,t_start_s,x_start_m,v_start_m_s,t_end_s,v_end_m_s,v_after_m_s,\
collision_loss_j,mean_a_turn_m_s2,min_a_m_s2,max_a_m_s2,mean_a_with_collision_m_s2,\
min_normal_n,min_normal_over_mg,max_friction_ratio";

/// Issue 10: at 80° the turn model hops in turn 1 (`docs/contact-forces.md`
/// §4.4); the note on stderr names t, x, v, turn, theta and omega, and the
/// CSV records `mu` and `collision`. With `--collision pivot` at 1°, v0 =
/// 0.45 m/s the log is stuck at the first step (§6.3), and `--mu` below
/// tan α/3 makes the snowless cylinder slip at once (§5.1).
#[test]
fn regression_10_hop_slip_and_stuck_are_reported() {
    let out = snowroll()
        .args([
            "simulate",
            "--model",
            "turns",
            "--alpha-deg",
            "80",
            "--turns",
            "5",
        ])
        .assert()
        .success()
        .stderr(predicate::str::contains("hops"))
        .stderr(predicate::str::contains("turn 1 (0-based), theta = 3.98"))
        .stderr(predicate::str::contains("omega = "));
    let csv = Csv::parse(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert!(csv.comments["stop"].starts_with("hop "));
    assert!(!csv.comments.contains_key("mu"));
    assert_eq!(csv.comments["collision"], "note");
    snowroll()
        .args([
            "simulate",
            "--model",
            "turns",
            "--collision",
            "pivot",
            "--alpha-deg",
            "1",
        ])
        .args(["--v0", "0.45", "--turns", "3"])
        .assert()
        .success()
        .stderr(predicate::str::contains("stuck"));
    snowroll()
        .args(["simulate", "--model", "snowless", "--mu", "0.19"])
        .assert()
        .success()
        .stderr(predicate::str::contains("slips"));
    snowroll()
        .args(["simulate", "--model", "snowless", "--mu", "0"])
        .assert()
        .failure()
        .stderr(predicate::str::contains("mu"));
}

#[test]
fn turns_gives_exactly_n_rows_numbered_from_zero() {
    for (model, n) in [("turns", 7usize), ("turns-exact", 3)] {
        let (out, _) = turns(&["--model", model, "--turns", &n.to_string()]);
        let csv = Csv::parse(&out);
        assert_eq!(csv.header, TURN_COLUMNS);
        assert_eq!(csv.rows.len(), n, "{model}");
        for (k, turn) in csv.column("turn").into_iter().enumerate() {
            assert_close(turn, k as f64, 0.0);
        }
        assert_eq!(csv.comments["turns"], n.to_string());
        assert!(csv.comments["stop"].starts_with("turns "));
    }
    // Without --turns: the documented default of 100.
    let (out, _) = turns(&["--model", "eq73"]);
    assert_eq!(Csv::parse(&out).rows.len(), 100);
    // Without --model: the note's own turn model, the same table as asked by name.
    let (out, _) = turns(&["--turns", "4"]);
    let (named, _) = turns(&["--model", "turns", "--turns", "4"]);
    let body = |text: &str| -> Vec<String> {
        text.lines()
            .filter(|l| !l.starts_with("# command"))
            .map(String::from)
            .collect()
    };
    assert_eq!(
        Csv::parse(&out).comments["model"],
        "turns (eqs. (73), (76), (89))"
    );
    assert_eq!(body(&out), body(&named));
}

#[test]
fn eq89_collision_ratio_and_its_energy_loss_hold_at_every_turn() {
    // (r0, b, rho, l) chosen away from the defaults.
    let (r0, b, rho, l) = (0.15, 0.02, 500.0, 2.0);
    for model in ["turns", "turns-exact"] {
        let (out, _) = turns(&[
            "--model",
            model,
            "--r0",
            "0.15",
            "--snow-depth",
            "0.02",
            "--density",
            "500",
            "--length",
            "2",
            "--turns",
            "40",
        ]);
        let csv = Csv::parse(&out);
        for k in 0..csv.rows.len() {
            let r = r0 + k as f64 * b;
            let r_next = r + b;
            let (v_end, v_after) = (csv.get(k, "v_end_m_s"), csv.get(k, "v_after_m_s"));
            // Eq. (89): angular momentum about the contact line is conserved.
            let ratio = (r_next * r_next + 2.0 * r * r) / (3.0 * r * r_next);
            assert_close(v_after / v_end, ratio, COLLISION_TOL);
            // Eqs. (85), (86): the disk r_{k+1} turns about a line at distance
            // r_k before, r_{k+1} after, with the same omega-to-v relations.
            let m_next = PI * rho * l * r_next * r_next;
            let omega_end = v_end / r;
            let t_end = m_next * (r_next * r_next / 2.0 + r * r) * omega_end * omega_end / 2.0;
            let t_after = 0.75 * m_next * v_after * v_after;
            assert_close(csv.get(k, "collision_loss_j"), t_end - t_after, LOSS_TOL);
        }
    }
}

#[test]
fn turns_follow_one_another_in_time_and_speed() {
    let (out, _) = turns(&["--model", "turns-exact", "--v0", "0.3", "--turns", "30"]);
    let csv = Csv::parse(&out);
    assert_close(csv.get(0, "t_start_s"), 0.0, 0.0);
    assert_close(csv.get(0, "v_start_m_s"), 0.3, CLOSED_FORM_TOL);
    for k in 0..csv.rows.len() {
        assert!(csv.get(k, "t_end_s") > csv.get(k, "t_start_s"));
        if k + 1 < csv.rows.len() {
            assert_close(csv.get(k + 1, "t_start_s"), csv.get(k, "t_end_s"), TIME_TOL);
            assert_close(
                csv.get(k + 1, "v_start_m_s"),
                csv.get(k, "v_after_m_s"),
                CLOSED_FORM_TOL,
            );
        }
    }
}

#[test]
fn eq74_gives_the_start_of_every_turn() {
    let (r0, b) = (0.12, 0.03);
    let (out, _) = turns(&[
        "--model",
        "turns",
        "--r0",
        "0.12",
        "--snow-depth",
        "0.03",
        "--turns",
        "200",
    ]);
    let csv = Csv::parse(&out);
    assert_eq!(csv.rows.len(), 200);
    for k in 0..csv.rows.len() {
        let kf = k as f64;
        // X_k = sum of the circumferences 2 pi r_j, j < k (0-based, eq. (74)).
        let want = 2.0 * PI * kf * r0 + kf * (kf - 1.0) * PI * b;
        assert_close(csv.get(k, "x_start_m"), want, EQ74_TOL);
    }
}

#[test]
fn turns_json_records_the_table_and_the_parameters() {
    let (out, _) = turns(&[
        "--model",
        "eq88",
        "--snow-depth",
        "0.02",
        "--r0",
        "0.15",
        "--alpha-deg",
        "40",
        "--turns",
        "4",
        "--format",
        "json",
    ]);
    let doc = json(&out);
    assert_eq!(doc["snowroll_version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(doc["model"]["id"], "turns-exact");
    assert_eq!(doc["stop"]["reason"], "turns");
    let params = &doc["params"];
    assert_eq!(params["turns"], 4);
    for (key, want) in [("snow_depth", 0.02), ("r0", 0.15), ("alpha_deg", 40.0)] {
        assert_close(params[key].as_f64().unwrap(), want, CLOSED_FORM_TOL);
    }
    let rows = doc["turns"].as_array().unwrap();
    assert_eq!(rows.len(), 4);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row["turn"], k);
        for key in TURN_COLUMNS.split(',') {
            assert!(row[key].is_number(), "turn {k} lacks {key}");
        }
    }
    // The overall mean with collisions is the net speed gain over the time
    // taken, in units of G = g sin alpha.
    let g_along = G * 40f64.to_radians().sin();
    let last = &rows[3];
    let want = last["v_after_m_s"].as_f64().unwrap() / last["t_end_s"].as_f64().unwrap() / g_along;
    let overall = doc["summary"]["checkpoints"]
        .as_array()
        .unwrap()
        .last()
        .unwrap();
    assert_eq!(overall["turns"], 4);
    assert_close(
        overall["mean_a_with_collision_over_g"].as_f64().unwrap(),
        want,
        CLOSED_FORM_TOL,
    );
}

/// The number after `label` in `text`.
fn number_after(text: &str, label: &str) -> f64 {
    let rest = &text[text
        .find(label)
        .unwrap_or_else(|| panic!("{label:?} not in {text}"))
        + label.len()..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .unwrap_or(rest.len());
    rest[..end].parse().unwrap()
}

#[test]
fn turns_summary_gives_the_long_run_means_of_the_table_and_the_notes_claim() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("turns.csv");
    let out = snowroll()
        .args(["turns", "--model", "turns", "--turns", "1000", "--output"])
        .arg(&path)
        .assert()
        .success()
        .stdout(predicate::str::is_empty());
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    let csv = Csv::parse(&fs::read_to_string(&path).unwrap());
    assert_eq!(entries(dir.path()), vec!["turns.csv".to_string()]);
    assert_eq!(csv.rows.len(), 1000);
    // Time-weighted means from the rows, over G = g sin alpha.
    let g_along = G * ALPHA_DEG.to_radians().sin();
    let n = csv.rows.len();
    let gain: f64 = (0..n)
        .map(|k| csv.get(k, "v_end_m_s") - csv.get(k, "v_start_m_s"))
        .sum();
    let in_turn = gain / csv.get(n - 1, "t_end_s") / g_along;
    let with_collisions = csv.get(n - 1, "v_after_m_s") / csv.get(n - 1, "t_end_s") / g_along;
    let label = "over all 1000 turns: in turn ";
    assert_close(number_after(&stderr, label), in_turn, SUMMARY_PRINT_TOL);
    assert_close(
        number_after(&stderr, "with collisions "),
        with_collisions,
        SUMMARY_PRINT_TOL,
    );
    // The in-turn range over the last decade, 100 <= k < 1000.
    let lo = (100..n)
        .map(|k| csv.get(k, "min_a_m_s2"))
        .fold(f64::INFINITY, f64::min);
    assert_close(
        number_after(&stderr, "ranges over ["),
        lo / g_along,
        SUMMARY_PRINT_TOL,
    );
    assert!(stderr.contains("the note's eq. (79) estimate: 4/9 = 0.444"));
    // One convergence line per checkpoint 1, 2, 5, ..., 500, 1000.
    for k in [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000] {
        assert!(
            stderr
                .lines()
                .any(|l| l.split_whitespace().next() == Some(&k.to_string())),
            "no checkpoint {k} in {stderr}"
        );
    }
}

#[test]
fn turns_cut_short_by_t_end_say_how_many_turns_were_done() {
    let (out, err) = turns(&["--model", "turns", "--t-end", "1"]);
    let csv = Csv::parse(&out);
    assert!(!csv.rows.is_empty() && csv.rows.len() < 100);
    assert!(csv.get(csv.rows.len() - 1, "t_end_s") <= 1.0);
    assert!(csv.comments["stop"].starts_with("end-time"));
    assert!(
        err.contains(&format!("after {} of the 100 turns", csv.rows.len())),
        "{err}"
    );
}

#[test]
fn simulate_turns_stops_after_n_turns_with_the_turn_columns() {
    let (r0, b) = (0.1, 0.01);
    let out = snowroll()
        .args(["simulate", "--model", "turns", "--turns", "3"])
        .assert()
        .success()
        .stderr(predicate::str::contains("requested number of turns"));
    let csv = Csv::parse(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert_eq!(
        csv.header,
        "t_s,x_m,v_m_s,a_m_s2,r_m,mass_kg,normal_n,friction_n,friction_ratio,turn,theta_rad,omega_rad_s"
    );
    assert!(csv.comments["stop"].starts_with("turns "));
    assert_eq!(csv.comments["turns"], "3");
    for i in 0..csv.rows.len() {
        // x = X_k + r_k theta, r_k = r0 + k b (eq. (74)).
        let k = csv.get(i, "turn");
        assert!((0.0..3.0).contains(&k));
        let r = r0 + k * b;
        assert_close(csv.get(i, "r_m"), r, CLOSED_FORM_TOL);
        let x_start = 2.0 * PI * k * r0 + k * (k - 1.0) * PI * b;
        assert_close(
            csv.get(i, "x_m"),
            x_start + r * csv.get(i, "theta_rad"),
            EQ74_TOL,
        );
        assert_close(
            csv.get(i, "v_m_s"),
            r * csv.get(i, "omega_rad_s"),
            CLOSED_FORM_TOL,
        );
    }
    // It ends at theta = 2 pi of turn 2, i.e. at X_3.
    let last = csv.rows.len() - 1;
    assert_close(csv.get(last, "turn"), 2.0, 0.0);
    assert_close(csv.get(last, "theta_rad"), 2.0 * PI, EVENT_TOL);
    assert_close(
        csv.get(last, "x_m"),
        6.0 * PI * r0 + 6.0 * PI * b,
        EVENT_TOL,
    );
}

#[test]
fn turns_and_a_case_insensitive_model_come_from_the_config_file() {
    let (_dir, path) = config_file(
        "turns.toml",
        "model = \"EQ88\"\nturns = 4\nsnow-depth = 0.02\n",
    );
    let config = path.to_str().unwrap();
    let doc = json(&simulate(&["--config", config, "--format", "json"]));
    assert_eq!(doc["model"]["id"], "turns-exact");
    assert_eq!(doc["stop"]["reason"], "turns");
    let (out, _) = turns(&["--config", config]);
    let csv = Csv::parse(&out);
    assert_eq!(csv.rows.len(), 4);
    assert_close(csv.param("snow_depth"), 0.02, CLOSED_FORM_TOL);
    // The flag overrides the file.
    let (out, _) = turns(&["--config", config, "--turns", "2"]);
    assert_eq!(Csv::parse(&out).rows.len(), 2);
    // A circular model in any case, too.
    fs::write(&path, "model = \"Torque-CM\"\nt-end = 1\n").unwrap();
    let doc = json(&simulate(&["--config", config, "--format", "json"]));
    assert_eq!(doc["model"]["id"], "torque-cm");
}

#[test]
fn zero_turns_are_rejected() {
    let err = fails(&["simulate", "--model", "turns", "--turns", "0"]);
    assert_one_line_error(&err, &["turns", "= 0", "turns >= 1"]);
    let err = fails(&["turns", "--model", "turns", "--turns", "0"]);
    assert_one_line_error(&err, &["turns", "= 0", "turns >= 1"]);
}

#[test]
fn turns_flag_with_a_circular_model_is_rejected() {
    let err = fails(&["simulate", "--model", "torque-cm", "--turns", "3"]);
    assert_one_line_error(&err, &["--turns", "turns, turns-exact", "torque-cm"]);
    // Also when `turns` comes from the config file.
    let (_dir, path) = config_file("c.toml", "model = \"energy\"\nturns = 3\n");
    let err = fails(&["simulate", "--config", path.to_str().unwrap()]);
    assert_one_line_error(&err, &["turns", "turns, turns-exact", "energy"]);
}

#[test]
fn turns_command_rejects_a_circular_model_listing_the_turn_models() {
    // On the command line, only the turn models are values of `--model`.
    let out = snowroll()
        .args(["turns", "--model", "torque-cm"])
        .assert()
        .code(2);
    let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        err.contains("'torque-cm'") && err.contains("[possible values: turns, turns-exact]"),
        "{err}"
    );
    // From a config file, the same one-line error as before.
    let (_dir, path) = config_file("c.toml", "model = \"torque-cm\"\n");
    let err = fails(&["turns", "--config", path.to_str().unwrap()]);
    assert_one_line_error(&err, &["turns, turns-exact", "torque-cm"]);
    // Without a model, `turns` runs the note's (turns_gives_exactly_n_rows_numbered_from_zero).
}

#[test]
fn turns_config_with_sampling_keys_is_rejected() {
    let (_dir, path) = config_file("s.toml", "model = \"turns\"\ndt = 0.1\n");
    let err = fails(&["turns", "--config", path.to_str().unwrap()]);
    assert_one_line_error(&err, &["s.toml", "`dt`", "simulate"]);
}

// ---------------------------------------------------------------- models

#[test]
fn models_lists_every_model_with_its_alias() {
    let out = snowroll().arg("models").assert().success();
    let text = std::str::from_utf8(&out.get_output().stdout).unwrap();
    for kind in ModelKind::ALL {
        let line = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(kind.id()))
            .unwrap_or_else(|| panic!("{} not listed", kind.id()));
        assert!(line.contains(kind.alias()), "{line}");
    }
    assert!(text.contains("1/5 = 0.2000"), "eq. (4): G/5 (fn. 4)");
}

#[test]
fn models_json_gives_the_terminal_fractions_of_the_note() {
    let out = snowroll()
        .args(["models", "--format", "json"])
        .assert()
        .success();
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    let models = doc["models"].as_array().unwrap();
    assert_eq!(models.len(), ModelKind::ALL.len());
    let fraction = |id: &str| {
        models.iter().find(|m| m["id"] == id).unwrap()["terminal_fraction"]
            .as_f64()
            .unwrap()
    };
    // Loney (fn. 4): G/5; eq. (35): G/3; App. A: 2G/3.
    assert_close(fraction("torque-cm"), 1.0 / 5.0, CLOSED_FORM_TOL);
    assert_close(fraction("loney"), 1.0 / 5.0, CLOSED_FORM_TOL);
    assert_close(fraction("energy"), 1.0 / 3.0, CLOSED_FORM_TOL);
    assert_close(fraction("snowless"), 2.0 / 3.0, CLOSED_FORM_TOL);
}

#[test]
fn models_stall_slope_is_the_threshold_of_eq14_and_of_simulate() {
    let out = snowroll()
        .args(["models", "--format", "json"])
        .assert()
        .success();
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    let energy = doc["models"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["id"] == "energy")
        .unwrap();
    let stall_deg = energy["stall_slope_deg"].as_f64().unwrap();
    // Eq. (14) at x = 0, v = 0: a = 0 when (2/3) g sin a = g cos a (3 b r0 + b^2)/(3 pi r0^2).
    let (b, r0) = (
        doc["snow_depth"].as_f64().unwrap(),
        doc["r0"].as_f64().unwrap(),
    );
    let want = ((3.0 * b * r0 + b * b) / (2.0 * PI * r0 * r0))
        .atan()
        .to_degrees();
    assert_close(stall_deg, want, CLOSED_FORM_TOL);
    // And simulate agrees on either side of it.
    let reason = |alpha: f64| {
        let a = alpha.to_string();
        json(&simulate(&[
            "--model",
            "energy",
            "--alpha-deg",
            &a,
            "--format",
            "json",
            "--t-end",
            "1",
        ]))["stop"]["reason"]
            .clone()
    };
    assert_eq!(reason(stall_deg * 0.99), "does-not-start");
    assert_eq!(reason(stall_deg * 1.01), "end-time");
}

/// Issue 22, item 4: `snowroll models` takes the scenario flags, and its
/// stall slopes are those of that body and those losses. The ball's eq. (14)
/// from rest: a(0) = 0 where tan α = 2b/(π r0) + 3b²/(4π r0²) (issue 21,
/// `docs/snowball-and-losses.md`); with rolling resistance c_rr and no snow
/// the snowless log stalls where tan α = c_rr.
#[test]
fn models_takes_the_scenario_flags_for_its_stall_slopes() {
    let stall = |args: &[&str], id: &str| -> Option<f64> {
        let mut all = vec!["models", "--format", "json"];
        all.extend_from_slice(args);
        let out = snowroll().args(&all).assert().success();
        let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
        let row = doc["models"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["id"] == id)
            .unwrap()
            .clone();
        row["stall_slope_deg"].as_f64()
    };
    let (b, r0) = (0.05_f64, 0.04_f64);
    let ball = ["--shape", "sphere", "--snow-depth", "0.05", "--r0", "0.04"];
    let want = (2.0 * b / (PI * r0) + 3.0 * b * b / (4.0 * PI * r0 * r0))
        .atan()
        .to_degrees();
    assert_close(stall(&ball, "energy").unwrap(), want, CLOSED_FORM_TOL);
    // The turn models take no ball, and no losses.
    assert_eq!(stall(&ball, "turns"), None);
    let rolling = ["--rolling-resistance", "0.5"];
    assert_close(
        stall(&rolling, "snowless").unwrap(),
        0.5_f64.atan().to_degrees(),
        CLOSED_FORM_TOL,
    );
    assert_eq!(stall(&rolling, "turns"), None);
    // The table names the flags it was computed for; a bad value is an
    // error naming it.
    let text = snowroll().args(["models"]).args(ball).assert().success();
    let text = String::from_utf8(text.get_output().stdout.clone()).unwrap();
    assert!(
        text.contains("(--snow-depth 0.05 --r0 0.04 --shape sphere)"),
        "{text}"
    );
    snowroll()
        .args(["models", "--r0", "-1"])
        .assert()
        .failure()
        .stderr(predicate::str::contains("r0"));
}

/// The turn-0 stall slope of eq. (73) from a grid of 10⁶ points over (0, 2π]:
/// the grid misses the maximum of Q/P by ~(Q/P)″h²/8 ≈ 1e-12 relative.
const GRID_STALL_TOL: f64 = 1e-9;

#[test]
fn models_turn_stall_slope_is_where_the_turn_model_stalls_in_its_first_turn() {
    let out = snowroll()
        .args(["models", "--format", "json"])
        .assert()
        .success()
        .stdout(predicate::str::contains("stalls-in-first-turn"));
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    let turns = doc["models"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["id"] == "turns")
        .unwrap();
    assert_eq!(turns["stall_kind"], "stalls-in-first-turn");
    let stall_deg = turns["stall_slope_deg"].as_f64().unwrap();
    // From rest, eq. (73) gives θ̇² = −2W/I in turn 0: the log completes the
    // turn iff tan α > max ε(θ − sin θ)/(θ + ε(θ²/2 − 1 + cos θ)), ε = b/(πr0).
    let (b, r0) = (
        doc["snow_depth"].as_f64().unwrap(),
        doc["r0"].as_f64().unwrap(),
    );
    let eps = b / (PI * r0);
    let want = (1..=1_000_000)
        .map(|i| {
            let t = 2.0 * PI * f64::from(i) / 1e6;
            eps * (t - t.sin()) / (t + eps * (t * t / 2.0 - 1.0 + t.cos()))
        })
        .fold(f64::NEG_INFINITY, f64::max);
    assert_close(stall_deg.to_radians().tan(), want, GRID_STALL_TOL);
    assert!((stall_deg - 2.09).abs() < 0.01, "{stall_deg}");
    // simulate: just below, the log starts and stalls inside turn 0; just above it completes the turn.
    let stop = |alpha: f64| {
        let a = alpha.to_string();
        json(&simulate(&[
            "--model",
            "turns",
            "--alpha-deg",
            &a,
            "--turns",
            "1",
            "--format",
            "json",
        ]))["stop"]
            .clone()
    };
    let below = stop(stall_deg * 0.99);
    assert_eq!(below["reason"], "stalled");
    assert!(below["x_m"].as_f64().unwrap() < 2.0 * PI * r0);
    assert_eq!(stop(stall_deg * 1.01)["reason"], "turns");
}

/// The stall time against its energy integral: the midpoint rule's error,
/// O(h²) ≈ 1e-10 at 2·10⁵ points, and the run's, rtol 1e-10 on a smooth
/// θ(t), are far below; 1e-7 leaves room for the stall event's location
/// where θ̇ → 0 like √(θ_s − θ).
const STALL_TIME_TOL: f64 = 1e-7;

/// Stall time of `turns-exact` from rest on slope `alpha` (radians), from
/// the exact first turn's energy integral (`docs/turn-model.md`, "The first
/// turn with exact geometry"; per ρl, D_n = (r + b)ⁿ − rⁿ):
/// `I_C θ̇²/2 + V = 0` with `I_C = (3/2)πr⁴ + θ(r²D₂/2 + D₄/4) − (2/3)rD₃ sin θ`,
/// `V = C[m_s(r + b/2) − D₃ sin θ/3] − G[x(m + m_s/2) − D₃(1 − cos θ)/3]`,
/// m = πr², m_s = θD₂/2, x = rθ. The log stops at the first root θ_s of V;
/// `t = ∫₀^θs dθ/θ̇`, with θ = θ_s(1 − cos φ)/2 taking out the inverse
/// square roots at both ends (midpoint rule in φ). Returns (t, θ_s).
fn exact_first_turn_stall(alpha: f64, b: f64, r: f64, g: f64) -> (f64, f64) {
    let (gs, gc) = (g * alpha.sin(), g * alpha.cos());
    let d = |n: i32| (r + b).powi(n) - r.powi(n);
    let m = PI * r * r;
    let v = |t: f64| {
        let m_s = t * d(2) / 2.0;
        gc * (m_s * (r + b / 2.0) - d(3) * t.sin() / 3.0)
            - gs * (r * t * (m + m_s / 2.0) - d(3) * (1.0 - t.cos()) / 3.0)
    };
    let inertia = |t: f64| {
        1.5 * PI * r.powi(4) + t * (r * r * d(2) / 2.0 + d(4) / 4.0)
            - 2.0 / 3.0 * r * d(3) * t.sin()
    };
    // The first sign change of V after 0, then bisection.
    let step = 2.0 * PI / 4096.0;
    let k = (1..=4096)
        .find(|&k| v(k as f64 * step) >= 0.0)
        .expect("stalls in turn 0");
    let (mut lo, mut hi) = ((k - 1) as f64 * step, k as f64 * step);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if v(mid) >= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let theta_s = 0.5 * (lo + hi);
    let n = 200_000;
    let h = PI / n as f64;
    let t: f64 = (0..n)
        .map(|i| {
            let phi = (i as f64 + 0.5) * h;
            let theta = theta_s * (1.0 - phi.cos()) / 2.0;
            theta_s / 2.0 * phi.sin() * (inertia(theta) / (-2.0 * v(theta))).sqrt()
        })
        .sum::<f64>()
        * h;
    (t, theta_s)
}

#[test]
fn thick_snow_warns_on_stderr_and_in_the_output_metadata() {
    // The case of issue 8: alpha 40 degrees, b 0.2 m, r0 0.15 m. The exact
    // model stalls in turn 0 while the first-order one rolls on.
    let thick = ["--alpha-deg", "40", "--snow-depth", "0.2", "--r0", "0.15"];
    let out = snowroll()
        .args(["turns", "--model", "turns", "--turns", "3"])
        .args(thick)
        .assert()
        .success()
        .stderr(
            predicate::str::contains("warning: turns is used beyond its range: b/r0 = 1.333")
                .and(predicate::str::contains("part ways")),
        );
    let csv = std::str::from_utf8(&out.get_output().stdout).unwrap();
    assert_eq!(csv.matches("# warning = ").count(), 2, "{csv}");
    let out = snowroll()
        .args(["simulate", "--model", "turns-exact", "--format", "json"])
        .args(thick)
        .assert()
        .success()
        .stderr(predicate::str::contains("warning").not());
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert_eq!(doc["stop"]["reason"], "stalled");
    // The stall time from the exact first turn's energy integral (0.936 s).
    let (t_stall, theta_s) = exact_first_turn_stall(
        40f64.to_radians(),
        0.2,
        0.15,
        snowroll::Scenario::default().gravity(),
    );
    let t_s = doc["stop"]["t_s"].as_f64().unwrap();
    assert!(
        (t_s / t_stall - 1.0).abs() < STALL_TIME_TOL,
        "stall at t = {t_s} s, the energy integral gives {t_stall} s (θ_s = {theta_s} rad)"
    );
    // In range: no warning, and no `warnings` key.
    let out = snowroll()
        .args([
            "simulate", "--model", "turns", "--turns", "2", "--format", "json",
        ])
        .assert()
        .success()
        .stderr(predicate::str::contains("warning").not());
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    assert!(doc["params"].get("warnings").is_none());
}

/// Issue 32, item 8: what the user guide says of `turns --method ode`
/// (`docs/guide/running.md`) is what the two tables measure. At the default
/// `--rtol 1e-10`, 1000 turns: every column within 5e-9 relative (measured
/// 4.6e-9, `mean_a_with_collision_m_s2`) except `min_a_m_s2`, which passes
/// near 0 in late turns: within 1e-9 G absolute (measured 5.4e-10 G, 2e-5
/// relative). At `--rtol 1e-15`, 100 turns: within 1e-12 relative (measured
/// 7.3e-13; 2.2e-12 over 1000 turns, as the integrator's error grows).
#[test]
fn regression_32_closed_and_ode_tables_differ_as_the_guide_says() {
    let table = |args: &[&str]| {
        let mut all = vec!["--model", "turns"];
        all.extend_from_slice(args);
        Csv::parse(&turns(&all).0)
    };
    // (largest relative difference but min_a, largest |Δ min_a|/G).
    let differences = |a: &Csv, b: &Csv| -> (f64, f64) {
        assert_eq!(a.header, b.header);
        assert_eq!(a.rows.len(), b.rows.len());
        let g = a.comments["g"].parse::<f64>().unwrap() * 0.5; // sin 30° = 1/2
        let mut worst = (0.0f64, 0.0f64);
        for name in a.header.split(',') {
            for (x, y) in a.column(name).iter().zip(b.column(name)) {
                if name == "min_a_m_s2" {
                    worst.1 = worst.1.max((x - y).abs() / g);
                } else if x.to_bits() != y.to_bits() {
                    worst.0 = worst.0.max((x - y).abs() / x.abs().max(y.abs()));
                }
            }
        }
        worst
    };
    let closed = table(&["--turns", "1000"]);
    let ode = table(&["--turns", "1000", "--method", "ode"]);
    let (rel, min_a) = differences(&closed, &ode);
    assert!(rel <= 5e-9 && rel > 1e-10, "default rtol: {rel:e}");
    assert!(min_a <= 1e-9, "default rtol, min_a: {min_a:e} G");
    let closed = table(&["--turns", "100"]);
    let ode = table(&["--turns", "100", "--method", "ode", "--rtol", "1e-15"]);
    let (rel, min_a) = differences(&closed, &ode);
    assert!(
        rel <= 1e-12 && min_a <= 1e-12,
        "rtol 1e-15: {rel:e}, {min_a:e} G"
    );
    let guide = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/guide/running.md"),
    )
    .unwrap();
    assert!(
        guide.contains("to 5e-9 relative")
            && guide.contains("1e-9 G")
            && !guide.contains("same table to 1e-12"),
        "docs/guide/running.md does not state the measured differences"
    );
}

// ---------------------------------------------------------------- help

#[test]
fn turns_help_gives_units_and_columns() {
    snowroll()
        .args(["turns", "--help"])
        .assert()
        .success()
        .stdout(
            predicate::str::contains("in degrees")
                .and(predicate::str::contains("in m "))
                .and(predicate::str::contains("in s"))
                .and(predicate::str::contains("m/s^2"))
                .and(predicate::str::contains("collision_loss_j"))
                .and(predicate::str::contains("J)"))
                .and(predicate::str::contains("[default: 100]")),
        );
}

#[test]
fn simulate_help_gives_units() {
    snowroll()
        .args(["simulate", "--help"])
        .assert()
        .success()
        .stdout(
            predicate::str::contains("in degrees")
                .and(predicate::str::contains("in m "))
                .and(predicate::str::contains("in s"))
                .and(predicate::str::contains("in m/s"))
                .and(predicate::str::contains("[default: 30]")),
        );
}

/// Issue 32, item 8: no `--help` shows the source's syntax. The help
/// texts come from doc comments (clap's derive, the library's
/// `ValueEnum`s), where rustdoc links (`[`TurnModel::method_for`]`), paths
/// (`crate::x`) and attributes read as code; every command's help, the
/// program's own and `help`'s, must be free of them.
#[test]
fn regression_32_no_help_shows_source_syntax() {
    let help = |args: &[&str]| -> String {
        let out = snowroll().args(args).output().unwrap();
        assert!(out.status.success(), "{args:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    let top = help(&["--help"]);
    let commands: Vec<String> = top
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next().map(String::from))
        .collect();
    assert!(
        ["simulate", "turns", "models", "paper", "sweep", "merge"]
            .iter()
            .all(|c| commands.iter().any(|x| x == c)),
        "{commands:?}"
    );
    let mut texts = vec![("--help".to_string(), top.clone())];
    for c in commands.iter().filter(|c| *c != "help") {
        texts.push((format!("help {c}"), help(&["help", c])));
        texts.push((format!("{c} --help"), help(&[c, "--help"])));
        texts.push((format!("{c} -h"), help(&[c, "-h"])));
    }
    for (args, text) in &texts {
        // IPv6 addresses (`::1`, `[::1]`, `::`) are what `serve --host` takes,
        // not a Rust path: they are taken out before `::` is looked for.
        let text = &text
            .replace("[::1]", "")
            .replace("::1", "")
            .replace(" :: ", " ")
            .replace(" ::\n", "\n");
        // Issue 36, item 4: no Rust path, test name, path of the code, or
        // ASCII index (`kg/m^3`, `C_d`) beside a set one (`r²`) either.
        crate::source_text::assert_clean(&format!("`snowroll {args}`"), text, &[]);
        for syntax in ["[`", "`]", "::", "](", "#[", "///", "//!", "crate", "Self"] {
            assert!(
                !text.contains(syntax),
                "`snowroll {args}` shows source syntax {syntax:?}: {}",
                text.lines().find(|l| l.contains(syntax)).unwrap_or("")
            );
        }
    }
}

// ---------------------------------------------------------------- errors

/// Stderr is exactly one line starting `error: ` containing every `needle`.
fn assert_one_line_error(stderr: &str, needles: &[&str]) {
    assert_eq!(stderr.lines().count(), 1, "not one line: {stderr:?}");
    assert!(stderr.starts_with("error: "), "{stderr:?}");
    for n in needles {
        assert!(stderr.contains(n), "{stderr:?} lacks {n:?}");
    }
}

#[test]
fn negative_snow_depth_is_rejected_by_name_value_and_range() {
    // A negative depth is an unwinding roll (issue 35): without its core
    // radius it is refused, naming what it needs.
    let err = fails(&["simulate", "--model", "eq4", "--snow-depth", "-1"]);
    assert_one_line_error(
        &err,
        &[
            "snow_depth",
            "-1",
            "snow_depth >= 0 without core_radius",
            "--core-radius",
        ],
    );
}

/// A negative value in exponent form is a value, not a flag: `--snow-depth
/// -1e-4` runs as `--snow-depth=-1e-4` (clap took `-1e-4` for an unknown
/// flag and advised `-- -1e-4`, a tester's case), and a negative tube mass
/// is refused by its own range, naming the value.
#[test]
fn negative_values_in_exponent_form_are_values() {
    let roll = [
        "simulate",
        "--model",
        "energy-thin",
        "--alpha-deg",
        "0",
        "--r0",
        "0.06",
        "--core-radius",
        "0.02",
        "--t-end",
        "1",
        "--dt",
        "0.5",
    ];
    let spaced = snowroll()
        .args(roll)
        .args(["--snow-depth", "-1e-4"])
        .output()
        .unwrap();
    let joined = snowroll()
        .args(roll)
        .arg("--snow-depth=-1e-4")
        .output()
        .unwrap();
    assert!(
        spaced.status.success(),
        "{}",
        String::from_utf8_lossy(&spaced.stderr)
    );
    assert_eq!(spaced.stdout, joined.stdout);
    let mut args = roll.to_vec();
    args.extend(["--snow-depth", "-1e-4", "--core-mass", "-5e-3"]);
    let err = fails(&args);
    assert_one_line_error(&err, &["core_mass", "-0.005", "core_mass > 0 kg"]);
}

#[test]
fn right_angle_slope_is_rejected() {
    let err = fails(&["simulate", "--model", "eq4", "--alpha-deg", "90"]);
    assert_one_line_error(&err, &["alpha_deg", "90", "0 < alpha_deg < 90"]);
}

#[test]
fn nan_is_rejected() {
    let err = fails(&["simulate", "--model", "eq4", "--snow-depth", "NaN"]);
    assert_one_line_error(&err, &["snow_depth", "NaN", "finite snow_depth m"]);
    let err = fails(&["simulate", "--model", "eq4", "--t-end", "nan"]);
    assert_one_line_error(&err, &["t_end", "NaN"]);
}

#[test]
fn unknown_model_lists_the_valid_ids() {
    let err = fails(&["simulate", "--model", "eq99"]);
    assert!(err.contains("eq99"), "{err}");
    for kind in ModelKind::ALL {
        assert!(err.contains(kind.id()), "{err} lacks {}", kind.id());
    }
}

#[test]
fn missing_model_says_how_to_give_one() {
    let err = fails(&["simulate"]);
    assert_one_line_error(&err, &["--model", "torque-cm"]);
}

#[test]
fn unreadable_config_names_the_file() {
    let err = fails(&["simulate", "--config", "/no/such/dir/run.toml"]);
    assert_one_line_error(&err, &["/no/such/dir/run.toml"]);
}

#[test]
fn malformed_config_names_the_file_and_line() {
    let (_dir, path) = config_file("bad.toml", "model = \"eq4\"\nalpha-deg = = 3\n");
    let err = fails(&["simulate", "--config", path.to_str().unwrap()]);
    assert_one_line_error(&err, &["bad.toml", "line 2"]);
    // A value of the wrong type too.
    fs::write(&path, "snow-depth = \"deep\"\n").unwrap();
    let err = fails(&[
        "simulate",
        "--model",
        "eq4",
        "--config",
        path.to_str().unwrap(),
    ]);
    assert_one_line_error(&err, &["bad.toml", "line 1"]);
}

#[test]
fn unknown_config_key_is_named() {
    let (_dir, path) = config_file("typo.toml", "model = \"eq4\"\nalpha = 25\n");
    let err = fails(&["simulate", "--config", path.to_str().unwrap()]);
    assert_one_line_error(&err, &["typo.toml", "alpha", "alpha-deg"]);
}

#[test]
fn config_with_unknown_model_lists_the_ids() {
    let (_dir, path) = config_file("m.toml", "model = \"eq99\"\n");
    let err = fails(&["simulate", "--config", path.to_str().unwrap()]);
    assert_one_line_error(
        &err,
        &["m.toml", "eq99", "torque-cm", "quasi-circular-lift"],
    );
}

#[test]
fn descending_times_are_rejected() {
    let err = fails(&["simulate", "--model", "eq4", "--times", "2,1"]);
    assert_one_line_error(&err, &["ascending"]);
}

#[test]
fn zero_dt_is_rejected() {
    let err = fails(&["simulate", "--model", "eq4", "--dt", "0"]);
    assert_one_line_error(&err, &["dt", "= 0", "dt > 0"]);
}

#[test]
fn times_and_dt_conflict() {
    let err = fails(&["simulate", "--model", "eq4", "--times", "1", "--dt", "1"]);
    assert!(err.contains("--times") && err.contains("--dt"), "{err}");
}

#[test]
fn output_in_a_missing_directory_fails_and_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("missing").join("out.csv");
    let err = fails(&[
        "simulate",
        "--model",
        "eq4",
        "--output",
        path.to_str().unwrap(),
    ]);
    assert_one_line_error(&err, &["out.csv"]);
    assert!(!path.exists());
    assert!(entries(dir.path()).is_empty());
}

#[test]
fn failed_run_leaves_an_existing_output_untouched_and_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.csv");
    fs::write(&path, "previous results\n").unwrap();
    // Rejected before the output is opened.
    let err = fails(&[
        "simulate",
        "--model",
        "eq4",
        "--snow-depth",
        "-0.5",
        "--output",
        path.to_str().unwrap(),
    ]);
    assert_one_line_error(&err, &["snow_depth"]);
    // Fails after the output is opened: by t = 1e200 s, x = g t^2/5 would
    // be 1e400 m, beyond f64; the integrator gives up on the way.
    let err = fails(&[
        "simulate",
        "--model",
        "eq4",
        "--t-end",
        "1e200",
        "--output",
        path.to_str().unwrap(),
    ]);
    assert_one_line_error(&err, &["simulating torque-cm"]);
    assert_eq!(fs::read_to_string(&path).unwrap(), "previous results\n");
    assert_eq!(entries(dir.path()), vec!["out.csv".to_string()]);
}

#[test]
fn a_repeated_flag_takes_the_last_value() {
    let csv = Csv::parse(&simulate(&[
        "--model",
        "eq4",
        "--alpha-deg",
        "10",
        "--alpha-deg",
        "45",
        "--t-end",
        "1",
    ]));
    assert_close(
        csv.get(0, "a_m_s2"),
        two_thirds_g_sin(45.0, G),
        CLOSED_FORM_TOL,
    );
}

#[test]
fn a_closed_pipe_ends_quietly() {
    // 10^5 rows (megabytes) cannot fit in a pipe buffer, so the program is
    // still writing when the reader goes away, as with `| head`.
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin!("snowroll"))
        .args(["simulate", "--model", "eq4", "--dt", "0.001"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 10];
    let mut stdout = child.stdout.take().unwrap();
    std::io::Read::read_exact(&mut stdout, &mut first).unwrap();
    assert_eq!(&first, b"# snowroll");
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success());
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn out_of_scale_inputs_fail_with_one_line_not_a_panic() {
    // An absolute tolerance so small that a zero component's error overflows.
    let err = fails(&["simulate", "--model", "eq14", "--atol", "1e-300"]);
    assert_one_line_error(&err, &["atol", "1e-300", "1e-30"]);
    // g so large that the first steps would overflow: refused at validation,
    // with the range of magnitudes the program computes in.
    let err = fails(&["simulate", "--model", "eq14", "--g", "1e300"]);
    assert_one_line_error(&err, &["g (m/s^2)", "1e300", "1e150"]);
    // A run that overflows later: the integrator gives up cleanly.
    let err = fails(&["simulate", "--model", "eq14", "--t-end", "1e200"]);
    assert_one_line_error(&err, &["simulating energy"]);
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn a_log_that_cannot_start_on_any_slope_says_so() {
    // b = 1 km of snow on a 10 cm log: the stall slope of eq. (14) is 90°.
    let out = snowroll()
        .args(["simulate", "--model", "eq14", "--snow-depth", "1000"])
        .assert()
        .success();
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(stderr.contains("cannot start on any slope"), "{stderr}");
}

#[test]
fn models_lists_the_shapes_and_the_balls_terminal_fractions() {
    // issue 11: the turn models take the log only; every circular model and
    // loney take the ball too, with the fractions of
    // docs/snowball-and-losses.md §1.3 (1/6 for torque-cm, the TPT letter's).
    let out = snowroll()
        .args(["models", "--format", "json"])
        .assert()
        .success();
    let doc = json(std::str::from_utf8(&out.get_output().stdout).unwrap());
    let model = |id: &str| {
        doc["models"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["id"] == id)
            .unwrap()
            .clone()
    };
    for id in ["turns", "turns-exact"] {
        assert_eq!(model(id)["shapes"], serde_json::json!(["cylinder"]), "{id}");
        assert!(model(id)["sphere_terminal_fraction"].is_null());
    }
    for (id, exact) in [
        ("snowless", "5/7"),
        ("torque-cm", "1/6"),
        ("loney", "1/6"),
        ("torque-contact", "1/7"),
        ("energy", "2/7"),
        ("lagrangian-printed", "5/28"),
    ] {
        assert_eq!(
            model(id)["shapes"],
            serde_json::json!(["cylinder", "sphere"])
        );
        assert_eq!(model(id)["sphere_terminal_fraction_exact"], exact, "{id}");
    }
    let table = snowroll().arg("models").assert().success();
    let text = std::str::from_utf8(&table.get_output().stdout).unwrap();
    assert!(text.contains("shapes") && text.contains("cylinder,sphere"));
}

#[test]
fn a_snowless_ball_rolls_at_five_sevenths_g_sin_alpha() {
    let out = simulate(&[
        "--model",
        "snowless",
        "--shape",
        "sphere",
        "--alpha-deg",
        "40",
        "--t-end",
        "2",
    ]);
    let want = 5.0 / 7.0 * 9.81 * 40f64.to_radians().sin();
    let mut rows = 0;
    for line in out.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let a: f64 = line.split(',').nth(3).unwrap().parse().unwrap();
        // Written in shortest round-trip form, and 5G/7 is exact to 2 ulp.
        assert_close(a, want, 1e-14);
        rows += 1;
    }
    assert!(rows > 1);
    assert!(out.contains("# shape = sphere\n"));
}

/// A run the model refuses (`Model::check`) writes nothing to stdout: no
/// header first. The message names the model and the reason; the same holds
/// for an output file, which is not created.
#[test]
fn a_refused_run_writes_nothing_before_the_error() {
    let cases: [(&[&str], &[&str]); 4] = [
        (
            &["simulate", "--model", "turns", "--shape", "sphere"],
            &["model turns", "shape = sphere", "the log's"],
        ),
        (
            &["turns", "--model", "turns-exact", "--shape", "sphere"],
            &["model turns-exact", "shape = sphere"],
        ),
        (
            &[
                "simulate",
                "--model",
                "loney",
                "--shape",
                "sphere",
                "--swath-width",
                "0.1",
            ],
            &["model loney", "area law"],
        ),
        (
            &[
                "simulate", "--model", "turns", "--format", "json", "--rtol", "1e-20",
            ],
            &["rtol"],
        ),
    ];
    for (args, needles) in cases {
        let out = snowroll().args(args).assert().code(1);
        let o = out.get_output();
        assert!(o.stdout.is_empty(), "{args:?}: stdout {:?}", o.stdout);
        let err = String::from_utf8(o.stderr.clone()).unwrap();
        assert!(err.starts_with("error: "), "{err}");
        for n in needles {
            assert!(err.contains(n), "{args:?}: {err:?} lacks {n:?}");
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.csv");
    snowroll()
        .args([
            "simulate", "--model", "turns", "--shape", "sphere", "--output",
        ])
        .arg(&path)
        .assert()
        .code(1);
    assert!(!path.exists());
}

/// Issue 20, item 7: the format follows the name of `-o` when `--format` is
/// not given, and a format that contradicts the name is refused before
/// anything is written; a `--dt` grid's row count counts the points the run
/// would write (0, 0.1, 0.2, 0.3: four, though 0.3/0.1 rounds below 3).
#[test]
fn output_name_sets_the_format_and_row_counts_are_exact() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("run.JSON");
    snowroll()
        .args([
            "simulate", "--model", "energy", "--t-end", "1", "--dt", "0.5", "-o",
        ])
        .arg(&json)
        .assert()
        .success();
    let text = fs::read_to_string(&json).unwrap();
    assert!(serde_json::from_str::<Value>(&text).is_ok(), "{text}");
    let csv = dir.path().join("run.csv");
    snowroll()
        .args(["simulate", "--model", "energy", "--format", "json", "-o"])
        .arg(&csv)
        .assert()
        .failure()
        .stderr(predicate::str::contains(
            "ends in .csv but the format is json",
        ));
    assert!(!csv.exists());
    snowroll()
        .args([
            "simulate", "--model", "energy", "--dt", "0.1", "--t-end", "0.3",
        ])
        .args(["--max-rows", "3"])
        .assert()
        .failure()
        .stderr(predicate::str::contains("would write 4 rows"));
    let out = snowroll()
        .args([
            "simulate", "--model", "energy", "--dt", "0.1", "--t-end", "0.3",
        ])
        .args(["--max-rows", "4"])
        .assert()
        .success();
    let rows = String::from_utf8_lossy(&out.get_output().stdout)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .count();
    assert_eq!(rows, 5, "header and four rows");
}

/// Issue 20, item 7: a newline in the output's name does not split the
/// `# command:` line of a sweep's header (it is written as `$'…\n…'`, as a
/// shell reads it back), and the file reads back as a `--config`.
#[test]
fn a_newline_in_a_sweep_path_keeps_the_command_on_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("two\nlines.csv");
    snowroll()
        .args([
            "sweep",
            "-q",
            "--model",
            "torque-cm",
            "--alpha-deg",
            "10,20",
            "-o",
        ])
        .arg(&out)
        .assert()
        .success();
    let text = fs::read_to_string(&out).unwrap();
    let command: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("# command: "))
        .collect();
    assert_eq!(command.len(), 1, "{text}");
    assert!(command[0].contains(r"two\nlines.csv'"), "{}", command[0]);
    // Every header line is a `#` line: nothing of the name leaked onto its own.
    let header: Vec<&str> = text
        .lines()
        .take_while(|l| !l.starts_with("index,"))
        .collect();
    assert!(header.iter().all(|l| l.starts_with('#')), "{header:?}");
    let again = dir.path().join("again.csv");
    snowroll()
        .args(["sweep", "-q", "--config"])
        .arg(&out)
        .arg("-o")
        .arg(&again)
        .assert()
        .success();
    let rows = |t: &str| {
        t.lines()
            .filter(|l| !l.starts_with('#'))
            .map(String::from)
            .collect::<Vec<_>>()
    };
    assert_eq!(rows(&fs::read_to_string(&again).unwrap()), rows(&text));
}

/// In a build without the `serve` feature (`--no-default-features`),
/// `snowroll serve` names the feature to enable, whatever flags follow,
/// rather than clap's "unrecognized subcommand".
#[cfg(not(feature = "serve"))]
#[test]
fn serve_without_its_feature_names_the_feature() {
    for args in [&["serve"][..], &["serve", "--port", "0", "--open"]] {
        snowroll()
            .args(args)
            .assert()
            .failure()
            .code(1)
            .stderr(predicate::str::contains("the `serve` feature"))
            .stderr(predicate::str::contains("unrecognized").not());
    }
}

/// Issue 32, item 7: the human summary on stderr writes G = g sin α to six
/// significant digits (9.81 · sin 30° = 4.905 to rounding, printed as
/// such), while the CSV's `# summary` line keeps the shortest round-trip
/// digits of the same f64.
#[test]
fn regression_32_turns_summary_writes_g_for_people() {
    let (stdout, stderr) = turns(&["--turns", "2"]);
    assert!(
        stderr.contains("as fractions of G = g sin(alpha) = 4.905 m/s^2\n"),
        "{stderr}"
    );
    let g = 9.81 * 30f64.to_radians().sin();
    assert!(
        stdout.contains(&format!(
            "# summary: 2 turns; accelerations over G = g sin(alpha) = {g} m/s^2"
        )),
        "{stdout}"
    );
}

/// Issue 32, item 8: the crate table of `docs/architecture.md` is the
/// crates' own: each crate's `snowroll*` dependencies in its `Cargo.toml`
/// are the ones the table names (it once drew the Python package on the
/// report, and not on the formats crate it reads).
#[test]
fn regression_32_architecture_names_each_crates_dependencies() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = std::fs::read_to_string(root.join("docs/architecture.md")).unwrap();
    let table: Vec<&str> = doc
        .lines()
        .skip_while(|l| !l.starts_with("crate ") || !l.contains("depends on"))
        .skip(1)
        .take_while(|l| !l.starts_with("```"))
        .collect();
    assert_eq!(table.len(), 6, "{table:?}");
    for line in table {
        let name = line.split_whitespace().next().unwrap();
        let named: std::collections::BTreeSet<String> = line
            .split("  ")
            .map(str::trim)
            .filter(|c| !c.is_empty())
            .nth(1)
            .unwrap()
            .split(", ")
            .filter(|d| d.starts_with("snowroll"))
            .map(String::from)
            .collect();
        let manifest =
            std::fs::read_to_string(root.join("crates").join(name).join("Cargo.toml")).unwrap();
        let deps: std::collections::BTreeSet<String> = manifest
            .lines()
            .skip_while(|l| l.trim() != "[dependencies]")
            .skip(1)
            .take_while(|l| !l.starts_with('['))
            .filter_map(|l| l.split(['.', ' ', '=']).next())
            .filter(|d| d.starts_with("snowroll"))
            .map(String::from)
            .collect();
        assert_eq!(named, deps, "{name}: the table against its Cargo.toml");
    }
}

/// Issue 32, item 3, where no closed form confirms the hop (`--collision
/// pivot`): at 5.4026775058442° turn 3's least N is within the
/// integrator's error of 0 and the hop turn moved with `--rtol` without a
/// word. The run says so on stderr and in the output's notes (CSV `# note =`
/// and JSON `notes`), naming the turn; 5.41° (clear of it) says nothing.
#[test]
fn turns_say_when_a_pivot_hop_may_depend_on_the_tolerance() {
    let run = |alpha: &str, format: &str| {
        let out = snowroll()
            .args([
                "turns",
                "--collision",
                "pivot",
                "--turns",
                "50",
                "--rtol",
                "1e-8",
            ])
            .args(["--alpha-deg", alpha, "--format", format])
            .assert()
            .success();
        let o = out.get_output();
        (
            String::from_utf8(o.stdout.clone()).unwrap(),
            String::from_utf8(o.stderr.clone()).unwrap(),
        )
    };
    let said = "the first hop may depend on the tolerance: turn 3 keeps least N/(m_k g) = ";
    let (csv, stderr) = run("5.402677505844167", "csv");
    assert!(stderr.contains(&format!("note: {said}")), "{stderr}");
    assert!(csv.contains(&format!("# note = {said}")), "{csv}");
    let (json, _) = run("5.402677505844167", "json");
    let v: Value = serde_json::from_str(&json).unwrap();
    let notes = v["notes"].as_array().unwrap();
    assert!(
        notes.iter().any(|n| n.as_str().unwrap().starts_with(said)),
        "{notes:?}"
    );
    let (csv, stderr) = run("5.41", "csv");
    assert!(!stderr.contains("may depend on the tolerance"), "{stderr}");
    assert!(!csv.contains("may depend on the tolerance"), "{csv}");
}

/// Issue 32, item 3, on `simulate`'s path: a turn-model run with the pivot
/// collision (no closed form confirms its hop) says so when its first hop is
/// within the integrator's estimated error, as `turns` does, on stderr and in
/// the output's notes; and not where the margin is clear (5.41°).
#[test]
fn simulate_says_when_a_pivot_hop_may_depend_on_the_tolerance() {
    let run = |alpha: &str| {
        let out = snowroll()
            .args(["simulate", "--model", "turns", "--collision", "pivot"])
            .args(["--rtol", "1e-8", "--t-end", "60", "--dt", "1"])
            .args(["--alpha-deg", alpha])
            .assert()
            .success();
        let o = out.get_output();
        (
            String::from_utf8(o.stdout.clone()).unwrap(),
            String::from_utf8(o.stderr.clone()).unwrap(),
        )
    };
    let said = "the first hop may depend on the tolerance: turn 3 keeps least N/(m_k g) = ";
    let (csv, stderr) = run("5.402677505844167");
    assert!(stderr.contains(&format!("note: {said}")), "{stderr}");
    assert!(csv.contains(&format!("# note = {said}")), "{csv}");
    let (csv, stderr) = run("5.41");
    assert!(!stderr.contains("may depend on the tolerance"), "{stderr}");
    assert!(!csv.contains("may depend on the tolerance"), "{csv}");
}
