//! Regime maps: the rows of a sweep as coloured cells over two swept
//! parameters, coloured by [`Outcome`](snowroll::sweep::Outcome) or by a result column, with the
//! closed-form borders of [`boundaries`] drawn over them.
//!
//! A [`RegimeMap`] is plain data (cells, classes, curves) built from rows by
//! [`RegimeMap::from_rows`]; it never runs a simulation.

mod cells;
mod draw;

use super::{Axis, Chart, Scale, Series, Style};
use cells::{classes_of, distinct, edges, param_axis, place_cells};
use snowroll::sweep::{boundaries, AxisParam, Grid, SweepRow};

/// What colours the cells.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColorBy {
    /// The [`Outcome`](snowroll::sweep::Outcome) of each row.
    #[default]
    Outcome,
    /// Time at the end, s (`t_s`).
    TimeS,
    /// Distance at the end, m (`x_m`).
    XM,
    /// Speed at the end, m/s (`v_m_s`).
    VMS,
    /// Acceleration at the end over g sin α (`a_over_g_sin_alpha`).
    AOverGSinAlpha,
    /// Turns completed (`turns`).
    Turns,
}

impl ColorBy {
    /// Every choice, outcome first.
    pub const ALL: [ColorBy; 6] = [
        ColorBy::Outcome,
        ColorBy::TimeS,
        ColorBy::XM,
        ColorBy::VMS,
        ColorBy::AOverGSinAlpha,
        ColorBy::Turns,
    ];

    /// The column name (`outcome` for the outcome).
    pub fn key(self) -> &'static str {
        match self {
            ColorBy::Outcome => "outcome",
            ColorBy::TimeS => "t_s",
            ColorBy::XM => "x_m",
            ColorBy::VMS => "v_m_s",
            ColorBy::AOverGSinAlpha => "a_over_g_sin_alpha",
            ColorBy::Turns => "turns",
        }
    }

    /// What the column measures, its symbol and its unit (`1` for a pure
    /// number): `("speed at the end", "v", "m/s")`; `None` for the outcome.
    pub fn quantity(self) -> Option<(&'static str, &'static str, &'static str)> {
        match self {
            ColorBy::Outcome => None,
            ColorBy::TimeS => Some(("time at the end", "t", "s")),
            ColorBy::XM => Some(("distance at the end", "x", "m")),
            ColorBy::VMS => Some(("speed at the end", "v", "m/s")),
            ColorBy::AOverGSinAlpha => Some(("acceleration at the end", "a/(g sin α)", "1")),
            ColorBy::Turns => Some(("turns completed", "turns", "1")),
        }
    }

    /// The title of the colour legend: `v [m/s]`, `a/(g sin α)`, `outcome`.
    pub fn legend_title(self) -> String {
        match self.quantity() {
            None => "outcome".to_string(),
            Some((_, sym, "1")) => sym.to_string(),
            Some((_, sym, unit)) => format!("{sym} [{unit}]"),
        }
    }

    /// The choice of a column name.
    pub fn from_key(key: &str) -> Option<ColorBy> {
        ColorBy::ALL.into_iter().find(|c| c.key() == key)
    }

    fn value(self, row: &SweepRow) -> Option<f64> {
        match self {
            ColorBy::Outcome => None,
            ColorBy::TimeS => row.t_s,
            ColorBy::XM => row.x_m,
            ColorBy::VMS => row.v_m_s,
            ColorBy::AOverGSinAlpha => row.a_over_g_sin_alpha,
            ColorBy::Turns => row.turns.map(|k| k as f64),
        }
        .filter(|v| v.is_finite())
    }
}

/// A map that cannot be made from the rows.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MapError {
    /// The two axes are the same parameter.
    #[error("the map needs two different parameters, got {0} twice")]
    SameAxis(AxisParam),
    /// An axis is not swept with at least two values.
    #[error("{0} is not swept over at least two values: a map needs two such axes")]
    NotSwept(AxisParam),
    /// Two rows fall in the same cell.
    #[error(
        "rows {first} and {second} fall in the same cell of the map: sweep only the two plotted \
         parameters (one model, one value of every other setting)"
    )]
    SharedCell {
        /// Index of the first row.
        first: u64,
        /// Index of the second row.
        second: u64,
    },
    /// The grid has points outside the plane: other swept settings or
    /// several models would put several rows in each cell.
    #[error(
        "the grid has {points} points but the {x} × {y} plane has {cells} cells: sweep only the two \
         plotted parameters (one model, one value of every other setting)"
    )]
    NotAPlane {
        /// The plotted parameters.
        x: AxisParam,
        /// The plotted parameters.
        y: AxisParam,
        /// Points of the grid.
        points: u64,
        /// Cells of the plane.
        cells: u64,
    },
    /// No row.
    #[error("no row to draw")]
    NoRows,
}

/// One cell: a rectangle in data coordinates and its class.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// Left and right edges.
    pub x: (f64, f64),
    /// Bottom and top edges.
    pub y: (f64, f64),
    /// Index into [`RegimeMap::classes`].
    pub class: usize,
}

/// One legend entry and its colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Class {
    /// Legend text.
    pub label: String,
    /// Fill colour, RGB.
    pub rgb: (u8, u8, u8),
}

/// A regime map ready to draw.
#[derive(Debug, Clone, PartialEq)]
pub struct RegimeMap {
    /// Title drawn above the map.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// The cells.
    pub cells: Vec<Cell>,
    /// The classes the cells use, in legend order.
    pub classes: Vec<Class>,
    /// Closed-form borders: legend text and curve.
    pub curves: Vec<(String, Vec<(f64, f64)>)>,
    /// Title of the colour legend: the quantity and its unit (`v [m/s]`).
    pub legend_title: String,
}

impl RegimeMap {
    /// Whether a map of `grid` over `x` × `y` can be drawn, decided from the
    /// grid alone, so that a sweep can refuse `--plot` before it runs: two
    /// different parameters, each swept over two or more values, and no
    /// other swept setting or second model (one row per cell).
    ///
    /// # Errors
    /// [`MapError::SameAxis`], [`MapError::NotSwept`], [`MapError::NotAPlane`].
    pub fn check_plane(grid: &Grid, x: AxisParam, y: AxisParam) -> Result<(), MapError> {
        if x == y {
            return Err(MapError::SameAxis(x));
        }
        let count = |p: AxisParam| {
            grid.axes()
                .iter()
                .find(|a| a.param == p)
                .map_or(0, |a| a.values.len())
        };
        let (nx, ny) = (count(x), count(y));
        for (p, n) in [(x, nx), (y, ny)] {
            if n < 2 {
                return Err(MapError::NotSwept(p));
            }
        }
        if grid.len() != nx.saturating_mul(ny) {
            return Err(MapError::NotAPlane {
                x,
                y,
                points: grid.len(),
                cells: nx.saturating_mul(ny),
            });
        }
        Ok(())
    }
    /// The map of `rows` (from `grid`) over parameters `x` and `y`,
    /// coloured by `color`, with the closed-form borders of
    /// [`boundaries`].
    ///
    /// # Errors
    /// [`MapError`]: the same parameter twice, an axis that is not swept, two
    /// rows in one cell, no rows.
    pub fn from_rows(
        grid: &Grid,
        rows: &[SweepRow],
        x: AxisParam,
        y: AxisParam,
        color: ColorBy,
    ) -> Result<RegimeMap, MapError> {
        if x == y {
            return Err(MapError::SameAxis(x));
        }
        if rows.is_empty() {
            return Err(MapError::NoRows);
        }
        let xs = distinct(rows.iter().map(|r| r.param(x)).collect());
        let ys = distinct(rows.iter().map(|r| r.param(y)).collect());
        for (p, v) in [(x, &xs), (y, &ys)] {
            if v.len() < 2 || v.iter().any(|t| !t.is_finite()) {
                return Err(MapError::NotSwept(p));
            }
        }
        let (x_axis, y_axis) = (param_axis(x, &xs), param_axis(y, &ys));
        let xe = edges(&xs, x_axis.scale == Scale::Log);
        let ye = edges(&ys, y_axis.scale == Scale::Log);
        let (classes, class_of_row) = classes_of(rows, color);
        let cells = place_cells(rows, class_of_row, (x, &xs, &xe), (y, &ys, &ye))?;
        Ok(RegimeMap {
            title: map_title(grid, color),
            x: x_axis,
            y: y_axis,
            cells,
            classes,
            curves: borders_inside(grid, rows, (x, &xe), (y, &ye)),
            legend_title: color.legend_title(),
        })
    }

    /// The map as a [`Chart`] named `name`, for the report: one marker
    /// series per class at the cells' centres (geometric on a log axis), one
    /// line per border.
    pub fn to_chart(&self, name: &str) -> Chart {
        let centre = |(a, b): (f64, f64), scale: Scale| match scale {
            Scale::Log => (a * b).sqrt(),
            Scale::Linear => 0.5 * (a + b),
        };
        let mut chart = Chart::new(name, &self.title, self.x.clone(), self.y.clone());
        for (k, class) in self.classes.iter().enumerate() {
            let points: Vec<(f64, f64)> = self
                .cells
                .iter()
                .filter(|c| c.class == k)
                .map(|c| (centre(c.x, self.x.scale), centre(c.y, self.y.scale)))
                .collect();
            if !points.is_empty() {
                chart = chart.with_series(Series::new(&class.label, points).style(Style::Markers));
            }
        }
        for (k, (label, points)) in self.curves.iter().enumerate() {
            let style = if k % 2 == 0 {
                Style::Line
            } else {
                Style::Dashed
            };
            chart = chart.with_series(Series::new(label, points.clone()).style(style));
        }
        chart
    }
}

/// The closed-form borders of [`boundaries`] over `x` × `y`, each cut to the
/// drawn range (the cells' outer `edges` on each axis); only those that cross
/// it (a stall slope below the smallest α drawn would be a legend entry with
/// no line).
fn borders_inside(
    grid: &Grid,
    rows: &[SweepRow],
    (x, xe): (AxisParam, &[f64]),
    (y, ye): (AxisParam, &[f64]),
) -> Vec<(String, Vec<(f64, f64)>)> {
    let (nx, ny) = (xe.len() - 1, ye.len() - 1);
    let (lo_x, hi_x) = (xe[0].min(xe[nx]), xe[0].max(xe[nx]));
    let (lo_y, hi_y) = (ye[0].min(ye[ny]), ye[0].max(ye[ny]));
    boundaries(grid, rows, x, y)
        .into_iter()
        .map(|b| {
            let inside: Vec<(f64, f64)> = b
                .points
                .into_iter()
                .filter(|&(x, y)| x >= lo_x && x <= hi_x && y >= lo_y && y <= hi_y)
                .collect();
            (b.label, inside)
        })
        .filter(|(_, points)| points.len() >= 2)
        .collect()
}

/// The map's title: the regimes (or the coloured column) of the grid's models.
fn map_title(grid: &Grid, color: ColorBy) -> String {
    let models: Vec<&str> = grid.models().iter().map(|m| m.id()).collect();
    if color == ColorBy::Outcome {
        format!("Regimes of {}", models.join(", "))
    } else {
        let (what, _, _) = color.quantity().unwrap_or(("value", "", "1"));
        format!("{what}, {}, of {}", color.legend_title(), models.join(", "))
    }
}
