//! The parameter table and the models as the explorer's page reads them
//! (JSON): one writer for the two engines that answer the page, the
//! WebAssembly module (`crates/snowroll-wasm`) and `snowroll serve`'s
//! `/api/params`, so the page builds the same form from either.

use snowroll::models::{TURNS_DEFAULT, TURNS_T_END_S};
use snowroll::params::{Applies, Group, Kind, Scope};
use snowroll::{ModelKind, Param, Settings, Value, PARAMS};

/// Whether `snowroll simulate` takes parameter `p`, as its flags do.
pub fn simulate_takes(p: &Param) -> bool {
    matches!(p.scope, Scope::Shared | Scope::Sampling | Scope::Turns)
}

/// Whether `snowroll turns` takes parameter `p`, as its flags do.
pub fn turns_takes(p: &Param) -> bool {
    matches!(p.scope, Scope::Shared | Scope::Turns)
}

/// The table as a JSON object: `params` (each settable parameter, with its
/// slider), `models`, and `turns_command_defaults`. A server adds its own
/// keys (its limits) to the object.
pub fn page_table() -> serde_json::Map<String, serde_json::Value> {
    let params: Vec<serde_json::Value> = PARAMS
        .iter()
        .filter(|p| p.settable())
        .map(param_json)
        .collect();
    let models: Vec<serde_json::Value> = ModelKind::ALL
        .iter()
        .map(|m| {
            serde_json::json!({
                "id": m.id(),
                "alias": m.alias(),
                "equation": m.equation(),
                "description": m.description(),
                "turn_model": m.is_turn_model(),
            })
        })
        .collect();
    let mut table = serde_json::Map::new();
    table.insert("params".into(), params.into());
    table.insert("models".into(), models.into());
    table.insert(
        "turns_command_defaults".into(),
        serde_json::json!({ "turns": TURNS_DEFAULT, "t_end": TURNS_T_END_S }),
    );
    table
}

/// A parameter's value as JSON (`null` for none).
pub fn value_json(v: &Value) -> serde_json::Value {
    match v {
        Value::None => serde_json::Value::Null,
        Value::Real(x) => serde_json::json!(x),
        Value::Count(n) => serde_json::json!(n),
        Value::Flag(b) => serde_json::json!(b),
        Value::Word(w) => serde_json::json!(w),
        Value::Reals(xs) => serde_json::json!(xs),
    }
}

/// One parameter as the page reads it.
fn param_json(p: &Param) -> serde_json::Value {
    let mut commands = Vec::new();
    if simulate_takes(p) {
        commands.push("simulate");
    }
    if turns_takes(p) {
        commands.push("turns");
    }
    let choices = match p.kind {
        Kind::Choice(c) => c.ids(),
        Kind::OptionalRealOr(word) => vec![word],
        _ => Vec::new(),
    };
    serde_json::json!({
        "key": p.key,
        "flag": p.flag(),
        "unit": p.unit,
        "kind": kind_id(p.kind),
        "group": match p.group { Group::Scenario => "scenario", Group::Run => "run", Group::Losses => "losses" },
        "scope": match p.scope { Scope::Shared => "shared", Scope::Sampling => "sampling", Scope::Turns => "turns", Scope::Record => "record" },
        "applies": match p.applies { Applies::All => "all", Applies::Sphere => "sphere", Applies::TurnModels => "turn-models", Applies::CircularModels => "circular-models" },
        "range": p.range,
        "help": p.help,
        "default": value_json(&p.get(&Settings::default())),
        "default_text": p.default_text(),
        "choices": choices,
        "commands": commands,
        "slider": slider(p),
    })
}

/// The kind as a word.
fn kind_id(kind: Kind) -> &'static str {
    match kind {
        Kind::Real => "real",
        Kind::OptionalReal => "optional-real",
        Kind::OptionalRealOr(_) => "optional-real-or-word",
        Kind::Count => "count",
        Kind::OptionalCount => "optional-count",
        Kind::Flag => "flag",
        Kind::Choice(_) => "choice",
        Kind::Reals => "reals",
        Kind::Text => "text",
    }
}

/// The bounds the range text sets on either side of the key: `(lower,
/// lower is strict, upper)`; `infinity` or no bound is `None`.
pub fn bounds(p: &Param) -> (Option<f64>, bool, Option<f64>) {
    let words: Vec<&str> = p.range.split_whitespace().collect();
    let num = |i: usize| words.get(i).and_then(|w| w.parse::<f64>().ok());
    let Some(at) = words.iter().position(|w| *w == p.key) else {
        return (None, false, None);
    };
    let (mut lo, mut strict, mut hi) = (None, false, None);
    if at >= 2 && matches!(words[at - 1], "<" | "<=") {
        lo = num(at - 2);
        strict = words[at - 1] == "<";
    }
    match words.get(at + 1).copied() {
        Some("<" | "<=") => hi = num(at + 2).filter(|x| x.is_finite()),
        Some(op @ (">" | ">=")) => {
            lo = num(at + 2);
            strict = op == ">";
        }
        _ => {}
    }
    (lo, strict, hi)
}

/// A slider's span for a real parameter: its range where that is finite and
/// within a thousand times the default's size, else up to ten times the
/// default; logarithmic for the tolerances. A parameter with no lower bound
/// (the snow depth, negative for the unwinding roll) spans as far below 0
/// as above. `null` for other kinds.
fn slider(p: &Param) -> serde_json::Value {
    if !matches!(
        p.kind,
        Kind::Real | Kind::OptionalReal | Kind::OptionalRealOr(_)
    ) {
        return serde_json::Value::Null;
    }
    let (lo, strict, hi) = bounds(p);
    let unbounded_below = lo.is_none();
    let lo = lo.unwrap_or(0.0);
    let size = match p.get(&Settings::default()) {
        Value::Real(x) => x.abs().max(1.0),
        _ => 1.0,
    };
    let max = match hi {
        Some(h) if p.exponent || h - lo <= 1000.0 * size => h,
        _ => lo + 10.0 * size,
    };
    let min = if unbounded_below {
        -max
    } else if strict && !p.exponent {
        lo + (max - lo) * 1e-3
    } else {
        lo
    };
    serde_json::json!({ "min": min, "max": max, "log": p.exponent })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_read_the_range_text() {
        let b = |key| bounds(Param::of_key(key).unwrap());
        assert_eq!(b("alpha_deg"), (Some(0.0), true, Some(90.0)));
        // Any finite depth: negative for the unwinding roll.
        assert_eq!(b("snow_depth"), (None, false, None));
        let depth = slider(Param::of_key("snow_depth").unwrap());
        assert_eq!(
            (depth["min"].as_f64(), depth["max"].as_f64()),
            (Some(-10.0), Some(10.0))
        );
        assert_eq!(b("rtol"), (Some(1e-15), false, Some(1.0)));
        assert_eq!(b("t_end"), (Some(0.0), true, None));
    }
}
