//! Drawing a [`Chart`] with `plotters`: SVG string, PNG bytes.

use std::fmt;

use plotters::coord::combinators::{BindKeyPoints, LogCoord, WithKeyPoints};
use plotters::coord::ranged1d::{AsRangedCoord, BoldPoints, Ranged, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::font::{wrap, FAMILY, PAGE_TEXT};
use super::legend::{colour_slots, PALETTE};
use super::ticks::{log_ticks, AxisTicks};
use super::{
    Axis, Chart, Marker, PlotError, Provenance, Scale, Series, Style, MARKS_ON_A_LINE, NO_DATA,
};

/// Size of an SVG figure (and of a PNG before [`PNG_SCALE`]), px.
pub const FIGURE_SIZE: (u32, u32) = (960, 600);

/// PNG figures are drawn this many times larger than [`FIGURE_SIZE`] so that
/// text stays crisp when the image is viewed full width.
pub const PNG_SCALE: f64 = 1.5;

/// SVG figures are drawn on a canvas this many times [`FIGURE_SIZE`] and
/// shown at [`FIGURE_SIZE`] through their `viewBox`: `plotters` places
/// points on whole pixels, and on the larger canvas a whole pixel is a
/// quarter of a shown one, so nearly flat curves do not step.
pub const SVG_OVERSAMPLE: u32 = 4;

/// Margin added around the data range of a linear axis, as a fraction of the range.
const LINEAR_PAD: f64 = 0.04;

/// Margin added around the data range of a logarithmic axis, as a fraction
/// of the range in decades.
const LOG_PAD: f64 = 0.04;

/// Decades added on each side of a logarithmic axis whose data sit at one value.
const LOG_PAD_SINGLE: f64 = 1.0;

impl Chart {
    /// The drawn ranges `(x_min..x_max, y_min..y_max)` with margins.
    pub(crate) fn ranges(&self) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in self.drawable_points() {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if x0 > x1 {
            // No point: empty axes over a unit range (a decade on a log axis).
            let unit = |axis: &Axis| match axis.scale {
                Scale::Linear => 0.0..1.0,
                Scale::Log => 1.0..10.0,
            };
            return (unit(&self.x), unit(&self.y));
        }
        (pad(&self.x, x0, x1), pad(&self.y, y0, y1))
    }

    pub(super) fn backend(&self, e: impl fmt::Display) -> PlotError {
        PlotError::Backend {
            chart: self.name.clone(),
            reason: e.to_string(),
        }
    }

    /// Draws `part` of the figure on `root`, every length multiplied by
    /// `scale`: title, axes, series and footer, or the legend column to the
    /// right of the plot.
    pub(super) fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        provenance: &Provenance,
        scale: f64,
        part: Part,
    ) -> Result<(), PlotError> {
        let px = |v: f64| (v * scale).round() as u32;
        let (width, height) = root.dim_in_pixel();
        // The footer takes as many lines as its text needs at this width
        // (one for most figures; a fit's fixed parameters can fill two).
        let font = (FAMILY, px(15.0)).into_font().color(&RGBColor(90, 90, 90));
        let lines = wrap(
            root,
            &provenance.line(),
            &font,
            width.saturating_sub(px(24.0)),
        );
        let line_height = px(19.0);
        let extra = line_height * u32::try_from(lines.len().saturating_sub(1)).unwrap_or(0);
        let (main, footer) = root.split_vertically(height.saturating_sub(px(28.0) + extra));
        // The title spans the figure, above plot and legend.
        let (title, main) = main.split_vertically(px(TITLE_HEIGHT));
        let (plot, legend) = main.split_horizontally(width - self.legend_width(root, scale));
        if part == Part::Legend {
            return self.draw_legend_column(&legend, scale);
        }
        root.fill(&WHITE).map_err(|e| self.backend(e))?;
        self.draw_title(&title, scale)?;
        for (k, line) in (0u32..).zip(&lines) {
            footer
                .draw_text(
                    line,
                    &font,
                    (px(12.0) as i32, (px(4.0) + k * line_height) as i32),
                )
                .map_err(|e| self.backend(e))?;
        }
        self.draw_plot(&plot, scale, AxisLook::FILE)
    }

    /// Draws the figure for a page ([`PAGE_WIDTH`] wide, see
    /// [`Chart::render_svg_page`]) on `root`: the title, the plot
    /// [`PAGE_PLOT_HEIGHT`] high labelled as [`AxisLook::PAGE`], and the
    /// legend under it; no footer (the page's caption names
    /// the version and the parameters). `part` as in [`Chart::draw`].
    pub(super) fn draw_page<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        scale: f64,
        part: Part,
    ) -> Result<(), PlotError> {
        let px = |v: f64| (v * scale).round() as u32;
        let (plot, legend) = root.split_vertically(px(PAGE_PLOT_HEIGHT));
        if part == Part::Legend {
            return self.draw_legend_rows(&legend, scale);
        }
        root.fill(&WHITE).map_err(|e| self.backend(e))?;
        self.draw_plot(&plot, scale, AxisLook::PAGE)
    }

    /// The title, centred in its band `area`.
    fn draw_title<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        scale: f64,
    ) -> Result<(), PlotError> {
        let px = |v: f64| (v * scale).round() as u32;
        let width = area.dim_in_pixel().0;
        let centred = TextStyle::from((FAMILY, px(26.0)).into_font())
            .pos(Pos::new(HPos::Center, VPos::Center));
        area.draw_text(
            &self.title,
            &centred,
            ((width / 2) as i32, px(TITLE_HEIGHT / 2.0 + 4.0) as i32),
        )
        .map_err(|e| self.backend(e))
    }

    /// The axes and the series on `plot`, labelled as `look` says.
    fn draw_plot<DB: DrawingBackend>(
        &self,
        plot: &DrawingArea<DB, Shift>,
        scale: f64,
        look: AxisLook,
    ) -> Result<(), PlotError> {
        let (xr, yr) = self.ranges();
        match (self.x.scale, self.y.scale) {
            (Scale::Linear, Scale::Linear) => self.draw_in(plot, xr, yr, scale, look),
            (Scale::Linear, Scale::Log) => self.draw_in(plot, xr, log_axis(yr), scale, look),
            (Scale::Log, Scale::Linear) => self.draw_in(plot, log_axis(xr), yr, scale, look),
            (Scale::Log, Scale::Log) => self.draw_in(plot, log_axis(xr), log_axis(yr), scale, look),
        }
    }

    /// Draws the axes and every series on `area` over the ranges `xr` ×
    /// `yr`, every length times `scale`, at most `look.ticks` labels an
    /// axis and its text `look.text` times the usual size; every tick of an
    /// axis in one format.
    fn draw_in<'a, DB, XR, YR>(
        &self,
        area: &'a DrawingArea<DB, Shift>,
        xr: XR,
        yr: YR,
        scale: f64,
        look: AxisLook,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        XR: AsRangedCoord<Value = f64>,
        YR: AsRangedCoord<Value = f64>,
        XR::CoordDescType: ValueFormatter<f64>,
        YR::CoordDescType: ValueFormatter<f64>,
    {
        let px = |v: f64| (v * scale).round() as u32;
        let font = |size: f64| (FAMILY, px(size * look.text)).into_font();
        let ticks = look.ticks;
        let (xc, yc): (XR::CoordDescType, YR::CoordDescType) = (xr.into(), yr.into());
        let (xf, yf) = (
            axis_ticks(&xc, &self.x, ticks),
            axis_ticks(&yc, &self.y, ticks),
        );
        // Room for the widest y tick label and the axis title beside it.
        let label_font: TextStyle = font(18.0).into();
        let widest = yc
            .key_points(BoldPoints(ticks))
            .iter()
            .filter_map(|&v| area.estimate_text_size(&yf.label(v), &label_font).ok())
            .map(|(w, _)| w)
            .max()
            .unwrap_or(0);
        let y_area = px(86.0 * look.text).max(widest + px(44.0 * look.text));
        let mut chart = ChartBuilder::on(area)
            .margin(px(14.0))
            .margin_right(px(16.0))
            .x_label_area_size(px(58.0 * look.text))
            .y_label_area_size(y_area)
            .build_cartesian_2d(xc, yc)
            .map_err(|e| self.backend(e))?;
        chart
            .configure_mesh()
            .x_desc(self.x.title())
            .y_desc(self.y.title())
            .axis_desc_style(font(21.0))
            .label_style(font(18.0))
            .x_labels(ticks)
            .y_labels(ticks)
            .x_label_formatter(&|v| xf.label(*v))
            .y_label_formatter(&|v| yf.label(*v))
            .bold_line_style(RGBColor(220, 220, 220))
            .light_line_style(RGBColor(242, 242, 242))
            .draw()
            .map_err(|e| self.backend(e))?;
        for ((i, s), slot) in self
            .series
            .iter()
            .enumerate()
            .zip(colour_slots(&self.series))
        {
            self.draw_series(&mut chart, (i, PALETTE[slot % PALETTE.len()]), s, scale)?;
        }
        if self.is_empty() {
            // Nothing to draw: say so in the middle of the empty axes.
            let plot = chart.plotting_area().strip_coord_spec();
            let (pw, ph) = plot.dim_in_pixel();
            let note = font(22.0)
                .color(&RGBColor(90, 90, 90))
                .pos(Pos::new(HPos::Center, VPos::Center));
            plot.draw_text(NO_DATA, &note, ((pw / 2) as i32, (ph / 2) as i32))
                .map_err(|e| self.backend(e))?;
        }
        Ok(())
    }

    /// Draws series `s`, the `i`-th of the chart (which sets where its marks
    /// fall), in `colour` on `chart`: its marks and its line, every length
    /// times `scale`.
    fn draw_series<'a, DB, CT>(
        &self,
        chart: &mut ChartContext<'a, DB, CT>,
        (i, colour): (usize, RGBColor),
        s: &Series,
        scale: f64,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        CT: CoordTranslate<From = (f64, f64)>,
    {
        let px = |v: f64| (v * scale).round() as u32;
        let width = px(2.0);
        let dot = px(4.0);
        let style = ShapeStyle::from(colour).stroke_width(width);
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|&p| self.drawable(p))
            .collect();
        let marker = s.marker.unwrap_or_default();
        let marks = marks_of(s, i, &pts);
        let filled = style.filled();
        self.draw_marks(chart, marks, marker, filled, dot)?;
        match s.style.dash_pattern() {
            // Markers only: the marks above are the series.
            _ if s.style == Style::Markers => return Ok(()),
            None => chart.draw_series(LineSeries::new(pts, style)),
            Some((on, off)) => {
                chart.draw_series(DashedLineSeries::new(pts, px(on), px(off), style))
            }
        }
        .map_err(|e| self.backend(e))?;
        Ok(())
    }

    /// Draws `marker`s of radius `dot` px in style `filled` at `marks`.
    fn draw_marks<DB, CT>(
        &self,
        chart: &mut ChartContext<'_, DB, CT>,
        marks: Vec<(f64, f64)>,
        marker: Marker,
        filled: ShapeStyle,
        dot: u32,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend,
        CT: CoordTranslate<From = (f64, f64)>,
    {
        let d = dot as i32;
        match marker {
            Marker::Circle => {
                chart.draw_series(marks.into_iter().map(|p| Circle::new(p, dot, filled)))
            }
            Marker::Triangle => chart.draw_series(
                marks
                    .into_iter()
                    .map(|p| TriangleMarker::new(p, dot + dot / 2, filled)),
            ),
            Marker::Square => chart.draw_series(
                marks
                    .into_iter()
                    .map(|p| EmptyElement::at(p) + Rectangle::new([(-d, -d), (d, d)], filled)),
            ),
        }
        .map_err(|e| self.backend(e))?;
        Ok(())
    }
}

/// Which part of a figure [`Chart::draw`] draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Part {
    /// Title, axes, series, footer.
    Body,
    /// The legend column.
    Legend,
}

/// Ticks (bold grid lines with a label) asked of each axis.
pub(super) const TICKS: usize = 11;

/// How the axes of a figure are labelled: how many tick labels at most,
/// and their text's size against the figure files'.
#[derive(Debug, Clone, Copy)]
pub(super) struct AxisLook {
    /// Tick labels asked of each axis.
    pub ticks: usize,
    /// Size of the axes' text, times that of the figure files.
    pub text: f64,
}

impl AxisLook {
    /// The figure files' axes: [`TICKS`] labels, 18 px labels, 21 px titles.
    pub const FILE: AxisLook = AxisLook {
        ticks: TICKS,
        text: 1.0,
    };
    /// The axes of a figure drawn for a page ([`Chart::render_svg_page`]):
    /// its plot is about half as wide, so fewer labels, and its text
    /// [`PAGE_TEXT`] times larger, to stay readable on a phone.
    pub const PAGE: AxisLook = AxisLook {
        ticks: 7,
        text: PAGE_TEXT,
    };
}

/// Height of the band of the title above plot and legend, px.
const TITLE_HEIGHT: f64 = 40.0;

/// Width of a figure drawn for a page ([`Chart::render_svg_page`]), px:
/// on a desktop two figures side by side show it at about full size.
pub const PAGE_WIDTH: u32 = 540;

/// Height of the plot (axes and their labels) of such a figure, px.
pub(super) const PAGE_PLOT_HEIGHT: f64 = 400.0;

/// A log axis over `r` labelled at [`log_ticks`]: every decade, and 2 and 5
/// of each where a decade is wide, with light lines at the other multiples.
pub(super) fn log_axis(r: std::ops::Range<f64>) -> WithKeyPoints<LogCoord<f64>> {
    let (bold, light) = log_ticks(r.start, r.end);
    r.log_scale().with_key_points(bold).with_light_points(light)
}

/// The one format of the tick labels of `axis`, drawn by `coord` with at
/// most `ticks` labels.
pub(super) fn axis_ticks<R: Ranged<ValueType = f64>>(
    coord: &R,
    axis: &Axis,
    ticks: usize,
) -> AxisTicks {
    let r = coord.range();
    AxisTicks::new(
        &coord.key_points(BoldPoints(ticks)),
        r.end - r.start,
        axis.scale == Scale::Log,
    )
}

/// `svg` with the drawing of `legend` (an SVG document of the same size)
/// added as its last element, a group `<g class="legend">`.
pub(super) fn with_legend_group(svg: &str, legend: &str) -> String {
    let body = legend
        .find('>')
        .and_then(|start| legend.rfind("</svg>").map(|end| &legend[start + 1..end]))
        .unwrap_or("");
    match svg.rfind("</svg>") {
        Some(end) => format!(
            "{}<g class=\"legend\">{body}</g>\n{}",
            &svg[..end],
            &svg[end..]
        ),
        None => svg.to_string(),
    }
}

/// The points of series `s` (the `i`-th, drawn at `pts`) that carry a
/// marker: every point of a markers-only series; along a line with a marker,
/// [`MARKS_ON_A_LINE`] spread evenly over the points, shifted by series so
/// that the marks of coinciding curves do not fall together; else none.
fn marks_of(s: &Series, i: usize, pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    match (s.style, s.marker) {
        (Style::Markers, _) => pts.to_vec(),
        (_, Some(_)) if !pts.is_empty() => {
            let n = pts.len();
            let shift = (i as f64 * 0.37).fract();
            (0..MARKS_ON_A_LINE.min(n))
                .map(|j| {
                    let f = (j as f64 + shift) / MARKS_ON_A_LINE.min(n) as f64;
                    pts[((f * n as f64) as usize).min(n - 1)]
                })
                .collect()
        }
        _ => Vec::new(),
    }
}

/// Size of a PNG figure, px.
pub fn png_size() -> (u32, u32) {
    let s = |v: u32| (f64::from(v) * PNG_SCALE).round() as u32;
    (s(FIGURE_SIZE.0), s(FIGURE_SIZE.1))
}

impl Axis {
    /// Leaves `share` (0 to 0.5) of the drawn length empty after the last
    /// data, at least.
    pub fn margin_after(mut self, share: f64) -> Self {
        self.margin_after = Some(share.clamp(0.0, 0.5));
        self
    }
}

/// The drawn range of `axis` for data spanning `lo..hi`, with margins.
fn pad(axis: &Axis, lo: f64, hi: f64) -> std::ops::Range<f64> {
    match axis.scale {
        Scale::Linear => {
            let span = hi - lo;
            let margin = if span > 0.0 {
                span * LINEAR_PAD
            } else {
                lo.abs().max(1.0) * LINEAR_PAD
            };
            let start = lo - margin;
            // The data's end at 1 − share of the drawn length.
            let wanted = axis
                .margin_after
                .map_or(hi + margin, |m| start + (hi - start) / (1.0 - m));
            start..(hi + margin).max(wanted)
        }
        Scale::Log => {
            let decades = (hi / lo).log10();
            let margin = if decades > 0.0 {
                decades * LOG_PAD
            } else {
                LOG_PAD_SINGLE
            };
            let factor = 10_f64.powf(margin);
            let (start, end) = (lo / factor, hi * factor);
            // The data's end at 1 − share of the drawn decades.
            let wanted = axis
                .margin_after
                .map_or(end, |m| start * (hi / start).powf(1.0 / (1.0 - m)));
            start..end.max(wanted)
        }
    }
}

/// Makes text safe inside an XML comment (no `--`).
fn escape_comment(s: &str) -> String {
    s.replace("--", "- -")
}

/// `svg` with an XML comment right after its opening tag naming what it
/// shows and how it was made: `parts[0]: parts[1] | parts[2] ...`.
pub(super) fn with_provenance_comment(svg: String, parts: &[&str]) -> String {
    let (head, rest) = parts.split_first().map_or(("", &[][..]), |(h, r)| (*h, r));
    let rest: Vec<String> = rest.iter().map(|p| escape_comment(p)).collect();
    let comment = format!("<!-- {}: {} -->\n", escape_comment(head), rest.join(" | "));
    match svg.find('>') {
        Some(end) => format!("{}\n{comment}{}", &svg[..=end], &svg[end + 1..]),
        None => svg,
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Axis, Chart, Provenance, Series};

    /// A footer longer than the figure is wide is drawn on several lines,
    /// each starting inside the figure and every parameter on one of them
    /// (a fit's footer ran off the right edge, hiding `core_radius` and
    /// `free`); a short one stays on one line.
    #[test]
    fn a_long_footer_wraps_inside_the_figure() {
        let chart = Chart::new(
            "t",
            "a title",
            Axis::linear("x", "m"),
            Axis::linear("y", "m"),
        )
        .with_series(Series::new("line", vec![(0.0, 0.0), (1.0, 1.0)]));
        let footer_texts = |prov: &Provenance| {
            let svg = chart.render_svg(prov).unwrap();
            svg.split("<text")
                .skip(1)
                .filter_map(|t| t.split("</text>").next())
                .filter(|t| t.contains("snowroll 0.1.0") || t.contains("key_"))
                .count()
        };
        let long = Provenance {
            software: "snowroll 0.1.0".into(),
            params: (0..24)
                .map(|i| (format!("key_{i}"), "0.125".to_string()))
                .collect(),
        };
        let svg = chart.render_svg(&long).unwrap();
        for i in 0..24 {
            assert!(svg.contains(&format!("key_{i} = 0.125")), "key_{i} missing");
        }
        assert!(
            footer_texts(&long) >= 2,
            "one line: {}",
            footer_texts(&long)
        );
        let short = Provenance {
            software: "snowroll 0.1.0".into(),
            params: vec![("key_0".into(), "1".into())],
        };
        assert_eq!(footer_texts(&short), 1);
    }
}
