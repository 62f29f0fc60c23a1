//! `snowroll fit`: SYNTHETIC tracks made here (a model's run plus Gaussian
//! noise of known σ from a fixed seed, [`snowroll::fit::noisy`]), written
//! as Tracker exports them or as CSV, fitted by the program.

use std::path::Path;

use serde_json::Value;
use snowroll::fit::noisy;
use snowroll::{ModelKind, Sampling, Scenario, ScenarioFile, SimOptions};

use crate::support::{fails_in, run_in};

/// Writes a Tracker-style table (name line, tab-separated `t x`) of
/// `model` at 30° with b = 1 cm, 60 frames over 3 s, σ = 3 mm.
fn tracker_file(dir: &Path, model: ModelKind) -> String {
    let t: Vec<f64> = (1..=60).map(|k| k as f64 * 0.05).collect();
    let s = Scenario::new(ScenarioFile {
        alpha_deg: 30.0,
        snow_depth: 0.01,
        r0: 0.1,
        ..ScenarioFile::default()
    })
    .unwrap();
    let opts = SimOptions {
        t_end: 3.0,
        sampling: Sampling::Times(t.clone()),
        ..SimOptions::default()
    };
    let run = model.build().simulate(&s, &opts).unwrap();
    let x: Vec<f64> = run.samples.iter().map(|s| s.x_m).collect();
    let x = noisy(&x, 0.003, 11);
    let mut text = String::from("mass A (SYNTHETIC test data)\nt\tx\ty\n");
    for (t, x) in t.iter().zip(&x) {
        text += &format!("{t}\t{x}\t0\n");
    }
    let name = "track.txt";
    std::fs::write(dir.join(name), text).unwrap();
    name.to_string()
}

/// Every number in `v` is finite (JSON cannot hold others, but a `null`
/// must be where one was not finite, never a string or a missing key).
fn all_finite(v: &Value) -> bool {
    match v {
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(a) => a.iter().all(all_finite),
        Value::Object(o) => o.values().all(all_finite),
        _ => true,
    }
}

/// JSON: `fits` sorted by rank, the model that made the data first (for
/// two different truths), each with params {KEY: {value, stderr}}, rms_m,
/// aic, bic, rank, converged.
#[test]
fn json_ranks_the_model_that_made_the_data_first() {
    for truth in [ModelKind::Energy, ModelKind::TorqueContact] {
        let dir = tempfile::tempdir().unwrap();
        let data = tracker_file(dir.path(), truth);
        let out = run_in(
            dir.path(),
            &[
                "fit",
                &data,
                "--alpha-deg",
                "30",
                "--r0",
                "0.1",
                "--free",
                "snow_depth,x0",
                "--t0",
                "0",
                "--format",
                "json",
            ],
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert!(all_finite(&v));
        let fits = v["fits"].as_array().unwrap();
        assert!(fits.len() >= 7, "every circular model: {}", fits.len());
        assert_eq!(fits[0]["model"], truth.id(), "{:#}", v["fits"]);
        for (k, f) in fits.iter().enumerate() {
            assert_eq!(f["rank"], k + 1);
            for key in ["rms_m", "aic", "bic", "converged"] {
                assert!(!f[key].is_null(), "{key}");
            }
        }
        let b = &fits[0]["params"]["snow_depth"];
        let (value, se) = (b["value"].as_f64().unwrap(), b["stderr"].as_f64().unwrap());
        assert!((value - 0.01).abs() < 5.0 * se, "b = {value} ± {se}");
        assert_eq!(v["data"]["name"], "mass A (SYNTHETIC test data)");
    }
}

/// Text by default, and `--plot` draws the figure with the data labelled
/// SYNTHETIC; a CSV with units in its header reads the same numbers.
#[test]
fn text_plot_and_csv_units() {
    let dir = tempfile::tempdir().unwrap();
    let data = tracker_file(dir.path(), ModelKind::Energy);
    let out = run_in(
        dir.path(),
        &[
            "fit",
            &data,
            "--model",
            "energy,torque-cm",
            "--plot",
            "fit.svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("1    energy") && text.contains("snow_depth = "),
        "{text}"
    );
    let svg = std::fs::read_to_string(dir.path().join("fit.svg")).unwrap();
    assert!(svg.contains("SYNTHETIC") && svg.contains("residuals"));
    // The same track in cm and ms under a CSV header gives the same fit.
    let tracker = std::fs::read_to_string(dir.path().join(&data)).unwrap();
    let mut csv = String::from("time (ms),x (cm)\n");
    for line in tracker.lines().skip(2) {
        let c: Vec<f64> = line.split('\t').map(|v| v.parse().unwrap()).collect();
        csv += &format!("{},{}\n", c[0] * 1e3, c[1] * 1e2);
    }
    std::fs::write(dir.path().join("track.csv"), csv).unwrap();
    let json = |name: &str| -> Value {
        let out = run_in(
            dir.path(),
            &["fit", name, "--model", "energy", "--format", "json"],
        );
        serde_json::from_slice(&out.stdout).unwrap()
    };
    let (a, b) = (json(&data), json("track.csv"));
    let value = |v: &Value| {
        v["fits"][0]["params"]["snow_depth"]["value"]
            .as_f64()
            .unwrap()
    };
    // Unit conversion rounds each point by an ulp or so: the fits agree far
    // inside their standard error.
    let se = a["fits"][0]["params"]["snow_depth"]["stderr"]
        .as_f64()
        .unwrap();
    assert!((value(&a) - value(&b)).abs() < 1e-3 * se);
}

/// Bad data fail with status 1 and a message naming the file and the line.
#[test]
fn bad_data_name_the_line() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "t,x\n0,0\n0.1,0.01\n0.2,0.04\n0.15,0.09\n0.4,0.16\n0.5,0.25\n",
            "line 5",
        ),
        (
            "t,x\n0,0\n0.1,nan\n0.2,0.04\n0.3,0.09\n0.4,0.16\n",
            "line 3",
        ),
        ("t,x\n0,0\n0.1,0.01\n", "at least 5"),
        ("when,where\n0,0\n", "no header"),
    ];
    for (k, (text, want)) in cases.iter().enumerate() {
        let name = format!("bad{k}.csv");
        std::fs::write(dir.path().join(&name), text).unwrap();
        let e = fails_in(dir.path(), &["fit", &name]);
        assert!(e.contains(&name) && e.contains(want), "{text:?}: {e}");
    }
    let e = fails_in(dir.path(), &["fit", "missing.csv"]);
    assert!(e.contains("missing.csv"), "{e}");
    let data = tracker_file(dir.path(), ModelKind::Energy);
    let e = fails_in(dir.path(), &["fit", &data, "--free", "rtol"]);
    assert!(e.contains("rtol") && e.contains("alpha_deg"), "{e}");
    let e = fails_in(dir.path(), &["fit", &data, "--plot", "fit.pdf"]);
    assert!(e.contains(".svg or .png"), "{e}");
    assert!(!dir.path().join("fit.pdf").exists());
}
