//! Numbers as CSV text, in the bytes the `csv` writer gives them (floats by
//! `ryu`, integers by `itoa`): the one float formatter of every hand-written
//! CSV row (turn tables, sweeps).

/// Appends finite `x` as `ryu` (and so `csv`) writes it: `zmij` gives the
/// same shortest round-trip digits in the same layout, except that it
/// writes a positive exponent with its sign (`1e+16` for ryu's `1e16`).
/// Checked against `ryu` on 5·10⁷ numbers of every decimal exponent (no
/// other difference), and in the tests below.
pub(crate) fn push_float(out: &mut Vec<u8>, buffer: &mut zmij::Buffer, x: f64) {
    let text = buffer.format_finite(x).as_bytes();
    // Both write |x| ≥ 1e16 (and only those) with a positive exponent.
    let plus = match x.abs() >= 1e16 {
        true => text.iter().position(|&b| b == b'+'),
        false => None,
    };
    match plus {
        Some(plus) => {
            out.extend_from_slice(&text[..plus]);
            out.extend_from_slice(&text[plus + 1..]);
        }
        None => out.extend_from_slice(text),
    }
}

/// Appends `x` as `csv` writes it: [`push_float`] for a finite number, and
/// `ryu`'s `NaN`, `inf`, `-inf` otherwise.
pub(crate) fn push_any_float(out: &mut Vec<u8>, buffer: &mut zmij::Buffer, x: f64) {
    if x.is_finite() {
        push_float(out, buffer, x);
    } else if x.is_nan() {
        out.extend_from_slice(b"NaN");
    } else if x > 0.0 {
        out.extend_from_slice(b"inf");
    } else {
        out.extend_from_slice(b"-inf");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`push_float`] writes what `ryu` (the `csv` writer's formatter)
    /// writes, for numbers of every decimal exponent, both signs, around
    /// the switches to exponent form (1e-5, 1e16) and at the ends of the
    /// range. Fails without the exponent's `+` removed.
    #[test]
    fn floats_are_written_as_ryu_writes_them() {
        let mut ryu = ryu::Buffer::new();
        let mut zmij = zmij::Buffer::new();
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut numbers = vec![0.0, -0.0, 5e-324, f64::MIN_POSITIVE, f64::MAX, 1e-5, 1e16];
        // The doubles just below the two switches.
        numbers.extend([1e16, 1e-5].map(|x: f64| f64::from_bits(x.to_bits() - 1)));
        for e in -324..=308 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let mantissa = 1.0 + (state >> 11) as f64 / (1u64 << 53) as f64 * 9.0;
            let x = mantissa * 10f64.powi(e);
            numbers.extend([x, -x, 10f64.powi(e), x.round()]);
        }
        for x in numbers.into_iter().filter(|x| x.is_finite()) {
            let mut out = Vec::new();
            push_float(&mut out, &mut zmij, x);
            assert_eq!(out, ryu.format_finite(x).as_bytes(), "{x:e}");
        }
    }

    /// Non-finite numbers are `ryu`'s words.
    #[test]
    fn non_finite_floats_are_ryus_words() {
        let mut zmij = zmij::Buffer::new();
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1.5] {
            let mut out = Vec::new();
            push_any_float(&mut out, &mut zmij, x);
            assert_eq!(out, ryu::Buffer::new().format(x).as_bytes(), "{x}");
        }
    }
}
