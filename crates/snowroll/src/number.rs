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

/// Significant digits of [`format_readable`]: enough for any figure a
/// person compares by eye, few enough that rounding noise never shows.
pub const READABLE_DIGITS: usize = 6;

/// A number for text people read (a summary line, a note on stderr): `x`
/// rounded to [`READABLE_DIGITS`] significant digits, then written in its
/// shortest digits by [`format_number`], so `9.81 · sin 30°` reads `4.905`,
/// not `4.904999999999999`. Data files keep [`format_number`]'s exact digits.
///
/// ```
/// use snowroll::format_readable;
/// assert_eq!(format_readable(9.81 * 30f64.to_radians().sin()), "4.905");
/// assert_eq!(format_readable(1.0 / 3.0), "0.333333");
/// assert_eq!(format_readable(0.1 + 0.2), "0.3");
/// assert_eq!(format_readable(-2.5e-7), "-2.5e-7");
/// assert_eq!(format_readable(f64::INFINITY), "inf");
/// ```
pub fn format_readable(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return format_number(x);
    }
    let rounded: f64 = format!("{:.*e}", READABLE_DIGITS - 1, x)
        .parse()
        .unwrap_or(x);
    format_number(rounded)
}
