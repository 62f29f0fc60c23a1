//! The writers (`docs/contact-forces.md` §5): what CSV and JSON make of a
//! value that is undefined in some rows.

use snowroll::{ModelKind, OnHop, Sampling, Scenario, ScenarioFile, SimOptions};
use snowroll_io::{write_trajectory, write_turn_table, Format, RunParams};

fn scenario(alpha_deg: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        ..ScenarioFile::default()
    })
    .unwrap()
}

fn turn_opts(turns: u64) -> SimOptions {
    SimOptions {
        t_end: 1e7,
        turns: Some(turns),
        ..SimOptions::default()
    }
}

/// |F|/N is undefined where N ≤ 0 (`docs/contact-forces.md` §5): never
/// written as a number, never non-finite. At 80° the turn model loses
/// contact in turn 1 (§4.4); with `--on-hop continue` the run goes on, so
/// some samples and some turns have N ≤ 0. There the CSV cell is empty and
/// the JSON value is `null`; everywhere else the ratio is |F|/N of the same
/// row (the writer prints the shortest round-trip form, so equality is exact).
#[test]
fn friction_ratio_is_empty_in_csv_and_null_in_json_where_n_is_not_positive() {
    let s = scenario(80.0);
    let opts = SimOptions {
        on_hop: OnHop::Continue,
        sampling: Sampling::Every(0.01),
        ..turn_opts(4)
    };
    let traj = ModelKind::Turns.build().simulate(&s, &opts).unwrap();
    let off = traj.samples.iter().filter(|p| p.normal_n <= 0.0).count();
    assert!(off > 0 && off < traj.samples.len(), "{off}");
    for p in &traj.samples {
        assert_eq!(p.friction_ratio.is_none(), p.normal_n <= 0.0, "{p:?}");
    }
    let params = RunParams::new(&s, &opts);
    let mut csv = Vec::new();
    write_trajectory(&mut csv, Format::Csv, &traj, &params).unwrap();
    let text = String::from_utf8(csv).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (n_col, f_col, ratio_col) = (col("normal_n"), col("friction_n"), col("friction_ratio"));
    let mut empty = 0;
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let n: f64 = cells[n_col].parse().unwrap();
        let f: f64 = cells[f_col].parse().unwrap();
        if n <= 0.0 {
            assert_eq!(cells[ratio_col], "", "{line}");
            empty += 1;
        } else {
            let ratio: f64 = cells[ratio_col].parse().unwrap();
            assert_eq!(ratio.to_bits(), (f.abs() / n).to_bits(), "{line}");
        }
    }
    assert_eq!(empty, off);
    let mut json = Vec::new();
    write_trajectory(&mut json, Format::Json, &traj, &params).unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&json).unwrap();
    let samples = doc["samples"].as_array().unwrap();
    let nulls = samples
        .iter()
        .filter(|p| p["friction_ratio"].is_null())
        .inspect(|p| assert!(p["normal_n"].as_f64().unwrap() <= 0.0, "{p}"))
        .count();
    assert_eq!(nulls, off);

    let table = snowroll::run_turns(ModelKind::Turns, &s, &opts).unwrap();
    let lost: Vec<bool> = table.rows.iter().map(|r| r.min_normal_n <= 0.0).collect();
    assert!(lost.contains(&true) && lost.contains(&false), "{lost:?}");
    for (row, lost) in table.rows.iter().zip(&lost) {
        assert_eq!(row.max_friction_ratio.is_none(), *lost, "{row:?}");
    }
    let mut csv = Vec::new();
    write_turn_table(&mut csv, Format::Csv, &table, &params).unwrap();
    let text = String::from_utf8(csv).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let last = lines
        .next()
        .unwrap()
        .split(',')
        .position(|h| h == "max_friction_ratio");
    let cells: Vec<String> = lines
        .map(|l| l.split(',').nth(last.unwrap()).unwrap().to_string())
        .collect();
    let empty: Vec<bool> = cells.iter().map(String::is_empty).collect();
    assert_eq!(empty, lost);
}
