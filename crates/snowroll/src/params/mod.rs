//! The one parameter table: every scenario and run parameter, declared once
//! ([`PARAMS`], in `table.rs`) with its key, unit, kind, default, range,
//! help line, the bodies and models it applies to, and how outputs record it.
//!
//! Everything that names parameters reads this table instead of spelling
//! them: the command line's flags (`snowroll-cli`, `args/table.rs`), the
//! keys of a config file and of an output read back as one, the `params` of
//! every output (`snowroll-io`'s `RunParams`, through
//! [`Settings::csv_lines`] and [`Settings::json_entries`]), the axes of a
//! sweep, the Python keywords, their checks, signatures, docstrings and the
//! `.pyi` stub (`snowroll-py`). Adding a parameter is one row of the table
//! plus the physics that uses it (`docs/architecture.md`).
//!
//! A parameter's value is a [`Value`]; a set of given values is a [`Given`],
//! applied over the defaults ([`Settings::default`]) to make the library's
//! [`ScenarioFile`] and [`SimOptions`]. The defaults themselves are those of
//! [`ScenarioFile::default`] and [`SimOptions::default`]: the table reads
//! them ([`Param::default_value`]) rather than repeating them.

mod base;
mod given;
mod keys;
mod record;
mod sampling;
mod table;
mod value;

use std::fmt;

use crate::error::ParamError;
use crate::number::format_number;
use crate::scenario::{ScenarioFile, Shape};
use crate::trajectory::{CollisionModel, OnHop, SimOptions};

pub use given::Given;
pub use keys::{named_keys, render_keys};
pub use sampling::{RecordedSampling, UnknownSampling};
pub use table::PARAMS;
pub(crate) use table::TABLE;
pub use value::{RealOrWord, Value, WrongKind};

/// The kind of value a parameter takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A real number in the parameter's unit.
    Real,
    /// A real number, or none (the feature it sets is off).
    OptionalReal,
    /// A real number, this one word (any case), or none: `swath_width`'s
    /// width in metres or `chord`.
    OptionalRealOr(&'static str),
    /// A whole number, at least 0 (the range says more).
    Count,
    /// A whole number, or none.
    OptionalCount,
    /// On or off.
    Flag,
    /// One word of a closed set.
    Choice(Choice),
    /// A list of real numbers, or none.
    Reals,
    /// Words that an output records and nothing sets (`sampling`).
    Text,
}

/// The closed sets of words a [`Kind::Choice`] parameter takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Choice {
    /// [`Shape`]: `cylinder`, `sphere`.
    Shape,
    /// [`CollisionModel`]: `note`, `charged`, `pivot`.
    Collision,
    /// [`OnHop`]: `stop`, `continue`.
    OnHop,
}

impl Choice {
    /// The words, the default first.
    pub fn ids(self) -> Vec<&'static str> {
        match self {
            Choice::Shape => Shape::ALL.iter().map(|s| s.id()).collect(),
            Choice::Collision => CollisionModel::ALL.iter().map(|c| c.id()).collect(),
            Choice::OnHop => OnHop::ALL.iter().map(|h| h.id()).collect(),
        }
    }

    /// The words with the help of each, as `--help` lists them (from the
    /// enums' own documentation).
    #[cfg(feature = "clap")]
    pub fn possible_values(self) -> Vec<clap::builder::PossibleValue> {
        use clap::ValueEnum;
        fn of<T: ValueEnum>() -> Vec<clap::builder::PossibleValue> {
            T::value_variants()
                .iter()
                .filter_map(ValueEnum::to_possible_value)
                .collect()
        }
        match self {
            Choice::Shape => of::<Shape>(),
            Choice::Collision => of::<CollisionModel>(),
            Choice::OnHop => of::<OnHop>(),
        }
    }
}

/// Where a parameter is set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scope {
    /// A flag of `simulate` and `turns` alike, a config key, a keyword of the
    /// Python `simulate` and `turns`.
    Shared,
    /// How `simulate` samples its rows (`times`, `dt`): its flags, config
    /// keys and Python keywords only.
    Sampling,
    /// The turn count: a flag of each command with its own help (`simulate`
    /// stops there, `turns` runs that many), a config key and a keyword.
    Turns,
    /// Recorded by outputs, set by nothing (`sampling`).
    Record,
}

/// The part of the library's inputs a parameter belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// [`ScenarioFile`]: the slope, the snow and the body.
    Scenario,
    /// [`SimOptions`]: when to stop, the integrator, what to record.
    Run,
    /// [`SimOptions::losses`](crate::Losses): outputs record the group only
    /// when one of it differs from its default, so that outputs of lossless
    /// runs read as before the losses existed.
    Losses,
}

/// The bodies and models a parameter applies to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Applies {
    /// Every body and model.
    All,
    /// The ball (`shape = sphere`) only.
    Sphere,
    /// The turn models (`turns`, `turns-exact`) only.
    TurnModels,
    /// The circular models only (the turn models take none but 0).
    CircularModels,
}

impl fmt::Display for Applies {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Applies::All => "all",
            Applies::Sphere => "sphere",
            Applies::TurnModels => "turn models",
            Applies::CircularModels => "circular models",
        })
    }
}

/// When an output's record holds a parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Presence {
    /// Always (none written as JSON `null`, CSV `none`).
    Always,
    /// When it has a value.
    WhenSet,
    /// When any parameter of [`Group::Losses`] differs from its default.
    WithLosses,
}

/// Where a CSV output's `#` header holds a parameter: the lines come in
/// section order, table order within a section.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Section {
    /// The parameters every run has.
    Head,
    /// The optional ones: the swath, μ, the losses.
    Extra,
    /// How the rows were sampled (`dt`, `times`).
    Tail,
}

/// One parameter: a row of [`PARAMS`].
#[derive(Clone, Copy)]
pub struct Param {
    /// The name everywhere: config key, output record key, Python keyword,
    /// sweep column; the long flag is its kebab-case form.
    pub key: &'static str,
    /// Other names read back: those of earlier outputs (`slope_deg`).
    pub aliases: &'static [&'static str],
    /// Its SI unit as written in text (`m/s^2`); empty when dimensionless.
    pub unit: &'static str,
    /// The placeholder of its value in `--help` (`DEG`).
    pub value_name: &'static str,
    /// The kind of value.
    pub kind: Kind,
    /// Where it is set.
    pub scope: Scope,
    /// Which input of the library it sets.
    pub group: Group,
    /// The bodies and models it applies to.
    pub applies: Applies,
    /// The allowed values, in words, as the library's check states them
    /// when it refuses a value (`0 < alpha_deg < 90 degrees`; a test holds
    /// each check's message to this text).
    pub range: &'static str,
    /// One line of help: what it is, its unit and its range.
    pub help: &'static str,
    /// The default in words where it is not a value (`none, no slip check`);
    /// `None`: the default value itself ([`Param::default_text`]).
    pub default_note: Option<&'static str>,
    /// When a JSON output's `params` holds it.
    pub json: Presence,
    /// Where and when a CSV output's header holds it.
    pub csv: (Section, Presence),
    /// Written in exponent form in a CSV header (`1e-10`), for tolerances.
    pub exponent: bool,
    /// An axis of `snowroll sweep`: a value, a list or a range of numbers,
    /// or a list of words; a column of its rows ([`crate::sweep::SweepRow`]).
    pub sweep: bool,
    /// The label and unit of its axis on a plot (a regime map), for a
    /// numeric sweep parameter; empty for the others.
    pub plot: (&'static str, &'static str),
    get: fn(&Settings) -> Value,
    set: fn(&mut Settings, Value) -> Result<(), WrongKind>,
}

impl fmt::Debug for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Param").field("key", &self.key).finish()
    }
}

impl PartialEq for Param {
    fn eq(&self, other: &Self) -> bool {
        self.key == other.key
    }
}

/// Every setting of a run: the scenario, the options, and whether its rows
/// are one per turn (`snowroll turns`, recorded as its sampling).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Settings {
    /// The scenario, not yet validated.
    pub scenario: ScenarioFile,
    /// The options, not yet validated.
    pub options: SimOptions,
    /// One row per turn (a turn table) rather than per sample.
    pub per_turn: bool,
}

impl Param {
    /// The parameter of `key`: its snake-case key, its flag's name in
    /// kebab case (`alpha-deg`) or one of its [`aliases`](Param::aliases).
    pub fn find(key: &str) -> Option<&'static Param> {
        let snake = key.replace('-', "_");
        PARAMS
            .iter()
            .find(|p| p.key == snake || p.aliases.contains(&key))
    }

    /// Its place in [`PARAMS`]: the order of help, records and sweep axes.
    pub fn position(&self) -> usize {
        PARAMS
            .iter()
            .position(|q| q.key == self.key)
            .unwrap_or(PARAMS.len())
    }

    /// Every name [`Param::find`] knows `self` by: the key, the flag's name
    /// when it differs, the aliases.
    pub fn names(&self) -> Vec<String> {
        let mut names = vec![self.key.to_string()];
        if self.flag() != self.key {
            names.push(self.flag());
        }
        names.extend(self.aliases.iter().map(|a| a.to_string()));
        names
    }

    /// The parameter of exactly this snake-case key.
    pub fn of_key(key: &str) -> Option<&'static Param> {
        PARAMS.iter().find(|p| p.key == key)
    }

    /// The long flag's name, without the dashes (`alpha-deg`).
    pub fn flag(&self) -> String {
        self.key.replace('_', "-")
    }

    /// Whether the user may set it (every scope but [`Scope::Record`]).
    pub fn settable(&self) -> bool {
        self.scope != Scope::Record
    }

    /// Its value in `settings`.
    pub fn get(&self, settings: &Settings) -> Value {
        (self.get)(settings)
    }

    /// Sets it in `settings`.
    ///
    /// # Errors
    /// [`ParamError::WrongKind`] when `value` is not of the parameter's
    /// [`Kind`], [`ParamError::UnknownShape`] or [`ParamError::UnknownChoice`]
    /// for a word outside a choice.
    pub fn set(&self, settings: &mut Settings, value: Value) -> Result<(), ParamError> {
        let value = match (self.kind, value) {
            (Kind::Choice(c), Value::Word(w)) => Value::Word(parse_choice(self.key, c, &w)?),
            (Kind::OptionalRealOr(word), Value::Word(w)) => {
                if w.trim().eq_ignore_ascii_case(word) {
                    Value::Word(word.to_string())
                } else {
                    return Err(ParamError::UnknownChoice {
                        key: self.key,
                        given: w,
                        expected: format!("a number or {word}"),
                    });
                }
            }
            (_, v) => v,
        };
        (self.set)(settings, value).map_err(|WrongKind| ParamError::WrongKind {
            key: self.key,
            expected: self.kind_words(),
        })
    }

    /// Sets the number `x` in `settings` with the row's own setter, without
    /// [`Param::set`]'s reading of words (the sweep's grid, point by point).
    ///
    /// # Errors
    /// [`ParamError::WrongKind`] when the parameter is not a number.
    pub(crate) fn set_real(&self, settings: &mut Settings, x: f64) -> Result<(), ParamError> {
        (self.set)(settings, Value::Real(x)).map_err(|WrongKind| ParamError::WrongKind {
            key: self.key,
            expected: self.kind_words(),
        })
    }

    /// Its default value (that of [`Settings::default`]).
    pub fn default_value(&self) -> Value {
        self.get(&Settings::default())
    }

    /// The default as `--help` shows it: the note, else the value in its
    /// shortest form (`30`, `1e-10`, `cylinder`).
    pub fn default_text(&self) -> String {
        if let Some(note) = self.default_note {
            return note.to_string();
        }
        match self.default_value() {
            Value::Real(x) => short(x),
            v => self.text(&v),
        }
    }

    /// The help line with its default, as `--help` shows it.
    pub fn help_with_default(&self) -> String {
        format!("{} [default: {}]", self.help, self.default_text())
    }

    /// The kind of value in words, for messages (`a number`).
    pub fn kind_words(&self) -> &'static str {
        match self.kind {
            Kind::Real => "a number",
            Kind::OptionalReal => "a number or none",
            Kind::OptionalRealOr(_) => "a number, its word or none",
            Kind::Count | Kind::OptionalCount => "a whole number",
            Kind::Flag => "true or false",
            Kind::Choice(_) => "one of its words",
            Kind::Reals => "a list of numbers",
            Kind::Text => "text",
        }
    }

    /// `value` as a CSV header writes it: numbers in their shortest form
    /// that reads back to the same `f64` (exponent form for tolerances),
    /// `none` for no value, lists comma-separated.
    pub fn text(&self, value: &Value) -> String {
        match value {
            Value::None => "none".to_string(),
            Value::Real(x) if self.exponent => format!("{x:e}"),
            Value::Real(x) => format_number(*x),
            Value::Count(n) => n.to_string(),
            Value::Flag(b) => b.to_string(),
            Value::Word(w) => w.clone(),
            Value::Reals(xs) => xs
                .iter()
                .map(|x| format_number(*x))
                .collect::<Vec<_>>()
                .join(","),
        }
    }

    /// Reads back what [`Param::text`] wrote (a CSV header's value): `none`
    /// is no value; a choice is its first word.
    ///
    /// # Errors
    /// A sentence naming the key and the text, when it is not of the kind.
    pub fn parse_text(&self, text: &str) -> Result<Value, String> {
        let text = text.trim();
        if text == "none" {
            return Ok(Value::None);
        }
        let key = self.key;
        let number = |t: &str| -> Result<f64, String> {
            let x: f64 = t
                .parse()
                .map_err(|_| format!("`{key} = {t}` is not a number"))?;
            if x.is_finite() {
                Ok(x)
            } else {
                Err(format!("`{key} = {t}` is not a finite number"))
            }
        };
        Ok(match self.kind {
            Kind::Real | Kind::OptionalReal => Value::Real(number(text)?),
            Kind::OptionalRealOr(word) if text.eq_ignore_ascii_case(word) => {
                Value::Word(word.to_string())
            }
            Kind::OptionalRealOr(_) => Value::Real(number(text)?),
            Kind::Count | Kind::OptionalCount => Value::Count(
                text.parse()
                    .map_err(|_| format!("`{key} = {text}` is not a whole number"))?,
            ),
            Kind::Flag => Value::Flag(
                text.parse()
                    .map_err(|_| format!("`{key} = {text}` is not true or false"))?,
            ),
            Kind::Choice(_) => Value::Word(text.split_whitespace().next().unwrap_or("").into()),
            Kind::Reals => Value::Reals(
                text.split(',')
                    .map(|t| number(t.trim()))
                    .collect::<Result<_, _>>()?,
            ),
            Kind::Text => Value::Word(text.to_string()),
        })
    }
}

/// The id of the choice `given` (any case), or an error naming the
/// parameter and the words it takes.
fn parse_choice(key: &'static str, choice: Choice, given: &str) -> Result<String, ParamError> {
    if choice == Choice::Shape {
        return given.parse::<Shape>().map(|s| s.id().to_string());
    }
    let ids = choice.ids();
    let wanted = given.trim().to_ascii_lowercase();
    ids.iter()
        .find(|id| **id == wanted)
        .map(|id| id.to_string())
        .ok_or_else(|| ParamError::UnknownChoice {
            key,
            given: given.to_string(),
            expected: ids.join(", "),
        })
}

/// A number as a person would type it: `1e-10` rather than `0.0000000001`.
pub fn short(x: f64) -> String {
    if x != 0.0 && !(1e-3..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        x.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_is_unique_and_snake_case() {
        let mut names: Vec<&str> = PARAMS.iter().map(|p| p.key).collect();
        names.extend(PARAMS.iter().flat_map(|p| p.aliases.iter().copied()));
        let n = names.len();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), n, "a key or alias is spelt twice");
        for p in PARAMS.iter() {
            assert!(
                p.key
                    .bytes()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_'),
                "{}",
                p.key
            );
        }
    }

    /// Every parameter reads back, through its setter, the value its getter
    /// gives, and the CSV text of a value parses back to it.
    #[test]
    fn get_set_and_text_round_trip() {
        let d = Settings::default();
        for p in PARAMS.iter().filter(|p| p.settable()) {
            let v = p.get(&d);
            let mut s = Settings::default();
            p.set(&mut s, v.clone()).unwrap();
            assert_eq!(s, d, "{}", p.key);
            assert_eq!(p.parse_text(&p.text(&v)), Ok(v), "{}", p.key);
        }
    }

    /// A setter writes the field its getter reads and no other: setting a
    /// changed value changes that parameter's reading and leaves every
    /// other parameter's reading alone.
    #[test]
    fn each_setter_touches_its_own_field() {
        for p in PARAMS.iter().filter(|p| p.settable()) {
            let changed = match p.kind {
                Kind::Real | Kind::OptionalReal | Kind::OptionalRealOr(_) => Value::Real(0.123),
                Kind::Count | Kind::OptionalCount => Value::Count(7),
                Kind::Flag => Value::Flag(true),
                Kind::Choice(c) => Value::Word(c.ids()[1].to_string()),
                Kind::Reals => Value::Reals(vec![0.5, 1.5]),
                Kind::Text => unreachable!("not settable"),
            };
            let mut s = Settings::default();
            p.set(&mut s, changed.clone()).unwrap();
            assert_eq!(p.get(&s), changed, "{}", p.key);
            for q in PARAMS.iter().filter(|q| q.key != p.key && q.settable()) {
                let sampling_pair = matches!((p.key, q.key), ("dt", "times") | ("times", "dt"));
                if !sampling_pair {
                    assert_eq!(
                        q.get(&s),
                        q.get(&Settings::default()),
                        "{} moved {}",
                        p.key,
                        q.key
                    );
                }
            }
        }
    }

    /// Every check of the library refuses a value out of range with a
    /// message that states the table's range: a NaN for a number, 0 for a
    /// count (each parameter alone, the others at their defaults; the swath
    /// on a ball, whose it is).
    #[test]
    fn each_check_states_the_table_s_range() {
        use crate::scenario::Scenario;
        for p in PARAMS.iter().filter(|p| p.settable()) {
            let bad = match p.kind {
                Kind::Real | Kind::OptionalReal | Kind::OptionalRealOr(_) => Value::Real(f64::NAN),
                Kind::Count | Kind::OptionalCount => Value::Count(0),
                _ => continue,
            };
            let mut s = Settings::default();
            if p.applies == Applies::Sphere {
                s.scenario.shape = Shape::Sphere;
            }
            p.set(&mut s, bad).unwrap();
            let e = Scenario::new(s.scenario)
                .and_then(|_| s.options.sampling.validate())
                .and_then(|()| s.options.validate())
                .expect_err(p.key);
            let message = e.to_string();
            // The check may add why after the range.
            assert!(
                message.contains(p.key) && message.contains(&format!("expected {}", p.range)),
                "{}: {message:?} does not state {:?}",
                p.key,
                p.range
            );
        }
    }

    #[test]
    fn wrong_kinds_and_words_are_refused_by_name() {
        let mut s = Settings::default();
        let alpha = Param::of_key("alpha_deg").unwrap();
        let e = alpha.set(&mut s, Value::Flag(true)).unwrap_err();
        assert!(e.to_string().contains("alpha_deg"), "{e}");
        let collision = Param::of_key("collision").unwrap();
        let e = collision
            .set(&mut s, Value::Word("bounce".into()))
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown collision \"bounce\": expected one of note, charged, pivot"
        );
        collision.set(&mut s, Value::Word("PIVOT".into())).unwrap();
        assert_eq!(s.options.collision, CollisionModel::Pivot);
    }

    #[test]
    fn flags_and_aliases_find_their_parameter() {
        assert_eq!(Param::find("alpha-deg").unwrap().key, "alpha_deg");
        assert_eq!(Param::find("slope_deg").unwrap().key, "alpha_deg");
        assert_eq!(Param::find("terminal-tol").unwrap().key, "terminal_tol");
        assert!(Param::find("--terminal-tol").is_none());
        assert!(Param::find("no_such").is_none());
    }
}
