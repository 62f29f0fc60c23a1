//! Numbers in messages and outputs: the shortest decimal digits that
//! round-trip, in plain or exponent form by magnitude.

/// A number as people read it and programs parse it back exactly: the
/// shortest decimal digits that round-trip to the same `f64` (Rust's `{}`
/// and `{:e}` both give those), plain for ordinary magnitudes and in
/// exponent form for very small or very large ones (`1e-300`, `1e150`, not
/// hundreds of zeros).
///
/// ```
/// use snowroll::format_number;
/// assert_eq!(format_number(0.01), "0.01");
/// assert_eq!(format_number(1e308), "1e308");
/// assert_eq!(format_number(1.5e-7), "1.5e-7");
/// assert_eq!(format_number(0.1 + 0.2).parse::<f64>(), Ok(0.1 + 0.2));
/// ```
pub fn format_number(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e9).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        x.to_string()
    }
}
