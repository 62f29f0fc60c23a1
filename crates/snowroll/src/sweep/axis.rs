//! The axes of a sweep: the parameters a sweep can vary ([`AxisParam`]), the
//! values of one axis ([`Values`], a list or a range never expanded into
//! memory), and what can be wrong with them ([`GridError`]).

use std::fmt;

mod grid_error;
use crate::error::ParamError;
use crate::number::{format_number, READABLE_DIGITS};
use crate::params::{Kind, Settings, Value, PARAMS, TABLE};
#[cfg(test)]
pub(crate) use grid_error::count_text;
pub use grid_error::GridError;

/// A parameter that a sweep can vary: a row of the parameter table
/// ([`PARAMS`]) that a sweep varies (`sweep: true`) and that is a number
/// (kind real or optional real). The axes, their order, keys, checks and
/// setters, and the sweep rows' columns all follow from the table: a new
/// numeric sweep parameter is a new row there and nothing here.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AxisParam(
    /// Its row's place in [`PARAMS`] (the grid's order is the table's).
    u8,
);

/// Whether a row of the table is an axis of a sweep.
const fn is_axis(p: &crate::params::Param) -> bool {
    p.sweep && matches!(p.kind, Kind::Real | Kind::OptionalReal)
}

/// How many rows of the table are axes.
pub(crate) const AXES: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < TABLE.len() {
        if is_axis(&TABLE[i]) {
            n += 1;
        }
        i += 1;
    }
    n
};

/// Whether two keys are the same text (a `const` comparison).
const fn same_key(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

impl AxisParam {
    /// Every parameter, in grid order (the last varies fastest): the
    /// table's numeric sweep rows, in the table's order.
    pub const ALL: [AxisParam; AXES] = {
        let mut all = [AxisParam(0); AXES];
        let (mut n, mut i) = (0, 0);
        while i < TABLE.len() {
            if is_axis(&TABLE[i]) {
                all[n] = AxisParam(i as u8);
                n += 1;
            }
            i += 1;
        }
        all
    };

    /// The axis of `key`, for a key known when the program is written:
    /// use it in a `const` (`const ALPHA: AxisParam = AxisParam::named("alpha_deg")`)
    /// so that a key that is not an axis fails to compile.
    ///
    /// # Panics
    /// When `key` is not the key of an axis: in a `const`, which is where
    /// the library and the report call it, that is a build error, never a
    /// panic of a run (tests call it directly too).
    #[allow(
        clippy::panic,
        reason = "called in `const` items and blocks: a wrong key fails the build"
    )]
    pub const fn named(key: &str) -> AxisParam {
        let mut k = 0;
        while k < AxisParam::ALL.len() {
            if same_key(TABLE[AxisParam::ALL[k].0 as usize].key, key) {
                return AxisParam::ALL[k];
            }
            k += 1;
        }
        panic!("not a numeric sweep parameter of the table")
    }

    /// Its row of the parameter table.
    pub fn spec(self) -> &'static crate::params::Param {
        &PARAMS[usize::from(self.0)]
    }

    /// Its key, in a `const` (the sweep rows' column names are computed
    /// from it at compile time).
    pub(crate) const fn key_const(self) -> &'static str {
        TABLE[self.0 as usize].key
    }

    /// Its place among the axes: its index in [`AxisParam::ALL`] (a sweep
    /// row's [`params`](super::SweepRow::params)).
    pub fn axis_index(self) -> usize {
        /// The axis index of each row of the table (`u8::MAX` for a row
        /// that is not an axis).
        const OF_ROW: [u8; TABLE.len()] = {
            let mut of = [u8::MAX; TABLE.len()];
            let mut k = 0;
            while k < AxisParam::ALL.len() {
                of[AxisParam::ALL[k].0 as usize] = k as u8;
                k += 1;
            }
            of
        };
        usize::from(OF_ROW[usize::from(self.0)])
    }

    /// The snake-case key (config files, CSV columns, metadata).
    pub fn key(self) -> &'static str {
        self.spec().key
    }

    /// The parameter of a snake-case key or a kebab-case flag name.
    pub fn from_key(key: &str) -> Option<AxisParam> {
        let key = key.replace('-', "_");
        AxisParam::ALL.into_iter().find(|p| p.key() == key)
    }

    /// Sets it to `x` in `settings`, with the table's setter.
    ///
    /// # Errors
    /// Never for an axis (a number is of its kind); [`ParamError`] from the
    /// table's setter otherwise.
    pub fn set(self, settings: &mut Settings, x: f64) -> Result<(), ParamError> {
        self.spec().set_real(settings, x)
    }

    /// Its value in `settings` (`None` for an optional one that is unset).
    pub fn get(self, settings: &Settings) -> Option<f64> {
        match self.spec().get(settings) {
            Value::Real(x) => Some(x),
            _ => None,
        }
    }
}

impl fmt::Debug for AxisParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "AxisParam({})", self.key())
    }
}

impl fmt::Display for AxisParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// The values of one axis: a list, or an evenly spaced range that is never
/// expanded into memory.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// These values, in this order.
    List(Vec<f64>),
    /// `count` values from `start` to `end` inclusive, evenly spaced.
    Range {
        /// First value.
        start: f64,
        /// Last value.
        end: f64,
        /// How many, ≥ 1 (1 only when `start == end`).
        count: u64,
    },
}

impl Values {
    /// Parses `a,b,c` (a list) or `start:end:count` (a range, both ends
    /// included).
    ///
    /// # Errors
    /// [`GridError::Syntax`] naming `param` for anything else, for non-finite
    /// numbers, and for a count of 0 (or of 1 with different ends).
    pub fn parse(param: &str, text: &str) -> Result<Values, GridError> {
        let bad = |reason: &str| GridError::Syntax {
            param: param.to_string(),
            text: text.to_string(),
            reason: reason.to_string(),
        };
        let number = |s: &str| -> Result<f64, GridError> {
            let s = s.trim();
            match s.parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(x),
                Ok(_) => Err(bad(&format!("{s} is not a finite number"))),
                Err(_) => Err(bad(&format!("{s:?} is not a number"))),
            }
        };
        if text.contains(':') {
            let parts: Vec<&str> = text.split(':').collect();
            let [start, end, count] = parts[..] else {
                return Err(bad("a range is start:end:count, e.g. 5:60:12"));
            };
            let (start, end) = (number(start)?, number(end)?);
            let count: u64 = count.trim().parse().map_err(|_| {
                bad(&format!(
                    "the count {:?} is not a whole number >= 1",
                    count.trim()
                ))
            })?;
            if count == 0 {
                return Err(bad("the count of a range must be at least 1"));
            }
            if count == 1 && start.to_bits() != end.to_bits() {
                return Err(bad(
                    "a range of 1 value needs start = end (give one value instead)",
                ));
            }
            return Ok(Values::Range { start, end, count });
        }
        let list = text
            .split(',')
            .map(|s| {
                if s.trim().is_empty() {
                    Err(bad("empty item in the list"))
                } else {
                    number(s)
                }
            })
            .collect::<Result<Vec<f64>, GridError>>()?;
        Ok(Values::List(list))
    }

    /// How many values.
    pub fn len(&self) -> u64 {
        match self {
            Values::List(v) => v.len() as u64,
            Values::Range { count, .. } => *count,
        }
    }

    /// Whether there are none (never, for a parsed axis).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `k`-th value, `k < len()`. For a range it is
    /// `start + (end − start)·k/(count − 1)` in decimal: with the decimal
    /// places of `start` and `end` as written, and of the step where it ends
    /// within 15 significant digits (`0.001:0.1:100` gives `0.012`, not
    /// `0.012000000000000002`); a step that does not end (`0:1:4`) is kept
    /// to [`READABLE_DIGITS`] significant digits. The value returned is the
    /// `f64` of that decimal, so the value printed ([`format_number`]) is
    /// the value run, and a row reruns from its printed values. The ends are
    /// exactly `start` and `end`. Ends too far apart in magnitude for exact
    /// integer arithmetic (`1e-100:1:3`) fall back to the binary formula.
    pub fn get(&self, k: u64) -> f64 {
        self.get_planned(self.decimal_range().as_ref(), k)
    }

    /// [`Values::get`] with the plan [`Values::decimal_range`] made
    /// beforehand (a grid makes it once per axis, not once per point).
    pub fn get_planned(&self, plan: Option<&DecimalRange>, k: u64) -> f64 {
        match self {
            Values::List(v) => v.get(k as usize).copied().unwrap_or(f64::NAN),
            Values::Range { start, end, count } => {
                if k + 1 >= *count {
                    *end
                } else if k == 0 {
                    *start
                } else {
                    match plan {
                        Some(plan) => plan.value(k),
                        None => start + (end - start) * (k as f64 / (*count - 1) as f64),
                    }
                }
            }
        }
    }

    /// The decimal plan of a range ([`DecimalRange`]), made once so that
    /// [`Values::get`]'s values cost no text; `None` for a list, a range of
    /// one value, or ends too far apart for exact integers.
    pub fn decimal_range(&self) -> Option<DecimalRange> {
        match self {
            Values::List(_) => None,
            Values::Range { start, end, count } => DecimalRange::new(*start, *end, *count),
        }
    }

    /// The smallest and largest values: every value lies between them, so
    /// checking these two checks the axis against an interval.
    pub(super) fn bounds(&self) -> (f64, f64) {
        match self {
            Values::List(v) => v
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                    (lo.min(x), hi.max(x))
                }),
            Values::Range { start, end, .. } => (start.min(*end), start.max(*end)),
        }
    }
}

impl fmt::Display for Values {
    /// As it would be typed: `a,b,c` or `start:end:count`, each number as
    /// every output writes one ([`format_number`]: exponent form outside
    /// 1e-4..1e9, the shortest text that reads back to the same value).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Values::List(v) => {
                let items: Vec<String> = v.iter().map(|&x| format_number(x)).collect();
                f.write_str(&items.join(","))
            }
            Values::Range { start, end, count } => write!(
                f,
                "{}:{}:{count}",
                format_number(*start),
                format_number(*end)
            ),
        }
    }
}

/// `x` as ±`digits`·10^`exp` with the fewest digits (the shortest text
/// that round-trips): `0.012` is (12, −3), `2.5e12` is (25, 11).
fn decimal_parts(x: f64) -> Option<(i128, i32)> {
    let text = format!("{:e}", x.abs());
    let (mantissa, exp) = text.split_once('e')?;
    let exp: i32 = exp.parse().ok()?;
    let (whole, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: i128 = format!("{whole}{frac}").parse().ok()?;
    let sign = if x < 0.0 { -1 } else { 1 };
    Some((sign * digits, exp - frac.len() as i32))
}

/// `10^n` for `n ≥ 0`, if it fits.
fn pow10(n: i32) -> Option<i128> {
    10i128.checked_pow(u32::try_from(n).ok()?)
}

/// `num/den` rounded to the nearest integer, halves away from zero; `den > 0`.
fn div_round(num: i128, den: i128) -> i128 {
    let (q, r) = (num / den, num % den);
    if 2 * r.abs() >= den {
        q + num.signum()
    } else {
        q
    }
}

/// The decimal values of a range `start:end:count` ([`Values::get`]): the
/// k-th is `(start + k·span/intervals)·10^exp` in integers, `span/intervals`
/// rounded to the nearest integer where it does not end. Made once per axis
/// ([`Values::decimal_range`]), so that a grid's points cost no text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DecimalRange {
    /// `start` in units of 10^`exp`.
    start: i128,
    /// `end − start` in units of 10^`exp` (divided by `intervals` only
    /// after the multiplication by k, so that the k-th value rounds once).
    span: i128,
    /// `count − 1`.
    intervals: i128,
    /// The decimal exponent of the unit.
    exp: i32,
}

impl DecimalRange {
    /// The plan of `start:end:count` (`count ≥ 2`), or `None` when its
    /// integers would overflow.
    pub fn new(start: f64, end: f64, count: u64) -> Option<Self> {
        let ((ds, es), (de, ee)) = (decimal_parts(start)?, decimal_parts(end)?);
        // Both ends as integers of the unit 10^low.
        let low = es.min(ee);
        let s = ds.checked_mul(pow10(es - low)?)?;
        let e = de.checked_mul(pow10(ee - low)?)?;
        let span = e.checked_sub(s)?;
        let intervals = i128::from(count.checked_sub(1).filter(|&n| n > 0)?);
        // Extra decimal places: the fewest at which the step ends, while it
        // has at most 15 significant digits; else READABLE_DIGITS of the step.
        let mut extra = 0;
        loop {
            let scaled = span.checked_mul(pow10(extra)?)?;
            if scaled % intervals == 0 {
                break;
            }
            if (scaled / intervals).abs() >= pow10(15)? {
                extra = 0;
                while (span.checked_mul(pow10(extra)?)? / intervals).abs()
                    < pow10(READABLE_DIGITS as i32 - 1)?
                {
                    extra += 1;
                }
                break;
            }
            extra += 1;
        }
        let unit = pow10(extra)?;
        let plan = Self {
            start: s.checked_mul(unit)?,
            span: span.checked_mul(unit)?,
            intervals,
            exp: low - extra,
        };
        // Every k ≤ intervals must fit: the largest offset is span·intervals.
        plan.span.checked_mul(intervals)?;
        Some(plan)
    }

    /// The `k`-th value (`k ≤ count − 1`).
    pub fn value(&self, k: u64) -> f64 {
        let k = i128::from(k).min(self.intervals);
        // Cannot overflow: checked for k = intervals in `new`.
        let v = self.start + div_round(self.span * k, self.intervals);
        decimal_to_f64(v, self.exp)
    }
}

/// Exact powers of ten in `f64`, 10^0 to 10^22.
const POW10_F64: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// `v·10^exp` rounded to the nearest `f64`, as parsing its text would give:
/// one IEEE multiplication or division of two exact numbers where `v` fits
/// in 53 bits and |exp| ≤ 22 (correctly rounded), else by parsing.
fn decimal_to_f64(v: i128, exp: i32) -> f64 {
    if v.unsigned_abs() <= 1 << 53 {
        if let Some(&p) = POW10_F64.get(exp.unsigned_abs() as usize) {
            let m = v as f64;
            return if exp >= 0 { m * p } else { m / p };
        }
    }
    format!("{v}e{exp}").parse().unwrap_or(f64::NAN)
}

/// One swept parameter and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Which parameter.
    pub param: AxisParam,
    /// Its values.
    pub values: Values,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A header's axis line reads back to the values it was written from,
    /// bit for bit, and a tiny or huge value is in exponent form (issue 20:
    /// `# alpha_deg: 0.000…0001` had a hundred digits).
    #[test]
    fn values_print_in_exponent_form_outside_the_plain_range_and_read_back() {
        for text in [
            "1e-100,0.5",
            "1e-10,0.0001,1e9,2.5e12",
            "1e-12:1e-6:3",
            "5:60:12",
        ] {
            let values = Values::parse("rtol", text).unwrap();
            let shown = values.to_string();
            assert!(shown.len() < 40, "{text} shown as {shown}");
            assert_eq!(Values::parse("rtol", &shown).unwrap(), values, "{shown}");
        }
        let shown = Values::parse("rtol", "1e-100,0.5").unwrap().to_string();
        assert_eq!(shown, "1e-100,0.5");
    }

    /// Issue 32, item 7: a range's values have the decimal digits its spec
    /// needs, printed and run alike.
    #[test]
    fn range_values_have_the_digits_of_their_spec() {
        let shown = |text: &str| -> Vec<String> {
            let v = Values::parse("snow_depth", text).unwrap();
            (0..v.len()).map(|k| format_number(v.get(k))).collect()
        };
        let fine = shown("0.001:0.1:100");
        assert_eq!(fine[11], "0.012");
        for (k, text) in fine.iter().enumerate() {
            let want: f64 = format!("{:.3}", 0.001 * (k + 1) as f64).parse().unwrap();
            assert_eq!(text, &format_number(want), "{k}");
            assert!(text.len() <= 5, "{text}");
        }
        assert_eq!(shown("0.1:0.7:4"), ["0.1", "0.3", "0.5", "0.7"]);
        assert_eq!(shown("1e-12:1e-6:3"), ["1e-12", "5.000005e-7", "1e-6"]);
        assert_eq!(shown("0:1:4"), ["0", "0.333333", "0.666667", "1"]);
        assert_eq!(shown("31:29:3"), ["31", "30", "29"]);
        assert_eq!(shown("-1:1:5"), ["-1", "-0.5", "0", "0.5", "1"]);
        assert_eq!(shown("0:1:9")[3], "0.375");
        assert_eq!(shown("0:1:8")[3], "0.428571");
        // Ends too far apart for i128: the binary formula, still in range.
        let wide = shown("1e-100:1:3");
        assert_eq!(wide[0], "1e-100");
        assert_eq!(wide[1], "0.5");
        assert_eq!(wide[2], "1");
    }

    /// The fast conversion of a planned value (one IEEE operation on exact
    /// numbers, [`decimal_to_f64`]) gives the `f64` that parsing the
    /// decimal's text gives, and a grid's planned values are `get`'s.
    #[test]
    fn planned_values_are_their_decimals_parsed() {
        for text in [
            "0.001:0.1:1000",
            "1e-12:1e-6:7",
            "5:60:12",
            "0:1:3",
            "1.5e-300:2.5e-300:11",
            "123456.789:987654.321:77",
            "0.3:0.1:7",
            "1e-5:89.99:1001",
            "9007199254740993:9007199254741993:3",
        ] {
            let v = Values::parse("x", text).unwrap();
            let plan = v.decimal_range();
            assert!(plan.is_some(), "{text}");
            for k in 0..v.len() {
                let p = plan.unwrap();
                let exact = p.start + div_round(p.span * i128::from(k), p.intervals);
                let parsed: f64 = format!("{exact}e{}", p.exp).parse().unwrap();
                assert_eq!(p.value(k).to_bits(), parsed.to_bits(), "{text}, k = {k}");
                assert_eq!(
                    v.get(k).to_bits(),
                    v.get_planned(plan.as_ref(), k).to_bits(),
                    "{text}, k = {k}"
                );
            }
        }
    }
}
