//! Which samples a run records ([`Sampling`]), and the times of a regular
//! grid, exact to the decimal its step prints as.

use crate::error::ParamError;
use crate::units::Seconds;

/// Which samples a run records.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Sampling {
    /// The start and every accepted step (closed forms: 500 even steps).
    #[default]
    Steps,
    /// Exactly these times, s (strictly ascending, non-negative, none after
    /// `t_end`: [`SimOptions::validate`](super::SimOptions::validate)
    /// refuses those), from the dense output; times after an earlier stop
    /// (distance, stall) are not written, and the command line notes how
    /// many.
    Times(Vec<Seconds>),
    /// A regular grid 0, dt, 2dt, … up to the stop, s.
    Every(Seconds),
    /// Only the start and the end (fastest).
    Ends,
}

/// The number of points of the grid `0, dt, 2 dt, …` up to `t_end`,
/// counted as [`Sampling::grid_time`] places them (a point within a few
/// ulps of `t_end` is the last): `⌊t_end/dt⌋ + 1`, corrected by one where
/// the quotient's rounding falls on the other side of a point (dt = 0.1,
/// t_end = 0.3: 0.3/0.1 = 2.9999999999999996, yet 0.3 is a point, so 4
/// rows). Beyond 2^52 points the quotient itself is the count.
fn grid_rows(dt: Seconds, t_end: Seconds) -> f64 {
    /// Points looked at on either side of `t_end/dt`: the decimal grid
    /// points are within an ulp or two of `i dt` for a normal `dt`, so the
    /// last one is within a step or two of the quotient. The bound keeps a
    /// step that is not normal (refused by [`Sampling::validate`]) from
    /// searching for ever.
    const SEARCH: usize = 64;
    let n = (t_end / dt).floor();
    if !(0.0..4.0e15).contains(&n) {
        return n + 1.0;
    }
    let mut last = n as usize;
    for _ in 0..SEARCH {
        if Sampling::grid_time(dt, last + 1, t_end).is_none() {
            break;
        }
        last += 1;
    }
    for _ in 0..SEARCH {
        if last == 0 || Sampling::grid_time(dt, last, t_end).is_some() {
            break;
        }
        last -= 1;
    }
    last as f64 + 1.0
}

/// The range of a grid step that is not normal.
pub(crate) const NORMAL_DT: &str =
    "dt > 0 s, at least 2.2250738585072014e-308 s (a smaller, subnormal, step has too few \
     significant bits to count time by)";

impl Sampling {
    /// Point `i` of the regular grid `0, dt, 2dt, …` that ends at `t_end`, s;
    /// `None` past the end. A point within a few ulps of `t_end` (on either
    /// side) is moved onto it, so a grid that divides the run evenly ends
    /// exactly there.
    ///
    /// The point is `i` times the decimal that `dt` prints as (its shortest
    /// round-trip form), rounded once to the nearest `f64`: with `dt = 0.1`
    /// point 3 is `0.3`, not the `0.30000000000000004` of `3.0 * 0.1`. It lies
    /// within about one ulp of `i * dt`, and the grid never decreases with
    /// `i` (rounding to nearest is monotone); it increases strictly wherever
    /// `dt` is larger than the spacing of `f64` near the point.
    pub fn grid_time(dt: Seconds, i: usize, t_end: Seconds) -> Option<Seconds> {
        let t = decimal_multiple(dt, i);
        let near_end = (t - t_end).abs() <= 4.0 * f64::EPSILON * t_end;
        (t <= t_end || near_end).then_some(if near_end { t_end } else { t })
    }

    /// The number of samples this sampling records on a run that reaches
    /// `t_end`, when it is known before the run: the count of `Times`, and
    /// `⌊t_end/dt⌋ + 1` for `Every` (a float: it may exceed every integer).
    /// `None` for `Steps` (the step count is found while running); 2 for `Ends`.
    pub fn known_rows(&self, t_end: Seconds) -> Option<f64> {
        match self {
            Sampling::Times(ts) => Some(ts.len() as f64),
            Sampling::Every(dt) => Some(grid_rows(*dt, t_end)),
            Sampling::Steps => None,
            Sampling::Ends => Some(2.0),
        }
    }

    /// Checks times and grid spacing.
    ///
    /// # Errors
    /// [`ParamError::InvalidTimes`] for non-finite, negative, descending or repeated
    /// times; [`ParamError::InvalidParameter`] for a grid spacing `dt <= 0`.
    pub fn validate(&self) -> Result<(), ParamError> {
        match self {
            Sampling::Times(ts) => {
                if ts.iter().any(|t| !t.is_finite() || *t < 0.0) {
                    return Err(ParamError::InvalidTimes {
                        reason: "every time must be finite and >= 0 s",
                    });
                }
                if ts.windows(2).any(|w| w[1] < w[0]) {
                    return Err(ParamError::InvalidTimes {
                        reason: "times must be in ascending order",
                    });
                }
                if ts.windows(2).any(|w| w[1] <= w[0]) {
                    return Err(ParamError::InvalidTimes {
                        reason: "a time is repeated: each time may be asked for once",
                    });
                }
                Ok(())
            }
            Sampling::Every(dt) if !(dt.is_finite() && *dt > 0.0) => {
                Err(ParamError::InvalidParameter {
                    name: "dt (s)",
                    value: *dt,
                    expected: "dt > 0 s",
                })
            }
            // A subnormal step carries a few bits at most: its multiples
            // are not the decimals asked for, and counting them took
            // forever (issue 33, item 4: `--dt 5e-324 --t-end 1e-308`).
            Sampling::Every(dt) if !dt.is_normal() => Err(ParamError::InvalidParameter {
                name: "dt (s)",
                value: *dt,
                expected: NORMAL_DT,
            }),
            _ => Ok(()),
        }
    }
}

/// `i · dt` computed on the decimal that `dt` prints as: `dt = m · 10^e` with
/// integer `m` (the shortest digits that round-trip), then `(i m) · 10^e`
/// rounded once to the nearest `f64`. Falls back to `i as f64 * dt` for a
/// `dt` that is not finite and positive, or whose product does not fit.
fn decimal_multiple(dt: f64, i: usize) -> f64 {
    let plain = i as f64 * dt;
    if !(dt.is_finite() && dt > 0.0) {
        return plain;
    }
    // `{:e}` prints the shortest digits that round-trip: "2.5e-3", "1e-1".
    let text = format!("{dt:e}");
    let Some((digits, exp)) = text.split_once('e') else {
        return plain;
    };
    let (whole, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let (Ok(m), Ok(e)) = (format!("{whole}{frac}").parse::<u128>(), exp.parse::<i32>()) else {
        return plain;
    };
    let Some(im) = m.checked_mul(i as u128) else {
        return plain;
    };
    let e = e - frac.len() as i32;
    // Both factors exact in f64 (im < 2^53, 10^k exact up to k = 22): one
    // multiplication or division rounds once, correctly.
    if im < (1u128 << 53) && e.unsigned_abs() <= 22 {
        let p = 10f64.powi(e.abs());
        let x = im as f64;
        return if e < 0 { x / p } else { x * p };
    }
    // Otherwise the standard library's correctly rounded decimal parser.
    format!("{im}e{e}").parse().unwrap_or(plain)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regression_33_a_subnormal_step_is_refused_and_its_count_ends() {
        // `--dt 5e-324 --t-end 1e-308`: counting the grid's points looked
        // at some 10^13 of them one by one. Refused by the check, and the
        // count, should anyone ask, ends (bounded search).
        let e = Sampling::Every(5e-324).validate().unwrap_err().to_string();
        assert!(e.contains("2.2250738585072014e-308"), "{e}");
        assert!(Sampling::Every(1e-310).validate().is_err());
        assert!(Sampling::Every(f64::MIN_POSITIVE).validate().is_ok());
        let n = Sampling::Every(5e-324).known_rows(1e-308).unwrap();
        assert!(n > 1e15, "{n}");
    }

    /// The count known before the run is the number of points the grid
    /// writes (issue 20: 0.3/0.1 rounds below 3, yet 0.3 is a point).
    #[test]
    fn known_rows_count_the_points_written() {
        for (dt, t_end) in [
            (0.1, 0.3),
            (0.1, 1.0),
            (0.25, 1.0),
            (0.3, 1.0),
            (0.7, 2.1),
            (1e-3, 1.0),
        ] {
            let mut count = 0;
            while Sampling::grid_time(dt, count, t_end).is_some() {
                count += 1;
            }
            // Whole numbers: compared as such.
            let known = Sampling::Every(dt).known_rows(t_end).unwrap() as usize;
            assert_eq!(known, count, "dt = {dt}, t_end = {t_end}");
        }
        assert_eq!(
            Sampling::Every(0.1).known_rows(0.3).map(|n| n as usize),
            Some(4)
        );
    }

    /// The decimal `i · q / 10^d` written out by integer arithmetic alone,
    /// e.g. (3, 1, 1) → "0.3": what a person means by point i of a grid of
    /// step q·10^−d.
    fn decimal(i: u64, q: u64, d: u32) -> String {
        let n = i * q;
        let scale = 10u64.pow(d);
        format!("{}.{:0width$}", n / scale, n % scale, width = d as usize)
    }

    #[test]
    fn grid_times_print_the_decimal_that_was_meant() {
        // dt = q · 10^−d for steps people type; each point must be the f64
        // nearest the exact decimal i·dt (parsed independently from its
        // digits), so it prints as that decimal.
        for (q, d) in [
            (1, 1),
            (1, 3),
            (5, 3),
            (2, 3),
            (1, 4),
            (3, 1),
            (25, 2),
            (7, 5),
        ] {
            let dt: f64 = decimal(1, q, d).parse().unwrap();
            for i in 0..20_000u64 {
                let want: f64 = decimal(i, q, d).parse().unwrap();
                let got = Sampling::grid_time(dt, i as usize, f64::MAX).unwrap();
                assert_eq!(got.to_bits(), want.to_bits(), "dt = {dt}, i = {i}");
            }
        }
        assert_eq!(
            Sampling::grid_time(0.1, 3, 100.0).unwrap().to_string(),
            "0.3"
        );
        assert_eq!(
            Sampling::grid_time(1e-4, 1, 100.0).unwrap().to_string(),
            "0.0001"
        );
    }

    #[test]
    fn grid_times_stay_within_an_ulp_of_i_dt_and_increase() {
        // Steps that are not short decimals (1/3, π/100) and a huge index:
        // the decimal route must stay within 2ε·t of the plain product i·dt
        // (dt's digits are within ε/2 of dt, relatively, and each of the two
        // products rounds once more by ε/2: 3ε/2 in all) and strictly increase.
        for dt in [1.0 / 3.0, std::f64::consts::PI / 100.0, 0.1, 2.5e-7, 1e3] {
            let mut last = -1.0;
            for i in (0..2_000usize).chain(1_000_000_000..1_000_000_100) {
                let t = Sampling::grid_time(dt, i, f64::MAX).unwrap();
                let plain = i as f64 * dt;
                let tol = 2.0 * f64::EPSILON * plain;
                assert!(
                    (t - plain).abs() <= tol,
                    "dt = {dt}, i = {i}: {t} vs {plain}"
                );
                assert!(t > last, "dt = {dt}, i = {i}: {t} after {last}");
                last = t;
            }
        }
    }

    #[test]
    fn grid_ends_exactly_at_t_end_and_not_beyond() {
        // 0.1 · 10 lands on 1 exactly; the next point is past the end.
        assert_eq!(Sampling::grid_time(0.1, 10, 1.0), Some(1.0));
        assert_eq!(Sampling::grid_time(0.1, 11, 1.0), None);
        // A point within rounding of t_end is moved onto it.
        assert_eq!(Sampling::grid_time(1.0 / 3.0, 3, 1.0), Some(1.0));
    }
}
