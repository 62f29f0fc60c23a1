//! The flags that come from the parameter table ([`snowroll::params`]):
//! those of `simulate` and `turns` ([`ParamArgs`]) and the axes of `sweep`
//! ([`AxisArgs`]). clap's derive cannot loop over a table, so `clap::Args`
//! is implemented here with clap's builder.

use clap::builder::PossibleValuesParser;
use clap::{Arg, ArgAction};
use snowroll::params::{Group, Kind, Scope};
use snowroll::{Given, Param, Value, PARAMS};

/// One flag per [`Scope::Shared`] parameter of [`PARAMS`], built from the
/// table (name, unit placeholder, help with its default, kind): the flags
/// given are in [`ParamArgs::given`], the others take their defaults later.
/// clap's derive cannot loop over a table, so `clap::Args` is implemented
/// here with clap's builder.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ParamArgs {
    /// The values of the flags given on the command line.
    pub given: Given,
}

/// The shared parameters, in table order.
fn shared() -> impl Iterator<Item = &'static Param> {
    PARAMS.iter().filter(|p| p.scope == Scope::Shared)
}

/// The shared parameters of the scenario and the losses (not of the run:
/// no end, tolerance or sampling), in table order.
fn bodily() -> impl Iterator<Item = &'static Param> {
    shared().filter(|p| matches!(p.group, Group::Scenario | Group::Losses))
}

/// The values given on the command line of the flags of `params`.
fn given_of(params: impl Iterator<Item = &'static Param>, m: &clap::ArgMatches, given: &mut Given) {
    for p in params {
        let value = match p.kind {
            Kind::Flag => m.get_flag(p.key).then_some(Value::Flag(true)),
            Kind::Count | Kind::OptionalCount => m.get_one::<u64>(p.key).map(|n| Value::Count(*n)),
            Kind::Choice(_) => m.get_one::<String>(p.key).map(|w| Value::Word(w.clone())),
            Kind::OptionalRealOr(_) => m.get_one::<Value>(p.key).cloned(),
            _ => m.get_one::<f64>(p.key).map(|x| Value::Real(*x)),
        };
        if let Some(v) = value {
            given.insert(p, v);
        }
    }
}

/// The flag of parameter `p`.
fn param_arg(p: &'static Param) -> Arg {
    let arg = Arg::new(p.key)
        .long(p.flag())
        .help(p.help_with_default())
        .required(false);
    match p.kind {
        Kind::Flag => arg.action(ArgAction::SetTrue),
        Kind::Count | Kind::OptionalCount => arg
            .value_name(p.value_name)
            .action(ArgAction::Set)
            .value_parser(clap::value_parser!(u64)),
        Kind::Choice(c) => arg
            .value_name(p.value_name)
            .action(ArgAction::Set)
            .ignore_case(true)
            .value_parser(PossibleValuesParser::new(c.possible_values())),
        // A value may start with a hyphen (clap takes `-0.0001` for a
        // number but `-1e-4` for a flag): `--snow-depth -1e-4` works as
        // `--snow-depth=-1e-4`, and a flag given in a value's place is
        // refused as a value that is not a number.
        Kind::OptionalRealOr(word) => arg
            .value_name(p.value_name)
            .action(ArgAction::Set)
            .allow_hyphen_values(true)
            .value_parser(clap::builder::ValueParser::new(
                move |text: &str| -> Result<Value, String> {
                    if text.trim().eq_ignore_ascii_case(word) {
                        return Ok(Value::Word(word.to_string()));
                    }
                    text.trim()
                        .parse::<f64>()
                        .map(Value::Real)
                        .map_err(|_| format!("expected a number or {word}"))
                },
            )),
        Kind::Real | Kind::OptionalReal | Kind::Reals | Kind::Text => arg
            .value_name(p.value_name)
            .action(ArgAction::Set)
            .allow_hyphen_values(true)
            .value_parser(clap::value_parser!(f64)),
    }
}

impl clap::Args for ParamArgs {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        cmd.args(shared().map(param_arg))
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl clap::FromArgMatches for ParamArgs {
    fn from_arg_matches(m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let mut me = Self::default();
        me.update_from_arg_matches(m)?;
        Ok(me)
    }

    fn update_from_arg_matches(&mut self, m: &clap::ArgMatches) -> Result<(), clap::Error> {
        given_of(shared(), m, &mut self.given);
        Ok(())
    }
}

/// `clap::Args` for a struct `{ given: Given }` whose flags are the table's
/// parameters that `$params()` yields (the builder, since clap's derive
/// cannot loop over a table).
macro_rules! flags_of_table {
    ($name:ident, $params:path) => {
        impl clap::Args for $name {
            fn augment_args(cmd: clap::Command) -> clap::Command {
                cmd.args($params().map(param_arg))
            }

            fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
                Self::augment_args(cmd)
            }
        }

        impl clap::FromArgMatches for $name {
            fn from_arg_matches(m: &clap::ArgMatches) -> Result<Self, clap::Error> {
                let mut me = Self::default();
                me.update_from_arg_matches(m)?;
                Ok(me)
            }

            fn update_from_arg_matches(&mut self, m: &clap::ArgMatches) -> Result<(), clap::Error> {
                given_of($params(), m, &mut self.given);
                Ok(())
            }
        }
    };
}

/// One flag per parameter of the scenario and the losses ([`Group::Scenario`],
/// [`Group::Losses`]), for commands that describe a body on a slope
/// without running it (`snowroll models`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BodyArgs {
    /// The values of the flags given on the command line.
    pub given: Given,
}

flags_of_table!(BodyArgs, bodily);

/// The shared parameters of the scenario only ([`Group::Scenario`]).
fn scenic() -> impl Iterator<Item = &'static Param> {
    shared().filter(|p| p.group == Group::Scenario)
}

/// One flag per parameter of the scenario ([`Group::Scenario`]): the slope,
/// the snow and the body that `snowroll paper` judges the note on.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SlopeArgs {
    /// The values of the flags given on the command line.
    pub given: Given,
}

flags_of_table!(SlopeArgs, scenic);

/// One flag per parameter of the table that a sweep varies
/// ([`Param::sweep`]), each taking a value, a list `a,b,c` or a range
/// `start:end:count` (numbers), or a list of words; kept as typed, read by
/// the grid (`commands/sweep_grid.rs`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct AxisArgs {
    /// The axes given, in table order, as typed.
    pub given: Vec<(&'static Param, String)>,
}

/// The sweep axes, in table order.
pub fn sweep_axes() -> impl Iterator<Item = &'static Param> {
    PARAMS.iter().filter(|p| p.sweep)
}

/// The flag of sweep axis `p`.
fn axis_arg(p: &'static Param) -> Arg {
    let (value_name, what) = match p.kind {
        Kind::Choice(_) => (
            format!("{}[,{}...]", p.value_name, p.value_name),
            "a word, or a list a,b of them",
        ),
        _ => (
            p.value_name.to_string(),
            "value, list a,b,c or range start:end:count",
        ),
    };
    Arg::new(p.key)
        .long(p.flag())
        .value_name(value_name)
        .allow_hyphen_values(true)
        .action(ArgAction::Set)
        .help(format!(
            "{}: {what} [default: {}]",
            p.help,
            p.default_text()
        ))
}

impl clap::Args for AxisArgs {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        cmd.args(sweep_axes().map(axis_arg))
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl clap::FromArgMatches for AxisArgs {
    fn from_arg_matches(m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let mut me = Self::default();
        me.update_from_arg_matches(m)?;
        Ok(me)
    }

    fn update_from_arg_matches(&mut self, m: &clap::ArgMatches) -> Result<(), clap::Error> {
        for p in sweep_axes() {
            if let Some(text) = m.get_one::<String>(p.key) {
                self.given.retain(|(q, _)| q.key != p.key);
                self.given.push((p, text.clone()));
            }
        }
        self.given.sort_by_key(|(p, _)| p.position());
        Ok(())
    }
}

impl AxisArgs {
    /// The text given for axis `key`, if any.
    pub fn get(&self, key: &str) -> Option<&String> {
        self.given
            .iter()
            .find(|(p, _)| p.key == key)
            .map(|(_, t)| t)
    }

    /// Gives axis `p` the text `text` unless it already has one.
    pub fn fill(&mut self, p: &'static Param, text: Option<String>) {
        if let (None, Some(text)) = (self.get(p.key), text) {
            self.given.push((p, text));
            self.given.sort_by_key(|(p, _)| p.position());
        }
    }
}
