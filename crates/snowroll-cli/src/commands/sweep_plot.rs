//! `snowroll sweep --plot map.svg`: the regime map of the finished rows.

use std::io::Read;
use std::path::Path;

use anyhow::{anyhow, Context, Result};
use snowroll::sweep::{AxisParam, Grid, SweepRow};
use snowroll_io::VERSION;
use snowroll_report::plot::{ColorBy, Provenance, RegimeMap};

use crate::args::{OutputArgs, SweepArgs};
use crate::sink::Sink;

/// The two plotted parameters: the flags, or the first swept axes with two
/// or more values, in grid order.
fn plane(args: &SweepArgs, grid: &Grid) -> Result<(AxisParam, AxisParam)> {
    let named = |flag: &str, text: &Option<String>| -> Result<Option<AxisParam>> {
        text.as_deref()
            .map(|t| {
                AxisParam::from_key(t).ok_or_else(|| {
                    anyhow!(
                        "{flag} {t:?}: expected one of {}",
                        AxisParam::ALL.map(AxisParam::key).join(", ")
                    )
                })
            })
            .transpose()
    };
    let x = named("--plot-x", &args.plot_x)?;
    let y = named("--plot-y", &args.plot_y)?;
    let mut swept = grid
        .axes()
        .iter()
        .filter(|a| a.values.len() >= 2)
        .map(|a| a.param)
        .filter(|p| Some(*p) != x && Some(*p) != y);
    let x = match x {
        Some(p) => p,
        None => swept.next().ok_or_else(|| {
            anyhow!("--plot: a map needs two parameters swept over two or more values")
        })?,
    };
    let y = match y {
        Some(p) => p,
        None => swept.next().ok_or_else(|| {
            anyhow!("--plot: a map needs two parameters swept over two or more values")
        })?,
    };
    Ok((x, y))
}

/// What `--plot` draws: the plane and the colouring.
#[derive(Debug, Clone, Copy)]
pub struct Plan {
    x: AxisParam,
    y: AxisParam,
    color: ColorBy,
}

/// Checks the `--plot*` flags against the grid before anything runs.
pub fn plan(args: &SweepArgs, grid: &Grid) -> Result<Plan> {
    let (x, y) = plane(args, grid)?;
    // Everything the map needs of the grid, before any row is computed.
    RegimeMap::check_plane(grid, x, y).context("--plot")?;
    let color = match args.plot_color.as_deref() {
        None => ColorBy::Outcome,
        Some(key) => ColorBy::from_key(key).ok_or_else(|| {
            anyhow!(
                "--plot-color {key:?}: expected one of {}",
                ColorBy::ALL.map(ColorBy::key).join(", ")
            )
        })?,
    };
    Ok(Plan { x, y, color })
}

/// Opens the map's output `path` (a temporary file beside it) before any
/// row is computed, so that a path that cannot be written (a missing
/// directory, a read-only one) is refused at once, not after the rows.
pub fn open(path: &Path) -> Result<Sink> {
    Sink::open(&OutputArgs {
        format: None,
        output: Some(path.to_path_buf()),
        config: None,
        plot: None,
    })
}

/// Reads the rows of the sweep CSV `csv` (its `#` header included), draws
/// their map and writes it to `sink` (opened by [`open`]; a temporary
/// file, renamed).
pub fn draw(plan: Plan, grid: &Grid, csv: impl Read, mut sink: Sink) -> Result<()> {
    let Plan { x, y, color } = plan;
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(csv);
    let rows = reader
        .deserialize::<SweepRow>()
        .collect::<Result<Vec<_>, _>>()
        .context("reading the rows back for --plot")?;
    let map = RegimeMap::from_rows(grid, &rows, x, y, color).context("--plot")?;
    let mut params = vec![(
        "model".to_string(),
        grid.models()
            .iter()
            .map(|m| m.id())
            .collect::<Vec<_>>()
            .join(","),
    )];
    for axis in grid.axes() {
        params.push((axis.param.key().to_string(), axis.values.to_string()));
    }
    let provenance = Provenance {
        software: format!("snowroll {VERSION}"),
        params,
    };
    let svg = map.render_svg(&provenance)?;
    let name = sink.name();
    std::io::Write::write_all(&mut sink, svg.as_bytes())
        .with_context(|| format!("writing {name}"))?;
    sink.commit().with_context(|| format!("writing {name}"))?;
    Ok(())
}
