//! Fuzz cases of the readers of issue 20: outputs of snowroll read back
//! (`simulate`/`turns --config` of a CSV or JSON output, `sweep --config` of
//! a sweep, `merge` of shards) and `sweep --grid` TOML files, each taken
//! from a real output made at the start and then corrupted (a byte changed,
//! inserted or cut, the file truncated, lines dropped, repeated or swapped,
//! a number replaced by an odd one, a byte order mark put before it, a key
//! given twice), made adversarial (a 2 MiB line, 9 MiB
//! of blanks, 10^5 header lines), or replaced by an endless device
//! (`/dev/zero`, `/dev/urandom`). Outputs are drawn so that they often clash
//! with the input or with each other (`-o` the input however spelt, `--plot`
//! equal to `-o` or to its `FILE.partial`). The checks are those of every
//! case ([`crate::checks::check`]): a clear error or a run, no panic, no
//! hang, no stray file, and the input's bytes unchanged.

use std::ffi::OsString;
use std::fs;
use std::path::Path;

use proptest::prelude::*;

use crate::inputs::{pick, Case, Prepared};

/// One kind of input, with the real file it starts from.
#[derive(Debug, Clone)]
pub(crate) struct Seed {
    /// The name the corrupted copy gets in the case's directory.
    name: &'static str,
    /// What reads it: `config`, `sweep-config`, `grid` or `merge`.
    reader: &'static str,
    bytes: Vec<u8>,
}

/// The grid file the sweep seeds are made from: two models, a range and a
/// list, a few points (so that every case stays short).
const GRID: &str = "model = [\"energy\", \"eq4\"]\nalpha_deg = \"10:30:3\"\nsnow_depth = [0.001, 0.002]\nt_end = 2\n";

/// Runs the program in-process with `args` (in `dir`, by absolute paths);
/// it must succeed.
fn make(args: &[&str]) {
    let argv: Vec<OsString> = std::iter::once("snowroll")
        .chain(args.iter().copied())
        .map(OsString::from)
        .collect();
    let (status, captured) = snowroll_cli::console::capture(|| snowroll_cli::run_from(argv));
    assert_eq!(
        status,
        0,
        "seed {args:?}: {}",
        String::from_utf8_lossy(&captured.stderr)
    );
}

/// The real files the cases start from, made once in `dir`.
pub(crate) fn seeds(dir: &Path) -> Vec<Seed> {
    let p = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let sim = ["simulate", "--model", "eq4", "--t-end", "1", "--dt", "0.25"];
    let turns = ["turns", "--model", "turns", "--turns", "5"];
    for (run, out) in [
        (&sim[..], "s.csv"),
        (&sim[..], "s.json"),
        (&turns[..], "t.csv"),
        (&turns[..], "t.json"),
    ] {
        let mut args = run.to_vec();
        let path = p(out);
        args.extend(["-o", &path]);
        make(&args);
    }
    fs::write(dir.join("g.toml"), GRID).unwrap();
    let grid = p("g.toml");
    let sweep = ["sweep", "-q", "--grid", &grid];
    for (extra, out) in [
        (None, "w.csv"),
        (Some("0/2"), "w0.csv"),
        (Some("1/2"), "w1.csv"),
    ] {
        let mut args = sweep.to_vec();
        if let Some(shard) = extra {
            args.extend(["--shard", shard]);
        }
        let path = p(out);
        args.extend(["-o", &path]);
        make(&args);
    }
    let read = |name: &str| fs::read(dir.join(name)).unwrap();
    vec![
        Seed {
            name: "in.csv",
            reader: "config",
            bytes: read("s.csv"),
        },
        Seed {
            name: "in.json",
            reader: "config",
            bytes: read("s.json"),
        },
        Seed {
            name: "in.csv",
            reader: "config",
            bytes: read("t.csv"),
        },
        Seed {
            name: "in.json",
            reader: "config",
            bytes: read("t.json"),
        },
        Seed {
            name: "in.csv",
            reader: "sweep-config",
            bytes: read("w.csv"),
        },
        Seed {
            name: "in.toml",
            reader: "grid",
            bytes: GRID.as_bytes().to_vec(),
        },
        Seed {
            name: "in.csv",
            reader: "merge",
            bytes: read("w0.csv"),
        },
        // The other shard, written beside a corrupted first one.
        Seed {
            name: "w1.csv",
            reader: "shard",
            bytes: read("w1.csv"),
        },
    ]
}

/// Numbers that no reader should take silently.
const ODD: &[&str] = &[
    "nan",
    "inf",
    "-1",
    "0",
    "1e309",
    "-0",
    "1e-400",
    "",
    " ",
    "0x10",
    "1_0",
    "99999999999999999999999",
    "1e15",
    "4.9e-324",
    "1e-310",
    "1,2",
    "5:60:0",
    "1:2:3:4",
];

/// `bytes` corrupted one way, or left whole.
fn corrupt(bytes: Vec<u8>) -> BoxedStrategy<Vec<u8>> {
    let n = bytes.len().max(1);
    let b = bytes.clone();
    let whole = Just(bytes.clone());
    let truncated = (0..n).prop_map({
        let b = b.clone();
        move |at| b[..at.min(b.len())].to_vec()
    });
    let changed = (0..n, any::<u8>()).prop_map({
        let b = b.clone();
        move |(at, c)| {
            let mut b = b.clone();
            if let Some(x) = b.get_mut(at) {
                *x = c;
            }
            b
        }
    });
    let inserted = (0..n, prop::collection::vec(any::<u8>(), 1..16)).prop_map({
        let b = b.clone();
        move |(at, junk)| {
            let mut b = b.clone();
            let at = at.min(b.len());
            b.splice(at..at, junk);
            b
        }
    });
    let lines = (0..64usize, 0..64usize, 0..3u8).prop_map({
        let b = b.clone();
        move |(i, j, how)| {
            let text = String::from_utf8_lossy(&b);
            let mut lines: Vec<&str> = text.split_inclusive('\n').collect();
            let (i, j) = (i % lines.len().max(1), j % lines.len().max(1));
            if !lines.is_empty() {
                match how {
                    0 => {
                        lines.remove(i);
                    }
                    1 => lines.insert(i, lines[i]),
                    _ => lines.swap(i, j),
                }
            }
            lines.concat().into_bytes()
        }
    });
    let number = (0..200usize, prop::sample::select(ODD)).prop_map({
        let b = b.clone();
        move |(k, odd)| replace_number(&b, k, odd)
    });
    let adversarial = (0..3u8).prop_map(move |how| {
        let mut b = b.clone();
        match how {
            0 => {
                // One line of 2 MiB, past a row's limit, inside the header.
                let at = b.iter().position(|&c| c == b'\n').map_or(0, |i| i + 1);
                b.splice(at..at, "#".repeat(2 << 20).into_bytes());
            }
            1 => b.splice(0..0, vec![b' '; 9 << 20]).for_each(drop),
            _ => b.splice(0..0, b"# x\n".repeat(100_000)).for_each(drop),
        }
        b
    });
    // Issue 33, item 5: a byte order mark before the file (a JSON or CSV
    // output must still read as one), and a key given twice with another
    // value (refused in every format).
    let bom = Just([&b"\xEF\xBB\xBF"[..], &bytes].concat());
    let twice = (0..64usize).prop_map(move |k| key_twice(&bytes, k));
    prop_oneof![
        3 => whole, 3 => truncated, 3 => changed, 2 => inserted, 3 => lines,
        3 => number, 1 => adversarial, 1 => bom, 1 => twice,
    ]
    .boxed()
}

/// `bytes` with one of its keys given twice, the second time with another
/// value: in a CSV header the `k`-th `# key = value` line is repeated with
/// `1` as its value; in JSON the `k`-th `"key":` is given again as
/// `"key":1,` before it; in TOML the `k`-th `key = value` line repeated.
fn key_twice(bytes: &[u8], k: usize) -> Vec<u8> {
    let text = String::from_utf8_lossy(bytes).into_owned();
    if text.trim_start().starts_with('{') {
        let keys: Vec<usize> = text.match_indices("\":").map(|(i, _)| i).collect();
        let Some(&end) = keys.get(k % keys.len().max(1)) else {
            return bytes.to_vec();
        };
        let start = text[..end].rfind('"').unwrap_or(end);
        let key = &text[start..end + 2];
        let mut out = text.clone();
        out.insert_str(start, &format!("{key}1,"));
        return out.into_bytes();
    }
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let keyed: Vec<usize> = (0..lines.len())
        .filter(|&i| lines[i].contains(" = "))
        .collect();
    let Some(&i) = keyed.get(k % keyed.len().max(1)) else {
        return bytes.to_vec();
    };
    let (key, _) = lines[i].split_once(" = ").unwrap_or_default();
    let again = format!("{key} = 1\n");
    let mut out: Vec<&str> = lines.clone();
    out.insert(i + 1, &again);
    out.concat().into_bytes()
}

/// `bytes` with its `k`-th number (a run of digits, modulo their count)
/// replaced by `odd`.
fn replace_number(bytes: &[u8], k: usize, odd: &str) -> Vec<u8> {
    let mut runs = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_digit() {
            let start = i;
            while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'.') {
                i += 1;
            }
            runs.push(start..i);
        } else {
            i += 1;
        }
    }
    let mut out = bytes.to_vec();
    if let Some(r) = runs.get(k % runs.len().max(1)) {
        out.splice(r.clone(), odd.bytes());
    }
    out
}

/// The command that reads `seed` (any config reader now and then, to read
/// an input of the wrong kind), with outputs that often clash.
fn command(seed: &Seed, input: String) -> BoxedStrategy<Vec<String>> {
    let reader = seed.reader;
    let out = prop::option::weighted(
        0.7,
        pick(&[
            "out.csv",
            "in.csv",
            "./in.csv",
            "in.json",
            "in.toml",
            "-",
            "out.csv.partial",
            "/dev/null",
            "d/../in.csv",
            "w1.csv",
        ]),
    );
    let plot = prop::option::weighted(
        0.2,
        pick(&["map.svg", "out.csv", "out.csv.partial", "in.csv", "in.toml"]),
    );
    let any_reader = prop::sample::select(&["config", "sweep-config", "grid", "merge"][..]);
    let which = prop_oneof![8 => Just(reader), 1 => any_reader];
    (which, any::<bool>(), out, plot)
        .prop_map(move |(which, turns, out, plot)| {
            let mut args: Vec<String> = match which {
                "config" if turns => vec!["turns".into(), "--config".into(), input.clone()],
                "config" => vec!["simulate".into(), "--config".into(), input.clone()],
                "grid" => vec!["sweep".into(), "-q".into(), "--grid".into(), input.clone()],
                "merge" => vec!["merge".into(), input.clone(), "w1.csv".into()],
                _ => vec![
                    "sweep".into(),
                    "-q".into(),
                    "--config".into(),
                    input.clone(),
                ],
            };
            // A corrupted header may drop `turns` and leave a turn model
            // under `simulate` with t_end = 1e9: a run bounded only by the
            // step budget (10^8, a minute; issue 7's finding 2). The flag
            // bounds the run, not the reading.
            if args[0] == "simulate" || args[0] == "turns" {
                args.extend(["--max-steps".to_string(), "100000".to_string()]);
            }
            if let Some(out) = out {
                args.extend(["-o".to_string(), out]);
            }
            if let (Some(plot), true) = (plot, args[0] == "sweep") {
                args.extend(["--plot".to_string(), plot]);
            }
            args
        })
        .boxed()
}

/// A case of the readers: a corrupted seed (or an endless device) and the
/// command that reads it.
pub(crate) fn readback_case(seeds: Vec<Seed>) -> BoxedStrategy<Case> {
    let shard = seeds.iter().find(|s| s.reader == "shard").cloned();
    let readable: Vec<Seed> = seeds.into_iter().filter(|s| s.reader != "shard").collect();
    let device = prop::option::weighted(0.03, pick(&["/dev/zero", "/dev/urandom", "/dev/null"]));
    (prop::sample::select(readable), device)
        .prop_flat_map(move |(seed, device)| {
            let input = device.clone().unwrap_or_else(|| seed.name.to_string());
            let mut files = vec![];
            if let Some(shard) = &shard {
                files.push((shard.name.to_string(), Just(shard.bytes.clone()).boxed()));
            }
            if device.is_none() {
                files.push((seed.name.to_string(), corrupt(seed.bytes.clone())));
            }
            let names: Vec<String> = files.iter().map(|(n, _)| n.clone()).collect();
            let contents: Vec<BoxedStrategy<Vec<u8>>> = files.into_iter().map(|(_, s)| s).collect();
            (command(&seed, input), contents).prop_map(move |(args, contents)| Case {
                args,
                config: None,
                files: names.iter().cloned().zip(contents).collect(),
                // `d` exists, so that `d/../in.csv` is the input.
                prepared: Prepared {
                    dir: true,
                    ..Prepared::default()
                },
            })
        })
        .boxed()
}
