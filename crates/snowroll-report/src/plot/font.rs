//! The embedded font every figure is drawn in: its bytes, the family name
//! it is registered under, and its registration with `plotters`. Below the
//! renderer and the legend, which both set text in it.

use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::{DrawingArea, DrawingBackend, TextStyle};
use plotters::style::FontStyle;

use super::PlotError;

/// The embedded font (DejaVu Sans, Bitstream Vera licence, see
/// `assets/fonts/DejaVuSans-LICENSE.txt`).
pub(crate) const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// The family name the embedded font is registered under.
pub(crate) const FAMILY: &str = "sans-serif";

/// Text of a figure drawn for a page, times that of the figure files:
/// `plotters` sets a font of N px at N/1.24 px, so the legend's 16 px
/// becomes 20 px drawn at 16.1 px, and shown on a 360 px phone (about
/// 327 px inside the page's margins, 0.6 of [`PAGE_WIDTH`](super::PAGE_WIDTH)) 9.7 px.
pub(super) const PAGE_TEXT: f64 = 1.25;

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

/// `text` in lines no wider than `width` px in `font`, broken after the
/// commas of its list; one line when it fits (or cannot be measured).
pub(super) fn wrap<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    text: &str,
    font: &TextStyle,
    width: u32,
) -> Vec<String> {
    let fits = |line: &str| {
        root.estimate_text_size(line, font)
            .map_or(true, |(w, _)| w <= width)
    };
    if fits(text) {
        return vec![text.to_string()];
    }
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for piece in text.split_inclusive(", ") {
        let longer = format!("{line}{piece}");
        if line.is_empty() || fits(longer.trim_end()) {
            line = longer;
        } else {
            lines.push(line.trim_end().to_string());
            line = piece.to_string();
        }
    }
    lines.push(line.trim_end().to_string());
    lines
}
