//! Tick labels: one format for every tick of an axis.
//!
//! An axis whose ticks all lie between 0.01 and 10⁴ in size is labelled in
//! plain decimals, every tick with the same number of decimals on a linear
//! axis (`0.0, 0.1, 0.2`); any other axis in powers of ten, every mantissa
//! with the same number of decimals (`5×10⁻³, 10⁻², 1.5×10⁻²` is not mixed
//! with `0.01`). A tick within 10⁻¹² of the axis' span of zero is `0`, never
//! `8.67×10⁻¹⁹` nor `−0.0`.

/// Ticks closer to zero than this fraction of the axis' span are zero.
const ZERO_FRACTION: f64 = 1e-12;

/// Plain decimals are used when every nonzero tick's size is in this range.
const PLAIN: std::ops::Range<f64> = 1e-2..1e4;

/// Most decimals a label carries (more would be noise from the tick step).
const MAX_DECIMALS: usize = 4;

/// The format of every label of one axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AxisTicks {
    /// Values of at most this size are printed as `0`.
    zero: f64,
    /// How every tick is written.
    format: Format,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    /// Plain decimals, this many after the point on every tick.
    Fixed(usize),
    /// Plain decimals, each tick as short as it can be (a log axis, whose
    /// ticks 0.01, 0.1, 1, 10 differ in decimals by nature).
    Shortest,
    /// `m×10ⁿ`, every mantissa with this many decimals (`10ⁿ` when it is 1
    /// with none).
    Powers(usize),
}

impl AxisTicks {
    /// The format for an axis with tick values `ticks` spanning `span`
    /// (its drawn range), logarithmic when `log`.
    pub(crate) fn new(ticks: &[f64], span: f64, log: bool) -> Self {
        // A log axis holds no zero: 10⁻⁹ on an axis to 10⁶ is a decade,
        // not round-off.
        let zero = if log { 0.0 } else { ZERO_FRACTION * span.abs() };
        let nonzero: Vec<f64> = ticks
            .iter()
            .copied()
            .filter(|v| v.is_finite() && v.abs() > zero)
            .collect();
        let plain = nonzero.iter().all(|v| PLAIN.contains(&v.abs()));
        let format = match (plain, log) {
            (true, true) => Format::Shortest,
            (true, false) => match decimals_for(&nonzero, |v| v) {
                Some(d) => Format::Fixed(d),
                None => Format::Powers(mantissa_decimals(&nonzero)),
            },
            (false, _) => Format::Powers(mantissa_decimals(&nonzero)),
        };
        Self { zero, format }
    }

    /// The label of tick `v`, with a Unicode minus.
    pub(crate) fn label(&self, v: f64) -> String {
        if !v.is_finite() {
            return crate::notation::fixed(v, 0);
        }
        if v.abs() <= self.zero || v == 0.0 {
            return match self.format {
                Format::Fixed(d) => format!("{:.d$}", 0.0),
                _ => "0".to_string(),
            };
        }
        let sign = if v < 0.0 { "−" } else { "" };
        let a = v.abs();
        let body = match self.format {
            Format::Fixed(d) => format!("{a:.d$}"),
            Format::Shortest => shortest(a),
            Format::Powers(d) => power(a, d),
        };
        format!("{sign}{body}")
    }
}

/// The fewest decimals (at most [`MAX_DECIMALS`]) that write every value of
/// `values`, mapped by `f`, exactly (to 10⁻⁹ of its size); `None` if more
/// are needed.
fn decimals_for(values: &[f64], f: impl Fn(f64) -> f64) -> Option<usize> {
    (0..=MAX_DECIMALS).find(|&d| {
        let k = 10_f64.powi(d as i32);
        values.iter().all(|&v| {
            let x = f(v);
            ((x * k).round() / k - x).abs() <= 1e-9 * x.abs().max(1e-300)
        })
    })
}

/// The decade of `a > 0` and its mantissa in [1, 10).
fn split(a: f64) -> (f64, i32) {
    let mut e = a.log10().floor() as i32;
    let mut m = a / 10_f64.powi(e);
    // log10 of 1000 may come out as 2.9999…: keep the mantissa in [1, 10).
    if m >= 10.0 - 1e-9 {
        m /= 10.0;
        e += 1;
    }
    (m, e)
}

/// The decimals every mantissa of `values` needs (at most [`MAX_DECIMALS`]).
fn mantissa_decimals(values: &[f64]) -> usize {
    decimals_for(values, |v| split(v.abs()).0).unwrap_or(MAX_DECIMALS)
}

/// `a > 0` as `m×10ⁿ` with `d` decimals in `m`; `10ⁿ` when `m` is 1 and `d` 0.
fn power(a: f64, d: usize) -> String {
    let (m, mut e) = split(a);
    let mut m = format!("{m:.d$}");
    // 9.96 at one decimal rounds to 10.0: one decade up.
    if m.starts_with("10") {
        e += 1;
        m = format!("{:.d$}", 1.0);
    }
    let p = format!("10{}", crate::notation::superscript(&e.to_string()));
    if m == "1" {
        p
    } else {
        format!("{m}×{p}")
    }
}

/// `a > 0` in plain decimals, as few as write it to [`MAX_DECIMALS`].
fn shortest(a: f64) -> String {
    let s = format!("{a:.prec$}", prec = MAX_DECIMALS);
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A log axis spanning at most this many decades is also labelled at 2 and
/// 5 of each decade (the regime map's 0.5–80°: 0.5, 1, 2, 5, 10, 20, 50;
/// turns 1–2000: 1, 2, 5, …, 1000, 2000), each decade then being at least
/// a sixth of a figure's plot; a wider one at its decades only.
const WIDE_DECADES: f64 = 4.0;

/// Most decades a log axis labels; a wider axis labels every second (or
/// third …) decade, so that labels such as `10⁻¹⁰` do not run together.
const MOST_DECADES: usize = 12;

/// The labelled ticks of a log axis drawn over `lo..hi` (both > 0): every
/// decade inside, and 2 and 5 of each decade when the axis spans at most
/// [`WIDE_DECADES`]; every integer multiple of a decade when fewer than two
/// ticks would be labelled otherwise. The second vector holds the unlabelled
/// minor ticks for light grid lines: the other multiples 2…9 of each decade
/// on a narrow axis, the unlabelled decades on a wide one.
pub(crate) fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return (Vec::new(), Vec::new());
    }
    let inside = |v: f64| v >= lo * (1.0 - 1e-12) && v <= hi * (1.0 + 1e-12);
    let multiples = |ms: &[u32]| -> Vec<f64> {
        let (e0, e1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
        (e0..=e1)
            .flat_map(|e| ms.iter().map(move |&m| f64::from(m) * 10_f64.powi(e)))
            .filter(|&v| inside(v))
            .collect()
    };
    let all = multiples(&[1, 2, 3, 4, 5, 6, 7, 8, 9]);
    let mut bold = if (hi / lo).log10() <= WIDE_DECADES {
        multiples(&[1, 2, 5])
    } else {
        // Every decade while their labels fit; beyond, every second or
        // third (by exponent, so 10⁰ stays labelled), the others light.
        let decades = multiples(&[1]);
        let step = decades.len().div_ceil(MOST_DECADES).max(1) as i32;
        decades
            .into_iter()
            .filter(|v| (v.log10().round() as i32).rem_euclid(step) == 0)
            .collect()
    };
    if bold.len() < 2 {
        bold.clone_from(&all);
    }
    // Light lines at the other multiples where a decade is wide; on a wide
    // axis at the unlabelled decades only (eight lines a decade would be a
    // grey wash).
    let wide = (hi / lo).log10() > WIDE_DECADES;
    let light = if wide { multiples(&[1]) } else { all }
        .into_iter()
        .filter(|v| !bold.iter().any(|b| (b - v).abs() <= 1e-9 * v))
        .collect();
    (bold, light)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_narrow_log_axis_is_labelled_at_1_2_5_of_each_decade() {
        let (bold, light) = log_ticks(0.45, 90.0);
        let f = AxisTicks::new(&bold, 90.0 - 0.45, true);
        let labels: Vec<String> = bold.iter().map(|&v| f.label(v)).collect();
        assert_eq!(labels, ["0.5", "1", "2", "5", "10", "20", "50"]);
        assert!(light.iter().any(|&v| (v - 3.0).abs() < 1e-12));
        assert!(!light.iter().any(|&v| (v - 2.0).abs() < 1e-12));
    }

    #[test]
    fn a_wide_log_axis_is_labelled_at_every_decade() {
        let (bold, _) = log_ticks(3e-7, 2.0);
        assert_eq!(log_ticks(1.0, 2000.0).0.len(), 11, "1, 2, 5 … 1000, 2000");
        assert_eq!(bold.len(), 7, "{bold:?}");
        for (v, e) in bold.iter().zip(-6..=0) {
            assert!((v / 10_f64.powi(e) - 1.0).abs() < 1e-12, "{v} vs 1e{e}");
        }
    }

    #[test]
    fn a_log_axis_of_many_decades_labels_every_second_and_no_zero() {
        let (bold, light) = log_ticks(3e-14, 2e6);
        let f = AxisTicks::new(&bold, 2e6, true);
        let labels: Vec<String> = bold.iter().map(|&v| f.label(v)).collect();
        assert_eq!(
            labels,
            [
                "10⁻¹²",
                "10⁻¹⁰",
                "10⁻⁸",
                "10⁻⁶",
                "10⁻⁴",
                "10⁻²",
                "10⁰",
                "10²",
                "10⁴",
                "10⁶"
            ]
        );
        assert!(light.iter().any(|&v| (v / 1e-9 - 1.0).abs() < 1e-9));
        assert!(!light.iter().any(|&v| (v / 2e-9 - 1.0).abs() < 1e-9));
    }

    #[test]
    fn a_log_axis_inside_one_decade_gets_every_multiple() {
        let (bold, _) = log_ticks(2.5, 4.5);
        assert_eq!(bold, [3.0, 4.0]);
    }

    /// Labels of `ticks` on a linear axis of span `span`.
    fn linear(ticks: &[f64], span: f64) -> Vec<String> {
        let f = AxisTicks::new(ticks, span, false);
        ticks.iter().map(|&v| f.label(v)).collect()
    }

    #[test]
    fn a_linear_axis_has_one_number_of_decimals() {
        assert_eq!(
            linear(&[0.0, 0.1, 0.2, 0.3], 0.35),
            ["0.0", "0.1", "0.2", "0.3"]
        );
        assert_eq!(
            linear(&[-0.5, 0.0, 0.5, 1.0], 1.6),
            ["−0.5", "0.0", "0.5", "1.0"]
        );
        assert_eq!(linear(&[0.0, 500.0, 1000.0], 1100.0), ["0", "500", "1000"]);
    }

    #[test]
    fn small_ticks_are_all_powers_never_mixed_with_decimals() {
        // 0.008 is below 0.01: the whole axis goes to powers of ten, and
        // 1.2×10⁻² gives every mantissa one decimal.
        assert_eq!(
            linear(&[0.006, 0.008, 0.01, 0.012], 0.007),
            ["6.0×10⁻³", "8.0×10⁻³", "1.0×10⁻²", "1.2×10⁻²"]
        );
        assert_eq!(linear(&[0.005, 0.01], 0.006), ["5×10⁻³", "10⁻²"]);
    }

    #[test]
    fn a_mantissa_has_the_decimals_of_the_axis() {
        // 1.5×10⁻³ needs one decimal, so every mantissa carries one.
        assert_eq!(
            linear(&[5e-4, 1e-3, 1.5e-3], 1.2e-3),
            ["5.0×10⁻⁴", "1.0×10⁻³", "1.5×10⁻³"]
        );
    }

    #[test]
    fn round_off_beside_zero_is_zero_and_zero_has_no_sign() {
        // 8.67e-19 is 1e-18 of the span: round-off of a tick at zero.
        assert_eq!(linear(&[-0.5, 8.67e-19, 0.5], 1.2), ["−0.5", "0.0", "0.5"]);
        assert_eq!(linear(&[-0.0, 1.0, 2.0], 2.2), ["0", "1", "2"]);
        // A value that is not round-off keeps its size.
        assert_eq!(linear(&[0.0, 2e-12], 4e-12), ["0", "2×10⁻¹²"]);
    }

    #[test]
    fn a_log_axis_is_plain_in_range_else_decades() {
        let f = AxisTicks::new(&[1.0, 10.0, 100.0, 1000.0], 2000.0, true);
        assert_eq!(f.label(1.0), "1");
        assert_eq!(f.label(1000.0), "1000");
        let f = AxisTicks::new(&[1e-6, 1e-4, 1e-2, 1.0], 1.0, true);
        assert_eq!(f.label(1e-6), "10⁻⁶");
        assert_eq!(f.label(1e-2), "10⁻²");
        assert_eq!(f.label(1.0), "10⁰");
        let f = AxisTicks::new(&[0.01, 0.1, 1.0], 1.0, true);
        assert_eq!([f.label(0.01), f.label(0.1)], ["0.01", "0.1"]);
    }

    #[test]
    fn mantissas_that_round_up_move_a_decade() {
        assert_eq!(power(9.999_999_9e-3, 0), "10⁻²");
        assert_eq!(power(1000.0, 0), "10³");
        assert_eq!(power(2.5e7, 1), "2.5×10⁷");
    }
}
