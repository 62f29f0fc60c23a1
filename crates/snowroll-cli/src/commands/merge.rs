//! `snowroll merge`: the shard files of one sweep (`snowroll sweep --shard
//! i/N`) joined into one file in grid order.
//!
//! Checks, before writing anything, that the files come from the same sweep
//! (every setting their headers record agrees, parsed: the differing ones
//! are named), that each
//! shard 0..N is there exactly once and that their rows tile the grid; then,
//! while copying, that each file holds exactly its rows, in order, each line
//! complete, each row parsed against the schema and equal in its parameters
//! to the grid point its index names.
//!
//! The result is the file the whole sweep run in one process would have
//! written to the same `-o` path, byte for byte, its command line included:
//! that of shard 0 without its `--shard`, the output replaced by this one
//! ([`one_process`]). Like that sweep, it writes Parquet to a FILE ending in
//! `.parquet` (in a build with the `parquet` feature), else CSV.

use std::fs::File;
use std::io::{BufReader, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use snowroll::sweep::shard_range;

use super::sweep::{command_line, format_of, COMMAND_KEY, SHARD_KEY};
use super::sweep_check::{check_rows, sweep_command, warnings_text, Recorded, WARNINGS};
use super::sweep_partial::kind_name;
use crate::args::{MergeArgs, OutputArgs, SweepArgs, SweepFormat};
use crate::clash::{refuse_clashes, RunFile};
use crate::sink::Sink;

/// One shard file, its header read. The file is not kept open: the rows
/// are read later, one shard after another ([`Shard::rows`]), so a merge
/// of more shards than the open-file limit allows works (issue 33, item 5).
struct Shard {
    path: PathBuf,
    /// Its header, parsed.
    recorded: Recorded,
    /// Its device and inode, to check that the file read for its rows is
    /// the one whose header was read.
    id: (u64, u64),
}

impl Shard {
    fn open(path: &Path) -> Result<Shard> {
        let shown = path.display().to_string();
        let (file, id) = open_regular(path)?;
        let mut reader = BufReader::new(file);
        let recorded = Recorded::read(&mut reader, &shown)?;
        Ok(Shard {
            path: path.to_path_buf(),
            recorded,
            id,
        })
    }

    fn shard(&self) -> u64 {
        self.recorded.shard.0
    }

    /// The file again, positioned at its first row.
    fn rows(&self) -> Result<BufReader<File>> {
        let shown = self.path.display();
        let (mut file, id) = open_regular(&self.path)?;
        if id != self.id {
            bail!("{shown} was replaced while the shards were merged");
        }
        file.seek(SeekFrom::Start(self.recorded.len))
            .with_context(|| format!("reading {shown}"))?;
        Ok(BufReader::new(file))
    }
}

/// `path` opened for reading, if it is a regular file (a shard is read
/// twice, its header then its rows; a device such as `/dev/zero`, a FIFO
/// or a directory is refused by name), with its device and inode.
fn open_regular(path: &Path) -> Result<(File, (u64, u64))> {
    use std::os::unix::fs::MetadataExt;
    let shown = path.display();
    let file = File::open(path).with_context(|| format!("reading {shown}"))?;
    let meta = file
        .metadata()
        .with_context(|| format!("reading {shown}"))?;
    if !meta.is_file() {
        bail!(
            "cannot merge {shown}: it is {}, not a regular file (a shard is a file written by \
             `snowroll sweep --shard`)",
            kind_name(&meta.file_type())
        );
    }
    Ok((file, (meta.dev(), meta.ino())))
}

/// Checks and joins the shards.
pub fn run(args: &MergeArgs) -> Result<()> {
    let mut files: Vec<RunFile> = (args.inputs.iter())
        .map(|p| RunFile::input(p, "input shard"))
        .collect();
    files.extend(
        args.output
            .as_deref()
            .map(|p| RunFile::output(p, "-o output")),
    );
    refuse_clashes(&files)?;
    let mut shards = args
        .inputs
        .iter()
        .map(|p| Shard::open(p))
        .collect::<Result<Vec<_>>>()?;
    shards.sort_by_key(Shard::shard);
    check_tiling(&shards)?;
    let points = shards[0].recorded.grid.len();

    let sweep = one_process(&shards[0], args.output.as_deref())?;
    let out = OutputArgs {
        format: None,
        output: args.output.clone(),
        config: None,
        plot: None,
    };
    let mut sink = Sink::open(&out)?;
    let name = sink.name();
    let format = format_of(&sweep, matches!(sink, Sink::Replace { .. }))?;
    let mut header = String::new();
    for line in &shards[0].recorded.header {
        if line.starts_with(COMMAND_KEY) {
            header.push_str(&format!("{COMMAND_KEY}{}", command_line(&sweep)));
        } else if line.starts_with(SHARD_KEY) {
            header.push_str(&format!("{SHARD_KEY}0/1, rows 0..{points}"));
        } else if line.starts_with(&format!("# {WARNINGS}: ")) {
            // Each shard's count is checked against its rows as they are copied.
            let all = shards.iter().map(|s| s.recorded.warnings).sum();
            header.push_str(&format!("# {WARNINGS}: {}", warnings_text(all)));
        } else {
            header.push_str(line);
        }
        header.push('\n');
    }
    match format {
        SweepFormat::Csv => {
            sink.write_all(header.as_bytes())
                .with_context(|| format!("writing {name}"))?;
            for s in &shards {
                copy_rows(s, &mut sink, &name)?;
            }
        }
        SweepFormat::Parquet => sink = to_parquet(&shards, &header, sink)?,
    }
    sink.commit().with_context(|| format!("writing {name}"))?;
    Ok(())
}

/// The sweep that the shards make up, run in one process writing to
/// `output`: the command line `first` records (shard 0's), parsed, without
/// its `--shard` and `--resume`, and with `output` for its `--output`.
/// Every shard was checked to record the same grid and settings, so this
/// sweep writes the rows of them all; its command line ([`command_line`])
/// is the merged file's.
///
/// # Errors
/// A command line that is not one of `snowroll sweep` (an edited header),
/// named with the file.
fn one_process(first: &Shard, output: Option<&Path>) -> Result<SweepArgs> {
    let shown = first.path.display();
    let line = (first.recorded.header.iter())
        .find_map(|l| l.strip_prefix(COMMAND_KEY))
        .ok_or_else(|| anyhow!("{shown}: its header has no `{}` line", COMMAND_KEY.trim()))?;
    let mut sweep = sweep_command(line).map_err(|why| anyhow!("{shown}: {why}"))?;
    sweep.shard = None;
    sweep.resume = false;
    sweep.output = output.map(Path::to_path_buf);
    Ok(sweep)
}

/// Writes `header` and the shards' rows as Parquet through `sink` (a
/// regular file), the way `sweep` does: the CSV first, to a temporary file
/// beside the output, then converted ([`snowroll_io::parquet::write`]).
#[cfg(feature = "parquet")]
fn to_parquet(shards: &[Shard], header: &str, sink: Sink) -> Result<Sink> {
    use crate::scratch::Scratch;
    use crate::sink::parent_or_dot;
    let Sink::Replace { target, .. } = &sink else {
        bail!("Parquet output needs -o FILE (a regular file)");
    };
    let name = sink.name();
    let (scratch, file) = Scratch::file_in(parent_or_dot(target), 0o600)
        .with_context(|| format!("cannot write {name}"))?;
    let csv_name = format!("the CSV for {name} ({})", scratch.path().display());
    let mut csv = std::io::BufWriter::new(file);
    csv.write_all(header.as_bytes())
        .with_context(|| format!("writing {csv_name}"))?;
    for s in shards {
        copy_rows(s, &mut csv, &csv_name)?;
    }
    csv.flush().with_context(|| format!("writing {csv_name}"))?;
    let rows = File::open(scratch.path()).with_context(|| format!("reading {csv_name}"))?;
    let sink = snowroll_io::parquet::write(BufReader::new(rows), header, sink)
        .with_context(|| format!("writing {name}"))?;
    drop(scratch);
    Ok(sink)
}

#[cfg(not(feature = "parquet"))]
fn to_parquet(_: &[Shard], _: &str, _: Sink) -> Result<Sink> {
    bail!("this snowroll was built without Parquet")
}

/// Checks, from the headers, that the shards (sorted by shard) are of one
/// sweep (every setting alike: the differing ones are named), that each
/// shard 0..N is there once and holds the rows that shard of the grid has,
/// so that together they cover the grid.
fn check_tiling(shards: &[Shard]) -> Result<()> {
    let first = &shards[0];
    let (_, n) = first.recorded.shard;
    let shown = |s: &Shard| s.path.display().to_string();
    for s in &shards[1..] {
        let names = (shown(first), shown(s));
        let mut differs = first
            .recorded
            .differences(&s.recorded, false, (&names.0, &names.1));
        if s.recorded.shard.1 != n {
            differs.push(format!(
                "shards: {n} in {}, {} in {}",
                names.0, s.recorded.shard.1, names.1
            ));
        }
        if !differs.is_empty() {
            bail!(
                "{} and {} are not shards of the same sweep: {}",
                names.0,
                names.1,
                differs.join("; ")
            );
        }
    }
    for pair in shards.windows(2) {
        if pair[0].shard() == pair[1].shard() {
            bail!(
                "shard {}/{n} is given twice: {} and {}",
                pair[0].shard(),
                shown(&pair[0]),
                shown(&pair[1])
            );
        }
    }
    let points = first.recorded.grid.len();
    let range = |i: u64| shard_range(points, i, n).map_err(|e| anyhow!("{e}"));
    let present: Vec<u64> = shards.iter().map(Shard::shard).collect();
    let mut missing = Vec::new();
    for i in (0..n).filter(|i| !present.contains(i)) {
        let r = range(i)?;
        missing.push(format!("{i}/{n} (rows {}..{})", r.start, r.end));
    }
    if !missing.is_empty() {
        bail!(
            "missing shards: {} of the {points} points",
            missing.join(", ")
        );
    }
    for s in shards {
        let want = range(s.shard())?;
        if s.recorded.rows != want {
            bail!(
                "{}: its shard line says rows {:?}, but shard {}/{n} of {points} points is rows {want:?}",
                shown(s),
                s.recorded.rows,
                s.shard()
            );
        }
    }
    Ok(())
}

/// Copies the rows of `s` to `out` (`name` in messages), each checked
/// ([`check_rows`]), and checks that they are all of its shard's rows.
fn copy_rows(s: &Shard, out: &mut impl Write, name: &str) -> Result<()> {
    let shown = s.path.display().to_string();
    let rows = s.recorded.rows.clone();
    let mut warned = 0u64;
    let mut reader = s.rows()?;
    let end = check_rows(
        &mut reader,
        &s.recorded.grid,
        &rows,
        s.recorded.lines + 1,
        &shown,
        |line, row| {
            warned += u64::from(row.warnings.is_some());
            out.write_all(line)
                .with_context(|| format!("writing {name}"))
        },
    )?;
    if end == rows.end && warned != s.recorded.warnings {
        bail!(
            "{shown}: its header says {} with warnings, its rows have {warned}",
            warnings_text(s.recorded.warnings)
        );
    }
    if end != rows.end {
        bail!(
            "{shown}: holds rows {}..{end} of its {rows:?}: rows {end}..{} are missing",
            rows.start,
            rows.end
        );
    }
    Ok(())
}
