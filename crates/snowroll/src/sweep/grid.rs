//! The grid of a sweep: one axis per swept parameter, the models, and the
//! order in which the points are numbered.
//!
//! A point's index `i` in `0..len` is a mixed-radix number: the model is the
//! most significant digit, then the collision law and the hop setting (the
//! two [`Choices`]), then the parameters in [`AxisParam::ALL`] order, the last
//! one varying fastest (nested loops written in that order). Ranges are
//! never expanded into memory: [`Values::get`] computes the k-th value.

use super::axis::{Axis, AxisParam, DecimalRange, GridError};
use crate::error::ParamError;
use crate::models::{CollisionModel, ModelKind};
use crate::params::Settings;
use crate::scenario::{Scenario, ScenarioFile};
use crate::trajectory::{OnHop, Sampling, SimOptions};

/// Most points of one grid. At about 200 bytes a row this is 200 GB of CSV
/// and, at the fast path's rate, an hour of two cores: beyond it a grid is
/// far more likely a typo (an extra digit in a count) than a plan.
pub const MAX_GRID_POINTS: u64 = 1_000_000_000;

/// One point of the grid: the model, the scenario and the run options.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Index in grid order.
    pub index: u64,
    /// The model.
    pub model: ModelKind,
    /// The scenario, validated.
    pub scenario: Scenario,
    /// The options: sampling [`Sampling::Ends`].
    pub options: SimOptions,
}

/// The models and the axes of a sweep; parameters not swept take the
/// library defaults ([`ScenarioFile::default`], [`SimOptions::default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    models: Vec<ModelKind>,
    /// The collision laws and hop settings.
    choices: Choices,
    /// At most one per parameter, in [`AxisParam::ALL`] order.
    axes: Vec<Axis>,
    /// The decimal plan of each axis ([`Values::decimal_range`](super::Values::decimal_range)), made once.
    plans: Vec<Option<DecimalRange>>,
    /// Number of points.
    len: u64,
}

impl Grid {
    /// Checks and orders the axes.
    ///
    /// # Errors
    /// [`GridError`], the first of: a parameter given twice, an empty axis, a
    /// value out of its parameter's range, no model, more than
    /// [`MAX_GRID_POINTS`].
    pub fn new(models: Vec<ModelKind>, mut axes: Vec<Axis>) -> Result<Grid, GridError> {
        // The axes are checked first: a bad value is reported even when the
        // model is missing too.
        axes.sort_by_key(|a| a.param);
        if let Some(w) = axes.windows(2).find(|w| w[0].param == w[1].param) {
            return Err(GridError::Duplicate {
                param: w[0].param.key().to_string(),
            });
        }
        // Each value is checked in the company of the other axes' first
        // values (a point of the grid): a parameter whose range depends on
        // another (the core radius, with a negative snow depth and below r0)
        // is checked against the grid's own, not against the defaults.
        let mut first = Settings::default();
        for axis in &axes {
            if axis.values.is_empty() {
                return Err(GridError::Syntax {
                    param: axis.param.key().to_string(),
                    text: String::new(),
                    reason: "no values".to_string(),
                });
            }
            axis.param
                .set(&mut first, axis.values.get(0))
                .map_err(|error| GridError::Value {
                    param: axis.param,
                    error,
                })?;
        }
        for axis in &axes {
            let (lo, hi) = axis.values.bounds();
            for x in [lo, hi] {
                check_value(&first, axis.param, x).map_err(|error| GridError::Value {
                    param: axis.param,
                    error,
                })?;
            }
        }
        if models.is_empty() {
            return Err(GridError::NoModel);
        }
        let points = axes.iter().fold(models.len() as u128, |n, a| {
            n.saturating_mul(a.values.len().into())
        });
        if points > u128::from(MAX_GRID_POINTS) {
            return Err(GridError::TooLarge {
                points,
                limit: MAX_GRID_POINTS,
            });
        }
        let plans = axes.iter().map(|a| a.values.decimal_range()).collect();
        Ok(Grid {
            models,
            choices: Choices::default(),
            axes,
            plans,
            len: points as u64,
        })
    }

    /// The same grid over these collision laws and hop settings (by default
    /// only the library's defaults, [`CollisionModel::Note`] and
    /// [`OnHop::Stop`]).
    ///
    /// # Errors
    /// [`GridError`]: an empty or repeated list, more than
    /// [`MAX_GRID_POINTS`].
    pub fn with_choices(self, choices: Choices) -> Result<Grid, GridError> {
        for (name, n, distinct) in [
            (
                "collision",
                choices.collision.len(),
                distinct(&choices.collision),
            ),
            ("on_hop", choices.on_hop.len(), distinct(&choices.on_hop)),
        ] {
            if n == 0 {
                return Err(GridError::Syntax {
                    param: name.to_string(),
                    text: String::new(),
                    reason: "no values".to_string(),
                });
            }
            if !distinct {
                return Err(GridError::Duplicate {
                    param: format!("a value of {name}"),
                });
            }
        }
        let base = self.len / self.choices.len();
        let points = u128::from(base) * choices.len() as u128;
        if points > u128::from(MAX_GRID_POINTS) {
            return Err(GridError::TooLarge {
                points,
                limit: MAX_GRID_POINTS,
            });
        }
        Ok(Grid {
            choices,
            len: points as u64,
            ..self
        })
    }

    /// The collision laws and hop settings, in grid order.
    pub fn choices(&self) -> &Choices {
        &self.choices
    }

    /// Number of points.
    pub fn len(&self) -> u64 {
        self.len
    }

    /// Whether there are no points (never: a grid has a model and non-empty axes).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The models, in grid order.
    pub fn models(&self) -> &[ModelKind] {
        &self.models
    }

    /// The swept parameters, in grid order.
    pub fn axes(&self) -> &[Axis] {
        &self.axes
    }

    /// The point of index `i < len()`.
    ///
    /// # Errors
    /// [`ParamError`] when `i` is out of range, or when the combination of
    /// values is invalid (each value alone was checked by [`Grid::new`]).
    pub fn point(&self, i: u64) -> Result<Point, ParamError> {
        if i >= self.len {
            return Err(ParamError::InvalidParameter {
                name: "grid index",
                value: i as f64,
                expected: "an index below the number of points",
            });
        }
        let mut s = Settings {
            scenario: ScenarioFile::default(),
            options: SimOptions {
                sampling: Sampling::Ends,
                ..SimOptions::default()
            },
            per_turn: false,
        };
        let mut rest = i;
        for (axis, plan) in self.axes.iter().zip(&self.plans).rev() {
            let n = axis.values.len();
            axis.param
                .set(&mut s, axis.values.get_planned(plan.as_ref(), rest % n))?;
            rest /= n;
        }
        let n_hop = self.choices.on_hop.len() as u64;
        s.options.on_hop = self.choices.on_hop[(rest % n_hop) as usize];
        rest /= n_hop;
        let n_collision = self.choices.collision.len() as u64;
        s.options.collision = self.choices.collision[(rest % n_collision) as usize];
        rest /= n_collision;
        let model = self.models[rest as usize];
        s.options.validate()?;
        Ok(Point {
            index: i,
            model,
            scenario: Scenario::new(s.scenario)?,
            options: s.options,
        })
    }
}

/// Whether no value of `items` repeats.
fn distinct<T: PartialEq>(items: &[T]) -> bool {
    items
        .iter()
        .enumerate()
        .all(|(i, a)| !items[..i].contains(a))
}

/// The settings a sweep can vary that are not numbers: the collision law of
/// the turn models and what a run does where N reaches 0. Each list is an
/// axis of the grid, in this order, after the model.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Choices {
    /// Collision laws (`--collision`), default `[note]`.
    pub collision: Vec<CollisionModel>,
    /// Hop settings (`--on-hop`), default `[stop]`.
    pub on_hop: Vec<OnHop>,
}

impl Default for Choices {
    fn default() -> Self {
        Self {
            collision: vec![CollisionModel::default()],
            on_hop: vec![OnHop::default()],
        }
    }
}

impl Choices {
    /// Points per model: the product of the two lists' lengths (≥ 1 for a
    /// grid's choices).
    fn len(&self) -> u64 {
        (self.collision.len() * self.on_hop.len()).max(1) as u64
    }
}

/// Checks one value of `param` with the library's own checks: the settings
/// `base` (the defaults with each axis at its first value) with that value
/// put in.
fn check_value(base: &Settings, param: AxisParam, x: f64) -> Result<(), ParamError> {
    let mut s = base.clone();
    param.set(&mut s, x)?;
    Scenario::new(s.scenario)?;
    s.options.validate()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::Values;

    /// The axes are the table's numeric sweep parameters, in its order, and
    /// each sets the field that the table's parameter of the same key reads.
    #[test]
    fn axes_are_the_table_s_numeric_sweep_parameters() {
        use crate::params::{Kind, Settings, Value, PARAMS};
        let numeric = |p: &&crate::params::Param| matches!(p.kind, Kind::Real | Kind::OptionalReal);
        let table: Vec<&str> = PARAMS
            .iter()
            .filter(|p| p.sweep)
            .filter(numeric)
            .map(|p| p.key)
            .collect();
        let axes: Vec<&str> = AxisParam::ALL.iter().map(|p| p.key()).collect();
        assert_eq!(axes, table);
        for p in AxisParam::ALL {
            let mut s = Settings::default();
            p.set(&mut s, 0.375).unwrap();
            let spec = crate::params::Param::of_key(p.key()).unwrap();
            assert_eq!(spec.get(&s), Value::Real(0.375), "{}", p.key());
            assert_eq!(p.get(&s), Some(0.375), "{}", p.key());
            assert!(!p.spec().plot.0.is_empty(), "{}: no plot label", p.key());
            assert_eq!(AxisParam::named(p.key()), p);
        }
        // The words a sweep lists: the table's choice parameters.
        let choices: Vec<&str> = PARAMS
            .iter()
            .filter(|p| p.sweep && matches!(p.kind, Kind::Choice(_)))
            .map(|p| p.key)
            .collect();
        assert_eq!(choices, ["collision", "on_hop"]);
    }

    #[test]
    fn parses_lists_and_ranges() {
        assert_eq!(
            Values::parse("snow_depth", "0.001, 0.01,0.1").unwrap(),
            Values::List(vec![0.001, 0.01, 0.1])
        );
        let r = Values::parse("alpha_deg", "5:60:12").unwrap();
        assert_eq!(r.len(), 12);
        // Spacing (60 - 5)/11 = 5 exactly in binary: every value is exact.
        let want: Vec<f64> = (0..12).map(|k| 5.0 + 5.0 * k as f64).collect();
        let got: Vec<f64> = (0..12).map(|k| r.get(k)).collect();
        assert_eq!(format!("{got:?}"), format!("{want:?}"));
        assert_eq!(
            Values::parse("v0", "2:2:1").unwrap(),
            Values::Range {
                start: 2.0,
                end: 2.0,
                count: 1
            }
        );
        // A descending range is allowed; its ends are exact.
        let d = Values::parse("alpha_deg", "31:29:3").unwrap();
        assert_eq!(format!("{:?}", [d.get(0), d.get(2)]), "[31.0, 29.0]");
        assert_eq!(d.to_string(), "31:29:3");
    }

    #[test]
    fn rejects_bad_axes_with_the_reason() {
        for (text, reason) in [
            ("", "empty item"),
            ("1,,2", "empty item"),
            ("1:2", "start:end:count"),
            ("1:2:3:4", "start:end:count"),
            ("1:2:0", "at least 1"),
            ("1:2:1", "start = end"),
            ("1:2:-3", "whole number"),
            ("1:2:x", "whole number"),
            ("abc", "not a number"),
            ("1,inf", "not a finite number"),
            ("nan:1:3", "not a finite number"),
        ] {
            let e = Values::parse("alpha_deg", text).unwrap_err().to_string();
            assert!(e.contains(reason), "{text:?}: {e}");
            assert!(e.starts_with("alpha_deg: "), "{e}");
        }
    }

    fn axis(param: AxisParam, text: &str) -> Axis {
        Axis {
            param,
            values: Values::parse(param.key(), text).unwrap(),
        }
    }

    #[test]
    fn grid_checks_values_duplicates_and_size() {
        let m = vec![ModelKind::TorqueCm];
        let e = Grid::new(
            m.clone(),
            vec![axis(AxisParam::named("alpha_deg"), "10:95:5")],
        )
        .unwrap_err();
        assert!(
            e.to_string().contains("= 95: expected 0 < alpha_deg < 90"),
            "{e}"
        );
        // The message is whole without its chain, and the chain adds nothing:
        // a printer of the chain shows it once.
        assert!(std::error::Error::source(&e).is_none(), "{e:?}");
        let e = Grid::new(
            m.clone(),
            vec![axis(AxisParam::named("snow_depth"), "0.1,-0.1")],
        )
        .unwrap_err();
        // A negative depth is an unwinding roll, which needs a core radius.
        assert!(
            e.to_string().starts_with(
                "invalid snow_depth (m) = -0.1: expected snow_depth >= 0 without core_radius"
            ),
            "{e}"
        );
        // A bad value is found before the missing model.
        let e = Grid::new(vec![], vec![axis(AxisParam::named("alpha_deg"), "5:95:3")]).unwrap_err();
        assert!(
            matches!(
                e,
                GridError::Value {
                    param,
                    ..
                } if param == AxisParam::named("alpha_deg")
            ),
            "{e:?}"
        );
        let e = Grid::new(m.clone(), vec![axis(AxisParam::named("rtol"), "1e-20")]).unwrap_err();
        assert!(e.to_string().contains("rtol"), "{e}");
        let e = Grid::new(
            m.clone(),
            vec![
                axis(AxisParam::named("r0"), "0.1"),
                axis(AxisParam::named("r0"), "0.2"),
            ],
        )
        .unwrap_err();
        assert_eq!(e.to_string(), "r0 is given twice");
        assert_eq!(Grid::new(vec![], vec![]).unwrap_err(), GridError::NoModel);
        let e = Grid::new(
            m.clone(),
            vec![
                axis(AxisParam::named("alpha_deg"), "10:80:100000"),
                axis(AxisParam::named("snow_depth"), "0:1:100000"),
            ],
        )
        .unwrap_err();
        assert!(
            e.to_string()
                .contains("10000000000 points, more than the limit of 1000000000"),
            "{e}"
        );
        // Issue 33, item 5: a huge count is written as the outputs write
        // numbers, not as 25 digits.
        let e = Grid::new(
            m.clone(),
            vec![
                axis(AxisParam::named("alpha_deg"), "10:80:1000000000000"),
                axis(AxisParam::named("snow_depth"), "0:1:1000000000000"),
            ],
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("the grid has 1e24 points, more than"), "{e}");
        assert_eq!(
            super::super::axis::count_text(1_000_000_000_000_000),
            "1000000000000000"
        );
        assert_eq!(
            super::super::axis::count_text(1_234_500_000_000_000_000),
            "1.2345e18"
        );
        // Exactly at the limit is allowed (nothing is expanded).
        let g = Grid::new(
            m,
            vec![axis(AxisParam::named("alpha_deg"), "10:80:1000000000")],
        )
        .unwrap();
        assert_eq!(g.len(), MAX_GRID_POINTS);
    }

    #[test]
    fn points_are_numbered_model_first_last_axis_fastest() {
        let g = Grid::new(
            vec![ModelKind::TorqueCm, ModelKind::Energy],
            // Given out of order: the grid orders them.
            vec![
                axis(AxisParam::named("snow_depth"), "0.001,0.01,0.1"),
                axis(AxisParam::named("alpha_deg"), "20,30"),
            ],
        )
        .unwrap();
        assert_eq!(g.len(), 12);
        let mut seen = Vec::new();
        for i in 0..g.len() {
            let p = g.point(i).unwrap();
            assert_eq!(p.index, i);
            assert_eq!(p.options.sampling, Sampling::Ends);
            let f = ScenarioFile::from(p.scenario);
            seen.push((p.model, f.alpha_deg.to_string(), f.snow_depth.to_string()));
        }
        let mut want = Vec::new();
        for m in [ModelKind::TorqueCm, ModelKind::Energy] {
            for a in ["20", "30"] {
                for b in ["0.001", "0.01", "0.1"] {
                    want.push((m, a.to_string(), b.to_string()));
                }
            }
        }
        assert_eq!(seen, want);
        assert!(g.point(12).is_err());
        // Parameters not swept keep the defaults.
        let p = g.point(0).unwrap();
        assert_eq!(p.options.x_end, None);
        assert_eq!(p.options.t_end.to_string(), "100");
    }
}
