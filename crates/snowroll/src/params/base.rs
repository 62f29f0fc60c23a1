//! The defaults the table's rows start from ([`BASE`], and its variants for
//! the run and the losses), and the parse of a choice's id.

use super::{Applies, Group, Kind, Param, Presence, Scope, Section, Value, WrongKind};

/// The row every field of which is the most common choice: a real number
/// of the scenario, set everywhere, recorded always at the head.
pub(super) const BASE: Param = Param {
    key: "",
    aliases: &[],
    unit: "",
    value_name: "X",
    kind: Kind::Real,
    scope: Scope::Shared,
    group: Group::Scenario,
    applies: Applies::All,
    range: "",
    help: "",
    default_note: None,
    json: Presence::Always,
    csv: (Section::Head, Presence::Always),
    exponent: false,
    sweep: false,
    plot: ("", ""),
    get: |_| Value::None,
    set: |_, _| Err(WrongKind),
};

/// A run parameter (of [`crate::SimOptions`]).
pub(super) const RUN: Param = Param {
    group: Group::Run,
    ..BASE
};

/// A loss parameter: recorded, after the optional ones, only with losses.
pub(super) const LOSS: Param = Param {
    group: Group::Losses,
    applies: Applies::CircularModels,
    json: Presence::WithLosses,
    csv: (Section::Extra, Presence::WithLosses),
    ..BASE
};

/// The variant of `all` whose id is `id` (ids are checked before a setter
/// runs: [`Param::set`]).
pub(super) fn pick<T: Copy>(
    all: &[T],
    id: &str,
    name: impl Fn(T) -> &'static str,
) -> Result<T, WrongKind> {
    all.iter()
        .copied()
        .find(|t| name(*t) == id)
        .ok_or(WrongKind)
}
