//! The legend beside the plot (or under it), and the colours of the series.
//!
//! The legend is a column to the right of the plotting area, so that it
//! covers no curve and no point (in a figure drawn for a page,
//! [`Chart::render_svg_page`], it is a box of rows under the plot); in the
//! SVG it is a group
//! `<g class="legend">`, which the report's browser test finds and checks
//! against every plotted point. Each curve has a colour of its own; a series
//! drawn [`Series::in_colour_of`] an earlier one (a closed form beside its
//! curve) takes that one's colour.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::font::{FAMILY, PAGE_TEXT};
use super::{Chart, Marker, PlotError, Series, Style};

/// Colours of successive curves: Tableau 10 (distinct, colour-blind aware),
/// then six darker colours far from each of them.
pub(crate) const PALETTE: [RGBColor; 16] = [
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
    RGBColor(0, 0, 0),
    RGBColor(0, 0, 128),
    RGBColor(128, 0, 0),
    RGBColor(85, 107, 47),
    RGBColor(0, 128, 128),
    RGBColor(184, 134, 11),
];

/// Legend text size, px at [`super::FIGURE_SIZE`].
pub(crate) const LEGEND_FONT: f64 = 16.0;

/// Length of a legend key (the line sample), px.
pub(crate) const KEY: f64 = 36.0;

/// Height of one legend entry, px.
const ROW: f64 = 23.0;

/// Padding inside the legend box and the gap from key to text, px.
const PAD: f64 = 8.0;

/// Top of the legend box below the top of its column (the plot's top margin), px.
const TOP: f64 = 14.0;

/// The legend column takes at most this share of the figure's width.
const MAX_SHARE: f64 = 0.42;

/// The palette index of each series of `series`: a new colour per series,
/// except that a series drawn [`Series::in_colour_of`] an earlier one takes
/// that one's (a later or missing one is ignored: the series gets its own).
pub(crate) fn colour_slots(series: &[Series]) -> Vec<usize> {
    let mut slots: Vec<usize> = Vec::with_capacity(series.len());
    let mut next = 0;
    for (i, s) in series.iter().enumerate() {
        match s.colour_of.filter(|&k| k < i) {
            Some(k) => slots.push(slots[k]),
            None => {
                slots.push(next);
                next += 1;
            }
        }
    }
    slots
}

/// Number of colours `series` need.
pub(crate) fn colours_needed(series: &[Series]) -> usize {
    colour_slots(series).into_iter().max().map_or(0, |k| k + 1)
}

/// Width of the legend column on `area` for labels of `widths` px (as
/// drawn, at `scale`): key, gaps, the longest label, padding; at most
/// [`MAX_SHARE`] of the area.
pub(crate) fn column_width(widths: impl Iterator<Item = u32>, total: u32, scale: f64) -> u32 {
    let longest = widths.max().unwrap_or(0);
    let want = f64::from(longest) + (KEY + 5.0 * PAD) * scale;
    want.min(MAX_SHARE * f64::from(total)).round() as u32
}

impl Chart {
    /// The legend column's width on `area`, every length times `scale`.
    pub(crate) fn legend_width<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        scale: f64,
    ) -> u32 {
        let font: TextStyle = (FAMILY, LEGEND_FONT * scale).into_font().into();
        let widths = self.series.iter().map(|s| {
            area.estimate_text_size(&s.name, &font)
                .map_or(0, |(w, _)| w)
        });
        column_width(widths, area.dim_in_pixel().0, scale)
    }

    /// Draws the legend in the column `area`: a framed box with one entry
    /// per series (its key: line pattern, marker, colour; its name).
    pub(crate) fn draw_legend_column<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        scale: f64,
    ) -> Result<(), PlotError> {
        if self.series.is_empty() {
            return Ok(());
        }
        let p = |v: f64| (v * scale).round() as i32;
        let (w, _) = area.dim_in_pixel();
        let rows = self.series.len() as f64;
        let top = p(TOP);
        let bottom = top + p(2.0 * PAD + ROW * rows);
        let frame = [(p(PAD), top), (w as i32 - p(PAD), bottom)];
        let draw_err = |e: DrawingAreaErrorKind<DB::ErrorType>| self.backend_error(e);
        area.draw(&Rectangle::new(frame, WHITE.filled()))
            .map_err(draw_err)?;
        area.draw(&Rectangle::new(frame, RGBColor(160, 160, 160)))
            .map_err(draw_err)?;
        let font = TextStyle::from((FAMILY, LEGEND_FONT * scale).into_font())
            .pos(Pos::new(HPos::Left, VPos::Center));
        for ((k, s), slot) in self
            .series
            .iter()
            .enumerate()
            .zip(colour_slots(&self.series))
        {
            let y = top + p(PAD + ROW * (k as f64 + 0.5));
            let x = p(2.0 * PAD);
            self.draw_key(area, s, PALETTE[slot % PALETTE.len()], (x, y), scale)?;
            area.draw(&Text::new(
                s.name.clone(),
                (x + p(KEY + PAD), y),
                font.clone(),
            ))
            .map_err(draw_err)?;
        }
        Ok(())
    }

    /// The legend under the plot on an area `width` px wide (at `scale`):
    /// its number of columns (as many of the longest label as fit, at most
    /// one per series) and the lines of each entry. In one column, a label
    /// wider than the column is broken at spaces into lines that fit.
    pub(crate) fn legend_layout<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        width: u32,
        scale: f64,
    ) -> (usize, Vec<Vec<String>>) {
        let n = self.series.len();
        let font: TextStyle = (FAMILY, LEGEND_FONT * PAGE_TEXT * scale).into_font().into();
        let text_width = |t: &str| area.estimate_text_size(t, &font).map_or(0, |(w, _)| w);
        let longest = self
            .series
            .iter()
            .map(|s| text_width(&s.name))
            .max()
            .unwrap_or(0);
        let key = (KEY + 3.0 * PAD) * scale;
        let room = f64::from(width) - 2.0 * PAD * scale;
        let cols = ((room / (f64::from(longest) + key)).floor() as usize).clamp(1, n.max(1));
        let room_for_text = (room - key).max(1.0) as u32;
        let lines = self
            .series
            .iter()
            .map(|s| {
                if cols > 1 {
                    return vec![s.name.clone()];
                }
                let mut lines: Vec<String> = Vec::new();
                for word in s.name.split(' ') {
                    match lines.last_mut() {
                        Some(line) if text_width(&format!("{line} {word}")) <= room_for_text => {
                            line.push(' ');
                            line.push_str(word);
                        }
                        _ => lines.push(word.to_string()),
                    }
                }
                lines
            })
            .collect();
        (cols, lines)
    }

    /// Lines of text the legend under the plot takes: the rows of its
    /// columns, each row as many lines as its tallest entry.
    pub(crate) fn legend_lines(cols: usize, entries: &[Vec<String>]) -> usize {
        if cols <= 1 {
            return entries.iter().map(Vec::len).sum();
        }
        entries.len().div_ceil(cols)
    }

    /// Height of the legend under the plot of `lines` lines of text, px at
    /// scale 1: the gap above its box, the box and a margin below.
    pub(crate) fn legend_rows_height(lines: usize) -> f64 {
        if lines == 0 {
            return 0.0;
        }
        TOP + 2.0 * PAD + ROW * PAGE_TEXT * lines as f64 + PAD
    }

    /// Draws the legend under the plot on `area`: a framed box across the
    /// figure, the entries in as many columns as fit
    /// ([`Chart::legend_layout`]), filled column by column so that each
    /// curve's entries stay together.
    pub(crate) fn draw_legend_rows<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        scale: f64,
    ) -> Result<(), PlotError> {
        if self.series.is_empty() {
            return Ok(());
        }
        let p = |v: f64| (v * scale).round() as i32;
        let (w, _) = area.dim_in_pixel();
        let (cols, entries) = self.legend_layout(area, w, scale);
        let lines = Chart::legend_lines(cols, &entries);
        let rows = entries.len().div_ceil(cols);
        let line_height = ROW * PAGE_TEXT;
        let top = p(TOP);
        let bottom = top + p(2.0 * PAD + line_height * lines as f64);
        let frame = [(p(PAD), top), (w as i32 - p(PAD), bottom)];
        let draw_err = |e: DrawingAreaErrorKind<DB::ErrorType>| self.backend_error(e);
        area.draw(&Rectangle::new(frame, WHITE.filled()))
            .map_err(draw_err)?;
        area.draw(&Rectangle::new(frame, RGBColor(160, 160, 160)))
            .map_err(draw_err)?;
        let font = TextStyle::from((FAMILY, LEGEND_FONT * PAGE_TEXT * scale).into_font())
            .pos(Pos::new(HPos::Left, VPos::Center));
        let column = f64::from(w as i32 - 2 * p(PAD)) / cols as f64;
        // The line each entry starts on (in one column, after the lines of
        // the entries above it).
        let mut line = 0usize;
        for ((k, s), slot) in self
            .series
            .iter()
            .enumerate()
            .zip(colour_slots(&self.series))
        {
            let (col, first) = if cols > 1 {
                (k / rows, k % rows)
            } else {
                (0, line)
            };
            line += entries[k].len();
            let y = |i: usize| top + p(PAD + line_height * ((first + i) as f64 + 0.5));
            let x = p(2.0 * PAD) + (column * col as f64).round() as i32;
            self.draw_key(area, s, PALETTE[slot % PALETTE.len()], (x, y(0)), scale)?;
            for (i, text) in entries[k].iter().enumerate() {
                area.draw(&Text::new(
                    text.clone(),
                    (x + p(KEY + PAD), y(i)),
                    font.clone(),
                ))
                .map_err(draw_err)?;
            }
        }
        Ok(())
    }

    /// Draws the key of series `s` in `colour` starting at `at`: its line
    /// pattern, and its marker when it has one.
    fn draw_key<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        s: &Series,
        colour: RGBColor,
        (x, y): (i32, i32),
        scale: f64,
    ) -> Result<(), PlotError> {
        let p = |v: f64| (v * scale).round() as i32;
        let key = p(KEY);
        let style = ShapeStyle::from(colour).stroke_width(p(2.0) as u32);
        let draw_err = |e: DrawingAreaErrorKind<DB::ErrorType>| self.backend_error(e);
        if s.style != Style::Markers {
            for (a, b) in key_pieces(s.style, key) {
                if b > a {
                    area.draw(&PathElement::new(vec![(x + a, y), (x + b, y)], style))
                        .map_err(draw_err)?;
                }
            }
        }
        if s.style == Style::Markers || s.marker.is_some() {
            let (c, d) = ((x + key / 2, y), p(4.0));
            let filled = style.filled();
            match s.marker.unwrap_or_default() {
                Marker::Circle => area.draw(&Circle::new(c, d as u32, filled)),
                Marker::Triangle => area.draw(&TriangleMarker::new(c, d + d / 2, filled)),
                Marker::Square => area.draw(&Rectangle::new(
                    [(c.0 - d, c.1 - d), (c.0 + d, c.1 + d)],
                    filled,
                )),
            }
            .map_err(draw_err)?;
        }
        Ok(())
    }

    fn backend_error(&self, e: impl std::fmt::Display) -> PlotError {
        PlotError::Backend {
            chart: self.name.clone(),
            reason: e.to_string(),
        }
    }
}

/// Up to four `(start, end)` pieces of a legend key `key` px long drawing
/// `style`'s dash pattern, shrunk to fit; unused pieces are empty.
pub(crate) fn key_pieces(style: Style, key: i32) -> [(i32, i32); 4] {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn line(name: &str) -> Series {
        Series::new(name, vec![(0.0, 0.0), (1.0, 1.0)])
    }

    #[test]
    fn every_curve_has_its_own_colour_and_a_closed_form_its_curves() {
        let series = [
            line("a"),
            line("a: closed form").style(Style::Dashed).in_colour_of(0),
            line("b"),
            line("b: closed form").style(Style::Dashed).in_colour_of(2),
            line("c"),
            line("a again").in_colour_of(0),
        ];
        assert_eq!(colour_slots(&series), [0, 0, 1, 1, 2, 0]);
        assert_eq!(colours_needed(&series), 3);
        // A series cannot take the colour of itself or a later one: it
        // gets its own.
        let odd = [line("x").in_colour_of(0), line("y").in_colour_of(5)];
        assert_eq!(colour_slots(&odd), [0, 1]);
    }

    /// The first number after `key="` in `text`.
    fn attr(text: &str, key: &str) -> f64 {
        let at = text.find(&format!("{key}=\"")).expect(key) + key.len() + 2;
        let end = text[at..].find('"').unwrap() + at;
        text[at..end].parse().unwrap()
    }

    #[test]
    fn the_legend_is_a_group_beside_every_plotted_point() {
        // Curves through every corner of the data, where a legend inside
        // the plot would have to sit on one.
        let chart = Chart::new(
            "t",
            "a title",
            super::super::Axis::linear("x", "m"),
            super::super::Axis::linear("y", "m"),
        )
        .with_series(line("rising"))
        .with_series(Series::new("falling", vec![(0.0, 1.0), (1.0, 0.0)]))
        .with_series(Series::new("dots", vec![(0.0, 0.5), (1.0, 0.5)]).style(Style::Markers));
        let svg = chart
            .render_svg(&super::super::Provenance::default())
            .unwrap();
        let (body, legend) = svg
            .split_once("<g class=\"legend\">")
            .expect("no legend group");
        let left = attr(legend, "x");
        assert!(legend.contains("rising") && legend.contains("falling") && legend.contains("dots"));
        let mut points = 0;
        for poly in body.split("<polyline").skip(1) {
            let pts = &poly[poly.find("points=\"").unwrap() + 8..];
            for xy in pts[..pts.find('"').unwrap()].split_whitespace() {
                let x: f64 = xy.split(',').next().unwrap().parse().unwrap();
                assert!(
                    x < left,
                    "a curve's point at x = {x} is under the legend (from {left})"
                );
                points += 1;
            }
        }
        for circle in body.split("<circle").skip(1) {
            assert!(attr(circle, "cx") < left, "a marker is under the legend");
            points += 1;
        }
        assert!(points >= 6, "only {points} points found");
    }

    #[test]
    fn the_palette_has_no_colour_twice() {
        for (i, a) in PALETTE.iter().enumerate() {
            for b in &PALETTE[i + 1..] {
                // Distinct by at least 40 of 255 in some channel: told apart
                // on screen, not only in the numbers.
                let d = [(a.0, b.0), (a.1, b.1), (a.2, b.2)]
                    .iter()
                    .map(|&(x, y)| x.abs_diff(y))
                    .max();
                assert!(d >= Some(40), "{a:?} and {b:?} are too close");
            }
        }
    }

    #[test]
    fn the_column_fits_the_longest_label_but_leaves_the_plot_room() {
        // 200 px of label: key 36 + 5 gaps of 8 + 200.
        assert_eq!(column_width([120, 200].into_iter(), 960, 1.0), 276);
        assert_eq!(column_width([400].into_iter(), 1920, 2.0), 552);
        // A label of 600 px on a 960 px figure: capped at 42 %.
        assert_eq!(column_width([600].into_iter(), 960, 1.0), 403);
    }
}
