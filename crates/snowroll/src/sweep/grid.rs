//! The grid of a sweep: one axis per swept parameter, the models, and the
//! order in which the points are numbered.
//!
//! A point's index `i` in `0..len` is a mixed-radix number: the model is the
//! most significant digit, then the collision law and the hop setting (the
//! two [`Choices`]), then the parameters in [`Param::ALL`] order, the last
//! one varying fastest (nested loops written in that order). Ranges are
//! never expanded into memory: [`Values::get`] computes the k-th value.

use std::fmt;

use thiserror::Error;

use crate::error::ParamError;
use crate::integrate::Tolerances;
use crate::models::{CollisionModel, ModelKind};
use crate::scenario::{Scenario, ScenarioFile};
use crate::trajectory::{OnHop, Sampling, SimOptions};

/// Most points of one grid. At about 200 bytes a row this is 200 GB of CSV
/// and, at the fast path's rate, an hour of two cores: beyond it a grid is
/// far more likely a typo (an extra digit in a count) than a plan.
pub const MAX_GRID_POINTS: u64 = 1_000_000_000;

/// A parameter that a sweep can vary. The names are the command line's
/// (`--alpha-deg`) in snake case (`alpha_deg`), as in config files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Param {
    /// Slope angle α, degrees, 0 < α < 90.
    AlphaDeg,
    /// Snow depth b, m, b ≥ 0.
    SnowDepth,
    /// Initial radius r0, m, r0 > 0.
    R0,
    /// Gravitational acceleration g, m/s², g > 0.
    G,
    /// Density ρ, kg/m³, ρ > 0.
    Density,
    /// Length l of the log, m, l > 0.
    Length,
    /// Initial speed v0, m/s, v0 ≥ 0.
    V0,
    /// End time, s, t_end > 0.
    TEnd,
    /// End distance, m, x_end > 0 (none when not swept).
    XEnd,
    /// Relative tolerance of the integrator.
    Rtol,
    /// Absolute tolerance of the integrator.
    Atol,
    /// Coefficient of static friction μ, μ > 0: the run stops with `slip`
    /// where |F| reaches μ N (none, no slip check, when not swept).
    Mu,
}

impl Param {
    /// Every parameter, in grid order (the last varies fastest).
    pub const ALL: [Param; 12] = [
        Param::AlphaDeg,
        Param::SnowDepth,
        Param::R0,
        Param::G,
        Param::Density,
        Param::Length,
        Param::V0,
        Param::TEnd,
        Param::XEnd,
        Param::Rtol,
        Param::Atol,
        Param::Mu,
    ];

    /// The snake-case key (config files, CSV columns, metadata).
    pub fn key(self) -> &'static str {
        match self {
            Param::AlphaDeg => "alpha_deg",
            Param::SnowDepth => "snow_depth",
            Param::R0 => "r0",
            Param::G => "g",
            Param::Density => "density",
            Param::Length => "length",
            Param::V0 => "v0",
            Param::TEnd => "t_end",
            Param::XEnd => "x_end",
            Param::Rtol => "rtol",
            Param::Atol => "atol",
            Param::Mu => "mu",
        }
    }

    /// The parameter of a snake-case key or a kebab-case flag name.
    pub fn from_key(key: &str) -> Option<Param> {
        let key = key.replace('-', "_");
        Param::ALL.into_iter().find(|p| p.key() == key)
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// A grid that cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum GridError {
    /// An axis that does not parse.
    #[error("{param}: cannot read {text:?}: {reason}")]
    Syntax {
        /// The axis.
        param: String,
        /// What was given.
        text: String,
        /// What is wrong, in words.
        reason: String,
    },
    /// A value outside the parameter's range.
    ///
    /// The message is the check's own, which names the parameter; it is not
    /// the error's source, so that a printed chain says it once.
    #[error("{error}")]
    Value {
        /// The axis.
        param: Param,
        /// The range check that failed.
        error: ParamError,
    },
    /// The same parameter given twice.
    #[error("{param} is given twice")]
    Duplicate {
        /// The axis.
        param: String,
    },
    /// No model to run.
    #[error("no model given: pass --model ID[,ID...] (`snowroll models` lists them)")]
    NoModel,
    /// Too many points.
    #[error(
        "the grid has {points} points, more than the limit of {limit}: fewer values on some axis, \
         or several sweeps"
    )]
    TooLarge {
        /// The product of the axis lengths (saturating).
        points: u128,
        /// [`MAX_GRID_POINTS`].
        limit: u64,
    },
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

    /// The `k`-th value, `k < len()`: for a range
    /// `start + (end − start)·k/(count − 1)`, with the last one exactly `end`.
    pub fn get(&self, k: u64) -> f64 {
        match self {
            Values::List(v) => v.get(k as usize).copied().unwrap_or(f64::NAN),
            Values::Range { start, end, count } => {
                if k + 1 >= *count {
                    *end
                } else {
                    start + (end - start) * (k as f64 / (*count - 1) as f64)
                }
            }
        }
    }

    /// The smallest and largest values: every value lies between them, so
    /// checking these two checks the axis against an interval.
    fn bounds(&self) -> (f64, f64) {
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
    /// As it would be typed: `a,b,c` or `start:end:count`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Values::List(v) => {
                let items: Vec<String> = v.iter().map(f64::to_string).collect();
                f.write_str(&items.join(","))
            }
            Values::Range { start, end, count } => write!(f, "{start}:{end}:{count}"),
        }
    }
}

/// One swept parameter and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Which parameter.
    pub param: Param,
    /// Its values.
    pub values: Values,
}

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
    /// At most one per parameter, in [`Param::ALL`] order.
    axes: Vec<Axis>,
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
        for axis in &axes {
            if axis.values.is_empty() {
                return Err(GridError::Syntax {
                    param: axis.param.key().to_string(),
                    text: String::new(),
                    reason: "no values".to_string(),
                });
            }
            let (lo, hi) = axis.values.bounds();
            for x in [lo, hi] {
                check_value(axis.param, x).map_err(|error| GridError::Value {
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
        Ok(Grid {
            models,
            choices: Choices::default(),
            axes,
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
        let mut file = ScenarioFile::default();
        let mut options = SimOptions {
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        let mut rest = i;
        for axis in self.axes.iter().rev() {
            let n = axis.values.len();
            set(
                &mut file,
                &mut options,
                axis.param,
                axis.values.get(rest % n),
            );
            rest /= n;
        }
        let n_hop = self.choices.on_hop.len() as u64;
        options.on_hop = self.choices.on_hop[(rest % n_hop) as usize];
        rest /= n_hop;
        let n_collision = self.choices.collision.len() as u64;
        options.collision = self.choices.collision[(rest % n_collision) as usize];
        rest /= n_collision;
        let model = self.models[rest as usize];
        options.validate()?;
        Ok(Point {
            index: i,
            model,
            scenario: Scenario::new(file)?,
            options,
        })
    }
}

/// Sets one parameter of a point.
fn set(file: &mut ScenarioFile, options: &mut SimOptions, param: Param, x: f64) {
    let tol: &mut Tolerances = &mut options.tolerances;
    match param {
        Param::AlphaDeg => file.alpha_deg = x,
        Param::SnowDepth => file.snow_depth = x,
        Param::R0 => file.r0 = x,
        Param::G => file.g = x,
        Param::Density => file.density = x,
        Param::Length => file.length = x,
        Param::V0 => file.v0 = x,
        Param::TEnd => options.t_end = x,
        Param::XEnd => options.x_end = Some(x),
        Param::Rtol => tol.rtol = x,
        Param::Atol => tol.atol = x,
        Param::Mu => options.mu = Some(x),
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

/// Checks one value of `param` with the library's own checks: the default
/// scenario and options with that value put in.
fn check_value(param: Param, x: f64) -> Result<(), ParamError> {
    let mut file = ScenarioFile::default();
    let mut options = SimOptions::default();
    set(&mut file, &mut options, param, x);
    Scenario::new(file)?;
    options.validate()
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let axes: Vec<&str> = Param::ALL.iter().map(|p| p.key()).collect();
        assert_eq!(axes, table);
        for p in Param::ALL {
            let mut s = Settings::default();
            set(&mut s.scenario, &mut s.options, p, 0.375);
            let spec = crate::params::Param::of_key(p.key()).unwrap();
            assert_eq!(spec.get(&s), Value::Real(0.375), "{}", p.key());
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

    fn axis(param: Param, text: &str) -> Axis {
        Axis {
            param,
            values: Values::parse(param.key(), text).unwrap(),
        }
    }

    #[test]
    fn grid_checks_values_duplicates_and_size() {
        let m = vec![ModelKind::TorqueCm];
        let e = Grid::new(m.clone(), vec![axis(Param::AlphaDeg, "10:95:5")]).unwrap_err();
        assert!(
            e.to_string().contains("= 95: expected 0 < alpha_deg < 90"),
            "{e}"
        );
        // The message is whole without its chain, and the chain adds nothing:
        // a printer of the chain shows it once.
        assert!(std::error::Error::source(&e).is_none(), "{e:?}");
        let e = Grid::new(m.clone(), vec![axis(Param::SnowDepth, "0.1,-0.1")]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid snow_depth (m) = -0.1: expected snow_depth >= 0 m"
        );
        // A bad value is found before the missing model.
        let e = Grid::new(vec![], vec![axis(Param::AlphaDeg, "5:95:3")]).unwrap_err();
        assert!(
            matches!(
                e,
                GridError::Value {
                    param: Param::AlphaDeg,
                    ..
                }
            ),
            "{e:?}"
        );
        let e = Grid::new(m.clone(), vec![axis(Param::Rtol, "1e-20")]).unwrap_err();
        assert!(e.to_string().contains("rtol"), "{e}");
        let e = Grid::new(
            m.clone(),
            vec![axis(Param::R0, "0.1"), axis(Param::R0, "0.2")],
        )
        .unwrap_err();
        assert_eq!(e.to_string(), "r0 is given twice");
        assert_eq!(Grid::new(vec![], vec![]).unwrap_err(), GridError::NoModel);
        let e = Grid::new(
            m.clone(),
            vec![
                axis(Param::AlphaDeg, "10:80:100000"),
                axis(Param::SnowDepth, "0:1:100000"),
            ],
        )
        .unwrap_err();
        assert!(
            e.to_string()
                .contains("10000000000 points, more than the limit of 1000000000"),
            "{e}"
        );
        // Exactly at the limit is allowed (nothing is expanded).
        let g = Grid::new(m, vec![axis(Param::AlphaDeg, "10:80:1000000000")]).unwrap();
        assert_eq!(g.len(), MAX_GRID_POINTS);
    }

    #[test]
    fn points_are_numbered_model_first_last_axis_fastest() {
        let g = Grid::new(
            vec![ModelKind::TorqueCm, ModelKind::Energy],
            // Given out of order: the grid orders them.
            vec![
                axis(Param::SnowDepth, "0.001,0.01,0.1"),
                axis(Param::AlphaDeg, "20,30"),
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
