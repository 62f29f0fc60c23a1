//! The inputs of the fuzz cases: argument vectors and config documents.

use proptest::prelude::*;

/// Largest valid end time generated, s.
pub(crate) const MAX_T_END: f64 = 100.0;
/// Smallest valid output grid generated, s: with [`MAX_T_END`], at most
/// 10^4 rows.
pub(crate) const MIN_DT: f64 = 0.01;
/// Most turns generated.
pub(crate) const MAX_TURNS: u64 = 500;
/// Weight of `paper` (a real run takes about a second) among the commands,
/// out of [`COMMAND_WEIGHT_TOTAL`].
pub(crate) const PAPER_WEIGHT: u32 = 1;
pub(crate) const COMMAND_WEIGHT_TOTAL: u32 = 20_000;

/// Values that any number flag may get: invalid, degenerate and extreme.
pub(crate) const ODD_NUMBERS: &[&str] = &[
    "0", "-0", "-1", "-1e-300", "nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e309",
    "-1e309", "1e-400", "abc", "", " ", "1e", "e5", "0x10", "1_000", "\u{661}", "+5", ".5",
    "5.", "--1", "1.0.0", "1e+", "\u{221e}", "0,5", "1 ", "\t2",
    "99999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999999",
];
/// Extreme but positive values for the physical parameters: a clear
/// error or a finite result, never garbage.
pub(crate) const EXTREME_POSITIVE: &[&str] = &[
    "1e308",
    "1.7976931348623157e308",
    "1e-300",
    "4.9e-324",
    "2.2250738585072014e-308",
    "1e-15",
    "1e15",
    "1e154",
    "1e155",
];

/// The flags of `simulate` and `turns`, and how their values are drawn.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Kind {
    Model,
    /// A physical parameter valid in `lo..hi`.
    Physical(f64, f64),
    TEnd,
    XEnd,
    Tolerance(f64, f64),
    Dt,
    Times,
    Turns,
    /// A row or step limit (`--max-rows`, `--max-steps`).
    Limit,
    Format,
    Output,
    Config,
}

pub(crate) const FLAGS: &[(&str, Kind)] = &[
    ("--model", Kind::Model),
    ("--alpha-deg", Kind::Physical(0.01, 89.99)),
    ("--snow-depth", Kind::Physical(0.0, 1.0)),
    ("--r0", Kind::Physical(0.01, 2.0)),
    ("--g", Kind::Physical(0.1, 30.0)),
    ("--density", Kind::Physical(1.0, 2000.0)),
    ("--length", Kind::Physical(0.1, 10.0)),
    ("--v0", Kind::Physical(0.0, 20.0)),
    ("--t-end", Kind::TEnd),
    ("--x-end", Kind::XEnd),
    ("--rtol", Kind::Tolerance(1e-15, 0.5)),
    ("--atol", Kind::Tolerance(1e-30, 1.0)),
    ("--dt", Kind::Dt),
    ("--times", Kind::Times),
    ("--turns", Kind::Turns),
    ("--max-rows", Kind::Limit),
    ("--max-steps", Kind::Limit),
    ("--format", Kind::Format),
    ("--output", Kind::Output),
    ("-o", Kind::Output),
    ("--config", Kind::Config),
];

/// Circular models: ids and aliases in any case.
pub(crate) const CIRCULAR_MODELS: &[&str] = &[
    "eq4",
    "torque-cm",
    "eq6",
    "eq14",
    "energy",
    "eq21",
    "eq32",
    "loney",
    "EQ4",
    "Energy",
];
/// Turn models, which `turns` takes.
pub(crate) const TURN_MODELS: &[&str] = &["turns", "eq73", "turns-exact", "eq88", "TURNS"];
/// Near misses.
pub(crate) const BAD_MODELS: &[&str] = &["eq99", "turnz", "", "eq4 ", "\u{e9}", "torque_cm"];

/// Output paths: new, existing (regular, directory, link, read-only, hard
/// link, the config itself), devices, missing folders, odd names.
pub(crate) const PATHS: &[&str] = &[
    "out.csv", "out.json", "new.csv", "d", ".", "-", "/dev/null", "/dev/full", "link.csv",
    "ro.csv", "hard.csv", "c.toml", "missing/x.csv", "../up.csv", "", "sub/", "r\u{e9}sultats.csv",
    "a\nb.csv", "d/inner.csv", "dangling.csv", "..", "/", "nul\u{7f}.csv",
    "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx.csv",
];

/// Config paths.
pub(crate) const CONFIGS: &[&str] = &[
    "c.toml",
    "c.toml",
    "c.toml",
    "missing.toml",
    "d",
    "/dev/null",
    "out.csv",
];

/// Config keys: every long flag, old names, near misses.
pub(crate) const KEYS: &[(&str, Kind)] = &[
    ("model", Kind::Model),
    ("alpha-deg", Kind::Physical(0.01, 89.99)),
    ("snow-depth", Kind::Physical(0.0, 1.0)),
    ("r0", Kind::Physical(0.01, 2.0)),
    ("g", Kind::Physical(0.1, 30.0)),
    ("density", Kind::Physical(1.0, 2000.0)),
    ("length", Kind::Physical(0.1, 10.0)),
    ("v0", Kind::Physical(0.0, 20.0)),
    ("t-end", Kind::TEnd),
    ("x-end", Kind::XEnd),
    ("rtol", Kind::Tolerance(1e-15, 0.5)),
    ("atol", Kind::Tolerance(1e-30, 1.0)),
    ("dt", Kind::Dt),
    ("times", Kind::Times),
    ("turns", Kind::Turns),
    ("max_rows", Kind::Limit),
    ("max-steps", Kind::Limit),
    ("format", Kind::Format),
    ("output", Kind::Output),
    ("alpha_deg", Kind::Physical(0.01, 89.99)),
    ("alpha_deg", Kind::Physical(0.01, 89.99)),
    ("snow_depth", Kind::Physical(0.0, 1.0)),
    ("t_end_s", Kind::TEnd),
    ("Model", Kind::Model),
    ("alpha", Kind::Physical(0.01, 89.99)),
    ("config", Kind::Config),
];

pub(crate) fn pick(items: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::sample::select(items).prop_map(str::to_string).boxed()
}

/// A number in `lo..=hi`, spread over decades when the range spans many.
pub(crate) fn in_range(lo: f64, hi: f64) -> BoxedStrategy<f64> {
    if lo > 0.0 && hi / lo > 100.0 {
        (lo.log10()..=hi.log10())
            .prop_map(|e| 10f64.powf(e))
            .boxed()
    } else {
        (lo..=hi).boxed()
    }
}

/// How a number is spelt: Rust's shortest form, or exponent notation.
pub(crate) fn spelt(x: f64) -> BoxedStrategy<String> {
    prop_oneof![
        Just(format!("{x}")),
        Just(format!("{x:e}")),
        Just(format!("{x:.3}"))
    ]
    .boxed()
}

pub(crate) fn number(lo: f64, hi: f64, extreme: bool) -> BoxedStrategy<String> {
    let valid = in_range(lo, hi).prop_flat_map(spelt);
    if extreme {
        prop_oneof![16 => valid, 1 => pick(ODD_NUMBERS), 2 => pick(EXTREME_POSITIVE)].boxed()
    } else {
        prop_oneof![16 => valid, 1 => pick(ODD_NUMBERS)].boxed()
    }
}

/// `--times` lists: ascending, shuffled, with odd items.
pub(crate) fn times() -> BoxedStrategy<String> {
    let item = prop_oneof![8 => in_range(1e-3, MAX_T_END).prop_map(|t| format!("{t}")), 1 => pick(ODD_NUMBERS)];
    prop_oneof![
        prop::collection::vec(in_range(1e-3, MAX_T_END), 1..50).prop_map(|mut v| {
            v.sort_by(f64::total_cmp);
            v.iter().map(f64::to_string).collect::<Vec<_>>().join(",")
        }),
        prop::collection::vec(item, 0..8).prop_map(|v| v.join(",")),
    ]
    .boxed()
}

pub(crate) fn turns() -> BoxedStrategy<String> {
    prop_oneof![
        6 => (1..=MAX_TURNS).prop_map(|n| n.to_string()),
        1 => pick(&["0", "-1", "1e3", "18446744073709551616", "abc", "", "1.5", "+3"]),
    ]
    .boxed()
}

/// A row or step limit: small ones end runs early (a stop, exit 0), and
/// values that are not limits.
pub(crate) fn limit() -> BoxedStrategy<String> {
    prop_oneof![
        6 => (1..=100_000u64).prop_map(|n| n.to_string()),
        1 => pick(&["0", "-1", "1e3", "18446744073709551615", "18446744073709551616", "abc", ""]),
    ]
    .boxed()
}

/// A value for a flag of `kind`, as it would be typed.
pub(crate) fn value(kind: Kind) -> BoxedStrategy<String> {
    match kind {
        Kind::Model => prop_oneof![
            30 => pick(CIRCULAR_MODELS),
            3 => pick(BAD_MODELS),
            1 => "\\PC{0,40}".boxed(),
            1 => Just("eq".repeat(500)).boxed(),
        ]
        .boxed(),
        Kind::Physical(lo, hi) => number(lo, hi, true),
        Kind::TEnd => number(1e-3, MAX_T_END, false),
        Kind::XEnd => number(1e-3, 1e4, true),
        Kind::Tolerance(lo, hi) => number(lo, hi, true),
        Kind::Dt => number(MIN_DT, 10.0, false),
        Kind::Times => times(),
        Kind::Turns => turns(),
        Kind::Limit => limit(),
        Kind::Format => pick(&["csv", "json", "CSV", "Json", "xml", "", "cs v"]),
        Kind::Output => pick(PATHS),
        Kind::Config => pick(CONFIGS),
    }
}

/// One command-line item: a flag with its value (separate, or `--flag=v`),
/// a flag alone, or a stray token.
pub(crate) fn item(command: &'static str) -> BoxedStrategy<Vec<String>> {
    // `turns` has every flag of `simulate` but the sampling; give it those
    // only now and then.
    let flags: Vec<(&str, Kind)> = FLAGS
        .iter()
        .copied()
        .filter(|(name, _)| command == "simulate" || !["--times", "--dt"].contains(name))
        .collect();
    let odd = prop::sample::select(&["--times", "--dt"][..]).prop_map(|f| (f, Kind::Dt));
    let chosen = prop_oneof![40 => prop::sample::select(flags), 1 => odd];
    let flag = chosen.prop_flat_map(|(name, kind)| {
        // Mostly `--flag value`, some `--flag=value`, a few bare flags.
        let form = prop_oneof![40 => Just(0u8), 12 => Just(1u8), 1 => Just(2u8)];
        (value(kind), form).prop_map(move |(v, form)| match form {
            1 if name.starts_with("--") => vec![format!("{name}={v}")],
            2 => vec![name.to_string()],
            _ => vec![name.to_string(), v],
        })
    });
    let stray = prop_oneof![
        pick(&[
            "-",
            "--",
            "-x",
            "--help",
            "-h",
            "--version",
            "-V",
            "--alpha",
            "--t_end",
            "--quiet",
            "simulate"
        ]),
        "\\PC{0,12}",
    ]
    .prop_map(|s| vec![s]);
    prop_oneof![30 => flag, 1 => stray].boxed()
}

/// A TOML value for a key of `kind`, as written in a file.
pub(crate) fn toml_value(kind: Kind) -> BoxedStrategy<String> {
    let quoted = |s: String| format!("{s:?}");
    let typed = match kind {
        Kind::Model | Kind::Format | Kind::Output | Kind::Config => {
            value(kind).prop_map(quoted).boxed()
        }
        Kind::Turns => turns(),
        Kind::Limit => limit(),
        Kind::Times => times().prop_map(|t| format!("[{t}]")).boxed(),
        _ => value(kind),
    };
    prop_oneof![
        8 => typed,
        1 => pick(&["true", "\"30\"", "[]", "{}", "{a = 1}", "1979-05-27", "nan", "+inf", "-inf", "0x1F", "1_0", "[1, \"a\"]", "'''x'''", ""]),
    ]
    .boxed()
}

/// A config document: `key = value` lines and some broken ones.
pub(crate) fn toml_document() -> BoxedStrategy<String> {
    let line = prop_oneof![
        10 => prop::sample::select(KEYS).prop_flat_map(|(k, kind)| toml_value(kind).prop_map(move |v| format!("{k} = {v}"))),
        1 => pick(&["[table]", "[[array]]", "key", "= 1", "\"unterminated", "# comment", "model = \"eq4\"\nmodel = \"eq6\"", "\u{feff}", "\0"]),
        1 => "\\PC{0,30}",
    ];
    prop::collection::vec(line, 0..10)
        .prop_map(|lines| lines.join("\n"))
        .boxed()
}

/// Files present before a case runs.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Prepared {
    pub(crate) out_csv: bool,
    pub(crate) dir: bool,
    pub(crate) link: bool,
    pub(crate) read_only: bool,
    pub(crate) hard_link: bool,
    pub(crate) dangling: bool,
}

/// One fuzz case.
#[derive(Clone)]
pub(crate) struct Case {
    /// Arguments after the program name.
    pub(crate) args: Vec<String>,
    /// The config document at `c.toml`, if any.
    pub(crate) config: Option<String>,
    /// Other input files, by name (the readers' cases of issue 20).
    pub(crate) files: Vec<(String, Vec<u8>)>,
    pub(crate) prepared: Prepared,
}

/// The files as name, length and start: a failing case is printed, and a
/// file may be megabytes.
impl std::fmt::Debug for Case {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let files: Vec<String> = (self.files.iter())
            .map(|(name, bytes)| {
                let start = String::from_utf8_lossy(&bytes[..bytes.len().min(300)]);
                format!("{name} ({} bytes): {start:?}", bytes.len())
            })
            .collect();
        f.debug_struct("Case")
            .field("args", &self.args)
            .field("config", &self.config)
            .field("files", &files)
            .field("prepared", &self.prepared)
            .finish()
    }
}

pub(crate) fn prepared() -> BoxedStrategy<Prepared> {
    any::<[bool; 6]>()
        .prop_map(|b| Prepared {
            out_csv: b[0],
            dir: b[1],
            link: b[2],
            read_only: b[3],
            hard_link: b[4],
            dangling: b[5],
        })
        .boxed()
}

/// `simulate` or `turns` with a model first (mostly), flags, and often an
/// output path last. A turn model under `simulate` always gets `--turns`
/// (at most [`MAX_TURNS`]): without it, an extreme parameter (g = 1e155
/// m/s^2) asks for more turns in the end time than the step budget allows,
/// and such a run ends at that budget only after a minute (issue 7 item 3,
/// the step limit, is tested on its own).
pub(crate) fn model_run(command: &'static str) -> BoxedStrategy<Vec<String>> {
    let first = if command == "turns" {
        pick(TURN_MODELS)
    } else {
        prop_oneof![3 => pick(CIRCULAR_MODELS), 1 => pick(TURN_MODELS)].boxed()
    };
    let model = prop_oneof![10 => first.prop_map(Some), 1 => value(Kind::Model).prop_map(Some), 1 => Just(None)];
    let output = prop::option::weighted(0.4, pick(PATHS));
    (
        model,
        prop::collection::vec(item(command), 0..6),
        output,
        1..=MAX_TURNS,
    )
        .prop_map(move |(model, items, output, turns)| {
            let mut args = vec![command.to_string()];
            let turn_model = model
                .as_deref()
                .is_some_and(|m| TURN_MODELS.iter().any(|t| t.eq_ignore_ascii_case(m)));
            if let Some(model) = model {
                args.extend(["--model".to_string(), model]);
            }
            args.extend(items.into_iter().flatten());
            if command == "simulate" && turn_model {
                args.extend(["--turns".to_string(), turns.to_string()]);
            }
            if let Some(output) = output {
                args.extend(["-o".to_string(), output]);
            }
            args
        })
        .boxed()
}

pub(crate) fn run_command() -> BoxedStrategy<Vec<String>> {
    prop_oneof![
        12 => model_run("simulate"),
        8 => model_run("turns"),
        1 => (pick(&["models", "paper", "help", "simulat", "", "--version"]), prop::collection::vec(pick(&["--format", "json", "table", "xml", "--quiet", "--out", "--turns", "3", "-h"]), 0..4)).prop_map(|(cmd, rest)| {
            let mut args = vec![cmd];
            // A real `paper` run is kept for `paper_command`: here its
            // --turns is always invalid.
            if args[0] == "paper" {
                args.extend(["--turns".to_string(), "9".to_string()]);
            }
            args.extend(rest);
            args
        }),
    ]
    .boxed()
}

/// A real `paper` run: `--turns` last, so that no other item overrides it.
pub(crate) fn paper_command() -> BoxedStrategy<Vec<String>> {
    (
        prop::option::of(pick(PATHS)),
        any::<bool>(),
        pick(&["10", "12", "9", "0", "x", ""]),
    )
        .prop_map(|(out, quiet, turns)| {
            let mut args = vec!["paper".to_string()];
            if let Some(out) = out {
                args.extend(["--out".to_string(), out]);
            }
            if quiet {
                args.push("--quiet".to_string());
            }
            args.extend(["--turns".to_string(), turns]);
            args
        })
        .boxed()
}

/// A case: mostly a command line with a TOML config (issue 7), else
/// (weight [`READBACK_WEIGHT`] in [`COMMAND_WEIGHT_TOTAL`]) a reader of
/// issue 20 given a corrupted output, grid or shard made from `seeds`.
pub(crate) fn case(seeds: Vec<crate::readback::Seed>) -> BoxedStrategy<Case> {
    prop_oneof![
        (COMMAND_WEIGHT_TOTAL - READBACK_WEIGHT) => command_line_case(),
        READBACK_WEIGHT => crate::readback::readback_case(seeds),
    ]
    .boxed()
}

/// Weight of the readers' cases among all, out of [`COMMAND_WEIGHT_TOTAL`].
pub(crate) const READBACK_WEIGHT: u32 = 5_000;

fn command_line_case() -> BoxedStrategy<Case> {
    let command = prop_oneof![
        (COMMAND_WEIGHT_TOTAL - PAPER_WEIGHT) => run_command(),
        PAPER_WEIGHT => paper_command(),
    ];
    (
        command,
        prop::option::weighted(0.8, toml_document()),
        any::<bool>(),
        prepared(),
    )
        .prop_map(|(mut args, config, use_config, prepared)| {
            if config.is_some()
                && use_config
                && args
                    .first()
                    .is_some_and(|c| c == "simulate" || c == "turns")
            {
                args.extend(["--config".to_string(), "c.toml".to_string()]);
            }
            Case {
                args,
                config,
                files: Vec::new(),
                prepared,
            }
        })
        .boxed()
}
