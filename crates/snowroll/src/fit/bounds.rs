//! The bounds of a free parameter, read from its row of the parameter
//! table ([`Param::range`]: `0 < alpha_deg < 90 degrees`, `r0 > 0 m`,
//! `0 <= drag_coefficient <= 100`). The scenario's own checks stay the
//! judge: a trial point they refuse is a rejected step, so a range text
//! this reader cannot read only makes the box wider, never wrong.

use crate::params::Param;

/// An interval, each end open (strict) or closed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bounds {
    pub lo: f64,
    pub lo_open: bool,
    pub hi: f64,
    pub hi_open: bool,
}

impl Bounds {
    pub const ALL: Bounds = Bounds {
        lo: f64::NEG_INFINITY,
        lo_open: true,
        hi: f64::INFINITY,
        hi_open: true,
    };

    /// The interval of `param`'s range text; the whole line where the text
    /// is not of the form `[a <] key [< b]` (each `<` may be `<=`, and
    /// `>`/`>=` after the key give a lower bound).
    pub fn of(param: &Param) -> Bounds {
        let words: Vec<&str> = param.range.split_whitespace().collect();
        let Some(at) = words.iter().position(|w| *w == param.key) else {
            return Bounds::ALL;
        };
        let mut b = Bounds::ALL;
        if at >= 2 {
            if let (Some(x), Some(open)) = (number(words[at - 2]), less(words[at - 1])) {
                b.lo = x;
                b.lo_open = open;
            }
        }
        if let (Some(op), Some(x)) = (words.get(at + 1), words.get(at + 2).and_then(|w| number(w)))
        {
            if let Some(open) = less(op) {
                b.hi = x;
                b.hi_open = open;
            } else if let Some(open) = greater(op) {
                b.lo = x;
                b.lo_open = open;
            }
        }
        b
    }

    /// The ends kept to: a closed end itself, an open one moved inside by
    /// `margin` relative to its size (at least `margin` itself).
    fn limits(&self, margin: f64) -> (f64, f64) {
        let inside = |end: f64| margin * end.abs().max(1.0);
        let lo = if self.lo_open && self.lo.is_finite() {
            self.lo + inside(self.lo)
        } else {
            self.lo
        };
        let hi = if self.hi_open && self.hi.is_finite() {
            self.hi - inside(self.hi)
        } else {
            self.hi
        };
        (lo, hi)
    }

    /// Whether `x` is inside the interval that [`Bounds::clamp`] keeps to.
    pub fn contains(&self, x: f64, margin: f64) -> bool {
        let (lo, hi) = self.limits(margin);
        (lo..=hi).contains(&x)
    }

    /// `x` moved inside the interval (see [`Bounds::limits`]).
    pub fn clamp(&self, x: f64, margin: f64) -> f64 {
        let (lo, hi) = self.limits(margin);
        x.max(lo).min(hi)
    }
}

fn number(w: &str) -> Option<f64> {
    match w {
        "infinity" => Some(f64::INFINITY),
        "-infinity" => Some(f64::NEG_INFINITY),
        _ => w.parse().ok(),
    }
}

/// `Some(open)` for `<` or `<=`.
fn less(op: &str) -> Option<bool> {
    match op {
        "<" => Some(true),
        "<=" => Some(false),
        _ => None,
    }
}

/// `Some(open)` for `>` or `>=`.
fn greater(op: &str) -> Option<bool> {
    match op {
        ">" => Some(true),
        ">=" => Some(false),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(key: &str) -> Bounds {
        Bounds::of(Param::find(key).unwrap())
    }

    #[test]
    fn the_table_s_range_texts_read_as_intervals() {
        let a = of("alpha_deg");
        assert_eq!((a.lo, a.hi, a.lo_open, a.hi_open), (0.0, 90.0, true, true));
        let r = of("r0");
        assert_eq!((r.lo, r.lo_open, r.hi), (0.0, true, f64::INFINITY));
        let d = of("drag_coefficient");
        assert_eq!(
            (d.lo, d.hi, d.lo_open, d.hi_open),
            (0.0, 100.0, false, false)
        );
        let air = of("air_density");
        assert_eq!((air.lo, air.hi, air.hi_open), (0.0, 1e4, false));
        // The whole line holds every number (an open infinite end is no margin).
        assert!(Bounds::ALL.contains(-1e300, 1e-9) && Bounds::ALL.contains(0.3, 1e-9));
        // A clamp onto an open end stays inside it.
        assert!(a.clamp(95.0, 1e-9) < 90.0 && a.clamp(-1.0, 1e-9) > 0.0);
    }
}
