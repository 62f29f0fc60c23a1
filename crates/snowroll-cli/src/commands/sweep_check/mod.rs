//! A sweep file read back, for `sweep --resume` and `merge`: its header
//! parsed into the grid and settings it records ([`Recorded`]), compared
//! setting by setting with another's ([`Recorded::differences`]), and its
//! rows each parsed against the schema and checked against the grid point
//! its index names ([`check_rows`]).
//!
//! Sameness is decided from the parsed values, never from the bytes of the
//! command line: `--t-end 20` and `--t-end 20.0`, `-o out.csv` and
//! `-o ./out.csv`, an axis left at its default and the same value given,
//! all make the same sweep.

use crate::bounded::MAX_ROW_LINE;
use std::collections::BTreeMap;
use std::io::{BufRead, Read};
use std::ops::Range;

use anyhow::{anyhow, bail, Context, Result};
use clap::Parser;
use snowroll::params::Value;
use snowroll::sweep::{AxisParam, Grid, Method, SweepRow, Values};
use snowroll_io::VERSION;

use super::sweep_csv::RowWriter;
use super::sweep_grid::{grid_of, is_grid_key, recorded_method};
use crate::args::{sweep_axes, Args, Command, SweepArgs};
use crate::shell::shell_words;

mod rows;
pub use rows::check_rows;
use rows::{check_columns, cut};

/// Longest header line read (an axis may be a long list).
const MAX_HEADER_LINE: u64 = crate::bounded::MAX_HEADER;
/// Most header lines: a sweep writes one per axis and a few more.
const MAX_HEADER_LINES: usize = 256;
/// Start of the first header line, before the version.
const VERSION_KEY: &str = "# snowroll sweep, version ";

/// What a sweep file's header records.
#[derive(Debug, Clone)]
pub struct Recorded {
    /// The version of snowroll that wrote it.
    pub version: String,
    /// The grid of its `model`, `collision`, `on_hop` and axis lines.
    pub grid: Grid,
    /// The method of its command line.
    pub method: Method,
    /// Its shard `i` of `n`.
    pub shard: (u64, u64),
    /// The grid indices of its rows.
    pub rows: Range<u64>,
    /// How many of its rows have warnings (its `# warnings: N rows` line).
    pub warnings: u64,
    /// Bytes of the header, the column line included: the rows start there.
    pub len: u64,
    /// Lines of the header.
    pub lines: u64,
    /// The header's lines as read, without their newlines, the column
    /// names last (empty for [`Recorded::of_run`]).
    pub header: Vec<String>,
}

impl Recorded {
    /// What this program would record for a sweep of `grid`.
    pub fn of_run(
        grid: &Grid,
        method: Method,
        shard: (u64, u64),
        rows: Range<u64>,
        warnings: u64,
    ) -> Self {
        Recorded {
            version: VERSION.to_string(),
            grid: grid.clone(),
            method,
            shard,
            rows,
            warnings,
            len: 0,
            lines: 0,
            header: Vec::new(),
        }
    }

    /// Reads the header of a sweep file from `input`, which is left at its
    /// first row; `shown` names the file in messages.
    ///
    /// # Errors
    /// Anything that is not a complete header of this program's sweeps:
    /// a missing or unknown line, a value that does not parse, a point
    /// count that is not the grid's, columns that are not [`SweepRow`]'s.
    pub fn read(input: &mut impl BufRead, shown: &str) -> Result<Recorded> {
        let (lines, columns, len) = header_lines(input, shown)?;
        check_columns(&columns, shown)?;
        let version = lines
            .first()
            .and_then(|l| l.strip_prefix(VERSION_KEY))
            .ok_or_else(|| anyhow!("{shown}: its first line is not `{}...`", VERSION_KEY))?
            .to_string();
        let mut fields: BTreeMap<&str, &str> = BTreeMap::new();
        for (k, line) in lines.iter().enumerate().skip(1) {
            let (key, value) = line
                .strip_prefix("# ")
                .and_then(|l| l.split_once(": "))
                .ok_or_else(|| anyhow!("{shown}: line {}: not `# key: value`", k + 1))?;
            let known = ["command", "points", "shard", WARNINGS].contains(&key) || is_grid_key(key);
            if !known {
                bail!("{shown}: line {}: unknown header key {key:?}", k + 1);
            }
            if fields.insert(key, value).is_some() {
                bail!("{shown}: line {}: {key} is given twice", k + 1);
            }
        }
        let get = |key: &str| {
            fields
                .get(key)
                .copied()
                .ok_or_else(|| anyhow!("{shown}: its header has no `# {key}:` line"))
        };
        let method = recorded_method(get("command")?).map_err(|e| anyhow!("{shown}: {e}"))?;
        let axes: BTreeMap<String, String> = fields
            .iter()
            .filter(|(k, _)| is_grid_key(k))
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        let grid = grid_of(axes, &|key, text| format!("{key} = {text} in {shown}"))?;
        let points = get("points")?;
        if points.parse::<u64>().ok() != Some(grid.len()) {
            bail!(
                "{shown}: its header says {points} points, its grid has {}",
                grid.len()
            );
        }
        let shard_text = get("shard")?;
        let (shard, rows) = parse_shard_line(shard_text)
            .ok_or_else(|| anyhow!("{shown}: cannot read its shard line {shard_text:?}"))?;
        let warnings = parse_warnings_line(get(WARNINGS)?).ok_or_else(|| {
            anyhow!(
                "{shown}: cannot read its warnings line {:?}",
                get(WARNINGS).unwrap_or_default()
            )
        })?;
        let n_lines = lines.len() as u64 + 1;
        let mut header = lines.clone();
        header.push(columns);
        // Every value was read; the lines must also be spelt, and in the
        // order, as snowroll writes them: `merge` copies the first shard's
        // header, so an edit (`1.0` for `1`, a line moved) would pass into
        // the merged file (issue 33, item 5).
        // The command line is provenance, not compared, but it must be a
        // sweep's: `merge` parses shard 0's, and a resumed file keeps its
        // own (a `# command: end-time` once passed through `--resume` into
        // a file that `merge` then refused; issue 33's campaign).
        sweep_command(get("command")?).map_err(|why| anyhow!("{shown}: {why}"))?;
        let want = header_text(&version, get("command")?, &grid, shard, &rows, warnings);
        let got_len: usize = header.iter().map(|l| l.len() + 1).sum();
        if got_len != want.len() || header.iter().zip(want.lines()).any(|(a, b)| a != b) {
            let (k, got, wanted) = first_edit(&header, &want);
            bail!(
                "{shown}: line {k}: `{}` is not as snowroll writes it (`{}`): an edited header \
                 is refused, as the edit would pass into the output; write it back as it was, \
                 or run the sweep again",
                cut(&got),
                cut(&wanted)
            );
        }
        Ok(Recorded {
            version,
            grid,
            method,
            shard,
            rows,
            warnings,
            len,
            lines: n_lines,
            header,
        })
    }

    /// Every setting, by name, as text: the version, the models, each
    /// sweep parameter of the table (its values, or its default when the
    /// sweep does not vary it), the method and, with `shard`, the shard.
    fn settings(&self, shard: bool) -> Vec<(String, String)> {
        let grid = &self.grid;
        let ids = |v: Vec<&str>| v.join(",");
        let mut out = vec![
            ("version".to_string(), self.version.clone()),
            (
                "model".to_string(),
                ids(grid.models().iter().map(|m| m.id()).collect()),
            ),
        ];
        let choices = grid.choices();
        for p in sweep_axes() {
            let text = match AxisParam::from_key(p.key) {
                Some(axis) => axis_text(grid, axis, p.default_value()),
                None if p.key == "collision" => {
                    ids(choices.collision.iter().map(|c| c.id()).collect())
                }
                None => ids(choices.on_hop.iter().map(|c| c.id()).collect()),
            };
            out.push((p.key.to_string(), text));
        }
        let method = match self.method {
            Method::Auto => "auto",
            Method::Ode => "ode",
        };
        out.push(("method".to_string(), method.to_string()));
        if shard {
            let (i, n) = self.shard;
            let rows = &self.rows;
            out.push((
                "shard".to_string(),
                format!("{i}/{n}, rows {}..{}", rows.start, rows.end),
            ));
            out.push((WARNINGS.to_string(), warnings_text(self.warnings)));
        }
        out
    }

    /// The settings in which `self` (called `mine`) and `other` (called
    /// `theirs`) differ, each as `key: A in MINE, B in THEIRS`; the shard
    /// is compared when `shard`.
    pub fn differences(&self, other: &Recorded, shard: bool, names: (&str, &str)) -> Vec<String> {
        self.settings(shard)
            .into_iter()
            .zip(other.settings(shard))
            .filter(|((_, a), (_, b))| a != b)
            .map(|((key, a), (_, b))| format!("{key}: {a} in {}, {b} in {}", names.0, names.1))
            .collect()
    }
}

/// The header a sweep writes, `#` lines and column names, each line ended
/// by a newline: written by `sweep`, and the one form `--resume` and
/// `merge` accept (an edited header is refused: [`Recorded::read`]).
pub fn header_text(
    version: &str,
    command: &str,
    grid: &Grid,
    (shard, shards): (u64, u64),
    range: &Range<u64>,
    warned: u64,
) -> String {
    let models: Vec<&str> = grid.models().iter().map(|m| m.id()).collect();
    let mut h = format!("{VERSION_KEY}{version}\n# command: {command}\n");
    h.push_str(&format!("# model: {}\n", models.join(",")));
    let ids = |v: Vec<&str>| v.join(",");
    let choices = grid.choices();
    h.push_str(&format!(
        "# collision: {}\n",
        ids(choices.collision.iter().map(|c| c.id()).collect())
    ));
    h.push_str(&format!(
        "# on_hop: {}\n",
        ids(choices.on_hop.iter().map(|c| c.id()).collect())
    ));
    for axis in grid.axes() {
        h.push_str(&format!("# {}: {}\n", axis.param.key(), axis.values));
    }
    h.push_str(&format!("# points: {}\n", grid.len()));
    h.push_str(&format!(
        "# shard: {shard}/{shards}, rows {}..{}\n",
        range.start, range.end
    ));
    h.push_str(&format!("# {WARNINGS}: {}\n", warnings_text(warned)));
    h.push_str(&SweepRow::COLUMNS.join(","));
    h.push('\n');
    h
}

/// The `snowroll sweep` command of a recorded `# command:` line, parsed
/// as a shell would split it.
///
/// # Errors
/// Why it is not one (an edited header), quoting the line.
pub fn sweep_command(line: &str) -> Result<SweepArgs, String> {
    let bad = |why: String| format!("its command line `{}` {why}", cut(line));
    let words = shell_words(line).map_err(|e| bad(format!("cannot be split into words: {e}")))?;
    let parsed = Args::try_parse_from(&words).map_err(|e| {
        let why = e.to_string();
        bad(format!(
            "does not parse: {}",
            why.lines().next().unwrap_or_default()
        ))
    })?;
    match parsed.command {
        Command::Sweep(sweep) => Ok(*sweep),
        _ => Err(bad("is not a `snowroll sweep` command".into())),
    }
}

/// The first line of `got` (a header as read, `lines` its lines) that is
/// not the one of `want` (the header snowroll writes for it), with its
/// number, for the message refusing an edited header.
fn first_edit(lines: &[String], want: &str) -> (usize, String, String) {
    let mut want_lines = want.lines();
    for (k, line) in lines.iter().enumerate() {
        let w = want_lines.next().unwrap_or_default();
        if line != w {
            return (k + 1, line.clone(), w.to_string());
        }
    }
    let extra = want_lines.next().unwrap_or_default().to_string();
    (lines.len() + 1, String::new(), extra)
}

/// The `#` lines of a header and its column line (without newlines), and
/// the header's length in bytes; bounded in lines and line length.
fn header_lines(input: &mut impl BufRead, shown: &str) -> Result<(Vec<String>, String, u64)> {
    let mut lines: Vec<String> = Vec::new();
    let mut len = 0u64;
    let columns = loop {
        if lines.len() >= MAX_HEADER_LINES {
            bail!("{shown}: more than {MAX_HEADER_LINES} header lines: not a sweep file");
        }
        let mut buf = Vec::new();
        let n = (&mut *input)
            .take(MAX_HEADER_LINE + 1)
            .read_until(b'\n', &mut buf)
            .with_context(|| format!("reading {shown}"))?;
        len += n as u64;
        let line_no = lines.len() + 1;
        if n == 0 || buf.last() != Some(&b'\n') {
            if n as u64 > MAX_HEADER_LINE {
                bail!(
                    "{shown}: line {line_no} is longer than {} MiB, the most snowroll reads of a sweep file's header (an endless file such as /dev/zero, or not a sweep file?)",
                    MAX_HEADER_LINE >> 20
                );
            }
            bail!("{shown}: ends inside its header (line {line_no}): not a complete sweep file");
        }
        let line =
            String::from_utf8(buf).map_err(|_| anyhow!("{shown}: line {line_no} is not UTF-8"))?;
        let line = line.trim_end_matches('\n').to_string();
        if !line.starts_with('#') {
            break line;
        }
        lines.push(line);
    };
    Ok((lines, columns, len))
}

/// The values of `axis` in `grid` as text, `start:end:count` for a range
/// of several values; its default (from the table) when not swept.
fn axis_text(grid: &Grid, axis: AxisParam, default: Value) -> String {
    match grid.axes().iter().find(|a| a.param == axis) {
        Some(a) => match &a.values {
            Values::Range {
                start, count: 1, ..
            } => Values::List(vec![*start]).to_string(),
            v => v.to_string(),
        },
        None => match default {
            Value::Real(x) => Values::List(vec![x]).to_string(),
            _ => "none".to_string(),
        },
    }
}

/// The key of the header line that counts the rows with warnings.
pub const WARNINGS: &str = "warnings";

/// The value of the warnings line: `N rows`.
pub fn warnings_text(rows: u64) -> String {
    format!("{rows} rows")
}

/// `N rows`, the value of the warnings line.
fn parse_warnings_line(text: &str) -> Option<u64> {
    text.strip_suffix(" rows")?.parse().ok()
}

/// `i/N, rows a..b`.
pub fn parse_shard_line(text: &str) -> Option<((u64, u64), Range<u64>)> {
    let (shard, rows) = text.split_once(", rows ")?;
    let (i, n) = shard.split_once('/')?;
    let (a, b) = rows.split_once("..")?;
    let (i, n, a, b): (u64, u64, u64, u64) = (
        i.parse().ok()?,
        n.parse().ok()?,
        a.parse().ok()?,
        b.parse().ok()?,
    );
    (i < n && a <= b).then_some(((i, n), a..b))
}
