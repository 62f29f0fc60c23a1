//! Figures of several panels: [`Chart`]s drawn one above the other in one
//! SVG or PNG (the figure of a run, `snowroll simulate --plot`); one chart
//! is the figure [`Chart::render_svg`] draws.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::font::register_embedded_font;
use super::render::{
    png_size, with_legend_group, with_provenance_comment, Part, FIGURE_SIZE, PAGE_PLOT_HEIGHT,
    PAGE_WIDTH, PNG_SCALE, SVG_OVERSAMPLE,
};
use super::{Chart, PlotError, Provenance};

impl Chart {
    /// Renders the chart as an SVG document (text as `<text>` elements in
    /// `sans-serif`), with a comment recording `provenance`.
    ///
    /// # Errors
    /// [`PlotError`] when the chart is invalid or drawing fails.
    pub fn render_svg(&self, provenance: &Provenance) -> Result<String, PlotError> {
        render_panels_svg(std::slice::from_ref(self), provenance)
    }

    /// Renders the chart as a PNG image, [`PNG_SCALE`] times [`FIGURE_SIZE`],
    /// recording `provenance` in `iTXt` chunks (`Software`, `Title`, `Comment`).
    ///
    /// # Errors
    /// [`PlotError`] when the chart is invalid, drawing or encoding fails.
    pub fn render_png(&self, provenance: &Provenance) -> Result<Vec<u8>, PlotError> {
        render_panels_png(std::slice::from_ref(self), provenance)
    }
}

/// Renders `charts` as one SVG document, one panel of [`FIGURE_SIZE`]
/// each, the first at the top: each with its title, axes, curves and legend
/// column, the footer naming `provenance` under the last (and the first
/// chart's name and title in the comment). One chart is the figure
/// [`Chart::render_svg`] draws.
///
/// # Errors
/// [`PlotError`] when a chart is invalid, there is none, or drawing fails.
pub fn render_panels_svg(charts: &[Chart], provenance: &Provenance) -> Result<String, PlotError> {
    let first = first_valid(charts)?;
    register_embedded_font()?;
    let n = charts.len() as u32;
    let (w, h) = FIGURE_SIZE;
    let k = SVG_OVERSAMPLE;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (w * k, h * k * n)).into_drawing_area();
        draw_panels(charts, &root, provenance, f64::from(k), Part::Body)?;
        root.present().map_err(|e| first.backend(e))?;
    }
    // The legends, drawn on a canvas of their own of the same size, go into
    // the figure as one group the browser test can find.
    let mut legend = String::new();
    {
        let root = SVGBackend::with_string(&mut legend, (w * k, h * k * n)).into_drawing_area();
        draw_panels(charts, &root, provenance, f64::from(k), Part::Legend)?;
        root.present().map_err(|e| first.backend(e))?;
    }
    let svg = with_legend_group(&svg, &legend);
    // Shown at FIGURE_SIZE a panel, drawn in the oversampled viewBox;
    // lines join and end round.
    let svg = svg
        .replacen(
            &format!("width=\"{}\" height=\"{}\"", w * k, h * k * n),
            &format!("width=\"{w}\" height=\"{}\"", h * n),
            1,
        )
        .replace(
            "<polyline fill=\"none\"",
            "<polyline fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\"",
        );
    Ok(with_provenance_comment(
        svg,
        &[&first.name, &first.title, &provenance.line()],
    ))
}

impl Chart {
    /// Renders the chart as an SVG document for a page that may be a
    /// phone's: [`PAGE_WIDTH`] wide (shown at any width through its
    /// `viewBox`), the legend in a box under the plot rather than beside it,
    /// fewer and larger tick labels, and no title or footer: the page's
    /// caption has the title, the version and the parameters (`provenance`,
    /// also recorded in the comment). The figure files keep the layout of [`Chart::render_svg`].
    ///
    /// # Errors
    /// [`PlotError`] when the chart is invalid or drawing fails.
    pub fn render_svg_page(&self, provenance: &Provenance) -> Result<String, PlotError> {
        self.validate()?;
        register_embedded_font()?;
        let k = SVG_OVERSAMPLE;
        let w = PAGE_WIDTH;
        // The legend's rows decide the height: measure on a canvas of the width.
        let lines = {
            let mut probe = String::new();
            let root = SVGBackend::with_string(&mut probe, (w * k, k)).into_drawing_area();
            let (cols, entries) = self.legend_layout(&root, w * k, f64::from(k));
            Chart::legend_lines(cols, &entries)
        };
        let h = (PAGE_PLOT_HEIGHT + Chart::legend_rows_height(lines)).round() as u32;
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (w * k, h * k)).into_drawing_area();
            self.draw_page(&root, f64::from(k), Part::Body)?;
            root.present().map_err(|e| self.backend(e))?;
        }
        let mut legend = String::new();
        {
            let root = SVGBackend::with_string(&mut legend, (w * k, h * k)).into_drawing_area();
            self.draw_page(&root, f64::from(k), Part::Legend)?;
            root.present().map_err(|e| self.backend(e))?;
        }
        let svg = with_legend_group(&svg, &legend)
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
}

/// Renders `charts` as one PNG image, panels stacked as in
/// [`render_panels_svg`], [`PNG_SCALE`] times their size, recording
/// `provenance` in `iTXt` chunks (`Software`, `Title`, `Comment`).
///
/// # Errors
/// [`PlotError`] when a chart is invalid, there is none, drawing or encoding fails.
pub fn render_panels_png(charts: &[Chart], provenance: &Provenance) -> Result<Vec<u8>, PlotError> {
    let first = first_valid(charts)?;
    register_embedded_font()?;
    let (w, h) = png_size();
    let h = h * charts.len() as u32;
    let mut rgb = vec![0_u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        draw_panels(charts, &root, provenance, PNG_SCALE, Part::Body)?;
        draw_panels(charts, &root, provenance, PNG_SCALE, Part::Legend)?;
        root.present().map_err(|e| first.backend(e))?;
    }
    let png_err = |e: png::EncodingError| PlotError::Png {
        chart: first.name.clone(),
        reason: e.to_string(),
    };
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.add_itxt_chunk("Software".into(), provenance.software.clone())
            .map_err(png_err)?;
        enc.add_itxt_chunk("Title".into(), first.title.clone())
            .map_err(png_err)?;
        enc.add_itxt_chunk("Comment".into(), provenance.line())
            .map_err(png_err)?;
        let mut writer = enc.write_header().map_err(png_err)?;
        writer.write_image_data(&rgb).map_err(png_err)?;
        writer.finish().map_err(png_err)?;
    }
    Ok(out)
}

/// The first of `charts`, once every one is valid.
fn first_valid(charts: &[Chart]) -> Result<&Chart, PlotError> {
    for c in charts {
        c.validate()?;
    }
    charts.first().ok_or_else(|| PlotError::NoDrawablePoints {
        chart: "figure".to_string(),
    })
}

/// Draws `part` of each of `charts` in its band of `root`, one above the
/// other; the footer with `provenance` under the last only.
fn draw_panels<DB: DrawingBackend>(
    charts: &[Chart],
    root: &DrawingArea<DB, Shift>,
    provenance: &Provenance,
    scale: f64,
    part: Part,
) -> Result<(), PlotError> {
    let bands = root.split_evenly((charts.len(), 1));
    let none = Provenance::default();
    for (i, (chart, band)) in charts.iter().zip(&bands).enumerate() {
        let footer = if i + 1 == charts.len() {
            provenance
        } else {
            &none
        };
        chart.draw(band, footer, scale, part)?;
    }
    Ok(())
}
