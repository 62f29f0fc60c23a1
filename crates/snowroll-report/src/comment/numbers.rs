//! The numbers the comment quotes, read from the claims' outcomes of the
//! run that writes it: each is the number printed after a label in a
//! claim's measured text, kept as printed (so a reader finds the same
//! digits in the report), with its value for the fractions the text names.

use crate::{ClaimId, ClaimResult, Report};

use super::markup::esc;
use super::CommentError;

/// A number as a claim's check printed it.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Number {
    /// The digits as printed (`0.25000`, `1.2e-14`).
    pub text: String,
    /// Its value.
    pub value: f64,
}

impl Number {
    /// The number as typst markup: plain digits, or `m × 10⁻ⁿ` set in
    /// math for an exponent form.
    pub fn typ(&self) -> String {
        match self.text.split_once('e') {
            Some((mantissa, exp)) => {
                let exp = exp.trim_start_matches('+').replace('-', "−");
                if mantissa == "1" {
                    format!("$10^({exp})$")
                } else {
                    format!("${mantissa} times 10^({exp})$")
                }
            }
            None => esc(&self.text),
        }
    }

    /// The number and, when it is within 5·10⁻⁴ (relative) of a fraction
    /// with a denominator up to 12, that fraction: `0.25000 (= 1/4)`.
    pub fn with_fraction(&self) -> String {
        match fraction(self.value) {
            Some((p, q)) => format!("{} (≈ ${p}\\/{q}$)", self.typ()),
            None => self.typ(),
        }
    }
}

/// The simplest fraction p/q (q ≤ 12) within 5·10⁻⁴ relative of `x > 0`,
/// if any: how the text names a measured ratio.
pub(super) fn fraction(x: f64) -> Option<(u64, u64)> {
    if !(x.is_finite() && x > 0.0) {
        return None;
    }
    (1..=12u64).find_map(|q| {
        let p = (x * q as f64).round();
        ((p >= 1.0) && ((p / q as f64 - x).abs() <= 5e-4 * x)).then_some((p as u64, q))
    })
}

/// The result of claim `id` in `report`.
///
/// # Errors
/// [`CommentError::MissingClaim`] when the report has no result for it.
pub(super) fn claim(report: &Report, id: ClaimId) -> Result<&ClaimResult, CommentError> {
    report
        .claims
        .iter()
        .find(|r| r.claim.id == id)
        .ok_or(CommentError::MissingClaim { claim: id })
}

/// The `nth` (0-based) number printed after `label` in the measured text
/// of `r` (spaces and `=` between them skipped).
///
/// # Errors
/// [`CommentError::MissingNumber`] when the label or a number after it is
/// not there: the check's text changed and the comment must follow it.
pub(super) fn after_nth(r: &ClaimResult, label: &str, nth: usize) -> Result<Number, CommentError> {
    let missing = || CommentError::MissingNumber {
        claim: r.claim.id,
        label: label.to_string(),
    };
    let (start, _) = r
        .measured
        .match_indices(label)
        .nth(nth)
        .ok_or_else(missing)?;
    let rest = r.measured[start + label.len()..].trim_start_matches([' ', '=']);
    let text: String = rest
        .char_indices()
        .take_while(|&(i, c)| {
            c.is_ascii_digit()
                || c == '.'
                || (i > 0 && c == 'e')
                || ((c == '-' || c == '−') && (i == 0 || rest[..i].ends_with('e')))
        })
        .map(|(_, c)| c)
        .collect();
    let text = text.trim_end_matches(['.', 'e']).to_string();
    let value = text
        .replace('−', "-")
        .parse::<f64>()
        .map_err(|_| missing())?;
    Ok(Number { text, value })
}

/// The first number after `label` that follows `anchor` in the measured
/// text of `r`.
///
/// # Errors
/// [`CommentError::MissingNumber`] as [`after_nth`].
pub(super) fn after_from(
    r: &ClaimResult,
    anchor: &str,
    label: &str,
) -> Result<Number, CommentError> {
    let start = r
        .measured
        .find(anchor)
        .ok_or_else(|| CommentError::MissingNumber {
            claim: r.claim.id,
            label: anchor.to_string(),
        })?;
    let skipped = r.measured[..start].matches(label).count();
    after_nth(r, label, skipped)
}

/// The first number after `label` ([`after_nth`]).
pub(super) fn after(r: &ClaimResult, label: &str) -> Result<Number, CommentError> {
    after_nth(r, label, 0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fractions_of_measured_ratios() {
        assert_eq!(fraction(0.25000), Some((1, 4)));
        assert_eq!(fraction(0.50009), Some((1, 2)));
        assert_eq!(fraction(0.222222), Some((2, 9)));
        assert_eq!(fraction(0.16666667), Some((1, 6)));
        assert_eq!(fraction(0.2856649), Some((2, 7)));
        // 5/28: a denominator above 12 is not named.
        assert_eq!(fraction(0.17854323), None);
        assert_eq!(fraction(f64::NAN), None);
    }

    #[test]
    fn exponent_forms_are_set_as_powers_of_ten() {
        let n = Number {
            text: "1.2e-14".into(),
            value: 1.2e-14,
        };
        assert_eq!(n.typ(), "$1.2 times 10^(−14)$");
    }
}
