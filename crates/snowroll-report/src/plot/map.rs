//! Regime maps: the rows of a sweep as coloured cells over two swept
//! parameters, coloured by [`Outcome`] or by a result column, with the
//! closed-form borders of [`boundaries`] drawn over them.
//!
//! A [`RegimeMap`] is plain data (cells, classes, curves) built from rows by
//! [`RegimeMap::from_rows`]; it never runs a simulation.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::render::{register_embedded_font, tick, FAMILY};
use super::{Axis, Chart, Legend, PlotError, Provenance, Scale, Series, Style};
use snowroll::sweep::{boundaries, Grid, Outcome, Param, SweepRow};

/// What colours the cells.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColorBy {
    /// The [`Outcome`] of each row.
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
    SameAxis(Param),
    /// An axis is not swept with at least two values.
    #[error("{0} is not swept over at least two values: a map needs two such axes")]
    NotSwept(Param),
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
        x: Param,
        /// The plotted parameters.
        y: Param,
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
}

/// Fill colours of the outcomes (colour-blind aware, stalls in shades of
/// one hue by turn).
fn outcome_rgb(o: Outcome) -> (u8, u8, u8) {
    match o {
        Outcome::NeverStarts => (120, 120, 120),
        Outcome::Stalls { turn } => {
            let shade = (turn.min(6) * 22) as u8;
            (200u8.saturating_sub(shade / 2), 150 + shade / 2, 230)
        }
        Outcome::RollsOn => (166, 219, 160),
        Outcome::Hops => (253, 174, 97),
        Outcome::Slips => (215, 48, 39),
        Outcome::Stuck => (118, 42, 131),
        Outcome::Failed => (0, 0, 0),
    }
}

/// Seven steps of a sequential colour scale (viridis), low to high.
const SCALE: [(u8, u8, u8); 7] = [
    (68, 1, 84),
    (68, 57, 131),
    (49, 104, 142),
    (33, 145, 140),
    (53, 183, 121),
    (144, 215, 67),
    (253, 231, 37),
];

/// The axis of a parameter: label and unit as in `--help`, logarithmic when
/// its values are positive and span two decades or more.
fn param_axis(p: Param, values: &[f64]) -> Axis {
    let (label, unit) = match p {
        Param::AlphaDeg => ("slope angle α", "deg"),
        Param::SnowDepth => ("snow depth b", "m"),
        Param::R0 => ("initial radius r0", "m"),
        Param::G => ("gravitational acceleration g", "m/s²"),
        Param::Density => ("density ρ", "kg/m³"),
        Param::Length => ("length l", "m"),
        Param::V0 => ("initial speed v0", "m/s"),
        Param::TEnd => ("end time", "s"),
        Param::XEnd => ("end distance", "m"),
        Param::Rtol => ("relative tolerance", "1"),
        Param::Atol => ("absolute tolerance", "1"),
        Param::Mu => ("friction coefficient μ", "1"),
    };
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let axis = if lo > 0.0 && hi / lo >= 100.0 {
        Axis::log(label, unit)
    } else {
        Axis::linear(label, unit)
    };
    axis.column(p.key())
}

/// The edges of the cells around sorted distinct `values`: halfway between
/// neighbours (geometric mean on a log axis), the outer cells as wide as
/// their inner neighbours.
fn edges(values: &[f64], log: bool) -> Vec<f64> {
    let mid = |a: f64, b: f64| if log { (a * b).sqrt() } else { 0.5 * (a + b) };
    let mut e = Vec::with_capacity(values.len() + 1);
    let n = values.len();
    let outer = |v: f64, inner: f64| if log { v * v / inner } else { 2.0 * v - inner };
    e.push(outer(values[0], mid(values[0], values[1])));
    for w in values.windows(2) {
        e.push(mid(w[0], w[1]));
    }
    e.push(outer(values[n - 1], mid(values[n - 2], values[n - 1])));
    e
}

/// Sorted distinct values (bit-exact, as the grid produced them).
fn distinct(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| a.to_bits() == b.to_bits());
    v
}

impl RegimeMap {
    /// Whether a map of `grid` over `x` × `y` can be drawn, decided from the
    /// grid alone, so that a sweep can refuse `--plot` before it runs: two
    /// different parameters, each swept over two or more values, and no
    /// other swept setting or second model (one row per cell).
    ///
    /// # Errors
    /// [`MapError::SameAxis`], [`MapError::NotSwept`], [`MapError::NotAPlane`].
    pub fn check_plane(grid: &Grid, x: Param, y: Param) -> Result<(), MapError> {
        if x == y {
            return Err(MapError::SameAxis(x));
        }
        let count = |p: Param| {
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
        x: Param,
        y: Param,
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
        let find = |v: &[f64], t: f64| v.iter().position(|u| u.to_bits() == t.to_bits());

        // Classes.
        let mut classes: Vec<Class> = Vec::new();
        let mut class_of_row: Vec<usize> = Vec::with_capacity(rows.len());
        if color == ColorBy::Outcome {
            let mut outcomes: Vec<Outcome> = rows.iter().map(Outcome::of).collect();
            outcomes.sort();
            outcomes.dedup();
            classes = outcomes
                .iter()
                .map(|o| Class {
                    label: o.to_string(),
                    rgb: outcome_rgb(*o),
                })
                .collect();
            for r in rows {
                let o = Outcome::of(r);
                class_of_row.push(outcomes.iter().position(|u| *u == o).unwrap_or(0));
            }
        } else {
            let values: Vec<Option<f64>> = rows.iter().map(|r| color.value(r)).collect();
            let (lo, hi) = values
                .iter()
                .flatten()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                    (lo.min(v), hi.max(v))
                });
            let bins = if lo < hi { SCALE.len() } else { 1 };
            let width = (hi - lo) / bins as f64;
            for (k, rgb) in SCALE.iter().enumerate().take(bins) {
                let (a, b) = (lo + width * k as f64, lo + width * (k + 1) as f64);
                let label = if bins == 1 {
                    format!("{} = {}", color.key(), tick(lo))
                } else {
                    format!("{} ≤ {} < {}", tick(a), color.key(), tick(b))
                };
                classes.push(Class { label, rgb: *rgb });
            }
            let none = classes.len();
            classes.push(Class {
                label: format!("no {}", color.key()),
                rgb: (200, 200, 200),
            });
            for v in values {
                class_of_row.push(match v {
                    Some(v) if bins > 1 => (((v - lo) / width) as usize).min(bins - 1),
                    Some(_) => 0,
                    None => none,
                });
            }
        }

        // Cells, one per row.
        let mut owner: Vec<Option<u64>> = vec![None; xs.len() * ys.len()];
        let mut cells = Vec::with_capacity(rows.len());
        for (r, class) in rows.iter().zip(class_of_row) {
            let (Some(i), Some(j)) = (find(&xs, r.param(x)), find(&ys, r.param(y))) else {
                continue;
            };
            let slot = &mut owner[j * xs.len() + i];
            if let Some(first) = *slot {
                return Err(MapError::SharedCell {
                    first,
                    second: r.index,
                });
            }
            *slot = Some(r.index);
            cells.push(Cell {
                x: (xe[i], xe[i + 1]),
                y: (ye[j], ye[j + 1]),
                class,
            });
        }
        // Only the borders that cross the drawn range (a stall slope below
        // the smallest α drawn would be a legend entry with no line).
        let (lo_x, hi_x) = (xe[0].min(xe[xs.len()]), xe[0].max(xe[xs.len()]));
        let (lo_y, hi_y) = (ye[0].min(ye[ys.len()]), ye[0].max(ye[ys.len()]));
        let curves = boundaries(grid, rows, x, y)
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
            .collect();
        let models: Vec<&str> = grid.models().iter().map(|m| m.id()).collect();
        let title = if color == ColorBy::Outcome {
            format!("Regimes of {}", models.join(", "))
        } else {
            format!("{} of {}", color.key(), models.join(", "))
        };
        Ok(RegimeMap {
            title,
            x: x_axis,
            y: y_axis,
            cells,
            classes,
            curves,
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
        let mut chart = Chart::new(name, &self.title, self.x.clone(), self.y.clone())
            .with_legend(Legend::UpperRight);
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

    /// The drawn range of both axes: the cells' outer edges.
    fn ranges(&self) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
        let mut r = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for c in &self.cells {
            r = (
                r.0.min(c.x.0),
                r.1.max(c.x.1),
                r.2.min(c.y.0),
                r.3.max(c.y.1),
            );
        }
        (r.0..r.1, r.2..r.3)
    }

    /// Renders the map as SVG: cells, borders, legend (classes then borders),
    /// axis labels with units, and `provenance` as footer and comment.
    ///
    /// # Errors
    /// [`PlotError`] when drawing fails or the map has no cell.
    pub fn render_svg(&self, provenance: &Provenance) -> Result<String, PlotError> {
        if self.cells.is_empty() {
            return Err(PlotError::NoDrawablePoints {
                chart: "regime-map".to_string(),
            });
        }
        register_embedded_font()?;
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, MAP_SIZE).into_drawing_area();
            root.fill(&WHITE).map_err(backend)?;
            let (_, height) = root.dim_in_pixel();
            let (main, footer) = root.split_vertically(height.saturating_sub(26));
            footer
                .draw_text(
                    &provenance.line(),
                    &(FAMILY, 13).into_font().color(&RGBColor(90, 90, 90)),
                    (12, 4),
                )
                .map_err(backend)?;
            let (xr, yr) = self.ranges();
            match (self.x.scale, self.y.scale) {
                (Scale::Linear, Scale::Linear) => self.draw_in(&main, xr, yr),
                (Scale::Linear, Scale::Log) => self.draw_in(&main, xr, yr.log_scale()),
                (Scale::Log, Scale::Linear) => self.draw_in(&main, xr.log_scale(), yr),
                (Scale::Log, Scale::Log) => self.draw_in(&main, xr.log_scale(), yr.log_scale()),
            }?;
            root.present().map_err(backend)?;
        }
        Ok(super::render::with_provenance_comment(
            svg,
            &["regime map", &self.title, &provenance.line()],
        ))
    }

    fn draw_in<'a, DB, XR, YR>(
        &self,
        area: &'a DrawingArea<DB, Shift>,
        xr: XR,
        yr: YR,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        XR: AsRangedCoord<Value = f64>,
        YR: AsRangedCoord<Value = f64>,
        XR::CoordDescType: ValueFormatter<f64>,
        YR::CoordDescType: ValueFormatter<f64>,
    {
        let font = |size: u32| (FAMILY, size).into_font();
        let (plot, legend) = area.split_horizontally(MAP_SIZE.0 - LEGEND_WIDTH);
        let mut chart = ChartBuilder::on(&plot)
            .caption(&self.title, font(24))
            .margin(14)
            .x_label_area_size(58)
            .y_label_area_size(86)
            .build_cartesian_2d(xr, yr)
            .map_err(backend)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(self.x.title())
            .y_desc(self.y.title())
            .axis_desc_style(font(20))
            .label_style(font(16))
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .draw()
            .map_err(backend)?;
        for c in &self.cells {
            let (r, g, b) = self.classes[c.class].rgb;
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(c.x.0, c.y.0), (c.x.1, c.y.1)],
                    RGBColor(r, g, b).filled(),
                )))
                .map_err(backend)?;
        }
        for (k, (_, points)) in self.curves.iter().enumerate() {
            let colour = CURVE_COLOURS[k % CURVE_COLOURS.len()];
            let style = ShapeStyle::from(colour).stroke_width(3);
            let inside = points.clone();
            if k % 2 == 0 {
                chart.draw_series(LineSeries::new(inside, style))
            } else {
                chart.draw_series(DashedLineSeries::new(inside, 10, 6, style))
            }
            .map_err(backend)?;
        }
        // The legend: a swatch per class, a line per border, in the right margin.
        let mut y = 60;
        legend
            .draw_text("legend", &font(17).into(), (8, y - 30))
            .map_err(backend)?;
        for class in &self.classes {
            let (r, g, b) = class.rgb;
            legend
                .draw(&Rectangle::new(
                    [(8, y), (30, y + 16)],
                    RGBColor(r, g, b).filled(),
                ))
                .map_err(backend)?;
            legend
                .draw(&Text::new(class.label.clone(), (38, y), font(14)))
                .map_err(backend)?;
            y += 24;
        }
        y += 10;
        for (k, (label, _)) in self.curves.iter().enumerate() {
            let colour = CURVE_COLOURS[k % CURVE_COLOURS.len()];
            legend
                .draw(&PathElement::new(
                    vec![(8, y + 8), (30, y + 8)],
                    ShapeStyle::from(colour).stroke_width(3),
                ))
                .map_err(backend)?;
            for (n, line) in wrap(label, LEGEND_CHARS).iter().enumerate() {
                legend
                    .draw(&Text::new(line.clone(), (38, y + 18 * n as i32), font(14)))
                    .map_err(backend)?;
            }
            y += 18 * wrap(label, LEGEND_CHARS).len() as i32 + 8;
        }
        Ok(())
    }
}

/// Size of a map, px: wider than a chart, for the legend column.
const MAP_SIZE: (u32, u32) = (1200, 640);
/// Width of the legend column, px.
const LEGEND_WIDTH: u32 = 300;
/// Characters per legend line.
const LEGEND_CHARS: usize = 34;
/// Colours of the borders: dark and distinct from the cell fills.
const CURVE_COLOURS: [RGBColor; 4] = [
    RGBColor(0, 0, 0),
    RGBColor(31, 70, 180),
    RGBColor(150, 0, 90),
    RGBColor(90, 60, 0),
];

/// `text` broken at spaces into lines of at most `width` characters.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let last = lines.len() - 1;
        if !lines[last].is_empty() && lines[last].chars().count() + 1 + word.chars().count() > width
        {
            lines.push(String::new());
        }
        let last = lines.len() - 1;
        if !lines[last].is_empty() {
            lines[last].push(' ');
        }
        lines[last].push_str(word);
    }
    lines
}

fn backend(e: impl std::fmt::Display) -> PlotError {
    PlotError::Backend {
        chart: "regime-map".to_string(),
        reason: e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cell_edges_lie_halfway_and_outer_cells_match_their_neighbours() {
        let e = edges(&[1.0, 2.0, 4.0], false);
        assert_eq!(format!("{e:?}"), "[0.5, 1.5, 3.0, 5.0]");
        // Log axis: geometric means, 1 → 10 → 100 gives edges √10 apart.
        let e = edges(&[1.0, 10.0, 100.0], true);
        for (got, want) in e.iter().zip([
            10f64.powf(-0.5),
            10f64.powf(0.5),
            10f64.powf(1.5),
            10f64.powf(2.5),
        ]) {
            assert!((got / want - 1.0).abs() < 1e-14, "{got} {want}");
        }
    }

    #[test]
    fn legend_lines_wrap_at_spaces() {
        assert_eq!(wrap("a bb ccc", 4), vec!["a bb", "ccc"]);
    }
}
