//! `snowroll sweep`: many trajectories over a grid, one row each.
//!
//! To a file, rows go to `FILE.partial` (locked while a sweep writes it) a
//! chunk at a time; at the end they are copied through the output [`Sink`]
//! (temporary file, renamed into place) and the partial file is removed.
//! A sweep that was killed leaves `FILE.partial`; `--resume` checks that its
//! header is this sweep's, drops a torn last line and continues after the
//! last complete row, so the result is the same bytes as an uninterrupted
//! run. Without `--resume` an existing partial file is refused, never
//! overwritten.

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufRead, BufReader, Read, Seek, SeekFrom, Write};
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{anyhow, bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use rustix::fs::{flock, FlockOperation};
use snowroll::sweep::{run_chunks, shard_range, Grid, Method, SweepRow, DEFAULT_CHUNK};
use snowroll_io::VERSION;

use super::sweep_csv::RowWriter;
use super::sweep_grid::{flag_axes, grid, run_files, with_config};
use crate::args::{OutputArgs, SweepArgs, SweepFormat};
use crate::clash::refuse_clashes;
use crate::console;
use crate::shell::shell_word;
use crate::sink::{replaced_target, Sink};

/// Start of the header line naming the command (not compared on resume or merge).
pub const COMMAND_KEY: &str = "# command: ";
/// Start of the header line naming the shard and its rows.
pub const SHARD_KEY: &str = "# shard: ";
/// Rows formatted by one task.
const FORMAT_ROWS: usize = 512;
/// What is appended to the output's name for the rows of a running sweep.
const PARTIAL_SUFFIX: &str = ".partial";
/// Longest wait between two `fsync`s of the partial file: a crash of the
/// machine loses at most this much work.
const SYNC_EVERY: Duration = Duration::from_secs(10);

/// Parses the grid, runs it (or this shard of it), writes the rows.
pub fn run(args: &SweepArgs) -> Result<()> {
    let partial = (args.output.as_deref().and_then(replaced_target))
        .map(|target| with_suffix(&target, PARTIAL_SUFFIX));
    refuse_clashes(&run_files(args, partial.as_deref()))?;
    let (args, command) = with_config(args)?;
    let args = &args;
    let grid = grid(args)?;
    let plot = match &args.plot {
        Some(path) => Some((super::sweep_plot::plan(args, &grid)?, path)),
        None => None,
    };
    let (shard, shards) = match &args.shard {
        Some(text) => parse_shard(text)?,
        None => (0, 1),
    };
    let range = shard_range(grid.len(), shard, shards).map_err(|e| anyhow!("--shard: {e}"))?;
    let header = header(args, command.as_deref(), &grid, shard, shards, &range);

    let out = OutputArgs {
        format: None,
        output: args.output.clone(),
        config: None,
    };
    let sink = Sink::open(&out)?;
    let partial_path = match &sink {
        Sink::Replace { target, .. } => Some(with_suffix(target, PARTIAL_SUFFIX)),
        _ => None,
    };
    let format = format_of(args, partial_path.is_some())?;
    let bar = progress(range.end - range.start, args.quiet);
    match partial_path {
        None => to_stream(args, &grid, range, &header, sink, &bar),
        Some(path) => to_partial(args, &grid, range, &header, sink, &bar, &path, format, plot),
    }
}

/// The output format: `--format`, else Parquet for a FILE ending in
/// `.parquet`, else CSV; refused when Parquet is asked of a build without
/// it or of a stream (`to_file`: the output is a regular file).
fn format_of(args: &SweepArgs, to_file: bool) -> Result<SweepFormat> {
    let format = args.format.unwrap_or_else(|| {
        let parquet = args
            .output
            .as_ref()
            .and_then(|p| p.extension())
            .is_some_and(|e| e.eq_ignore_ascii_case("parquet"));
        if parquet {
            SweepFormat::Parquet
        } else {
            SweepFormat::Csv
        }
    });
    if format == SweepFormat::Parquet {
        if cfg!(not(feature = "parquet")) {
            bail!(
                "this snowroll was built without Parquet: rebuild it with `--features parquet` \
                 (cargo install --path crates/snowroll-cli --features parquet), or write CSV"
            );
        }
        if !to_file {
            bail!("Parquet output needs --output FILE (a regular file)");
        }
    }
    Ok(format)
}

/// Writes the sweep straight to a stream (stdout, a device, a FIFO): no
/// partial file, so no resume and no map.
fn to_stream(
    args: &SweepArgs,
    grid: &Grid,
    range: Range<u64>,
    header: &str,
    mut sink: Sink,
    bar: &ProgressBar,
) -> Result<()> {
    let name = sink.name();
    if args.resume {
        bail!("--resume needs --output FILE (a regular file)");
    }
    if args.plot.is_some() {
        bail!("--plot needs --output FILE (a regular file): the map is drawn from its rows");
    }
    let chunk = args.chunk_rows.map_or(DEFAULT_CHUNK, |n| n as usize);
    sink.write_all(header.as_bytes())
        .with_context(|| format!("writing {name}"))?;
    write_rows(grid, range, chunk, args.method, &mut sink, bar, || Ok(()))
        .with_context(|| format!("writing {name}"))?;
    bar.finish_and_clear();
    sink.commit().with_context(|| format!("writing {name}"))?;
    Ok(())
}

/// Writes the sweep's rows to `path` (FILE.partial) as they are computed,
/// synced every [`SYNC_EVERY`]; resumes from the rows already there with
/// `--resume`; then draws the map and writes the finished file through
/// `sink`, and removes the partial file.
#[allow(clippy::too_many_arguments)]
fn to_partial(
    args: &SweepArgs,
    grid: &Grid,
    range: Range<u64>,
    header: &str,
    sink: Sink,
    bar: &ProgressBar,
    path: &Path,
    format: SweepFormat,
    plot: Option<(super::sweep_plot::Plan, &PathBuf)>,
) -> Result<()> {
    let name = sink.name();
    let chunk = args.chunk_rows.map_or(DEFAULT_CHUNK, |n| n as usize);
    let mut partial = Partial::open(path, header, args.resume)?;
    let done = partial.rows_done(&range)?;
    bar.inc(done);
    let shown = path.display().to_string();
    let mut last_sync = Instant::now();
    let file = &mut partial.file;
    let sync_file = file
        .try_clone()
        .with_context(|| format!("writing {shown}"))?;
    let mut writer = io::BufWriter::new(file);
    write_rows(
        grid,
        range.start + done..range.end,
        chunk,
        args.method,
        &mut writer,
        bar,
        || {
            if last_sync.elapsed() >= SYNC_EVERY {
                sync_file.sync_data()?;
                last_sync = Instant::now();
            }
            Ok(())
        },
    )
    .with_context(|| format!("writing {shown}"))?;
    writer.flush().with_context(|| format!("writing {shown}"))?;
    drop(writer);
    bar.finish_and_clear();
    partial
        .file
        .seek(SeekFrom::Start(0))
        .with_context(|| format!("reading {shown}"))?;
    if let Some((plan, plot)) = plot {
        super::sweep_plot::draw(plan, grid, &partial.file, plot)?;
        partial
            .file
            .seek(SeekFrom::Start(0))
            .with_context(|| format!("reading {shown}"))?;
    }
    finish(format, &mut partial, sink).with_context(|| format!("writing {name}"))?;
    fs::remove_file(path).with_context(|| format!("removing {shown}"))?;
    Ok(())
}

/// Writes the rows of the partial file (positioned at its start) to `sink`
/// in `format`, and renames the output into place.
fn finish(format: SweepFormat, partial: &mut Partial, mut sink: Sink) -> Result<()> {
    match format {
        SweepFormat::Csv => {
            io::copy(&mut partial.file, &mut sink)?;
        }
        #[cfg(feature = "parquet")]
        SweepFormat::Parquet => {
            let mut header = vec![0u8; partial.header_len as usize];
            partial.file.read_exact(&mut header)?;
            partial.file.seek(SeekFrom::Start(0))?;
            let header = String::from_utf8_lossy(&header).into_owned();
            sink = super::parquet::write(&partial.file, &header, sink)?;
        }
        #[cfg(not(feature = "parquet"))]
        SweepFormat::Parquet => bail!("this snowroll was built without Parquet"),
    }
    Ok(sink.commit()?)
}

/// Runs `range` and writes its rows as CSV records to `out`, calling
/// `after_chunk` after each chunk.
fn write_rows(
    grid: &Grid,
    range: Range<u64>,
    chunk: usize,
    method: Method,
    out: &mut impl Write,
    bar: &ProgressBar,
    mut after_chunk: impl FnMut() -> io::Result<()>,
) -> Result<()> {
    run_chunks(
        grid,
        range,
        chunk,
        method,
        |rows: &[SweepRow]| -> Result<()> {
            // Formatting is a fair part of a fast row's cost: in parallel too.
            let parts = rows
                .par_chunks(FORMAT_ROWS)
                .map(|part| -> Result<Vec<u8>, csv::Error> {
                    let mut buf = Vec::with_capacity(part.len() * 200);
                    let mut rows = RowWriter::new();
                    for row in part {
                        rows.write(&mut buf, row)?;
                    }
                    Ok(buf)
                })
                .collect::<Result<Vec<_>, _>>()?;
            for buf in parts {
                out.write_all(&buf)?;
            }
            out.flush()?;
            after_chunk()?;
            bar.inc(rows.len() as u64);
            Ok(())
        },
    )
}

/// A progress bar with rate and ETA on a terminal; hidden otherwise.
fn progress(len: u64, quiet: bool) -> ProgressBar {
    if quiet || !console::stderr_is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len);
    if let Ok(style) =
        ProgressStyle::with_template("{bar:32} {pos}/{len} {per_sec} ETA {eta} {msg}")
    {
        bar.set_style(style);
    }
    bar
}

/// `path` with `suffix` appended to its file name.
fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(suffix);
    PathBuf::from(name)
}

/// `i/N` with `0 <= i < N`.
pub fn parse_shard(text: &str) -> Result<(u64, u64)> {
    let bad = || anyhow!("--shard {text:?}: expected I/N with whole numbers 0 <= I < N, e.g. 0/4");
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let (i, n): (u64, u64) = (
        i.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if n == 0 || i >= n {
        return Err(bad());
    }
    Ok((i, n))
}

/// The `#` lines and the column names: everything a resumed run or a merge
/// checks, plus the command line (which they do not): `recorded`, the one a
/// `--config` file holds, when the run is that file's own; else `args`'.
fn header(
    args: &SweepArgs,
    recorded: Option<&str>,
    grid: &Grid,
    shard: u64,
    shards: u64,
    range: &Range<u64>,
) -> String {
    let mut command = String::from("snowroll sweep");
    if let Some(path) = &args.grid {
        command.push_str(&format!(
            " --grid {}",
            shell_word(&path.display().to_string())
        ));
    }
    for (key, value) in flag_axes(args) {
        command.push_str(&format!(
            " --{} {}",
            key.replace('_', "-"),
            shell_word(value)
        ));
    }
    if let Some(path) = &args.output {
        command.push_str(&format!(
            " --output {}",
            shell_word(&path.display().to_string())
        ));
    }
    if args.method != Method::Auto {
        command.push_str(" --method ode");
    }
    if let Some(f) = args.format {
        command.push_str(match f {
            SweepFormat::Csv => " --format csv",
            SweepFormat::Parquet => " --format parquet",
        });
    }
    if let Some(s) = &args.shard {
        command.push_str(&format!(" --shard {}", shell_word(s)));
    }
    if let Some(recorded) = recorded {
        command = recorded.to_string();
    }
    let models: Vec<&str> = grid.models().iter().map(|m| m.id()).collect();
    let mut h = format!("# snowroll sweep, version {VERSION}\n{COMMAND_KEY}{command}\n");
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
        "{SHARD_KEY}{shard}/{shards}, rows {}..{}\n",
        range.start, range.end
    ));
    h.push_str(&SweepRow::COLUMNS.join(","));
    h.push('\n');
    h
}

/// The rows file of a running sweep, locked for as long as it is open.
struct Partial {
    file: File,
    path: PathBuf,
    /// Length of the header, bytes: the rows start there.
    header_len: u64,
}

impl Partial {
    /// Opens (or creates) `path` and locks it; writes `header` into a new or
    /// empty one. An existing one is refused unless `resume`, and then must
    /// have been written by the same sweep.
    fn open(path: &Path, header: &str, resume: bool) -> Result<Partial> {
        let shown = path.display();
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(path)
            .with_context(|| format!("cannot write {shown}"))?;
        flock(&file, FlockOperation::NonBlockingLockExclusive)
            .map_err(|_| anyhow!("{shown} is being written by another sweep"))?;
        let len = file.metadata()?.len();
        let mut on_disk = String::new();
        if len > 0 {
            if !resume {
                bail!(
                    "{shown} holds the rows of an unfinished sweep: pass --resume (with the same \
                     flags) to continue it, or remove it to start again"
                );
            }
            let mut reader = BufReader::new(&file);
            for _ in 0..header.lines().count() {
                if reader.read_line(&mut on_disk)? == 0 {
                    break;
                }
            }
        }
        let lines = |h: &str| -> Vec<String> {
            h.lines()
                .filter(|l| !l.starts_with(COMMAND_KEY))
                .map(str::to_string)
                .collect()
        };
        let complete = on_disk.len() == header.len() && on_disk.ends_with('\n');
        if complete {
            if lines(&on_disk) != lines(header) {
                let differs = lines(&on_disk)
                    .into_iter()
                    .zip(lines(header))
                    .find(|(a, b)| a != b)
                    .map(|(a, b)| format!("it has {a:?} where this sweep has {b:?}"))
                    .unwrap_or_default();
                bail!(
                    "{shown} was written by another sweep ({differs}): remove it, or resume \
                     with the flags that started it"
                );
            }
        } else {
            // Nothing, or a header cut short: start afresh.
            file.set_len(0)?;
            file.seek(SeekFrom::Start(0))?;
            file.write_all(header.as_bytes())
                .with_context(|| format!("writing {shown}"))?;
            on_disk = header.to_string();
        }
        Ok(Partial {
            file,
            path: path.to_path_buf(),
            header_len: on_disk.len() as u64,
        })
    }

    /// How many rows of `range` are complete on disk: cuts a torn last line
    /// off and checks that the last row's index is the one expected; leaves
    /// the file positioned at its end.
    fn rows_done(&mut self, range: &Range<u64>) -> Result<u64> {
        let shown = self.path.display().to_string();
        let len = self.file.metadata()?.len();
        let end = last_newline(&mut self.file, self.header_len, len)?;
        self.file.set_len(end)?;
        self.file.seek(SeekFrom::End(0))?;
        if end == self.header_len {
            return Ok(0);
        }
        let start = last_newline(&mut self.file, self.header_len, end - 1)?;
        self.file.seek(SeekFrom::Start(start))?;
        let mut line = String::new();
        (&self.file).take(end - start).read_to_string(&mut line)?;
        self.file.seek(SeekFrom::End(0))?;
        let index: u64 = line
            .split(',')
            .next()
            .and_then(|i| i.parse().ok())
            .ok_or_else(|| anyhow!("{shown}: its last row {line:?} has no index"))?;
        if !range.contains(&index) {
            bail!("{shown}: its last row has index {index}, outside this sweep's rows {range:?}");
        }
        Ok(index + 1 - range.start)
    }
}

/// The position just after the last `\n` before `end` and at or after
/// `floor`, or `floor` when there is none.
fn last_newline(file: &mut File, floor: u64, end: u64) -> io::Result<u64> {
    const BLOCK: u64 = 64 * 1024;
    let mut hi = end;
    let mut buf = vec![0u8; BLOCK as usize];
    while hi > floor {
        let lo = hi.saturating_sub(BLOCK).max(floor);
        let n = (hi - lo) as usize;
        file.seek(SeekFrom::Start(lo))?;
        file.read_exact(&mut buf[..n])?;
        if let Some(k) = buf[..n].iter().rposition(|&c| c == b'\n') {
            return Ok(lo + k as u64 + 1);
        }
        hi = lo;
    }
    Ok(floor)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shard_syntax() {
        assert_eq!(parse_shard("0/4").unwrap(), (0, 4));
        assert_eq!(parse_shard("3/4").unwrap(), (3, 4));
        for bad in ["4/4", "1/0", "1", "a/2", "-1/2", "1/2/3"] {
            let e = parse_shard(bad).unwrap_err().to_string();
            assert!(e.contains("0 <= I < N"), "{bad}: {e}");
        }
    }
}
