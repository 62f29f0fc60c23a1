//! Where each model may be trusted: the order in b/r its derivation keeps,
//! the range of b/r0 the program uses it in without a warning, and the
//! slope below which it stalls (fn. 7).
//!
//! Every model's radius only grows (`π r² = π r0² + b x`, eq. (8), or
//! `r_k = r0 + k b`, eq. (74)), so b/r is largest at the start: a run
//! leaves a model's range exactly when its scenario does, and
//! [`validity_warnings`] needs only the model and the scenario.

use serde::Serialize;

use super::{first_turn_stall_slope, ModelKind, TurnVariant, WarningCode};
use crate::losses::Losses;
use crate::scenario::{Scenario, Shape};
use crate::units::{Meters, Radians};

/// Largest b/r0 at which the program uses a thin-snow model without a
/// warning. The first-order models drop terms one order of b/r below the
/// snow terms they keep, and the circular models rest on an assumption
/// (snow spread over the whole log at once) that only thin snow makes
/// harmless; at b/r0 = 0.1 the dropped terms change snow effects such as the
/// stall slope by about 10 % (the `paper` report's table of where the turn
/// models part ways).
pub const THIN_SNOW_MAX_B_OVER_R0: f64 = 0.1;

/// Relative slack on a range's limit, so that the rounding of b/r0 alone (the
/// defaults b = 0.01 m, r0 = 0.1 m sit on the thin-snow limit) never warns.
const B_OVER_R0_ROUNDING: f64 = 1e-12;

/// A model's range of validity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Validity {
    /// The order in b/r its derivation keeps: `Some(1)` for first-order
    /// truncations, `Some(0)` for the snowless model, `None` when no term in
    /// b/r is dropped (exact within the model's assumptions).
    pub order_in_b_over_r: Option<u32>,
    /// Largest b/r0 it is used at without a warning; `None`: no limit.
    pub max_b_over_r0: Option<f64>,
    /// Its assumptions and range, in words.
    pub statement: &'static str,
}

/// How a model fails to roll on a slope that is too gentle (fn. 7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StallKind {
    /// From rest its acceleration is not positive: it does not start (§2).
    DoesNotStart,
    /// It starts at a = 2G/3 but stalls inside its first turn (§3).
    StallsInFirstTurn,
}

/// The slope below which a model started from rest does not roll on.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StallThreshold {
    /// The critical slope α*, rad.
    pub slope: Radians,
    /// What happens below it.
    pub kind: StallKind,
}

impl ModelKind {
    /// The model's range of validity (see [`Validity`]).
    pub fn validity(self) -> Validity {
        let thin = Some(THIN_SNOW_MAX_B_OVER_R0);
        let (order, max, statement) = match self {
            ModelKind::Snowless => (
                Some(0),
                Some(0.0),
                "no snow: the b = 0 limit of every model (App. A)",
            ),
            ModelKind::TorqueCm
            | ModelKind::TorqueContact
            | ModelKind::Energy
            | ModelKind::LagrangianPrinted
            | ModelKind::Loney => (
                None,
                thin,
                "circular at all times (unphysical, §2.1.3); no term in b/r dropped within that assumption, which only thin snow makes harmless",
            ),
            ModelKind::EnergyThin => (
                Some(1),
                thin,
                "circular at all times (§2.1.3) and first order in b/r (eq. (15) drops the b² terms of eq. (14))",
            ),
            ModelKind::QuasiCircular | ModelKind::QuasiCircularLift => (
                Some(1),
                thin,
                "approximately circular (§2.4): first order in b/r, eqs. (23)–(30) are approximations",
            ),
            ModelKind::Turns => (
                Some(1),
                thin,
                "turn by turn, I_C and V to first order in b/r_k (eqs. (73), (76)); collision idealised (eq. (89))",
            ),
            ModelKind::TurnsExact => (
                None,
                None,
                "turn by turn with the exact mass properties of the disk and layer; collision idealised (eq. (89))",
            ),
        };
        Validity {
            order_in_b_over_r: order,
            max_b_over_r0: max,
            statement,
        }
    }

    /// The slope below which the model, started from rest with snow depth
    /// `b` and radius `r0`, does not roll on (fn. 7): for the circular
    /// models with a lift term, where a(0) ≤ 0
    /// ([`Coefficients::stall_slope`](super::Coefficients::stall_slope)); for
    /// the turn models, where the log stalls inside turn 0
    /// ([`first_turn_stall_slope`]). `None` for models that always roll on.
    /// For the log without losses; [`ModelKind::stall_threshold_in`] takes
    /// the run's own body and losses.
    pub fn stall_threshold(self, b: Meters, r0: Meters) -> Option<StallThreshold> {
        if let Some(variant) = TurnVariant::of(self) {
            return first_turn_stall_slope(variant, r0, b).map(|slope| StallThreshold {
                slope,
                kind: StallKind::StallsInFirstTurn,
            });
        }
        self.derivation()
            .and_then(|d| d.coefficients().stall_slope(b, r0))
            .map(|slope| StallThreshold {
                slope,
                kind: StallKind::DoesNotStart,
            })
    }
}

impl ModelKind {
    /// The stall threshold of fn. 7 for a run on `scenario` with `losses`:
    /// for the circular models, where a(0) from rest falls to zero with the
    /// run's own body, swath and losses
    /// ([`Derivation::stall_slope_in`](super::Derivation::stall_slope_in));
    /// for the turn models (the log, no losses), where the log stalls inside
    /// turn 0 ([`first_turn_stall_slope`]).
    pub fn stall_threshold_in(
        self,
        scenario: &Scenario,
        losses: &Losses,
    ) -> Option<StallThreshold> {
        if TurnVariant::of(self).is_some() {
            return self.stall_threshold(scenario.snow_depth(), scenario.initial_radius());
        }
        self.derivation()
            .and_then(|d| d.stall_slope_in(scenario, losses))
            .map(|slope| StallThreshold {
                slope,
                kind: StallKind::DoesNotStart,
            })
    }

    /// The stall threshold `snowroll models` and Python's `models()` list
    /// for `scenario` with `losses`: [`Self::stall_threshold_in`], or `None`
    /// when the model does not take that body (a turn model and a ball) or
    /// those losses (the turn models take none).
    pub fn stall_threshold_listed(
        self,
        scenario: &Scenario,
        losses: &Losses,
    ) -> Option<StallThreshold> {
        let takes =
            self.shapes().contains(&scenario.shape()) && !(self.is_turn_model() && losses.any());
        takes
            .then(|| self.stall_threshold_in(scenario, losses))
            .flatten()
    }
}

/// A run outside its model's range of validity, in words.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ValidityWarning {
    /// The model.
    pub model: ModelKind,
    /// What it is about, as a short code.
    pub code: WarningCode,
    /// What is wrong, one sentence.
    pub message: String,
}

impl std::fmt::Display for ValidityWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

/// The warning for a ball's fixed swath `w` wider than its diameter 2 r0
/// at the start (`docs/snowball-and-losses.md` §1.1).
fn wider_than_the_ball(w: f64, r0: f64) -> String {
    format!(
        "swath_width = {} m is wider than the ball's diameter 2 r0 = {} m at the start: the \
         ball picks up snow beyond its own width until r reaches w/2 = {} m (give a width at \
         most 2 r0, or chord or the default 2r)",
        crate::number::format_number(w),
        crate::number::format_number(2.0 * r0),
        crate::number::format_number(w / 2.0)
    )
}

/// The warnings for running `kind` on `scenario`: b/r0 beyond the model's
/// range ([`ModelKind::validity`]), and, for the first-order turn model
/// started from rest, a slope on which it and the exact geometry disagree
/// about stalling in the first turn; a ball's fixed swath wider than its
/// diameter 2 r0 at the start. Empty when the run is in range.
///
/// ```
/// use snowroll::{validity_warnings, ModelKind, Scenario, ScenarioFile};
/// assert!(validity_warnings(ModelKind::Turns, &Scenario::default()).is_empty());
/// let thick = Scenario::new(ScenarioFile {
///     alpha_deg: 40.0,
///     snow_depth: 0.2,
///     r0: 0.15,
///     ..ScenarioFile::default()
/// })?;
/// let w = validity_warnings(ModelKind::Turns, &thick);
/// assert_eq!(w.len(), 2); // b/r0 = 1.33, and turns-exact stalls in turn 0 here
/// # Ok::<(), snowroll::ParamError>(())
/// ```
pub fn validity_warnings(kind: ModelKind, scenario: &Scenario) -> Vec<ValidityWarning> {
    // The layer's thickness |b|: an unwinding roll (b < 0) is as far from
    // its model's range as a log picking up the same layer.
    let (b, r0) = (scenario.snow_depth().abs(), scenario.initial_radius());
    let ratio = b / r0;
    let validity = kind.validity();
    let mut out = Vec::new();
    let mut warn = |code: WarningCode, message: String| {
        out.push(ValidityWarning {
            model: kind,
            code,
            message,
        });
    };
    match validity.max_b_over_r0 {
        Some(max) if kind == ModelKind::Snowless && b > max => warn(
            WarningCode::SnowIgnored,
            format!(
            "{} ignores the snow (snow_depth = {} m): it is the b = 0 limit of the other models",
            kind.id(),
            crate::number::format_number(scenario.snow_depth())
        ),
        ),
        Some(max) if ratio > max * (1.0 + B_OVER_R0_ROUNDING) => warn(
            WarningCode::BOverR0,
            format!(
            "{} is used beyond its range: b/r0 = {} > {max}, so the terms it neglects are not small. \
             Its range: {}. {}",
            kind.id(),
            // Four significant digits, in the form of every other number.
            crate::number::format_number(format!("{ratio:.3e}").parse().unwrap_or(ratio)),
            validity.statement,
            match scenario.shape() {
                Shape::Cylinder => format!("Compare {}.", ModelKind::TurnsExact.id()),
                // The turn models are the log's (docs/snowball-and-losses.md §1.2).
                Shape::Sphere => "No model of a ball keeps its shape under thick snow \
                                  (the turn models are the log's)."
                    .to_owned(),
            }
        ),
        ),
        _ => {}
    }
    if let Some(w) = scenario.swath_width().filter(|w| *w > 2.0 * r0) {
        warn(WarningCode::WideSwath, wider_than_the_ball(w, r0));
    }
    if kind == ModelKind::Turns && scenario.initial_speed() <= 0.0 {
        let alpha = scenario.slope_angle();
        let first = first_turn_stall_slope(TurnVariant::Paper, r0, b);
        let exact = first_turn_stall_slope(TurnVariant::Exact, r0, b);
        if let (Some(first), Some(exact)) = (first, exact) {
            let stalls = |threshold: f64| alpha < threshold;
            if stalls(first) != stalls(exact) {
                let (this, other) = if stalls(exact) {
                    ("rolls through", "stalls in")
                } else {
                    ("stalls in", "rolls through")
                };
                warn(
                    WarningCode::Turn0Stall,
                    format!(
                    "at alpha = {:.4} degrees {} {this} its first turn, but with exact geometry ({}) \
                     the log {other} it (turn-0 stall slopes: {:.4} and {:.4} degrees): the models part ways here",
                    alpha.to_degrees(),
                    kind.id(),
                    ModelKind::TurnsExact.id(),
                    first.to_degrees(),
                    exact.to_degrees()
                ),
                );
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ball's threshold in the energy model, typed from
    /// `docs/snowball-and-losses.md` §1.2 (issue 21):
    /// tan α* = 2b/(π r0) + 3b²/(4π r0²); the log's, eq. (14):
    /// tan α* = (3 b r0 + b²)/(2π r0²). Each from the run's own body, not
    /// the log's for both. Tolerance 1e-12 rad: both are closed forms.
    /// A fixed swath wider than the ball's diameter at the start warns
    /// (w = 0.25 m > 2 r0 = 0.2 m); 2 r0 itself, a narrower width, the
    /// default 2r and the chord do not. Fed 0.2 in place of 0.25 it fails.
    #[test]
    fn swath_wider_than_the_ball_warns() {
        use crate::scenario::{ChordWord, ScenarioFile, SwathWidth};
        let warnings = |swath_width| {
            let s = Scenario::new(ScenarioFile {
                shape: Shape::Sphere,
                swath_width,
                ..ScenarioFile::default()
            })
            .unwrap();
            validity_warnings(ModelKind::TorqueCm, &s)
        };
        let wide = warnings(Some(SwathWidth::Metres(0.25)));
        assert_eq!(wide.len(), 1);
        assert!(
            wide[0].message.contains("swath_width = 0.25 m")
                && wide[0].message.contains("2 r0 = 0.2 m"),
            "{}",
            wide[0].message
        );
        for ok in [
            None,
            Some(SwathWidth::Metres(0.2)),
            Some(SwathWidth::Metres(0.05)),
            Some(SwathWidth::Chord(ChordWord::Chord)),
        ] {
            assert!(warnings(ok).is_empty(), "{ok:?}");
        }
    }

    #[test]
    fn stall_threshold_follows_the_body() {
        use crate::scenario::ScenarioFile;
        use std::f64::consts::PI;
        let (b, r0) = (0.05, 0.04);
        let at = |shape| {
            let s = Scenario::new(ScenarioFile {
                snow_depth: b,
                r0,
                shape,
                ..ScenarioFile::default()
            })
            .unwrap();
            ModelKind::Energy
                .stall_threshold_in(&s, &Losses::default())
                .unwrap()
                .slope
        };
        let ball = (2.0 * b / (PI * r0) + 3.0 * b * b / (4.0 * PI * r0 * r0)).atan();
        let log = ((3.0 * b * r0 + b * b) / (2.0 * PI * r0 * r0)).atan();
        assert!(
            (at(Shape::Sphere) - ball).abs() < 1e-12,
            "{}",
            at(Shape::Sphere).to_degrees()
        );
        assert!((at(Shape::Cylinder) - log).abs() < 1e-12);
        assert!((ball.to_degrees() - 49.450).abs() < 1e-3);
    }

    /// With losses a(0) from rest loses c_rr C and F_c/M to the drive
    /// (`docs/snowball-and-losses.md` §2.1), so: eq. (4), which always
    /// starts without losses, needs tan α > c_rr; eq. (14) needs
    /// tan α > (3 b r0 + b²)/(2π r0²) + c_rr; eq. (4) with compaction alone
    /// needs g sin α > e_c b/(π r0²) (F_c/M = e_c b/s0 at the start).
    /// Bisection to rounding: tolerance 1e-12 rad.
    #[test]
    fn stall_threshold_follows_the_losses() {
        use crate::scenario::ScenarioFile;
        use std::f64::consts::PI;
        let s = Scenario::new(ScenarioFile {
            alpha_deg: 20.0,
            ..ScenarioFile::default()
        })
        .unwrap();
        let (b, r0, g) = (s.snow_depth(), s.initial_radius(), s.gravity());
        let rolling = |c_rr| Losses {
            rolling_resistance: c_rr,
            ..Losses::default()
        };
        let slope = |kind: ModelKind, l: &Losses| kind.stall_threshold_in(&s, l).map(|t| t.slope);
        assert_eq!(slope(ModelKind::TorqueCm, &Losses::default()), None);
        let got = slope(ModelKind::TorqueCm, &rolling(0.3)).unwrap();
        assert!((got - 0.3f64.atan()).abs() < 1e-12, "{got}");
        let lift = (3.0 * b * r0 + b * b) / (2.0 * PI * r0 * r0);
        let got = slope(ModelKind::Energy, &rolling(0.5)).unwrap();
        assert!(
            (got - (lift + 0.5).atan()).abs() < 1e-12,
            "{}",
            got.to_degrees()
        );
        let e_c = 20.0;
        let compaction = Losses {
            compaction_energy: e_c,
            ..Losses::default()
        };
        let got = slope(ModelKind::TorqueCm, &compaction).unwrap();
        let want = (e_c * b / (PI * r0 * r0 * g)).asin();
        assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        // Compaction beyond g: no slope will do.
        let heavy = Losses {
            compaction_energy: 1e5,
            ..Losses::default()
        };
        assert_eq!(
            slope(ModelKind::TorqueCm, &heavy),
            Some(std::f64::consts::FRAC_PI_2)
        );
    }

    use crate::scenario::ScenarioFile;

    fn scenario(edit: impl FnOnce(&mut ScenarioFile)) -> Scenario {
        let mut f = ScenarioFile::default();
        edit(&mut f);
        Scenario::new(f).unwrap()
    }

    /// A ball in thick snow is not sent to `turns-exact`, which is the log's.
    #[test]
    fn a_thick_snow_warning_for_the_ball_does_not_suggest_a_turn_model() {
        let thick = |shape| {
            scenario(|f| {
                f.snow_depth = 0.05;
                f.shape = shape;
            })
        };
        let ball = validity_warnings(ModelKind::TorqueCm, &thick(Shape::Sphere));
        assert_eq!(ball.len(), 1);
        assert!(!ball[0].message.contains("turns-exact"), "{}", ball[0]);
        let log = validity_warnings(ModelKind::TorqueCm, &thick(Shape::Cylinder));
        assert!(log[0].message.contains("Compare turns-exact"), "{}", log[0]);
    }

    #[test]
    fn the_defaults_are_in_range_for_every_model_with_snow() {
        let s = Scenario::default();
        for kind in ModelKind::ALL {
            let w = validity_warnings(kind, &s);
            assert_eq!(
                w.len(),
                usize::from(kind == ModelKind::Snowless),
                "{kind}: {w:?}"
            );
        }
    }

    #[test]
    fn thick_snow_warns_every_thin_snow_model_but_not_the_exact_turns() {
        let s = scenario(|f| f.snow_depth = 0.03);
        for kind in ModelKind::ALL {
            let warned = !validity_warnings(kind, &s).is_empty();
            assert_eq!(warned, kind != ModelKind::TurnsExact, "{kind}");
        }
    }

    #[test]
    fn turns_warns_where_the_turn_models_disagree_about_stalling() {
        // Thin snow (b/r0 = 0.1) on a slope between the two turn-0 stall
        // slopes (2.09° and 2.30°): only the disagreement warns.
        let s = scenario(|f| f.alpha_deg = 2.2);
        let w = validity_warnings(ModelKind::Turns, &s);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].message.contains("part ways"));
        // Pushed, the comparison from rest does not apply.
        let s = scenario(|f| {
            f.alpha_deg = 2.2;
            f.v0 = 1.0;
        });
        assert!(validity_warnings(ModelKind::Turns, &s).is_empty());
    }

    #[test]
    fn stall_thresholds_say_what_happens_below_them() {
        let (b, r0) = (0.01, 0.1);
        assert_eq!(
            ModelKind::Energy.stall_threshold(b, r0).map(|t| t.kind),
            Some(StallKind::DoesNotStart)
        );
        assert_eq!(
            ModelKind::TurnsExact.stall_threshold(b, r0).map(|t| t.kind),
            Some(StallKind::StallsInFirstTurn)
        );
        assert!(ModelKind::TorqueCm.stall_threshold(b, r0).is_none());
    }
}
