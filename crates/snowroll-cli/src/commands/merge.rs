//! `snowroll merge`: the shard files of one sweep (`snowroll sweep --shard
//! i/N`) joined into one file in grid order.
//!
//! Checks, before writing anything, that the files come from the same sweep
//! (their headers agree but for the command line and the shard), that each
//! shard 0..N is there exactly once and that their rows tile the grid; then,
//! while copying, that each file holds exactly its rows, in order, each line
//! complete. The result is the uninterrupted sweep's file but for its
//! command line.

use std::fs::File;
use std::io::{BufReader, Write};
use std::ops::Range;
use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};

use super::sweep::{COMMAND_KEY, SHARD_KEY};
use crate::args::{MergeArgs, OutputArgs};
use crate::bounded::{self, MAX_ROW_LINE};
use crate::clash::{refuse_clashes, RunFile};
use crate::sink::Sink;

/// One shard file, its header read.
struct Shard {
    path: PathBuf,
    reader: BufReader<File>,
    /// The header lines (with their newlines), column names last.
    header: Vec<String>,
    shard: u64,
    shards: u64,
    rows: Range<u64>,
}

impl Shard {
    fn open(path: &Path) -> Result<Shard> {
        let shown = path.display();
        let file = File::open(path).with_context(|| format!("reading {shown}"))?;
        let mut reader = BufReader::new(file);
        let header =
            bounded::read_header(&mut reader).with_context(|| format!("reading {shown}"))?;
        if header.last().is_none_or(|l| l.starts_with('#')) {
            bail!("{shown}: ends inside its header: not a complete sweep file");
        }
        let shard_line = header
            .iter()
            .find_map(|l| l.strip_prefix(SHARD_KEY))
            .ok_or_else(|| anyhow!("{shown}: no `{}` line: not a sweep file", SHARD_KEY.trim()))?;
        let (shard, shards, rows) = parse_shard_line(shard_line.trim_end())
            .ok_or_else(|| anyhow!("{shown}: cannot read its shard line {shard_line:?}"))?;
        Ok(Shard {
            path: path.to_path_buf(),
            reader,
            header,
            shard,
            shards,
            rows,
        })
    }

    /// The header lines that must agree between the shards of one sweep.
    fn identity(&self) -> Vec<&str> {
        self.header
            .iter()
            .filter(|l| !l.starts_with(COMMAND_KEY) && !l.starts_with(SHARD_KEY))
            .map(String::as_str)
            .collect()
    }
}

/// `i/N, rows a..b`.
fn parse_shard_line(text: &str) -> Option<(u64, u64, Range<u64>)> {
    let (shard, rows) = text.split_once(", rows ")?;
    let (i, n) = shard.split_once('/')?;
    let (a, b) = rows.split_once("..")?;
    Some((
        i.parse().ok()?,
        n.parse().ok()?,
        a.parse().ok()?..b.parse().ok()?,
    ))
}

/// Refuses an output that is one of the shards (however spelt), then opens
/// each shard and reads its header.
fn open_shards(args: &MergeArgs) -> Result<Vec<Shard>> {
    let mut files: Vec<RunFile> = (args.inputs.iter())
        .map(|p| RunFile::input(p, "input shard"))
        .collect();
    files.extend(
        args.output
            .as_deref()
            .map(|p| RunFile::output(p, "-o output")),
    );
    refuse_clashes(&files)?;
    args.inputs.iter().map(|p| Shard::open(p)).collect()
}

/// Checks and joins the shards.
pub fn run(args: &MergeArgs) -> Result<()> {
    let mut shards = open_shards(args)?;
    shards.sort_by_key(|s| s.shard);
    let first = &shards[0];
    let n = first.shards;
    for s in &shards[1..] {
        if s.identity() != first.identity() || s.shards != n {
            bail!(
                "{} and {} are not shards of the same sweep (their headers differ)",
                first.path.display(),
                s.path.display()
            );
        }
    }
    for pair in shards.windows(2) {
        if pair[0].shard == pair[1].shard {
            bail!(
                "shard {}/{n} is given twice: {} and {}",
                pair[0].shard,
                pair[0].path.display(),
                pair[1].path.display()
            );
        }
    }
    let present: Vec<u64> = shards.iter().map(|s| s.shard).collect();
    let missing: Vec<String> = (0..n)
        .filter(|i| !present.contains(i))
        .map(|i| format!("{i}/{n}"))
        .collect();
    if !missing.is_empty() {
        bail!("missing shards: {}", missing.join(", "));
    }
    let mut next = 0;
    for s in &shards {
        if s.rows.start != next {
            bail!(
                "{}: rows {:?} do not follow the previous shard's (which ended at {next})",
                s.path.display(),
                s.rows
            );
        }
        next = s.rows.end;
    }

    let out = OutputArgs {
        format: None,
        output: args.output.clone(),
        config: None,
    };
    let mut sink = Sink::open(&out)?;
    let name = sink.name();
    let mut command = String::from("snowroll merge");
    for p in &args.inputs {
        command.push_str(&format!(" {}", p.display()));
    }
    let mut header = String::new();
    for line in &shards[0].header {
        if line.starts_with(COMMAND_KEY) {
            header.push_str(&format!("{COMMAND_KEY}{command}\n"));
        } else if line.starts_with(SHARD_KEY) {
            header.push_str(&format!("{SHARD_KEY}0/1, rows 0..{next}\n"));
        } else {
            header.push_str(line);
        }
    }
    sink.write_all(header.as_bytes())
        .with_context(|| format!("writing {name}"))?;
    for s in &mut shards {
        copy_rows(s, &mut sink).with_context(|| format!("writing {name}"))?;
    }
    sink.commit().with_context(|| format!("writing {name}"))?;
    Ok(())
}

/// Copies the rows of `s`, checking that their indices are `s.rows` in order.
fn copy_rows(s: &mut Shard, out: &mut impl Write) -> Result<()> {
    let shown = s.path.display().to_string();
    let mut expected = s.rows.start;
    let mut line = String::new();
    loop {
        line.clear();
        if bounded::read_line(&mut s.reader, &mut line, MAX_ROW_LINE, "a sweep row")
            .with_context(|| format!("reading {shown}"))?
            == 0
        {
            break;
        }
        if !line.ends_with('\n') {
            bail!("{shown}: its last line is cut short (an interrupted sweep? finish it with --resume)");
        }
        let index: Option<u64> = line.split(',').next().and_then(|i| i.parse().ok());
        if index != Some(expected) || expected >= s.rows.end {
            bail!(
                "{shown}: row {} where row {expected} of {:?} was expected",
                index.map_or_else(|| "without an index".to_string(), |i| i.to_string()),
                s.rows
            );
        }
        out.write_all(line.as_bytes())?;
        expected += 1;
    }
    if expected != s.rows.end {
        bail!(
            "{shown}: holds rows {}..{expected} of its {:?}",
            s.rows.start,
            s.rows
        );
    }
    Ok(())
}
