//! The `--config FILE` of `simulate` and `turns`, and its precedence:
//! command-line flags, then the file, then the library's defaults.
//!
//! A config file is one of three things, told apart by its content:
//! - a TOML file with one key per long flag of the two commands, spelt as
//!   the flag (`alpha-deg = 25`) or in snake_case (`alpha_deg = 25`), e.g.
//!   `model = "eq4"`, `times = [1.0, 2.0]`, `turns = 10`;
//! - a JSON output of snowroll (`--format json`): its `model` and `params`;
//! - a CSV output of snowroll: its `# key = value` header lines.
//!
//! The keys are the project's one parameter vocabulary ([`snowroll::ScenarioFile`],
//! [`snowroll::RunParams`]), so an output read back reproduces its run byte for
//! byte, in its own format. Unknown keys are an error, and so are keys of the
//! other command (`times`, `dt` for `turns`). The model is spelt as on the
//! command line: id or equation alias, in any case.

use std::fs::File;
use std::io::{self, BufRead, BufReader, Read};
use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use std::sync::OnceLock;

use serde::de::{DeserializeSeed, Error as _, MapAccess, Visitor};
use serde::{Deserialize, Deserializer};
use snowroll::params::{Kind, RealOrWord, Scope};
use snowroll::{Given, ModelKind, Param, Settings, TurnMethod, Value, PARAMS};
use snowroll_io::Format;

use crate::args::{ModelList, OutputArgs, ParamArgs, ScenarioArgs, SimulateArgs, TurnsArgs};
use crate::bounded::{self, Bounded, MAX_HEADER, MAX_SETTINGS_FILE};
mod de;
mod readback;

/// The keys of a config file: every long flag of `simulate` and `turns`
/// except `--config` itself, in snake_case; the flag's own spelling and the
/// parameter names of earlier outputs are aliases. The parameters are those
/// of the table ([`snowroll::params`]); `model`, `format`, `output` and
/// `plot` are the command's own.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ConfigFile {
    model: Option<ModelKind>,
    /// Every parameter of the table that the file sets.
    given: Given,
    format: Option<Format>,
    output: Option<PathBuf>,
    plot: Option<PathBuf>,
    /// How a turn table is computed (`snowroll turns --method`; a turn
    /// table records it).
    method: Option<TurnMethod>,
}

/// Every key a config file may have, with its aliases (for the message
/// naming an unknown key). Built once; the strings live as long as the
/// program, as serde's message wants.
fn known_keys() -> &'static [&'static str] {
    static KEYS: OnceLock<Vec<&'static str>> = OnceLock::new();
    KEYS.get_or_init(|| {
        let mut keys = vec!["model"];
        for p in PARAMS.iter().filter(|p| p.settable()) {
            keys.extend(
                p.names()
                    .into_iter()
                    .map(|n| &*Box::leak(n.into_boxed_str())),
            );
        }
        keys.extend(["format", "output", "plot", "method"]);
        keys
    })
}

impl ConfigFile {
    /// The value the file gives parameter `key` (a key of the table).
    fn value(&self, key: &str) -> Option<&Value> {
        Param::of_key(key).and_then(|p| self.given.get(p))
    }

    /// The sampling times of `simulate`, s, when the file sets them.
    fn times(&self) -> Option<Vec<f64>> {
        match self.value("times") {
            Some(Value::Reals(ts)) => Some(ts.clone()),
            _ => None,
        }
    }

    /// The grid spacing of `simulate`, s, when the file sets it.
    fn dt(&self) -> Option<f64> {
        match self.value("dt") {
            Some(Value::Real(dt)) => Some(*dt),
            _ => None,
        }
    }

    /// The turn count, when the file sets it.
    fn turns(&self) -> Option<u64> {
        match self.value("turns") {
            Some(Value::Count(n)) => Some(*n),
            _ => None,
        }
    }

    /// The parameters the file sets that are flags of both commands.
    pub(crate) fn shared(&self) -> Given {
        let mut given = Given::new();
        for (p, v) in self.given.iter().filter(|(p, _)| p.scope == Scope::Shared) {
            given.insert(p, v.clone());
        }
        given
    }
}

/// `csv` or `json`, in any case, as `--format` accepts it.
fn format_any_case(name: &str) -> Result<Format, String> {
    match name.to_ascii_lowercase().as_str() {
        "csv" => Ok(Format::Csv),
        "json" => Ok(Format::Json),
        _ => Err(format!("unknown format `{name}`, expected `csv` or `json`")),
    }
}

/// Which command wrote an output that is read back as a config file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// A TOML file written by hand.
    Toml,
    /// An output of `snowroll simulate`.
    Simulate,
    /// An output of `snowroll turns` (one row per turn).
    Turns,
}

/// Reads and parses a config file for command `command` (`simulate` or
/// `turns`). Every failure is one line naming the file; an output of the
/// other command is refused (its settings would not reproduce it).
pub fn load(path: &Path, command: Origin) -> Result<ConfigFile> {
    let (file, origin) = load_with_origin(path)?;
    let name = |o: Origin| match o {
        Origin::Turns => "turns",
        _ => "simulate",
    };
    if origin != Origin::Toml && origin != command {
        bail!(
            "config file {} is an output of `snowroll {}`; read it back with that command",
            path.display(),
            name(origin)
        );
    }
    Ok(file)
}

/// Reads and parses a config file and says what wrote it. Reads at most
/// what it needs, within the limits of [`crate::bounded`]: a TOML file
/// whole, of an output only its header (a CSV's `#` lines, a JSON output up
/// to its `model` and `params`), never its rows.
fn load_with_origin(path: &Path) -> Result<(ConfigFile, Origin)> {
    let shown = path.display();
    let cannot_read = || format!("cannot read config file {shown}");
    let file = File::open(path).with_context(cannot_read)?;
    let mut reader = BufReader::new(Bounded::new(file, MAX_HEADER, "the header of an output"));
    skip_bom(&mut reader).with_context(cannot_read)?;
    let (prefix, start) = sniff(&mut reader).with_context(cannot_read)?;
    let first = start.map(|i| prefix[i]);
    let starts_csv = start.is_some_and(|i| prefix[i..].starts_with(CSV_MARK));
    let mut whole = io::Cursor::new(prefix).chain(reader);
    let (file, origin) = if first == Some(b'{') {
        readback::from_json_output(&mut whole)
            .map_err(|e| anyhow!("config file {shown}: {}", crate::message(&e)))?
    } else if starts_csv {
        let header = bounded::read_header(&mut BufReader::new(whole)).with_context(cannot_read)?;
        readback::from_csv_output(&header.concat())
            .map_err(|e| anyhow!("config file {shown}: {}", crate::message(&e)))?
    } else {
        let mut bytes = Vec::new();
        Bounded::new(whole, MAX_SETTINGS_FILE, "a config file")
            .read_to_end(&mut bytes)
            .with_context(cannot_read)?;
        let text = String::from_utf8(bytes).map_err(|e| {
            let at = e.utf8_error().valid_up_to();
            anyhow!("config file {shown} is not UTF-8 text (byte {at} is not)")
        })?;
        (from_toml(&text, path)?, Origin::Toml)
    };
    if file.times().is_some() && file.dt().is_some() {
        bail!("config file {shown}: `times` and `dt` conflict, give one of them");
    }
    Ok((file, origin))
}

/// The UTF-8 byte order mark that some editors put at the start of a file.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Skips a UTF-8 byte order mark at the start of `reader` (issue 33, item
/// 5): a JSON or CSV file saved by such an editor is still that format,
/// where the mark used to make it look like TOML.
fn skip_bom(reader: &mut impl BufRead) -> io::Result<()> {
    let mut start = Vec::with_capacity(BOM.len());
    while start.len() < BOM.len() {
        let buf = reader.fill_buf()?;
        if buf.is_empty() {
            break;
        }
        let want = BOM.len() - start.len();
        let take = want.min(buf.len());
        if buf[..take] != BOM[start.len()..start.len() + take] {
            // Not a mark: nothing consumed beyond what matched so far,
            // which is only possible within the first buffer.
            break;
        }
        start.extend_from_slice(&buf[..take]);
        reader.consume(take);
    }
    if !start.is_empty() && start.len() < BOM.len() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidData,
            "it starts with a cut-off byte order mark",
        ));
    }
    Ok(())
}

/// How a CSV output of snowroll starts.
const CSV_MARK: &[u8] = b"# snowroll";

/// The first bytes of `reader`, up to the first that is not white space
/// and [`CSV_MARK`]'s length after it (they tell the format), and where
/// that byte is. Each chunk is scanned once.
fn sniff(reader: &mut impl BufRead) -> io::Result<(Vec<u8>, Option<usize>)> {
    let mut prefix = Vec::new();
    let mut start = None;
    loop {
        let buf = reader.fill_buf()?;
        if buf.is_empty() {
            return Ok((prefix, start));
        }
        let (scanned, n) = (prefix.len(), buf.len());
        prefix.extend_from_slice(buf);
        reader.consume(n);
        if start.is_none() {
            start = (prefix[scanned..].iter())
                .position(|c| !c.is_ascii_whitespace())
                .map(|i| scanned + i);
        }
        match start {
            Some(i) if prefix.len() >= i + CSV_MARK.len() => return Ok((prefix, start)),
            // White space only so far: a TOML file past its limit.
            None if prefix.len() as u64 > MAX_SETTINGS_FILE => {
                return Err(bounded::too_long(MAX_SETTINGS_FILE, "a config file"))
            }
            _ => {}
        }
    }
}

fn from_toml(text: &str, path: &Path) -> Result<ConfigFile> {
    toml::from_str(text).map_err(|e| {
        anyhow!(
            "config file {}{}: {}",
            path.display(),
            e.span()
                .map(|s| {
                    let (line, column) = line_column(text, s.start);
                    format!(", line {line}, column {column}")
                })
                .unwrap_or_default(),
            one_line(e.message())
        )
    })
}

/// A possibly multi-line message on one line.
fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}

/// 1-based line and column of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

impl ScenarioArgs {
    /// These flags, with every one that was not given taken from `file`.
    fn over(self, file: &ConfigFile) -> ScenarioArgs {
        ScenarioArgs {
            model: self.model.or(file.model.map(ModelList::one)),
            params: ParamArgs {
                given: self.params.given.or(&file.shared()),
            },
        }
    }
}

impl OutputArgs {
    /// These flags, with every one that was not given taken from `file`.
    fn over(self, file: &ConfigFile) -> OutputArgs {
        let OutputArgs {
            format,
            output,
            config,
            plot,
        } = self;
        OutputArgs {
            format: format.or(file.format),
            output: output.or_else(|| file.output.clone()),
            config,
            plot: plot.or_else(|| file.plot.clone()),
        }
    }
}

impl SimulateArgs {
    /// These flags, with every one that was not given taken from `file`.
    ///
    /// `times` and `dt` choose the sampling together: if either is on the
    /// command line, the file's sampling is ignored (the two conflict).
    pub fn over(self, file: ConfigFile) -> SimulateArgs {
        let SimulateArgs {
            scenario,
            times,
            dt,
            turns,
            output,
        } = self;
        let sampling_on_command_line = times.is_some() || dt.is_some();
        let (times, dt) = if sampling_on_command_line {
            (times, dt)
        } else {
            (file.times(), file.dt())
        };
        SimulateArgs {
            scenario: scenario.over(&file),
            times,
            dt,
            turns: turns.or(file.turns()),
            output: output.over(&file),
        }
    }
}

impl TurnsArgs {
    /// These flags, with every one that was not given taken from `file`,
    /// which was read from `path`.
    ///
    /// # Errors
    /// When the file sets `times` or `dt`, keys of `simulate` only: the turn
    /// table has one row per turn.
    pub fn over(self, file: ConfigFile, path: &Path) -> Result<TurnsArgs> {
        let TurnsArgs {
            scenario,
            turns,
            method,
            output,
        } = self;
        for (key, set) in [
            ("times", file.times().is_some()),
            ("dt", file.dt().is_some()),
        ] {
            if set {
                bail!(
                    "config file {}: `{key}` is a key of `snowroll simulate` only; \
                     `snowroll turns` writes one row per turn",
                    path.display()
                );
            }
        }
        Ok(TurnsArgs {
            scenario: scenario.over(&file),
            turns: turns.or(file.turns()),
            method: method.or(file.method),
            output: output.over(&file),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::args::Args;
    use clap::CommandFactory;

    /// `Given` with each `(key, value)`.
    fn given(values: &[(&str, Value)]) -> Given {
        let mut g = Given::new();
        for (k, v) in values {
            g.insert(Param::of_key(k).unwrap(), v.clone());
        }
        g
    }

    #[test]
    fn file_fills_only_missing_flags() {
        let flags = SimulateArgs {
            scenario: ScenarioArgs {
                params: ParamArgs {
                    given: given(&[("alpha_deg", Value::Real(40.0))]),
                },
                ..Default::default()
            },
            dt: Some(0.5),
            ..Default::default()
        };
        let file = ConfigFile {
            model: Some(ModelKind::Energy),
            given: given(&[
                ("alpha_deg", Value::Real(25.0)),
                ("snow_depth", Value::Real(0.02)),
                ("times", Value::Reals(vec![1.0, 2.0])),
                ("turns", Value::Count(7)),
            ]),
            format: Some(Format::Json),
            ..Default::default()
        };
        let merged = flags.over(file);
        assert_eq!(
            merged.scenario.model,
            Some(ModelList::one(ModelKind::Energy))
        );
        let p = &merged.scenario.params.given;
        assert_eq!(
            p.get(Param::of_key("alpha_deg").unwrap()),
            Some(&Value::Real(40.0))
        );
        assert_eq!(
            p.get(Param::of_key("snow_depth").unwrap()),
            Some(&Value::Real(0.02))
        );
        // The sampling and the turn count are not shared flags.
        assert_eq!(p.get(Param::of_key("times").unwrap()), None);
        assert_eq!(merged.turns, Some(7));
        assert_eq!(merged.output.format, Some(Format::Json));
        // The command line's sampling replaces the file's.
        assert_eq!(merged.dt, Some(0.5));
        assert_eq!(merged.times, None);
    }

    #[test]
    fn turns_takes_the_shared_keys_and_refuses_the_sampling_keys() {
        let path = Path::new("run.toml");
        let flags = TurnsArgs {
            turns: Some(5),
            ..Default::default()
        };
        let file = ConfigFile {
            model: Some(ModelKind::TurnsExact),
            given: given(&[("r0", Value::Real(0.2)), ("turns", Value::Count(50))]),
            ..Default::default()
        };
        let merged = flags.clone().over(file, path).unwrap();
        assert_eq!(
            merged.scenario.model,
            Some(ModelList::one(ModelKind::TurnsExact))
        );
        let r0 = Param::of_key("r0").unwrap();
        assert_eq!(
            merged.scenario.params.given.get(r0),
            Some(&Value::Real(0.2))
        );
        assert_eq!(merged.turns, Some(5));
        let file = ConfigFile {
            given: given(&[("dt", Value::Real(0.1))]),
            ..Default::default()
        };
        let err = flags.over(file, path).unwrap_err().to_string();
        assert!(err.contains("run.toml") && err.contains("`dt`"), "{err}");
    }

    /// Every spelling of a key reads, each value as its kind; a word outside
    /// a choice and a key given twice are refused.
    #[test]
    fn keys_read_in_every_spelling_and_kind() {
        let file: ConfigFile = toml::from_str(
            "alpha-deg = 25\nsnow_depth_m = 0.02\nmax_rows = 10\nledger = true\n\
             collision = \"PIVOT\"\ntimes = [1.0, 2]\nshape = \"Sphere\"\n",
        )
        .unwrap();
        let v = |k: &str| file.given.get(Param::of_key(k).unwrap()).cloned();
        assert_eq!(v("alpha_deg"), Some(Value::Real(25.0)));
        assert_eq!(v("snow_depth"), Some(Value::Real(0.02)));
        assert_eq!(v("max_rows"), Some(Value::Count(10)));
        assert_eq!(v("ledger"), Some(Value::Flag(true)));
        assert_eq!(v("collision"), Some(Value::Word("PIVOT".into())));
        assert_eq!(v("times"), Some(Value::Reals(vec![1.0, 2.0])));
        let e = toml::from_str::<ConfigFile>("collision = \"bounce\"").unwrap_err();
        assert!(e.message().contains("unknown collision"), "{e}");
        let e = toml::from_str::<ConfigFile>("alpha_deg = 1\nslope_deg = 2").unwrap_err();
        assert!(e.message().contains("duplicate field `alpha_deg`"), "{e}");
    }

    #[test]
    fn config_model_is_spelt_as_on_the_command_line() {
        for (text, want) in [
            ("turns", ModelKind::Turns),
            ("EQ73", ModelKind::Turns),
            ("Turns-Exact", ModelKind::TurnsExact),
            ("eq4", ModelKind::TorqueCm),
            ("Torque-CM", ModelKind::TorqueCm),
        ] {
            let file: ConfigFile = toml::from_str(&format!("model = \"{text}\"")).unwrap();
            assert_eq!(file.model, Some(want), "{text}");
        }
        assert!(toml::from_str::<ConfigFile>("model = \"eq99\"").is_err());
    }

    /// The long flags of subcommand `name`, less `--config` and `--help`.
    fn long_flags(name: &str) -> Vec<String> {
        let command = Args::command();
        let mut flags: Vec<String> = command
            .find_subcommand(name)
            .unwrap()
            .get_arguments()
            .filter_map(|a| a.get_long())
            .filter(|l| !["config", "help"].contains(l))
            .map(str::to_string)
            .collect();
        flags.sort_unstable();
        flags
    }

    #[test]
    fn config_keys_are_exactly_the_long_flags() {
        let err = toml::from_str::<ConfigFile>("no-such-key = 1")
            .unwrap_err()
            .message()
            .to_string();
        let (_, list) = err.split_once("expected one of").unwrap();
        // serde lists the aliases too: the flags' own kebab-case spelling
        // and the names of earlier outputs. Leave those out; the rest, in
        // kebab-case, must be exactly the long flags.
        const EARLIER_OUTPUT_NAMES: [&str; 9] = [
            "slope_deg",
            "snow_depth_m",
            "r0_m",
            "g_m_s2",
            "density_kg_m3",
            "length_m",
            "v0_m_s",
            "t_end_s",
            "x_end_m",
        ];
        let mut keys: Vec<String> = list
            .split(',')
            .map(|k| k.trim().trim_matches('`').to_string())
            .filter(|k| !k.contains('-') && !EARLIER_OUTPUT_NAMES.contains(&k.as_str()))
            .map(|k| k.replace('_', "-"))
            .collect();
        keys.sort_unstable();
        let mut flags = long_flags("simulate");
        flags.extend(long_flags("turns"));
        flags.sort_unstable();
        flags.dedup();
        assert_eq!(keys, flags);
        // `turns` has every flag of `simulate` but the sampling, and how the
        // table is computed.
        let mut sampling_free = long_flags("simulate");
        sampling_free.retain(|f| f != "times" && f != "dt");
        sampling_free.push("method".into());
        sampling_free.sort_unstable();
        let mut turns = long_flags("turns");
        turns.sort_unstable();
        assert_eq!(turns, sampling_free);
    }

    /// The format is told from the first byte that is not white space and
    /// the bytes after it, wherever the reader's chunks end (found by the
    /// fuzzing of issue 20: the mark cut by a chunk's end read as TOML, and
    /// each chunk rescanned the whole prefix, 9 MiB of blanks taking
    /// minutes).
    #[test]
    fn the_format_is_told_across_chunk_ends() {
        let text = b"      # snowroll simulate";
        let (prefix, start) = sniff(&mut io::BufReader::with_capacity(4, &text[..])).unwrap();
        assert_eq!(start, Some(6));
        assert!(prefix[6..].starts_with(CSV_MARK), "{prefix:?}");
        let (_, start) = sniff(&mut io::BufReader::with_capacity(4, &b"  \n "[..])).unwrap();
        assert_eq!(start, None);
        let blanks = vec![b' '; MAX_SETTINGS_FILE as usize + 1];
        let e = sniff(&mut io::BufReader::new(&blanks[..])).unwrap_err();
        assert!(e.to_string().contains("8 MiB"), "{e}");
    }

    #[test]
    fn line_and_column_are_one_based() {
        let text = "a = 1\nbb = x\n";
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, 11), (2, 6));
    }
}
