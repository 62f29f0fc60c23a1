//! Issue 37, item 4: the physics crate speaks no command line. Its errors
//! name parameters by their keys in the parameter table, and each front end
//! spells them (the CLI `--snow-depth`, Python `snow_depth=`): here, that
//! each error that tells the user what to change names the right keys, that
//! every key is one of the table, and that no error text of the crate's
//! source writes a flag.

use snowroll::error::Namer;
use snowroll::params::render_keys;
use snowroll::{
    check_turn_scale, ModelKind, ParamError, Scenario, ScenarioFile, Shape, SimError, SimOptions,
    PARAMS,
};

fn err(r: Result<impl std::fmt::Debug, impl Into<SimError>>) -> ParamError {
    match r.map_err(Into::into) {
        Err(SimError::Param(p)) => p,
        other => panic!("expected a parameter error, got {other:?}"),
    }
}

fn scenario_err(file: ScenarioFile) -> ParamError {
    err(Scenario::new(file))
}

/// A run's error before it starts: the checks of `kind` on `file` with `opts`.
fn run_err(kind: ModelKind, file: ScenarioFile, opts: SimOptions) -> ParamError {
    let s = Scenario::new(file).unwrap();
    err(kind.build().check(&s, &opts))
}

/// Flags as a command line spells them, written here.
fn flag(key: &str, word: Option<&str>) -> String {
    let f = format!("--{}", key.replace('_', "-"));
    word.map_or(f.clone(), |w| format!("{f} {w}"))
}

/// Keywords as a Python caller writes them, written here.
fn keyword(key: &str, word: Option<&str>) -> String {
    word.map_or(format!("{key}="), |w| format!("{key}='{w}'"))
}

#[test]
fn errors_name_the_keys_of_what_to_change() {
    let d = ScenarioFile::default;
    let cases: Vec<(ParamError, &[&str])> = vec![
        (
            scenario_err(ScenarioFile {
                snow_depth: 1e200,
                ..d()
            }),
            &["snow_depth"],
        ),
        (
            scenario_err(ScenarioFile {
                density: 1e140,
                r0: 1e6,
                ..d()
            }),
            &["density", "length", "r0"],
        ),
        (
            scenario_err(ScenarioFile {
                swath_width: Some(snowroll::SwathWidth::Metres(0.05)),
                ..d()
            }),
            &["shape", "swath_width"],
        ),
        (
            run_err(
                ModelKind::Turns,
                d(),
                SimOptions {
                    losses: snowroll::Losses {
                        drag_coefficient: 1.0,
                        ..snowroll::Losses::default()
                    },
                    ..SimOptions::default()
                },
            ),
            &["drag_coefficient", "ledger"],
        ),
        (
            err(SimOptions {
                t_end: 1.0,
                sampling: snowroll::Sampling::Times(vec![0.5, 2.0]),
                ..SimOptions::default()
            }
            .validate()),
            &["t_end"],
        ),
        (
            err(check_turn_scale(
                &Scenario::new(ScenarioFile {
                    density: 1e140,
                    ..d()
                })
                .unwrap(),
                &SimOptions {
                    turns: Some(u64::MAX / 2),
                    ..SimOptions::default()
                },
            )),
            &["turns", "snow_depth", "density", "length", "r0"],
        ),
        (
            run_err(
                ModelKind::TorqueCm,
                d(),
                SimOptions {
                    tolerances: snowroll::integrate::Tolerances {
                        atol: 1.0,
                        ..Default::default()
                    },
                    ..SimOptions::default()
                },
            ),
            &["atol"],
        ),
    ];
    let spell = |e: &ParamError, name: Namer<'_>| e.render(name);
    for (e, keys) in &cases {
        assert_eq!(e.named_keys(), *keys, "{e}");
        let (cli, py, text) = (spell(e, &flag), spell(e, &keyword), e.to_string());
        for k in *keys {
            assert!(
                PARAMS.iter().any(|p| p.key == *k),
                "{k} is not a key of the table"
            );
            assert!(cli.contains(&flag(k, None)), "{k}: {cli}");
            assert!(
                py.contains(&keyword(k, None)) || py.contains(&format!("{k}='")),
                "{k}: {py}"
            );
        }
        // No placeholder left, no flag where the library speaks for itself.
        for t in [&cli, &py, &text] {
            assert!(!t.contains('{'), "{t}");
        }
        assert!(!py.contains("--") && !text.contains("--"), "{py} / {text}");
    }
    // A word given with the key: `--shape sphere`, `shape='sphere'`.
    let (cli, py) = (spell(&cases[2].0, &flag), spell(&cases[2].0, &keyword));
    assert!(
        cli.ends_with("give --shape sphere or drop --swath-width"),
        "{cli}"
    );
    assert!(
        py.ends_with("give shape='sphere' or drop swath_width="),
        "{py}"
    );
    // A word that is no key is text, not a parameter (so a typo in a
    // placeholder shows, and fails the checks above).
    assert_eq!(
        render_keys("change {snow_dept}", &flag),
        "change {snow_dept}"
    );
    let _ = Shape::Sphere;
}

/// Where a flag may still be written in the crate's source: help texts of
/// the command line's flags (the parameter table's `help`, clap's value
/// help), not error messages.
const HELP_TEXTS: [(&str, &str); 5] = [
    ("params/table.rs", "(--dt: t_end/dt + 1,"),
    ("params/table.rs", "--times: their count"),
    ("params/table.rs", "on a --dt grid that --turns or --x-end"),
    ("sweep/run.rs", "--rtol at least 1e-12"),
    (
        "turn_by_turn/runner.rs",
        "`--collision pivot`, and a start from rest",
    ),
];

/// Whether `line` writes a flag: two dashes, then a lowercase letter, not
/// after a letter, digit or dash.
fn writes_flag(line: &str) -> bool {
    let b = line.as_bytes();
    (0..b.len().saturating_sub(2)).any(|i| {
        b[i] == b'-'
            && b[i + 1] == b'-'
            && b[i + 2].is_ascii_lowercase()
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'-'))
    })
}

fn sources(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn the_crates_source_writes_no_flag_outside_help_texts() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    let mut found = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        // Code before the unit tests (which may quote flags to refuse them).
        let code = text.split("#[cfg(test)]\nmod ").next().unwrap();
        let shown = path
            .strip_prefix(&root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        for (n, line) in code.lines().enumerate() {
            let t = line.trim_start();
            if t.starts_with("//") || !writes_flag(line) {
                continue;
            }
            let help = HELP_TEXTS
                .iter()
                .any(|(f, s)| shown.ends_with(f) && line.contains(s));
            if !help {
                found.push(format!("{shown}:{}: {}", n + 1, t));
            }
        }
    }
    assert!(
        found.is_empty(),
        "flags in the physics crate:\n{}",
        found.join("\n")
    );
    // The scan sees a flag where one is written (checked on a line of its kind).
    assert!(writes_flag(r#"hint: "change --snow-depth","#));
    assert!(!writes_flag("x--y, a -- b, ---x"));
}
