//! A figure that could not be drawn ([`PlotError`]).

use thiserror::Error;

/// A figure that could not be drawn.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PlotError {
    /// A text every figure must have (title, axis label, unit, series name) is empty.
    #[error("chart {chart:?}: the {field} is empty")]
    MissingText {
        /// The chart's name.
        chart: String,
        /// Which text.
        field: &'static str,
    },
    /// The chart's name is not usable as a file stem.
    #[error("chart name {name:?}: use lower-case letters, digits, '-' and '_' only")]
    InvalidName {
        /// The rejected name.
        name: String,
    },
    /// The chart has more curves than colours: two would share one.
    #[error("chart {chart:?} has {curves} curves of their own colour; at most {colours} can be told apart")]
    TooManyColours {
        /// The chart's name.
        chart: String,
        /// Curves that need a colour of their own.
        curves: usize,
        /// Colours in the palette.
        colours: usize,
    },
    /// No cell of a regime map can be drawn. (A [`Chart`](super::Chart) with no point
    /// is drawn, with the note [`NO_DATA`](super::NO_DATA) over empty axes.)
    #[error("chart {chart:?} has no point that can be drawn on its axes")]
    NoDrawablePoints {
        /// The chart's name.
        chart: String,
    },
    /// The embedded font could not be parsed.
    #[error("the embedded font could not be registered")]
    Font,
    /// The drawing backend failed.
    #[error("drawing chart {chart:?} failed: {reason}")]
    Backend {
        /// The chart's name.
        chart: String,
        /// The backend's message.
        reason: String,
    },
    /// PNG encoding failed.
    #[error("encoding the PNG of chart {chart:?} failed: {reason}")]
    Png {
        /// The chart's name.
        chart: String,
        /// The encoder's message.
        reason: String,
    },
}
