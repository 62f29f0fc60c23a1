//! `snowroll sweep`: many trajectories over a grid, one row each.
//!
//! To a file, rows go to `FILE.partial` (locked while a sweep writes it;
//! `sweep_partial.rs`) a chunk at a time; at the end the partial file,
//! which then holds the output's bytes, is renamed into place (a Parquet
//! output is converted from it, and it is removed after). Every output
//! (`-o`, the partial file, `--plot`) is opened before the first row is
//! computed, and a complete partial file is never removed on an error. A sweep that was killed leaves `FILE.partial`;
//! `--resume` checks that its header records the same grid and settings
//! (parsed, not compared as bytes) and that its rows are whole, in order
//! and those of the grid, drops a torn last line and continues after the
//! last complete row, so the result is the same bytes as an uninterrupted
//! run. Without `--resume` an existing partial file is refused, never
//! overwritten. A run that fails before its rows are complete removes the
//! partial file it created.

use std::io::{self, Seek, SeekFrom, Write};
use std::ops::Range;
use std::path::Path;
use std::time::{Duration, Instant};

use anyhow::{anyhow, bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use snowroll::sweep::{
    count_warnings, run_folded, shard_range, Grid, Method, DEFAULT_CHUNK, PART_ROWS,
};
use snowroll_io::VERSION;

use super::sweep_check::{header_text, Recorded};
use super::sweep_grid::{flag_axes, grid, run_files, with_config};
use super::sweep_partial::{partial_path, Partial};
use crate::args::{OutputArgs, SweepArgs, SweepFormat};
use crate::clash::refuse_clashes;
use crate::console::{self, report};
use crate::shell::shell_word;
use crate::sink::{replaced_target, Sink};
use snowroll_io::sweep::SweepCsv;

/// Start of the header line naming the command (not compared on resume or merge).
pub const COMMAND_KEY: &str = "# command: ";
/// Start of the header line naming the shard and its rows.
pub const SHARD_KEY: &str = "# shard: ";
/// Longest wait between two `fsync`s of the partial file: a crash of the
/// machine loses at most this much work.
const SYNC_EVERY: Duration = Duration::from_secs(10);

/// Parses the grid, runs it (or this shard of it), writes the rows.
pub fn run(args: &SweepArgs) -> Result<()> {
    let partial =
        (args.output.as_deref().and_then(replaced_target)).map(|target| partial_path(&target));
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
    let warned = count_warnings(&grid, range.clone())?;
    let header = header(
        args,
        command.as_deref(),
        &grid,
        (shard, shards),
        &range,
        warned,
    );
    let recorded = Recorded::of_run(&grid, args.method, (shard, shards), range.clone(), warned);

    let out = OutputArgs {
        format: None,
        output: args.output.clone(),
        config: None,
        plot: None,
    };
    let sink = Sink::open(&out)?;
    let partial_path = match &sink {
        Sink::Replace { target, .. } => Some(partial_path(target)),
        _ => None,
    };
    let format = format_of(args, partial_path.is_some())?;
    let rows = range.end - range.start;
    let bar = progress(rows, args.quiet);
    match partial_path {
        None => to_stream(args, &grid, range, &header, sink, &bar)?,
        Some(path) => {
            // Every output is opened before the first row is computed: a
            // map that cannot be written is refused now, not after hours.
            let plot = match plot {
                Some((plan, path)) => Some((plan, super::sweep_plot::open(path)?)),
                None => None,
            };
            let run = Run {
                recorded: &recorded,
                header: &header,
                format,
            };
            to_partial(args, &run, (sink, plot), &bar, &path)?;
        }
    }
    if warned > 0 {
        report!(
            "warning: {warned} of the {rows} rows have warnings, the ones simulate gives for \
             their points: see their warnings column (codes listed in docs/guide/sweeps.md)"
        );
    }
    Ok(())
}

/// The output format: `--format`, else Parquet for a FILE ending in
/// `.parquet`, else CSV; refused when Parquet is asked of a build without
/// it or of a stream (`to_file`: the output is a regular file).
pub fn format_of(args: &SweepArgs, to_file: bool) -> Result<SweepFormat> {
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

/// What a sweep to a file writes besides its rows.
struct Run<'a> {
    /// Its grid, settings and rows.
    recorded: &'a Recorded,
    /// Its header's text.
    header: &'a str,
    format: SweepFormat,
}

/// The outputs of a sweep to a file, opened before its rows are computed:
/// the `-o` file and the map, if any.
type Outputs = (Sink, Option<(super::sweep_plot::Plan, Sink)>);

/// Writes the sweep's rows to `path` (FILE.partial) as they are computed,
/// synced every [`SYNC_EVERY`]; resumes from the rows already there with
/// `--resume`; then draws the map and puts the finished file in place.
///
/// An error while the rows are computed removes the partial file if this
/// run created it (a full disk is not left fuller), and keeps it if it
/// holds an earlier run's rows. Once every row is there the partial file
/// is never removed on an error (issue 33, item 1): it is kept, and said
/// to be kept, for `--resume`, which then only writes the outputs.
fn to_partial(
    args: &SweepArgs,
    run: &Run,
    (sink, plot): Outputs,
    bar: &ProgressBar,
    path: &Path,
) -> Result<()> {
    let mut partial = Partial::open(path, run.header, run.recorded, args.resume)?;
    if let Err(e) = fill(args, run, &mut partial, bar, path) {
        partial.remove_if_created();
        return Err(e);
    }
    let rows = run.recorded.rows.end - run.recorded.rows.start;
    let name = sink.name();
    finish(run, partial, sink, plot).inspect_err(|_| {
        report!(
            "note: the {rows} rows are complete in {}, which is kept: once the cause is \
             fixed, the same command with --resume writes {name} without computing them again",
            path.display()
        );
    })
}

/// The rows of `run` not yet in `partial`, flushed to it.
fn fill(
    args: &SweepArgs,
    run: &Run,
    partial: &mut Partial,
    bar: &ProgressBar,
    path: &Path,
) -> Result<()> {
    let grid = &run.recorded.grid;
    let range = run.recorded.rows.clone();
    let chunk = args.chunk_rows.map_or(DEFAULT_CHUNK, |n| n as usize);
    let done = partial.rows_done(run.recorded)?;
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
    Ok(())
}

/// The map of the complete partial file, then the output: for CSV the
/// partial file itself, renamed into place (it holds the output's bytes;
/// a rename needs no room on the disk, where a copy needs as much again);
/// for Parquet the rows converted through `sink`, and the partial file
/// removed once the output is in place.
fn finish(
    run: &Run,
    mut partial: Partial,
    sink: Sink,
    plot: Option<(super::sweep_plot::Plan, Sink)>,
) -> Result<()> {
    let shown = partial.path().display().to_string();
    let name = sink.name();
    if let Some((plan, plot)) = plot {
        partial
            .file
            .seek(SeekFrom::Start(0))
            .with_context(|| format!("reading {shown}"))?;
        super::sweep_plot::draw(plan, &run.recorded.grid, &partial.file, plot)?;
    }
    match run.format {
        SweepFormat::Csv => {
            let path = partial.path().to_path_buf();
            sink.commit_by_rename(&partial.file, &path)
                .with_context(|| format!("writing {name}"))?;
            Ok(())
        }
        #[cfg(feature = "parquet")]
        SweepFormat::Parquet => {
            let mut header = vec![0u8; partial.header_len as usize];
            partial.file.seek(SeekFrom::Start(0))?;
            io::Read::read_exact(&mut partial.file, &mut header)?;
            partial.file.seek(SeekFrom::Start(0))?;
            let header = String::from_utf8_lossy(&header).into_owned();
            let sink = snowroll_io::parquet::write(&partial.file, &header, sink)
                .with_context(|| format!("writing {name}"))?;
            sink.commit().with_context(|| format!("writing {name}"))?;
            partial.remove()
        }
        #[cfg(not(feature = "parquet"))]
        SweepFormat::Parquet => bail!("this snowroll was built without Parquet"),
    }
}

/// Runs `range` and writes its rows as CSV records to `out`, calling
/// `after_chunk` after each chunk.
fn write_rows(
    grid: &Grid,
    range: Range<u64>,
    chunk: usize,
    method: Method,
    out: &mut (impl Write + Send),
    bar: &ProgressBar,
    mut after_chunk: impl FnMut() -> io::Result<()> + Send,
) -> Result<()> {
    // Each task formats its rows as it computes them (formatting is a fair
    // part of a fast row's cost); the text is written in grid order while
    // the next chunk is computed.
    run_folded(
        grid,
        range,
        (chunk, PART_ROWS),
        method,
        || (SweepCsv::new(), Vec::with_capacity(PART_ROWS * 200)),
        |(csv, buf), row| -> Result<()> { Ok(csv.write(buf, row)?) },
        |parts, rows| -> Result<()> {
            for (_, buf) in parts {
                out.write_all(&buf)?;
            }
            out.flush()?;
            after_chunk()?;
            bar.inc(rows);
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

/// The command line a sweep with `args` records (`# command:`): `snowroll
/// sweep`, then `--grid`, the axes, `--output`, `--method`, `--format` and
/// `--shard` as given, each word quoted for a shell ([`shell_word`]), in
/// this order whatever order they were typed in. `--resume`, `--quiet`,
/// `--plot` and `--chunk-rows` are not recorded: the rows do not depend on
/// them. `snowroll merge` writes the one of the sweep its shards make up.
pub fn command_line(args: &SweepArgs) -> String {
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
    command
}

/// The `#` lines and the column names: everything a resumed run or a merge
/// checks, plus the command line (which they do not): `recorded`, the one a
/// `--config` file holds, when the run is that file's own; else `args`'.
fn header(
    args: &SweepArgs,
    recorded: Option<&str>,
    grid: &Grid,
    (shard, shards): (u64, u64),
    range: &Range<u64>,
    warned: u64,
) -> String {
    let command = recorded.map_or_else(|| command_line(args), str::to_string);
    header_text(VERSION, &command, grid, (shard, shards), range, warned)
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
