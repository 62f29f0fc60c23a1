//! Drawing a [`Chart`] with `plotters`: SVG string, PNG bytes.

use std::fmt;
use std::sync::OnceLock;

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::{
    Axis, Chart, Legend, Marker, PlotError, Provenance, Scale, Series, Style, MARKS_ON_A_LINE,
};

/// The embedded font (DejaVu Sans, Bitstream Vera licence, see
/// `assets/fonts/DejaVuSans-LICENSE.txt`).
const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// The family name the embedded font is registered under.
pub(crate) const FAMILY: &str = "sans-serif";

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

/// Colours of successive series (Tableau 10: distinct, colour-blind aware).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Registers the embedded font with `plotters`, once per process.
///
/// # Errors
/// [`PlotError::Font`] when the font cannot be parsed.
pub fn register_embedded_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED
        .get_or_init(|| plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err(PlotError::Font)
    }
}

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
        (pad(&self.x, x0, x1), pad(&self.y, y0, y1))
    }

    /// Renders the chart as an SVG document (text as `<text>` elements in
    /// `sans-serif`), with a comment recording `provenance`.
    ///
    /// # Errors
    /// [`PlotError`] when the chart is invalid or drawing fails.
    pub fn render_svg(&self, provenance: &Provenance) -> Result<String, PlotError> {
        self.validate()?;
        register_embedded_font()?;
        let mut svg = String::new();
        let (w, h) = FIGURE_SIZE;
        let k = SVG_OVERSAMPLE;
        {
            let root = SVGBackend::with_string(&mut svg, (w * k, h * k)).into_drawing_area();
            self.draw(&root, provenance, f64::from(k))?;
            root.present().map_err(|e| self.backend(e))?;
        }
        // Shown at FIGURE_SIZE, drawn in the oversampled viewBox; lines
        // join and end round.
        let svg = svg
            .replacen(
                &format!("width=\"{}\" height=\"{}\"", w * k, h * k),
                &format!("width=\"{w}\" height=\"{h}\""),
                1,
            )
            .replace(
                "<polyline fill=\"none\"",
                "<polyline fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\"",
            );
        Ok(with_provenance_comment(
            svg,
            &[&self.name, &self.title, &provenance.line()],
        ))
    }

    /// Renders the chart as a PNG image, [`PNG_SCALE`] times [`FIGURE_SIZE`],
    /// recording `provenance` in `iTXt` chunks (`Software`, `Title`, `Comment`).
    ///
    /// # Errors
    /// [`PlotError`] when the chart is invalid, drawing or encoding fails.
    pub fn render_png(&self, provenance: &Provenance) -> Result<Vec<u8>, PlotError> {
        self.validate()?;
        register_embedded_font()?;
        let (w, h) = png_size();
        let mut rgb = vec![0_u8; w as usize * h as usize * 3];
        {
            let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
            self.draw(&root, provenance, PNG_SCALE)?;
            root.present().map_err(|e| self.backend(e))?;
        }
        let png_err = |e: png::EncodingError| PlotError::Png {
            chart: self.name.clone(),
            reason: e.to_string(),
        };
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, w, h);
            enc.set_color(png::ColorType::Rgb);
            enc.set_depth(png::BitDepth::Eight);
            enc.add_itxt_chunk("Software".into(), provenance.software.clone())
                .map_err(png_err)?;
            enc.add_itxt_chunk("Title".into(), self.title.clone())
                .map_err(png_err)?;
            enc.add_itxt_chunk("Comment".into(), provenance.line())
                .map_err(png_err)?;
            let mut writer = enc.write_header().map_err(png_err)?;
            writer.write_image_data(&rgb).map_err(png_err)?;
            writer.finish().map_err(png_err)?;
        }
        Ok(out)
    }

    fn backend(&self, e: impl fmt::Display) -> PlotError {
        PlotError::Backend {
            chart: self.name.clone(),
            reason: e.to_string(),
        }
    }

    /// Draws title, axes, series, legend and footer on `root`, every length
    /// multiplied by `scale`.
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        provenance: &Provenance,
        scale: f64,
    ) -> Result<(), PlotError> {
        let px = |v: f64| (v * scale).round() as u32;
        root.fill(&WHITE).map_err(|e| self.backend(e))?;
        let (_, height) = root.dim_in_pixel();
        let (main, footer) = root.split_vertically(height.saturating_sub(px(26.0)));
        footer
            .draw_text(
                &provenance.line(),
                &(FAMILY, px(13.0)).into_font().color(&RGBColor(90, 90, 90)),
                (px(12.0) as i32, px(4.0) as i32),
            )
            .map_err(|e| self.backend(e))?;
        let (xr, yr) = self.ranges();
        match (self.x.scale, self.y.scale) {
            (Scale::Linear, Scale::Linear) => self.draw_in(&main, xr, yr, scale),
            (Scale::Linear, Scale::Log) => self.draw_in(&main, xr, yr.log_scale(), scale),
            (Scale::Log, Scale::Linear) => self.draw_in(&main, xr.log_scale(), yr, scale),
            (Scale::Log, Scale::Log) => self.draw_in(&main, xr.log_scale(), yr.log_scale(), scale),
        }
    }

    /// Draws the axes, every series with its legend key, and the legend box
    /// on `area` over the ranges `xr` × `yr`, every length times `scale`.
    fn draw_in<'a, DB, XR, YR>(
        &self,
        area: &'a DrawingArea<DB, Shift>,
        xr: XR,
        yr: YR,
        scale: f64,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        XR: AsRangedCoord<Value = f64>,
        YR: AsRangedCoord<Value = f64>,
        XR::CoordDescType: ValueFormatter<f64>,
        YR::CoordDescType: ValueFormatter<f64>,
    {
        let px = |v: f64| (v * scale).round() as u32;
        let font = |size: f64| (FAMILY, px(size)).into_font();
        let mut chart = ChartBuilder::on(area)
            .caption(&self.title, font(26.0))
            .margin(px(14.0))
            .margin_right(px(36.0))
            .x_label_area_size(px(58.0))
            .y_label_area_size(px(86.0))
            .build_cartesian_2d(xr, yr)
            .map_err(|e| self.backend(e))?;
        chart
            .configure_mesh()
            .x_desc(self.x.title())
            .y_desc(self.y.title())
            .axis_desc_style(font(20.0))
            .label_style(font(16.0))
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .bold_line_style(RGBColor(220, 220, 220))
            .light_line_style(RGBColor(242, 242, 242))
            .draw()
            .map_err(|e| self.backend(e))?;
        for (i, s) in self.series.iter().enumerate() {
            self.draw_series(&mut chart, i, s, scale)?;
        }
        self.draw_legend_box(&mut chart, scale)
    }

    /// Draws series `s`, the `i`-th of the chart (which sets its colour and
    /// where its marks fall), on `chart`: its marks, its line, and its key in
    /// the legend, every length times `scale`.
    fn draw_series<'a, DB, CT>(
        &self,
        chart: &mut ChartContext<'a, DB, CT>,
        i: usize,
        s: &Series,
        scale: f64,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        CT: CoordTranslate<From = (f64, f64)>,
    {
        let px = |v: f64| (v * scale).round() as u32;
        let width = px(2.0);
        let key = px(36.0) as i32;
        let dot = px(4.0);
        let colour = PALETTE[i % PALETTE.len()];
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
        let drawn = match s.style.dash_pattern() {
            // Markers only: the marks above are the series.
            _ if s.style == Style::Markers => {
                chart.draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())
            }
            None => chart.draw_series(LineSeries::new(pts, style)),
            Some((on, off)) => {
                chart.draw_series(DashedLineSeries::new(pts, px(on), px(off), style))
            }
        }
        .map_err(|e| self.backend(e))?;
        // The legend key repeats the line's pattern and marker. One
        // element shape serves every style (a legend closure returns one
        // type): four line pieces and a marker, unused parts transparent.
        let hidden = ShapeStyle::from(TRANSPARENT);
        let pieces = key_pieces(s.style, key);
        let line = if s.style == Style::Markers {
            hidden
        } else {
            style
        };
        let shown = s.style == Style::Markers || s.marker.is_some();
        let (c, t, q) = match (shown, marker) {
            (false, _) => (hidden, hidden, hidden),
            (true, Marker::Circle) => (filled, hidden, hidden),
            (true, Marker::Triangle) => (hidden, filled, hidden),
            (true, Marker::Square) => (hidden, hidden, filled),
        };
        drawn.label(&s.name).legend(move |(x, y)| {
            let half = key / 2;
            let d = dot as i32;
            let piece = |k: usize| PathElement::new(vec![(pieces[k].0, 0), (pieces[k].1, 0)], line);
            EmptyElement::at((x, y))
                + piece(0)
                + piece(1)
                + piece(2)
                + piece(3)
                + Circle::new((half, 0), dot, c)
                + TriangleMarker::new((half, 0), dot + dot / 2, t)
                + Rectangle::new([(half - d, -d), (half + d, d)], q)
        });
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

    /// Draws the box of legend entries in the corner the chart asks for,
    /// every length times `scale`.
    fn draw_legend_box<'a, DB, CT>(
        &self,
        chart: &mut ChartContext<'a, DB, CT>,
        scale: f64,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        CT: CoordTranslate,
    {
        let px = |v: f64| (v * scale).round() as u32;
        let font = |size: f64| (FAMILY, px(size)).into_font();
        chart
            .configure_series_labels()
            .position(match self.legend {
                Legend::UpperRight => SeriesLabelPosition::UpperRight,
                Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
                Legend::LowerRight => SeriesLabelPosition::LowerRight,
                Legend::LowerLeft => SeriesLabelPosition::LowerLeft,
            })
            .margin(px(10.0))
            .legend_area_size(px(46.0))
            .label_font(font(15.0))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(160, 160, 160))
            .draw()
            .map_err(|e| self.backend(e))?;
        Ok(())
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

/// Up to four `(start, end)` pieces of a legend key `key` px long drawing
/// `style`'s dash pattern, shrunk to fit; unused pieces are empty.
fn key_pieces(style: Style, key: i32) -> [(i32, i32); 4] {
    let mut pieces = [(0, 0); 4];
    match style.dash_pattern() {
        None => pieces[0] = (0, key),
        Some((on, off)) => {
            // The pattern shrunk so that exactly four dashes fill the key.
            let period = f64::from(key) / (4.0 - off / (on + off));
            let on_px = period * on / (on + off);
            for (k, piece) in pieces.iter_mut().enumerate() {
                let start = k as f64 * period;
                *piece = (start.round() as i32, (start + on_px).round() as i32);
            }
        }
    }
    pieces
}

/// Size of a PNG figure, px.
pub fn png_size() -> (u32, u32) {
    let s = |v: u32| (f64::from(v) * PNG_SCALE).round() as u32;
    (s(FIGURE_SIZE.0), s(FIGURE_SIZE.1))
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
            (lo - margin)..(hi + margin)
        }
        Scale::Log => {
            let decades = (hi / lo).log10();
            let margin = if decades > 0.0 {
                decades * LOG_PAD
            } else {
                LOG_PAD_SINGLE
            };
            let factor = 10_f64.powf(margin);
            (lo / factor)..(hi * factor)
        }
    }
}

/// A tick label in the report's one notation: plain decimals between 0.01
/// and 10⁴ (`0.5`, `2500`), else powers of ten (`10⁻⁴`, `2.5×10⁷`); a
/// Unicode minus.
pub(crate) fn tick(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return crate::notation::fixed(v, 0);
    }
    let sign = if v < 0.0 { "−" } else { "" };
    let a = v.abs();
    if (1e-2..1e4).contains(&a) {
        let s = format!("{a:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        return format!("{sign}{s}");
    }
    let s = format!("{a:.2e}");
    let Some((m, e)) = s.split_once('e') else {
        return s;
    };
    let m = m.trim_end_matches('0').trim_end_matches('.');
    let power = format!("10{}", crate::notation::superscript(e));
    if m == "1" {
        format!("{sign}{power}")
    } else {
        format!("{sign}{m}×{power}")
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
    use super::*;

    #[test]
    fn ticks_are_short_and_exact_for_decades() {
        assert_eq!(tick(0.0), "0");
        assert_eq!(tick(0.5), "0.5");
        assert_eq!(tick(100.0), "100");
        assert_eq!(tick(1e-6), "10⁻⁶");
        assert_eq!(tick(2.5e7), "2.5×10⁷");
        assert_eq!(tick(1e-4), "10⁻⁴");
        assert_eq!(tick(1e4), "10⁴");
        assert_eq!(tick(1e5), "10⁵");
        assert_eq!(tick(2500.0), "2500");
        assert_eq!(tick(-0.25), "−0.25");
        assert_eq!(tick(0.01), "0.01");
    }
}
