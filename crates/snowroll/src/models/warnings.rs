//! The warnings of a run: every check `simulate` and `turns` report before
//! they run, gathered in one place with a short machine-readable code each,
//! so that a sweep's rows carry exactly the warnings a single run of the
//! same point would print (issue 20, item 8).

use std::fmt;

use serde::Serialize;

pub use super::warning_code::WarningCode;
use super::{tolerance_warning, validity_warnings, ModelKind};
use crate::scenario::Scenario;
use crate::trajectory::SimOptions;

/// One warning of a run: its code and its sentence for people.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunWarning {
    /// What it is about.
    pub code: WarningCode,
    /// What is wrong, in words (what `simulate` prints after `warning: `).
    pub message: String,
}

impl fmt::Display for RunWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// The warnings of running `kind` on `scenario` with `opts`, in the order
/// `simulate` and `turns` print them: the validity warnings
/// ([`validity_warnings`]), then the tolerance warning
/// ([`tolerance_warning`]). Empty for a run in range at the default
/// tolerances.
pub fn run_warnings(kind: ModelKind, scenario: &Scenario, opts: &SimOptions) -> Vec<RunWarning> {
    let mut out: Vec<RunWarning> = validity_warnings(kind, scenario)
        .into_iter()
        .map(|w| RunWarning {
            code: w.code,
            message: w.message,
        })
        .collect();
    out.extend(
        tolerance_warning(kind, scenario, opts).map(|message| RunWarning {
            code: WarningCode::LooseTolerance,
            message,
        }),
    );
    out
}

/// The codes of `warnings` joined by `;` (`b-over-r0;loose-tolerance`), as
/// a sweep's `warnings` cell holds them; `None` when there is none.
pub fn warning_codes(warnings: &[RunWarning]) -> Option<String> {
    (!warnings.is_empty()).then(|| {
        warnings
            .iter()
            .map(|w| w.code.code())
            .collect::<Vec<_>>()
            .join(";")
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::ScenarioFile;

    /// Codes are distinct, kebab-case, and hold neither separator.
    #[test]
    fn codes_are_distinct_words() {
        let codes: Vec<&str> = WarningCode::ALL.iter().map(|c| c.code()).collect();
        for (k, c) in codes.iter().enumerate() {
            assert!(!codes[..k].contains(c), "{c}");
            assert!(
                c.chars()
                    .all(|ch| ch.is_ascii_lowercase() || ch.is_ascii_digit() || ch == '-'),
                "{c}"
            );
            let serde = serde_json::to_value(WarningCode::ALL[k]).unwrap();
            assert_eq!(serde.as_str(), Some(*c));
        }
    }

    /// b/r0 = 5 is fifty times the thin-snow limit of 0.1: `turns` warns
    /// with b-over-r0 (and with a turn-0 disagreement only if the stall
    /// slopes straddle alpha); rtol = 0.5 is looser than 1e-6; the default
    /// scenario and tolerances give nothing.
    #[test]
    fn thick_snow_and_loose_tolerances_have_their_codes() {
        let thick = Scenario::new(ScenarioFile {
            snow_depth: 0.5,
            r0: 0.1,
            ..ScenarioFile::default()
        })
        .unwrap();
        let opts = SimOptions::default();
        let w = run_warnings(ModelKind::TorqueCm, &thick, &opts);
        assert_eq!(warning_codes(&w).as_deref(), Some("b-over-r0"));
        let mut loose = SimOptions::default();
        loose.tolerances.rtol = 0.5;
        let w = run_warnings(ModelKind::Turns, &Scenario::default(), &loose);
        assert_eq!(warning_codes(&w).as_deref(), Some("loose-tolerance"));
        assert!(run_warnings(ModelKind::Turns, &Scenario::default(), &opts).is_empty());
        assert_eq!(warning_codes(&[]), None);
    }
}
