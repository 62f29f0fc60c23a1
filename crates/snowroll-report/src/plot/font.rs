//! The embedded font every figure is drawn in: its bytes, the family name
//! it is registered under, and its registration with `plotters`. Below the
//! renderer and the legend, which both set text in it.

use std::sync::OnceLock;

use plotters::style::FontStyle;

use super::PlotError;

/// The embedded font (DejaVu Sans, Bitstream Vera licence, see
/// `assets/fonts/DejaVuSans-LICENSE.txt`).
const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// The family name the embedded font is registered under.
pub(crate) const FAMILY: &str = "sans-serif";

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
