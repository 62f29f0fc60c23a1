//! `snowroll sweep` and `snowroll merge` as whole processes: grid syntax
//! and its errors, the same bytes for any thread count, shards merged equal
//! the whole, and a sweep killed with SIGKILL then resumed equal to an
//! uninterrupted one.

use std::fs;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::thread;
use std::time::Duration;

use rustix::process::{kill_process, Pid, Signal};

fn bin() -> &'static Path {
    assert_cmd::cargo::cargo_bin!("snowroll")
}

fn run(args: &[&str], threads: &str) -> Output {
    Command::new(bin())
        .args(args)
        .env("RAYON_NUM_THREADS", threads)
        .output()
        .unwrap()
}

fn ok(args: &[&str]) -> String {
    let out = run(args, "2");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn fails(args: &[&str]) -> String {
    let out = run(args, "2");
    assert!(!out.status.success(), "{args:?} succeeded");
    String::from_utf8(out.stderr).unwrap()
}

/// `&str`s of `v`.
fn argv(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// The lines after the header.
fn rows(text: &str) -> Vec<&str> {
    text.lines()
        .skip_while(|l| l.starts_with('#'))
        .skip(1)
        .collect()
}

/// A grid over three kinds of model (circular, closed form, turns).
const GRID: [&str; 9] = [
    "sweep",
    "--model",
    "torque-cm,loney,energy,turns",
    "--alpha-deg",
    "5:60:12",
    "--snow-depth",
    "0.001,0.01,0.1",
    "--t-end",
    "2",
];

#[test]
fn one_row_per_point_in_grid_order_with_the_header() {
    let text = ok(&GRID);
    assert!(text.starts_with("# snowroll sweep, version "));
    assert!(text.contains("\n# alpha_deg: 5:60:12\n# snow_depth: 0.001,0.01,0.1\n"));
    assert!(text.contains("\n# points: 144\n"));
    let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
    assert!(header.starts_with("index,model,alpha_deg,snow_depth,"));
    let rows = rows(&text);
    assert_eq!(rows.len(), 4 * 12 * 3);
    let models = ["torque-cm", "loney", "energy", "turns"];
    for (i, row) in rows.iter().enumerate() {
        let f: Vec<&str> = row.split(',').collect();
        assert_eq!(f[0], i.to_string());
        assert_eq!(f[1], models[i / 36]);
        // 5:60:12 steps by 5 exactly.
        let alpha: f64 = f[2].parse().unwrap();
        assert!((alpha - (5.0 + 5.0 * ((i / 3) % 12) as f64)).abs() < 1e-12);
        assert_eq!(f[3], ["0.001", "0.01", "0.1"][i % 3]);
    }
}

#[test]
fn rows_are_the_same_bytes_for_one_and_two_threads() {
    let one = run(&GRID, "1");
    let two = run(&GRID, "2");
    assert!(one.status.success() && two.status.success());
    assert_eq!(one.stdout, two.stdout);
}

#[test]
fn grid_errors_are_clear() {
    for (args, want) in [
        (vec!["sweep", "--alpha-deg", "5:60"], "start:end:count"),
        (
            vec!["sweep", "--model", "eq4", "--alpha-deg", "5:95:3"],
            "0 < alpha_deg < 90",
        ),
        (
            vec!["sweep", "--model", "eq4", "--snow-depth", "0.1,,2"],
            "empty item",
        ),
        (vec!["sweep", "--model", "eq99"], "unknown model"),
        (vec!["sweep", "--alpha-deg", "30"], "no model given"),
        (
            vec![
                "sweep",
                "--model",
                "eq4",
                "--alpha-deg",
                "1:80:100000",
                "--r0",
                "0.1:1:100000",
            ],
            "more than the limit of 1000000000",
        ),
        (
            vec!["sweep", "--model", "eq4", "--shard", "2/2"],
            "0 <= I < N",
        ),
        (vec!["sweep", "--model", "eq4", "--resume"], "--output"),
    ] {
        let e = fails(&args);
        assert!(e.contains(want), "{args:?}: {e}");
    }
}

/// A bad axis value is reported once, on one line, as the flag was given,
/// with the key, the bad value and the allowed range; before a missing model.
#[test]
fn axis_value_errors_name_the_flag_once() {
    for (flag, text, want) in [
        (
            "--alpha-deg",
            "5:95:3",
            "invalid alpha_deg (degrees) = 95: expected 0 < alpha_deg < 90 degrees (0 <= \
             alpha_deg for an unwinding roll, snow_depth < 0)",
        ),
        (
            "--t-end",
            "-1",
            "invalid t_end (s) = -1: expected 0 < t_end < infinity s",
        ),
        ("--r0", "0,1", "invalid r0 (m) = 0: expected r0 > 0 m"),
        (
            "--rtol",
            "1e-30",
            "invalid rtol = 1e-30: expected 1e-15 <= rtol < 1",
        ),
        (
            "--snow-depth",
            "0.1,-0.1",
            "invalid snow_depth (m) = -0.1: expected snow_depth >= 0 without core_radius: a \
             negative snow depth is an unwinding roll, which needs --core-radius (0 < \
             core_radius < r0), the radius where it stops",
        ),
    ] {
        for with_model in [true, false] {
            let mut args = vec!["sweep", flag, text];
            if with_model {
                args.extend(["--model", "eq4"]);
            }
            let e = fails(&args);
            assert_eq!(e, format!("error: {flag} {text}: {want}\n"), "{args:?}");
        }
    }
    let e = fails(&["sweep", "--model", "eq4", "--snow-depth", "1:x:3"]);
    assert_eq!(
        e,
        "error: --snow-depth 1:x:3: cannot read it: \"x\" is not a number\n"
    );
}

#[test]
fn grid_file_gives_axes_and_flags_override_it() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("axes.toml");
    fs::write(
        &file,
        "model = [\"eq4\", \"energy\"]\nalpha-deg = \"20:30:3\"\nsnow_depth = [0.01, 0.1]\nt_end = 1\n",
    )
    .unwrap();
    let f = file.to_str().unwrap();
    let text = ok(&["sweep", "--grid", f]);
    assert_eq!(rows(&text).len(), 2 * 3 * 2);
    let text = ok(&["sweep", "--grid", f, "--model", "eq6"]);
    let rows = rows(&text);
    assert_eq!(rows.len(), 3 * 2);
    assert!(rows
        .iter()
        .all(|r| r.split(',').nth(1) == Some("torque-contact")));
    fs::write(&file, "slope = 3\n").unwrap();
    let e = fails(&["sweep", "--grid", f]);
    assert!(e.contains("unknown key \"slope\""), "{e}");
}

/// Five shards merged are the bytes the whole sweep writes to the same
/// path, `# command:` line included.
#[test]
fn shards_merged_equal_the_whole_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let mut args: Vec<String> = GRID.iter().map(|s| s.to_string()).collect();
    args.extend(["-o".to_string(), path("whole.csv")]);
    ok(&argv(&args));
    let whole = fs::read(path("whole.csv")).unwrap();
    fs::remove_file(path("whole.csv")).unwrap();
    let n = 5;
    for k in 0..n {
        let mut a: Vec<String> = GRID.iter().map(|s| s.to_string()).collect();
        a.extend([
            "--shard".to_string(),
            format!("{k}/{n}"),
            "-o".to_string(),
            path(&format!("part{k}.csv")),
        ]);
        ok(&argv(&a));
    }
    // Any order on the command line.
    let mut merge = vec!["merge".to_string(), "-o".to_string(), path("whole.csv")];
    merge.extend((0..n).rev().map(|k| path(&format!("part{k}.csv"))));
    ok(&argv(&merge));
    assert!(whole == fs::read(path("whole.csv")).unwrap());

    // A missing shard, a duplicate, a shard of another sweep, a cut file.
    let e = fails(&[
        "merge",
        &path("part0.csv"),
        &path("part2.csv"),
        &path("part3.csv"),
        &path("part4.csv"),
    ]);
    assert!(e.contains("missing shards: 1/5"), "{e}");
    let e = fails(&["merge", &path("part0.csv"), &path("part0.csv")]);
    assert!(e.contains("given twice"), "{e}");
    let e = fails(&["merge", &path("part0.csv"), &path("whole.csv")]);
    assert!(e.contains("not shards of the same sweep"), "{e}");
    let p1 = fs::read_to_string(path("part1.csv")).unwrap();
    fs::write(path("part1.csv"), &p1[..p1.len() - 3]).unwrap();
    let mut cut = vec!["merge".to_string()];
    cut.extend((0..n).map(|k| path(&format!("part{k}.csv"))));
    let e = fails(&argv(&cut));
    assert!(e.contains("cut short"), "{e}");
}

/// A sweep killed with SIGKILL (no clean-up possible) and resumed gives the
/// same file as an uninterrupted run; without `--resume` the partial rows
/// are refused rather than overwritten.
#[test]
fn a_killed_sweep_resumed_equals_an_uninterrupted_one() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.csv");
    let partial = dir.path().join("s.csv.partial");
    let o = out.to_str().unwrap();
    // The turn model is slow enough (about 0.1 ms a row) that the kill
    // lands after some chunks of 16 rows and long before the 4000th row.
    let args = [
        "sweep",
        "--model",
        "turns",
        "--alpha-deg",
        "20:40:4000",
        "--t-end",
        "2",
        "--chunk-rows",
        "16",
        "-o",
        o,
    ];
    let mut child = Command::new(bin())
        .args(args)
        .env("RAYON_NUM_THREADS", "1")
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Wait for some rows on disk (polling the file, not a clock).
    loop {
        let rows = fs::read_to_string(&partial)
            .map(|t| rows(&t).len())
            .unwrap_or(0);
        if rows >= 40 {
            break;
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the sweep ended before it could be killed"
        );
        thread::sleep(Duration::from_millis(5));
    }
    kill_process(Pid::from_child(&child), Signal::KILL).unwrap();
    child.wait().unwrap();
    assert!(!out.exists());
    let before = fs::read_to_string(&partial).unwrap();
    assert!(rows(&before).len() < 4000);

    let e = fails(&args);
    assert!(e.contains("pass --resume"), "{e}");
    let mut resume = args.to_vec();
    resume.push("--resume");
    ok(&resume);
    assert!(!partial.exists());
    let resumed = fs::read(&out).unwrap();

    fs::remove_file(&out).unwrap();
    ok(&args);
    let whole = fs::read(&out).unwrap();
    assert_eq!(resumed, whole);
}

/// Parquet (feature `parquet`): the same rows as the CSV, value for value,
/// and the header as key-value metadata.
#[cfg(feature = "parquet")]
#[test]
fn parquet_reads_back_with_the_csv_values() {
    use arrow_array::{Array, Float64Array, StringArray, UInt64Array};
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;

    let dir = tempfile::tempdir().unwrap();
    let pq = dir.path().join("s.parquet");
    let mut args: Vec<String> = GRID.iter().map(|s| s.to_string()).collect();
    args.extend(["-o".to_string(), pq.to_str().unwrap().to_string()]);
    ok(&argv(&args));
    let csv = ok(&GRID);
    let csv_rows: Vec<Vec<&str>> = rows(&csv).iter().map(|r| r.split(',').collect()).collect();
    // Columns by name: new sweep axes and results move the positions.
    let header: Vec<&str> = csv
        .lines()
        .find(|l| !l.starts_with('#'))
        .unwrap()
        .split(',')
        .collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();

    let file = fs::File::open(&pq).unwrap();
    let builder = ParquetRecordBatchReaderBuilder::try_new(file).unwrap();
    let kv = builder
        .metadata()
        .file_metadata()
        .key_value_metadata()
        .unwrap()
        .clone();
    let get = |k: &str| kv.iter().find(|e| e.key == k).and_then(|e| e.value.clone());
    assert_eq!(get("snowroll.alpha_deg").as_deref(), Some("5:60:12"));
    assert_eq!(get("snowroll.points").as_deref(), Some("144"));
    assert!(get("snowroll.version").is_some());
    let mut n = 0;
    for batch in builder.build().unwrap() {
        let batch = batch.unwrap();
        let col = |name: &str| batch.column(batch.schema().index_of(name).unwrap()).clone();
        let index = col("index");
        let index = index.as_any().downcast_ref::<UInt64Array>().unwrap();
        let model = col("model");
        let model = model.as_any().downcast_ref::<StringArray>().unwrap();
        let stop = col("stop");
        let stop = stop.as_any().downcast_ref::<StringArray>().unwrap();
        for i in 0..batch.num_rows() {
            let want = &csv_rows[n];
            assert_eq!(index.value(i).to_string(), want[at("index")]);
            assert_eq!(model.value(i), want[at("model")]);
            assert_eq!(stop.value(i), want[at("stop")]);
            // Floats: the same bits as the CSV's shortest round-trip text.
            for name in ["alpha_deg", "t_s", "x_m", "v_m_s"] {
                let c = col(name);
                let c = c.as_any().downcast_ref::<Float64Array>().unwrap();
                let want: f64 = want[at(name)].parse().unwrap();
                assert_eq!(c.value(i).to_bits(), want.to_bits(), "{name} row {n}");
            }
            assert!(col("x_end").is_null(i));
            n += 1;
        }
    }
    assert_eq!(n, csv_rows.len());
}

#[cfg(not(feature = "parquet"))]
#[test]
fn parquet_without_the_feature_says_how_to_get_it() {
    let e = fails(&[
        "sweep",
        "--model",
        "eq4",
        "-o",
        "/nonexistent-dir/s.parquet",
    ]);
    assert!(
        e.contains("--features parquet") || e.contains("cannot write"),
        "{e}"
    );
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("s.parquet");
    let e = fails(&["sweep", "--model", "eq4", "-o", p.to_str().unwrap()]);
    assert!(e.contains("--features parquet"), "{e}");
    assert!(!p.exists());
}

#[test]
fn plot_draws_a_regime_map_with_legend_axes_and_the_stall_border() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("e.csv");
    let svg = dir.path().join("e.svg");
    let (csv_s, svg_s) = (csv.display().to_string(), svg.display().to_string());
    ok(&[
        "sweep",
        "--model",
        "energy",
        "--alpha-deg",
        "0.5:20:12",
        "--snow-depth",
        "0.005:0.05:6",
        "--t-end",
        "2",
        "--output",
        &csv_s,
        "--plot",
        &svg_s,
    ]);
    let map = fs::read_to_string(&svg).unwrap();
    assert!(map.starts_with("<svg"), "{}", &map[..80]);
    for text in [
        // The colour legend's title says what the colours show.
        "\noutcome\n",
        "never starts",
        "rolls on",
        "stall slope (fn. 7)",
        "slope angle α [deg]",
        "snow depth b [m]",
    ] {
        assert!(map.contains(text), "{text} missing");
    }
    // The border is one polyline of many points; the cells are rectangles.
    assert!(map.contains("<polyline"), "no border drawn");
    assert!(map.matches("<rect").count() >= 12 * 6);
    // The CSV is written as without --plot.
    assert_eq!(rows(&fs::read_to_string(&csv).unwrap()).len(), 12 * 6);

    // Coloured by a result column: bins of v_m_s in the legend.
    ok(&[
        "sweep",
        "--model",
        "turns",
        "--alpha-deg",
        "20:80:7",
        "--mu",
        "0.2,0.6",
        "--t-end",
        "1",
        "--output",
        &csv_s,
        "--plot",
        &svg_s,
        "--plot-color",
        "v_m_s",
    ]);
    let map = fs::read_to_string(&svg).unwrap();
    // Bins of the quantity with its unit, under the title v [m/s], never
    // the column's name.
    assert!(
        map.contains(" ≤ v &lt; ") && map.contains(" m/s\n"),
        "no bins of v in m/s"
    );
    assert!(map.contains("\nv [m/s]\n"), "no legend title v [m/s]");
    assert!(!map.contains("v_m_s"), "the column name is shown");
    // A dimensionless axis carries no unit (report notation).
    assert!(map.contains("friction coefficient μ"));

    for (args, message) in [
        (vec!["--plot-color", "speed"], "expected one of outcome"),
        (vec!["--plot-x", "beta"], "--plot-x \"beta\""),
        (vec!["--plot-y", "r0"], "r0 is not swept"),
    ] {
        let mut all = vec![
            "sweep",
            "--model",
            "energy",
            "--alpha-deg",
            "10,20",
            "--snow-depth",
            "0.01,0.02",
            "--t-end",
            "1",
            "--output",
            &csv_s,
            "--plot",
            &svg_s,
        ];
        all.extend(args);
        let e = fails(&all);
        assert!(e.contains(message), "{e}");
    }
    let e = fails(&["sweep", "--model", "energy", "--plot", &svg_s]);
    assert!(e.contains("--output"), "{e}");

    // A third swept setting puts two rows in every cell: refused from the
    // grid before any row is computed, so no output is left behind.
    let out3 = dir.path().join("three-axes.csv");
    let out3_s = out3.to_str().unwrap();
    let e = fails(&[
        "sweep",
        "--model",
        "energy",
        "--alpha-deg",
        "10,20",
        "--snow-depth",
        "0.01,0.02",
        "--r0",
        "0.1,0.2",
        "--t-end",
        "1",
        "--output",
        out3_s,
        "--plot",
        &svg_s,
    ]);
    assert!(e.contains("the grid has 8 points but the"), "{e}");
    assert!(e.contains("has 4 cells"), "{e}");
    assert!(!out3.exists(), "a refused --plot left {out3_s}");
}

/// Issue 32, item 7: a range's values are printed with the digits its spec
/// needs (`0.001:0.1:100` steps by 0.001: `0.012`, not `0.012000000000000002`),
/// and the value printed is the value run, so a row reruns from its printed
/// values: the same sweep on the printed value alone gives the same row.
#[test]
fn regression_32_range_values_print_their_spec_digits_and_rerun_from_the_print() {
    let args = |depth: &str| {
        [
            "sweep",
            "--model",
            "loney,turns",
            "--snow-depth",
            depth,
            "--t-end",
            "2",
        ]
        .map(String::from)
    };
    let text = ok(&argv(&args("0.001:0.1:100")));
    let rows = rows(&text);
    assert_eq!(rows.len(), 200);
    for (i, row) in rows.iter().enumerate() {
        let depth = row.split(',').nth(3).unwrap();
        let k = i % 100 + 1;
        assert_eq!(
            depth.parse::<f64>().unwrap().to_bits(),
            format!("0.{k:03}").parse::<f64>().unwrap().to_bits()
        );
        assert!(depth.len() <= 5, "row {i}: snow_depth {depth}");
    }
    for i in (0..200).step_by(17) {
        let depth = rows[i].split(',').nth(3).unwrap();
        let again = ok(&argv(&args(depth)));
        let again = self::rows(&again);
        let without_index = |row: &str, want: usize| -> String {
            let (index, rest) = row.split_once(',').unwrap();
            assert_eq!(index.parse::<usize>().unwrap() % 100, want);
            rest.to_string()
        };
        assert_eq!(
            without_index(again[i / 100], i / 100),
            without_index(rows[i], i % 100),
            "row {i} rerun at snow_depth {depth}"
        );
    }
}
