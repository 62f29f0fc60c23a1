//! Figures: a small chart description rendered to SVG and PNG with
//! `plotters` (feature `plot`).
//!
//! A [`Chart`] is plain data: a title, two [`Axis`] descriptions (label, unit,
//! linear or logarithmic [`Scale`]) and named [`Series`] of `(x, y)` points.
//! Charts only read numbers (for instance the samples of a
//! [`Trajectory`](snowroll::Trajectory), see [`Series::from_samples`]); they
//! never run a simulation.
//!
//! Text is drawn with the DejaVu Sans font embedded in the library
//! (`assets/fonts/`, Bitstream Vera licence), registered with `plotters` on
//! first use, so rendering needs no system font and no fontconfig. Every
//! [`RegimeMap`] draws the rows of a sweep as cells over two parameters.
//! Every figure carries a title, axis labels with units, a legend and a footer
//! naming the program version and the parameters ([`Provenance`]); the SVG
//! also records them in a comment and the PNG in `iTXt` chunks.

mod error;
mod font;
mod legend;
mod map;
mod panels;
mod render;
mod ticks;

pub use error::PlotError;
pub use font::register_embedded_font;
#[cfg(feature = "comment")]
pub(crate) use font::FONT;
pub use map::{Cell, Class, ColorBy, MapError, RegimeMap};
pub use panels::{render_panels_png, render_panels_svg};
pub use render::{png_size, FIGURE_SIZE, PAGE_WIDTH, PNG_SCALE, SVG_OVERSAMPLE};

use snowroll::trajectory::Sample;

/// How an axis maps values to positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Scale {
    /// Evenly spaced values.
    #[default]
    Linear,
    /// Evenly spaced powers of ten; only positive values are drawn.
    Log,
}

/// One axis: what it shows, in which unit, on which scale.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// What the axis shows, e.g. `time t`.
    pub label: String,
    /// Its unit, e.g. `s`; `1` for a dimensionless ratio.
    pub unit: String,
    /// Linear or logarithmic.
    pub scale: Scale,
    /// Column name of this axis in the figure's CSV, e.g. `t_s`.
    pub column: String,
    /// The share of the drawn length left empty after the last data, where
    /// more than the usual margin is wanted (a border at the end of the
    /// data must not sit at the frame); `None`: the usual margin.
    pub margin_after: Option<f64>,
}

impl Axis {
    /// A linear axis; its CSV column name is derived from label and unit.
    pub fn linear(label: &str, unit: &str) -> Self {
        Self {
            label: label.to_string(),
            unit: unit.to_string(),
            scale: Scale::Linear,
            column: column_name(label, unit),
            margin_after: None,
        }
    }

    /// A logarithmic axis; its CSV column name is derived from label and unit.
    pub fn log(label: &str, unit: &str) -> Self {
        Self {
            scale: Scale::Log,
            ..Self::linear(label, unit)
        }
    }

    /// Sets the CSV column name.
    pub fn column(mut self, column: &str) -> Self {
        self.column = column.to_string();
        self
    }

    /// The label as drawn: `label [unit]`, or `label` alone for a
    /// dimensionless ratio (unit `1`).
    pub fn title(&self) -> String {
        if self.unit.trim() == "1" {
            self.label.clone()
        } else {
            format!("{} [{}]", self.label, self.unit)
        }
    }

    /// Whether `v` can be placed on this axis.
    pub fn accepts(&self, v: f64) -> bool {
        v.is_finite() && (self.scale == Scale::Linear || v > 0.0)
    }
}

/// A CSV-friendly column name: ASCII letters and digits of `label`, then the unit.
fn column_name(label: &str, unit: &str) -> String {
    let clean = |s: &str| {
        let mut out = String::new();
        for c in s.chars() {
            if c.is_ascii_alphanumeric() {
                out.push(c.to_ascii_lowercase());
            } else if !out.ends_with('_') && !out.is_empty() {
                out.push('_');
            }
        }
        out.trim_end_matches('_').to_string()
    };
    let (l, u) = (clean(label), clean(unit));
    match (l.is_empty(), u.is_empty() || u == "1") {
        (true, _) => "value".to_string(),
        (false, true) => l,
        (false, false) => format!("{l}_{u}"),
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Style {
    /// A solid line.
    #[default]
    Line,
    /// A dashed line (to tell apart curves that lie on top of each other).
    Dashed,
    /// A line of long dashes.
    LongDashed,
    /// A dotted line (short dashes close together).
    Dotted,
    /// A marker at each point, no line.
    Markers,
}

impl Style {
    /// Every style, in the order a chart hands them out.
    pub const ALL: [Style; 5] = [
        Style::Line,
        Style::Dashed,
        Style::LongDashed,
        Style::Dotted,
        Style::Markers,
    ];

    /// Dash and gap lengths of a broken line, px at [`FIGURE_SIZE`]; `None`
    /// for a solid line or markers.
    pub fn dash_pattern(self) -> Option<(f64, f64)> {
        match self {
            Style::Dashed => Some((10.0, 6.0)),
            Style::LongDashed => Some((22.0, 7.0)),
            Style::Dotted => Some((3.0, 5.0)),
            Style::Line | Style::Markers => None,
        }
    }
}

/// The shape of a series' markers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Marker {
    /// A filled circle.
    #[default]
    Circle,
    /// A filled triangle.
    Triangle,
    /// A filled square.
    Square,
}

/// The note drawn in a figure with no point to show ([`Chart::is_empty`]).
pub const NO_DATA: &str = "no data in this scenario";

/// Markers placed along a line series: this many, spread evenly over its
/// points, so that a curve hidden under another still shows its marks.
pub const MARKS_ON_A_LINE: usize = 14;

/// A named set of `(x, y)` points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<(f64, f64)>,
    /// Line, dashes or markers.
    pub style: Style,
    /// Marker shape: of every point for [`Style::Markers`], else of
    /// [`MARKS_ON_A_LINE`] marks along the line; `None` draws a line without
    /// marks (and circles for [`Style::Markers`]).
    pub marker: Option<Marker>,
    /// Drawn in the colour of the chart's series of this index, an earlier
    /// one (a closed form in the colour of its curve), instead of a colour
    /// of its own.
    pub colour_of: Option<usize>,
}

impl Series {
    /// A solid line through `points`.
    pub fn new(name: &str, points: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.to_string(),
            points,
            style: Style::Line,
            marker: None,
            colour_of: None,
        }
    }

    /// A series read from trajectory samples: `x(sample)`, `y(sample)`.
    pub fn from_samples(
        name: &str,
        samples: &[Sample],
        x: impl Fn(&Sample) -> f64,
        y: impl Fn(&Sample) -> f64,
    ) -> Self {
        Self::new(name, samples.iter().map(|s| (x(s), y(s))).collect())
    }

    /// Sets the drawing style.
    pub fn style(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// Sets the marker shape.
    pub fn marker(mut self, marker: Marker) -> Self {
        self.marker = Some(marker);
        self
    }

    /// Draws the series in the colour of the chart's `k`-th series, an
    /// earlier one: a closed form in the colour of the curve it describes
    /// (dashed, say, beside a solid curve).
    pub fn in_colour_of(mut self, k: usize) -> Self {
        self.colour_of = Some(k);
        self
    }

    /// How the series looks apart from its colour: line style and marker.
    pub fn look(&self) -> (Style, Option<Marker>) {
        (self.style, self.marker)
    }
}

/// Who drew a figure and from which parameters; drawn as the figure's footer
/// and recorded in the SVG comment and the PNG text chunks.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Provenance {
    /// Program and version, e.g. `snowroll 0.1.0`.
    pub software: String,
    /// Parameters as `(key, value)` pairs, keys unit-suffixed (`alpha_deg`).
    pub params: Vec<(String, String)>,
}

impl Provenance {
    /// `snowroll 0.1.0 · alpha_deg = 30, …` on one line.
    pub fn line(&self) -> String {
        let params = self
            .params
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect::<Vec<_>>()
            .join(", ");
        if params.is_empty() {
            self.software.clone()
        } else {
            format!("{} · {params}", self.software)
        }
    }
}

/// A chart: title, axes, series (the legend is drawn beside the plot).
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// File stem of the figure (`figures/NAME.svg`): lower-case letters, digits, `-`, `_`.
    pub name: String,
    /// Title drawn above the plot.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// The data.
    pub series: Vec<Series>,
}

impl Chart {
    /// A chart with no series yet.
    pub fn new(name: &str, title: &str, x: Axis, y: Axis) -> Self {
        Self {
            name: name.to_string(),
            title: title.to_string(),
            x,
            y,
            series: Vec::new(),
        }
    }

    /// Adds a series.
    pub fn with_series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Checks that the chart can be drawn and carries every text a figure
    /// needs. A chart with no series, or none of whose points an axis can
    /// show (a scenario in which the quantity does not arise: no turn
    /// completed, say), is valid: it is drawn as empty axes with the note
    /// [`NO_DATA`] ([`Chart::is_empty`]).
    ///
    /// # Errors
    /// [`PlotError`] naming the first problem.
    pub fn validate(&self) -> Result<(), PlotError> {
        let valid_name = !self.name.is_empty()
            && self
                .name
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-' || c == '_');
        if !valid_name {
            return Err(PlotError::InvalidName {
                name: self.name.clone(),
            });
        }
        let texts = [
            ("title", &self.title),
            ("x-axis label", &self.x.label),
            ("x-axis unit", &self.x.unit),
            ("y-axis label", &self.y.label),
            ("y-axis unit", &self.y.unit),
        ];
        for (field, text) in texts {
            if text.trim().is_empty() {
                return Err(self.missing(field));
            }
        }
        let curves = legend::colours_needed(&self.series);
        if curves > legend::PALETTE.len() {
            return Err(PlotError::TooManyColours {
                chart: self.name.clone(),
                curves,
                colours: legend::PALETTE.len(),
            });
        }
        if self.series.iter().any(|s| s.name.trim().is_empty()) {
            return Err(self.missing("series name"));
        }
        Ok(())
    }

    /// Whether no point of the chart can be drawn (no series, or every
    /// point non-finite or, on a logarithmic axis, not positive): the
    /// figure shows [`NO_DATA`] instead of curves.
    pub fn is_empty(&self) -> bool {
        self.drawable_points().next().is_none()
    }

    fn missing(&self, field: &'static str) -> PlotError {
        PlotError::MissingText {
            chart: self.name.clone(),
            field,
        }
    }

    /// Whether a point can be placed on both axes.
    pub(crate) fn drawable(&self, (x, y): (f64, f64)) -> bool {
        self.x.accepts(x) && self.y.accepts(y)
    }

    pub(crate) fn drawable_points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .filter(|&p| self.drawable(p))
    }

    /// Pairs of series (by name) that look the same apart from colour (same
    /// [`Series::look`]) and lie on top of each other: over more than half
    /// of the first one's points, within `tol` of the drawn height (0.005
    /// is 3 px of a 600 px figure). Such a pair hides one curve under the
    /// other; a chart should give them different dashes or markers.
    pub fn indistinct_pairs(&self, tol: f64) -> Vec<(String, String)> {
        let (xr, yr) = self.ranges();
        let unit = |axis: &Axis, r: &std::ops::Range<f64>, v: f64| match axis.scale {
            Scale::Linear => (v - r.start) / (r.end - r.start),
            Scale::Log => (v / r.start).log10() / (r.end / r.start).log10(),
        };
        let drawn = |s: &Series| -> Vec<(f64, f64)> {
            s.points
                .iter()
                .copied()
                .filter(|&p| self.drawable(p))
                .map(|(x, y)| (unit(&self.x, &xr, x), unit(&self.y, &yr, y)))
                .collect()
        };
        let mut pairs = Vec::new();
        for (i, a) in self.series.iter().enumerate() {
            for b in &self.series[i + 1..] {
                if a.look() != b.look() {
                    continue;
                }
                let (pa, pb) = (drawn(a), drawn(b));
                if pa.is_empty() || pb.windows(2).any(|w| w[1].0 < w[0].0) {
                    continue;
                }
                let close = pa
                    .iter()
                    .filter(|&&(x, y)| {
                        // pb[k−1].0 < x ≤ pb[k].0: interpolate; outside pb, skip.
                        let k = pb.partition_point(|p| p.0 < x);
                        let yb = match k {
                            0 if pb[0].0 <= x => pb[0].1,
                            k if k == 0 || k == pb.len() => return false,
                            k => {
                                let (l, r) = (pb[k - 1], pb[k]);
                                l.1 + (r.1 - l.1) * (x - l.0) / (r.0 - l.0)
                            }
                        };
                        (y - yb).abs() < tol
                    })
                    .count();
                if 2 * close > pa.len() {
                    pairs.push((a.name.clone(), b.name.clone()));
                }
            }
        }
        pairs
    }

    /// Number of points left out of the drawing because an axis cannot show
    /// them (non-finite, or not positive on a logarithmic axis). The CSV keeps them.
    pub fn omitted_points(&self) -> usize {
        self.series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|&&p| !self.drawable(p))
            .count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn column_names_are_ascii_with_unit() {
        assert_eq!(column_name("time t", "s"), "time_t_s");
        assert_eq!(column_name("a/(g sin α)", "1"), "a_g_sin");
        assert_eq!(column_name("r", "m"), "r_m");
    }
}
