//! Drawing a [`RegimeMap`] as SVG with `plotters`: the cells, the borders
//! and a legend column beside the plot.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::super::font::{register_embedded_font, FAMILY};
use super::super::render::{axis_ticks, log_axis, with_provenance_comment};
use super::super::{PlotError, Provenance, Scale};
use super::RegimeMap;

impl RegimeMap {
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
                (Scale::Linear, Scale::Log) => self.draw_in(&main, xr, log_axis(yr)),
                (Scale::Log, Scale::Linear) => self.draw_in(&main, log_axis(xr), yr),
                (Scale::Log, Scale::Log) => self.draw_in(&main, log_axis(xr), log_axis(yr)),
            }?;
            root.present().map_err(backend)?;
        }
        Ok(with_provenance_comment(
            svg,
            &["regime map", &self.title, &provenance.line()],
        ))
    }

    /// Draws the cells and the borders on `area` over the ranges `xr` × `yr`,
    /// and the legend beside them.
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
        let (xc, yc): (XR::CoordDescType, YR::CoordDescType) = (xr.into(), yr.into());
        let ticks = super::super::render::TICKS;
        let (xf, yf) = (
            axis_ticks(&xc, &self.x, ticks),
            axis_ticks(&yc, &self.y, ticks),
        );
        let mut chart = ChartBuilder::on(&plot)
            .caption(&self.title, font(24))
            .margin(14)
            .x_label_area_size(58)
            .y_label_area_size(86)
            .build_cartesian_2d(xc, yc)
            .map_err(backend)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_labels(super::super::render::TICKS)
            .y_labels(super::super::render::TICKS)
            .x_desc(self.x.title())
            .y_desc(self.y.title())
            .axis_desc_style(font(20))
            .label_style(font(16))
            .x_label_formatter(&|v| xf.label(*v))
            .y_label_formatter(&|v| yf.label(*v))
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
        self.draw_legend(&legend)
    }

    /// The legend in the right margin `legend`: a swatch per class, then a
    /// line per border with its label wrapped to [`LEGEND_CHARS`].
    fn draw_legend<DB: DrawingBackend>(
        &self,
        legend: &DrawingArea<DB, Shift>,
    ) -> Result<(), PlotError> {
        let font = |size: u32| (FAMILY, size).into_font();
        let mut y = 60;
        legend
            .draw_text(&self.legend_title, &font(17).into(), (8, y - 30))
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
    fn legend_lines_wrap_at_spaces() {
        assert_eq!(wrap("a bb ccc", 4), vec!["a bb", "ccc"]);
    }
}
