//! One model's fit ([`snowroll::fit::ModelFit`]) as a JSON record: the
//! element of `fits` in `snowroll fit --format json`, and the dict of
//! Python's `snowroll.fit(...)`, written once for both. No number that is
//! not finite is written: `null` stands where there is none (a standard
//! error the data do not give, the condition number of a parameter without
//! effect).

use serde_json::{json, Map, Value};
use snowroll::fit::ModelFit;

/// `x` as a JSON number, or `null` when not finite.
pub fn finite_or_null(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// The record: `model`, `equation`, `params` {KEY: {value, stderr, unit,
/// start}}, `correlations` {"A,B": r}, `unseparated` [{keys, text, value,
/// rel_stderr}], `rms_m`, `aic`, `bic`, `rank`, `converged`, `reason`,
/// `iterations`, `directions_fixed`, `condition`.
pub fn fit_record(f: &ModelFit) -> Value {
    let num = finite_or_null;
    let mut params = Map::new();
    for p in &f.params {
        params.insert(
            p.key.clone(),
            json!({
                "value": num(p.value),
                "stderr": p.stderr.map_or(Value::Null, num),
                "unit": p.unit,
                "start": num(p.start),
            }),
        );
    }
    let mut correlations = Map::new();
    for (i, a) in f.params.iter().enumerate() {
        for (j, b) in f.params.iter().enumerate().skip(i + 1) {
            let r = f.correlations[i][j].map_or(Value::Null, num);
            correlations.insert(format!("{},{}", a.key, b.key), r);
        }
    }
    let unseparated: Vec<Value> = f
        .unseparated
        .iter()
        .map(|u| {
            json!({
                "keys": u.keys,
                "text": u.text,
                "value": u.value.map_or(Value::Null, num),
                "rel_stderr": u.rel_stderr.map_or(Value::Null, num),
            })
        })
        .collect();
    json!({
        "model": f.model.id(),
        "equation": f.model.equation(),
        "params": params,
        "correlations": correlations,
        "unseparated": unseparated,
        "rms_m": num(f.rms_m),
        "aic": num(f.aic),
        "bic": num(f.bic),
        "rank": f.rank,
        "converged": f.converged,
        "reason": f.reason,
        "iterations": f.iterations,
        "directions_fixed": f.rank_params,
        "condition": num(f.condition),
    })
}
