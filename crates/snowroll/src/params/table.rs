//! The table itself: one row per parameter, in the order outputs record
//! them (JSON `params`; a CSV header sorts them by [`Section`] first) and
//! `--help` lists them.

use super::base::{pick, BASE, LOSS, RUN};
use super::{
    Applies, Choice, Kind, Param, Presence, RecordedSampling, Scope, Section, Value, WrongKind,
};
use crate::scenario::{ChordWord, Shape, SwathWidth};
use crate::trajectory::{CollisionModel, OnHop, Sampling};

/// Every parameter. See [`Param`] for the meaning of each field.
pub static PARAMS: [Param; 30] = TABLE;

/// [`PARAMS`] as a constant, for what is computed from it at compile time
/// (the sweep's axes, [`crate::sweep::AxisParam::ALL`]).
pub(crate) const TABLE: [Param; 30] = [
    Param {
        key: "alpha_deg",
        sweep: true,
        plot: ("slope angle α", "deg"),
        aliases: &["slope_deg"],
        unit: "deg",
        value_name: "DEG",
        range: "0 < alpha_deg < 90 degrees (0 <= alpha_deg for an unwinding roll, snow_depth < 0)",
        help: "Slope angle alpha, in degrees (0 < alpha < 90; 0, a level floor, for an unwinding \
               roll)",
        get: |s| Value::Real(s.scenario.alpha_deg),
        set: |s, v| v.real().map(|x| s.scenario.alpha_deg = x),
        ..BASE
    },
    Param {
        key: "snow_depth",
        sweep: true,
        plot: ("snow depth b", "m"),
        aliases: &["snow_depth_m"],
        unit: "m",
        value_name: "M",
        range: "finite snow_depth m (< 0: an unwinding roll, with core_radius)",
        help: "Snow depth b normal to the slope, in m (0 = no snow; b < 0: a roll of paper that \
               unwinds, laying |b| down, pi r^2 = pi r0^2 + b x, down to its core radius)",
        get: |s| Value::Real(s.scenario.snow_depth),
        set: |s, v| v.real().map(|x| s.scenario.snow_depth = x),
        ..BASE
    },
    Param {
        key: "r0",
        sweep: true,
        plot: ("initial radius r0", "m"),
        aliases: &["r0_m"],
        unit: "m",
        value_name: "M",
        range: "r0 > 0 m",
        help: "Initial radius r0 of the log, in m (r0 > 0)",
        get: |s| Value::Real(s.scenario.r0),
        set: |s, v| v.real().map(|x| s.scenario.r0 = x),
        ..BASE
    },
    Param {
        key: "g",
        sweep: true,
        plot: ("gravitational acceleration g", "m/s²"),
        aliases: &["g_m_s2"],
        unit: "m/s^2",
        value_name: "M/S^2",
        range: "g > 0 m/s^2",
        help: "Gravitational acceleration g, in m/s^2 (g > 0)",
        get: |s| Value::Real(s.scenario.g),
        set: |s, v| v.real().map(|x| s.scenario.g = x),
        ..BASE
    },
    Param {
        key: "density",
        sweep: true,
        plot: ("density ρ", "kg/m³"),
        aliases: &["density_kg_m3"],
        unit: "kg/m^3",
        value_name: "KG/M^3",
        range: "density > 0 kg/m^3",
        help: "Density rho of log and snow, in kg/m^3 (rho > 0)",
        get: |s| Value::Real(s.scenario.density),
        set: |s, v| v.real().map(|x| s.scenario.density = x),
        ..BASE
    },
    Param {
        key: "length",
        sweep: true,
        plot: ("length l", "m"),
        aliases: &["length_m"],
        unit: "m",
        value_name: "M",
        range: "length > 0 m",
        help: "Length l of the log, in m (l > 0)",
        get: |s| Value::Real(s.scenario.length),
        set: |s, v| v.real().map(|x| s.scenario.length = x),
        ..BASE
    },
    Param {
        key: "v0",
        sweep: true,
        plot: ("initial speed v0", "m/s"),
        aliases: &["v0_m_s"],
        unit: "m/s",
        value_name: "M/S",
        range: "v0 >= 0 m/s",
        help: "Initial speed v0 down the slope, in m/s (v0 >= 0)",
        get: |s| Value::Real(s.scenario.v0),
        set: |s, v| v.real().map(|x| s.scenario.v0 = x),
        ..BASE
    },
    Param {
        key: "shape",
        value_name: "SHAPE",
        kind: Kind::Choice(Choice::Shape),
        range: "cylinder or sphere",
        help: "The body: cylinder (the note's log) or sphere (a snowball, I = 2/5 M r^2; the turn \
               models take the cylinder only)",
        get: |s| Value::Word(s.scenario.shape.id().into()),
        set: |s, v| pick(&Shape::ALL, &v.word()?, Shape::id).map(|x| s.scenario.shape = x),
        ..BASE
    },
    Param {
        key: "swath_width",
        unit: "m",
        value_name: "M|chord",
        kind: Kind::OptionalRealOr(ChordWord::ID),
        applies: Applies::Sphere,
        range: "swath_width > 0 m, or chord",
        help: "Width w of the swath of snow a sphere picks up, in m (w > 0), or chord: the \
               contact chord 2 sqrt(2 r b - b^2) of a ball pressed through the layer (b <= r0; \
               sphere only)",
        default_note: Some(
            "none = the ball's diameter 2r, which grows with it, so that pi r^2 = pi r0^2 + b x \
             as for the log",
        ),
        json: Presence::WhenSet,
        csv: (Section::Extra, Presence::WhenSet),
        get: |s| match s.scenario.swath_width {
            None => Value::None,
            Some(SwathWidth::Metres(w)) => Value::Real(w),
            Some(SwathWidth::Chord(_)) => Value::Word(ChordWord::ID.into()),
        },
        set: |s, v| {
            s.scenario.swath_width = match v {
                Value::Word(w) if w == ChordWord::ID => Some(SwathWidth::Chord(ChordWord::Chord)),
                v => v.optional_real()?.map(SwathWidth::Metres),
            };
            Ok(())
        },
        ..BASE
    },
    Param {
        key: "core_radius",
        sweep: true,
        plot: ("core radius", "m"),
        unit: "m",
        value_name: "M",
        kind: Kind::OptionalReal,
        range: "0 < core_radius < r0 m (only with snow_depth < 0)",
        help:
            "Core radius of an unwinding roll (its tube), in m (0 < core_radius < r0, needed with \
               a negative snow depth): the run stops there (`unwound`); the tube's own mass is \
               core_mass",
        default_note: Some("none (no unwinding)"),
        json: Presence::WhenSet,
        csv: (Section::Extra, Presence::WhenSet),
        get: |s| Value::of_option(s.scenario.core_radius),
        set: |s, v| v.optional_real().map(|x| s.scenario.core_radius = x),
        ..BASE
    },
    Param {
        key: "core_mass",
        sweep: true,
        plot: ("core mass", "kg"),
        unit: "kg",
        value_name: "KG",
        kind: Kind::OptionalReal,
        range: "core_mass > 0 kg (only with core_radius)",
        help: "Mass of the unwinding roll's tube, in kg (core_mass > 0, with core_radius): a \
               thin-walled tube of that mass at the core radius (I = m r_c^2; a sphere's core a \
               thin shell, I = 2/3 m r_c^2), the roll hollow inside it",
        default_note: Some(
            "none = the roll is of one material down to its centre (M = pi rho l r^2, as the \
             note's log)",
        ),
        json: Presence::WhenSet,
        csv: (Section::Extra, Presence::WhenSet),
        get: |s| Value::of_option(s.scenario.core_mass),
        set: |s, v| v.optional_real().map(|x| s.scenario.core_mass = x),
        ..BASE
    },
    Param {
        key: "t_end",
        sweep: true,
        plot: ("end time", "s"),
        aliases: &["t_end_s"],
        unit: "s",
        value_name: "S",
        range: "0 < t_end < infinity s",
        help: "Stop at this time, in s (t_end > 0)",
        get: |s| Value::Real(s.options.t_end),
        set: |s, v| v.real().map(|x| s.options.t_end = x),
        ..RUN
    },
    Param {
        key: "x_end",
        sweep: true,
        plot: ("end distance", "m"),
        aliases: &["x_end_m"],
        unit: "m",
        value_name: "M",
        kind: Kind::OptionalReal,
        range: "0 < x_end < infinity m",
        help: "Also stop when the log has rolled this distance, in m (x_end > 0)",
        default_note: Some("none"),
        get: |s| Value::of_option(s.options.x_end),
        set: |s, v| v.optional_real().map(|x| s.options.x_end = x),
        ..RUN
    },
    Param {
        key: "turns",
        value_name: "N",
        kind: Kind::OptionalCount,
        scope: Scope::Turns,
        applies: Applies::TurnModels,
        range: "turns >= 1",
        help: "Full turns to run, N >= 1 (turn models only)",
        get: |s| s.options.turns.map_or(Value::None, Value::Count),
        set: |s, v| {
            s.options.turns = match v {
                Value::None => None,
                v => Some(v.count()?),
            };
            Ok(())
        },
        ..RUN
    },
    Param {
        key: "rtol",
        sweep: true,
        plot: ("relative tolerance", "1"),
        value_name: "R",
        range: "1e-15 <= rtol < 1",
        help: "Relative tolerance of the integrator (1e-15 <= rtol < 1)",
        exponent: true,
        get: |s| Value::Real(s.options.tolerances.rtol),
        set: |s, v| v.real().map(|x| s.options.tolerances.rtol = x),
        ..RUN
    },
    Param {
        key: "atol",
        sweep: true,
        plot: ("absolute tolerance", "1"),
        value_name: "A",
        unit: "m, m/s",
        range: "atol >= 1e-30",
        help: "Absolute tolerance of the integrator, in the units of x (m) and v (m/s) \
               (atol >= 1e-30)",
        exponent: true,
        get: |s| Value::Real(s.options.tolerances.atol),
        set: |s, v| v.real().map(|x| s.options.tolerances.atol = x),
        ..RUN
    },
    Param {
        key: "sampling",
        kind: Kind::Text,
        scope: Scope::Record,
        help: "How the rows were chosen, in words (`every 0.5 s`, `one row per turn`)",
        get: |s| {
            let r = if s.per_turn {
                RecordedSampling::PerTurn
            } else {
                RecordedSampling::from(&s.options.sampling)
            };
            Value::Word(r.to_string())
        },
        set: |_, _| Err(WrongKind),
        ..RUN
    },
    Param {
        key: "max_rows",
        value_name: "N",
        kind: Kind::Count,
        range: "max_rows >= 1",
        help: "Most rows one run writes, N >= 1: a run known to need more (--dt: t_end/dt + 1, \
               --times: their count, turns: the turn count) is refused before it starts; one \
               sampled at every step, or on a --dt grid that --turns or --x-end may end before \
               t_end, stops there, its rows kept (stop reason row-limit)",
        get: |s| Value::Count(s.options.max_rows),
        set: |s, v| v.count().map(|x| s.options.max_rows = x),
        ..RUN
    },
    Param {
        key: "max_steps",
        value_name: "N",
        kind: Kind::Count,
        range: "max_steps >= 1",
        help: "Most integrator steps (accepted, rejected, and events) of one run, N >= 1: the \
               run stops there, its rows kept (stop reason step-limit)",
        get: |s| Value::Count(s.options.tolerances.max_steps),
        set: |s, v| v.count().map(|x| s.options.tolerances.max_steps = x),
        ..RUN
    },
    Param {
        key: "dt",
        unit: "s",
        value_name: "S",
        kind: Kind::OptionalReal,
        scope: Scope::Sampling,
        range: "dt > 0 s",
        help: "Write a regular grid 0, dt, 2 dt, ... up to the stop, in s (dt > 0)",
        default_note: Some("every accepted step"),
        json: Presence::WhenSet,
        csv: (Section::Tail, Presence::WhenSet),
        get: |s| match s.options.sampling {
            Sampling::Every(dt) => Value::Real(dt),
            _ => Value::None,
        },
        set: |s, v| {
            match v.optional_real()? {
                Some(dt) => s.options.sampling = Sampling::Every(dt),
                None if matches!(s.options.sampling, Sampling::Every(_)) => {
                    s.options.sampling = Sampling::Steps;
                }
                None => {}
            }
            Ok(())
        },
        ..RUN
    },
    Param {
        key: "times",
        unit: "s",
        value_name: "T1,T2,...",
        kind: Kind::Reals,
        scope: Scope::Sampling,
        range: "ascending, each <= t_end",
        help: "Write exactly these times, in s, strictly ascending, each <= t_end",
        default_note: Some("every accepted step"),
        json: Presence::WhenSet,
        csv: (Section::Tail, Presence::WhenSet),
        get: |s| match &s.options.sampling {
            Sampling::Times(ts) => Value::Reals(ts.clone()),
            _ => Value::None,
        },
        set: |s, v| {
            match v {
                Value::Reals(ts) => s.options.sampling = Sampling::Times(ts),
                Value::None if matches!(s.options.sampling, Sampling::Times(_)) => {
                    s.options.sampling = Sampling::Steps;
                }
                Value::None => {}
                _ => return Err(WrongKind),
            }
            Ok(())
        },
        ..RUN
    },
    Param {
        key: "mu",
        sweep: true,
        plot: ("friction coefficient μ", "1"),
        value_name: "MU",
        kind: Kind::OptionalReal,
        range: "0 < mu < infinity",
        help: "Coefficient of static friction mu, dimensionless (mu > 0): stop with `slip` where \
               the friction rolling needs reaches mu times the normal force",
        default_note: Some("none, no slip check"),
        csv: (Section::Extra, Presence::WhenSet),
        get: |s| Value::of_option(s.options.mu),
        set: |s, v| v.optional_real().map(|x| s.options.mu = x),
        ..RUN
    },
    Param {
        key: "collision",
        sweep: true,
        value_name: "MODEL",
        kind: Kind::Choice(Choice::Collision),
        applies: Applies::TurnModels,
        range: "note, charged or pivot",
        help: "How a turn model climbs the step of each new layer: note (eq. (89)), charged \
               (eq. (89) plus the potential energy of the jump), pivot (about the new layer's \
               edge; may stop with `stuck`)",
        get: |s| Value::Word(s.options.collision.id().into()),
        set: |s, v| {
            pick(&CollisionModel::ALL, &v.word()?, CollisionModel::id)
                .map(|x| s.options.collision = x)
        },
        ..RUN
    },
    Param {
        key: "on_hop",
        sweep: true,
        value_name: "ACTION",
        kind: Kind::Choice(Choice::OnHop),
        range: "stop or continue",
        help: "What to do where the normal force reaches zero: stop (reason `hop`; past it the \
               log flies and no rolling model applies) or continue as if contact were kept",
        get: |s| Value::Word(s.options.on_hop.id().into()),
        set: |s, v| pick(&OnHop::ALL, &v.word()?, OnHop::id).map(|x| s.options.on_hop = x),
        ..RUN
    },
    Param {
        key: "drag_coefficient",
        value_name: "CD",
        range: "0 <= drag_coefficient <= 100",
        help: "Air drag coefficient C_d, dimensionless (0 <= C_d <= 100): drag 0.5 rho_a C_d A \
               v^2 with frontal area A = 2 r l for the log, pi r^2 for the ball \
               (docs/snowball-and-losses.md §2)",
        default_note: Some("0, no drag"),
        get: |s| Value::Real(s.options.losses.drag_coefficient),
        set: |s, v| v.real().map(|x| s.options.losses.drag_coefficient = x),
        ..LOSS
    },
    Param {
        key: "air_density",
        unit: "kg/m^3",
        value_name: "RHO_A",
        range: "0 < air_density <= 1e4 kg/m^3",
        help: "Air density rho_a for the drag, kg/m^3 (> 0)",
        get: |s| Value::Real(s.options.losses.air_density),
        set: |s, v| v.real().map(|x| s.options.losses.air_density = x),
        ..LOSS
    },
    Param {
        key: "rolling_resistance",
        value_name: "C_RR",
        range: "0 <= rolling_resistance < 10",
        help: "Rolling-resistance coefficient c_rr, dimensionless (0 <= c_rr < 10): a couple \
               c_rr N r, i.e. a force c_rr times the normal force N",
        default_note: Some("0, none"),
        get: |s| Value::Real(s.options.losses.rolling_resistance),
        set: |s, v| v.real().map(|x| s.options.losses.rolling_resistance = x),
        ..LOSS
    },
    Param {
        key: "compaction_energy",
        unit: "J/kg",
        value_name: "E_C",
        range: "0 <= compaction_energy <= 1e12 J/kg",
        help: "Work of compacting the snow picked up, J per kg of snow (>= 0)",
        default_note: Some("0, none"),
        get: |s| Value::Real(s.options.losses.compaction_energy),
        set: |s, v| v.real().map(|x| s.options.losses.compaction_energy = x),
        ..LOSS
    },
    Param {
        key: "ledger",
        kind: Kind::Flag,
        applies: Applies::All,
        range: "true or false",
        help: "Write the energy ledger columns (kinetic, released, each loss, model, collision, \
               created, residual, J) even without losses; a run with losses always writes them. \
               The turn models take no losses but keep the ledger (their collisions' losses; \
               `snowroll turns`: at each turn end, before its collision)",
        default_note: Some("off"),
        get: |s| Value::Flag(s.options.losses.ledger),
        set: |s, v| v.flag().map(|x| s.options.losses.ledger = x),
        ..LOSS
    },
    Param {
        key: "terminal_tol",
        value_name: "TOL",
        applies: Applies::All,
        range: "0 <= terminal_tol < 1",
        help: "Stop with `terminal` where |a| falls to TOL times the initial drive \
               (g sin a - c_rr g cos a)/(1 + k): only the snowless log or ball with drag has a \
               terminal velocity; 0 = keep going (0 <= TOL < 1)",
        exponent: true,
        get: |s| Value::Real(s.options.losses.terminal_tol),
        set: |s, v| v.real().map(|x| s.options.losses.terminal_tol = x),
        ..LOSS
    },
];
