//! The native half of the `snowroll` Python package (`snowroll._snowroll`).
//!
//! A thin binding: every number comes from the `snowroll` library, which this
//! crate calls exactly as the command line does (the same [`ScenarioFile`](snowroll::ScenarioFile)
//! defaults, the same [`SimOptions`], the same [`RunParams`]), so a run from
//! Python equals the CLI's run with the same parameters to the last bit. The
//! keyword names are the one parameter vocabulary of the project: the CLI's
//! long flags in snake_case. The Python layer (`python/snowroll/__init__.py`)
//! wraps the dictionaries returned here in its `Result` and `TurnResult`
//! classes.
//!
//! The GIL is released while the library computes ([`Python::detach`]).
//! Bad parameters raise `ValueError` with the library's message
//! ([`ParamError`]); a failed integration raises `RuntimeError` ([`SimError`]).
//! The library names parameters by key and leaves their spelling to each
//! front end: here the keyword (`snow_depth=`, `keyword`), where the
//! command line writes its flag (`--snow-depth`).

mod columns;
mod fit;
mod guard;
mod models;
mod sweep;

use numpy::IntoPyArray;
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};
use snowroll::models::{TURNS_DEFAULT, TURNS_T_END_S};
use snowroll::params::{Kind, Scope};
use snowroll::trajectory::Collected;
use snowroll::{
    run_turns_into, validity_warnings, Given, LedgerRow, ModelKind, Param, ParamError, Sampling,
    Scenario, Settings, SimError, SimOptions, Stop, Trajectory, TurnSummary, TurnTable, Value,
    PARAMS,
};
use snowroll_io::RunParams;

pub(crate) use columns::record;
use columns::{common, trajectory_columns, turn_columns, SummaryRecord};

/// A parameter that a library message names (by its key in the parameter
/// table, with the word given with it), as a Python caller writes it: the
/// keyword `snow_depth=`, `shape='sphere'`.
pub(crate) fn keyword(key: &str, word: Option<&str>) -> String {
    match word {
        Some(w) if w.parse::<f64>().is_ok() => format!("{key}={w}"),
        Some(w) => format!("{key}='{w}'"),
        None => format!("{key}="),
    }
}

/// `ValueError` with `message` as it is (a message of this binding's own,
/// or of the library naming no parameter).
pub(crate) fn value_error_text(message: &str) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// A bad parameter: `ValueError` with the library's message, the
/// parameters it names written as keywords ([`keyword`]).
pub(crate) fn value_error(e: ParamError) -> PyErr {
    PyValueError::new_err(e.render(&keyword))
}

/// A failed run: `ValueError` for bad parameters found by the run,
/// `RuntimeError` for a failed integration; both with the library's message.
fn sim_error(e: SimError) -> PyErr {
    match e {
        SimError::Param(p) => value_error(p),
        other => PyRuntimeError::new_err(other.render(&keyword)),
    }
}

/// The keywords of a call, read against the parameter table: each one a
/// parameter of `scopes`, its value converted to the parameter's kind;
/// `None` leaves the default. `function` names the call in the message for
/// an unknown keyword, as Python itself would.
pub(crate) fn given(
    function: &str,
    scopes: &[Scope],
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<Given> {
    let mut given = Given::new();
    let Some(kwargs) = kwargs else {
        return Ok(given);
    };
    for (k, v) in kwargs.iter() {
        let key: String = k.extract()?;
        let Some(p) = Param::of_key(&key).filter(|p| scopes.contains(&p.scope)) else {
            return Err(PyTypeError::new_err(format!(
                "{function}() got an unexpected keyword argument '{key}'"
            )));
        };
        if v.is_none() {
            continue;
        }
        let value = match p.kind {
            Kind::OptionalRealOr(_) if v.is_instance_of::<PyString>() => Value::Word(v.extract()?),
            Kind::Real | Kind::OptionalReal | Kind::OptionalRealOr(_) => Value::Real(v.extract()?),
            Kind::Count | Kind::OptionalCount => Value::Count(v.extract()?),
            Kind::Flag => Value::Flag(v.extract()?),
            Kind::Choice(_) | Kind::Text => Value::Word(v.extract()?),
            Kind::Reals => Value::Reals(v.extract()?),
        };
        given.insert(p, value);
    }
    Ok(given)
}

/// The table's parameter `key`.
fn param(key: &str) -> PyResult<&'static Param> {
    Param::of_key(key)
        .ok_or_else(|| PyRuntimeError::new_err(format!("no parameter {key} in the table")))
}

/// The validated scenario and options of `given` over `base`.
fn inputs(given: &Given, base: Settings) -> PyResult<(Scenario, SimOptions)> {
    let settings = given.apply(base).map_err(value_error)?;
    let scenario = Scenario::new(settings.scenario).map_err(value_error)?;
    settings.options.validate().map_err(value_error)?;
    Ok((scenario, settings.options))
}

/// The parameter table, one dict per parameter: `key`, `kind`, `choices`,
/// `unit`, `range`, `help`, `default` (the value, `None` when off),
/// `default_text` (as `--help` shows it), `scope`, `group` (`scenario`,
/// `run`, `losses`), `applies`, `aliases`.
/// The Python layer builds its keyword checks, signatures, docstrings and
/// stub from it.
fn param_table(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for p in PARAMS.iter() {
        let d = PyDict::new(py);
        d.set_item("key", p.key)?;
        let (kind, choices) = match p.kind {
            Kind::Real => ("real", None),
            Kind::OptionalReal => ("optional_real", None),
            Kind::OptionalRealOr(word) => ("optional_real_or", Some(vec![word])),
            Kind::Count => ("count", None),
            Kind::OptionalCount => ("optional_count", None),
            Kind::Flag => ("flag", None),
            Kind::Choice(c) => ("choice", Some(c.ids())),
            Kind::Reals => ("reals", None),
            Kind::Text => ("text", None),
        };
        d.set_item("kind", kind)?;
        d.set_item("choices", choices)?;
        d.set_item("unit", p.unit)?;
        d.set_item("range", p.range)?;
        d.set_item("help", p.help)?;
        d.set_item("default", record(py, &p.default_value())?)?;
        d.set_item("default_text", p.default_text())?;
        let scope = match p.scope {
            Scope::Shared => "shared",
            Scope::Sampling => "sampling",
            Scope::Turns => "turns",
            Scope::Record => "record",
        };
        d.set_item("scope", scope)?;
        d.set_item("group", format!("{:?}", p.group).to_lowercase())?;
        d.set_item("applies", p.applies.to_string())?;
        d.set_item("aliases", p.aliases.to_vec())?;
        list.append(d)?;
    }
    Ok(list)
}

/// `value` (a serde record) as Python numbers, strings, lists, dicts, `None`.
pub(crate) fn to_py<'py>(
    py: Python<'py>,
    value: &serde_json::Value,
) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => match (n.as_u64(), n.as_i64()) {
            (Some(u), _) => u.into_pyobject(py)?.into_any(),
            (None, Some(i)) => i.into_pyobject(py)?.into_any(),
            _ => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(to_py(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (k, v) in map {
                dict.set_item(k, to_py(py, v)?)?;
            }
            dict.into_any()
        }
    })
}

/// Runs one model for one scenario (`snowroll simulate`); returns a dict
/// with `columns`, `stop`, `params`, `version`, `model`, `equation`,
/// `warnings`. The keywords are the parameter table's (`PARAMS`); the
/// Python layer wraps the dict in `snowroll.Result`.
#[pyfunction]
#[pyo3(signature = (model = "torque-cm", *, max_memory = guard::MAX_MEMORY_DEFAULT, **params))]
fn simulate<'py>(
    py: Python<'py>,
    model: &str,
    max_memory: u64,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let scopes = [Scope::Shared, Scope::Sampling, Scope::Turns];
    let mut given = given("simulate", &scopes, params)?;
    let kind: ModelKind = model.parse().map_err(value_error)?;
    let turns = given.take(param("turns")?);
    if turns.is_some() && !kind.is_turn_model() {
        return Err(PyValueError::new_err(format!(
            "turns applies only to the turn models turns, turns-exact, not to {}",
            kind.id()
        )));
    }
    let (times, dt) = (given.get(param("times")?), given.get(param("dt")?));
    if times.is_some() && dt.is_some() {
        return Err(PyValueError::new_err(
            "`times` and `dt` conflict, give one of them",
        ));
    }
    let mut base = Settings::default();
    if let Some(Value::Count(n)) = turns {
        base.options.turns = Some(n);
    }
    let (scenario, opts) = inputs(&given, base)?;
    let guard = guard::Guard::new(max_memory, guard::sample_bytes());
    let mut collected = Collected::default();
    if let Some(rows) = opts.known_rows() {
        guard.check_up_front(rows, "simulate()")?;
        // The rows' room at once, fallibly (no doubling to pay for).
        collected.samples = guard::try_vec(rows as usize, "simulate()")?;
    }
    let mut sink = guard::GuardedSamples { collected, guard };
    let end = py.detach(|| kind.build().simulate_into(&scenario, &opts, &mut sink));
    let guard::GuardedSamples { collected, guard } = sink;
    let traj = collected.into_trajectory(kind, guard.outcome(end, sim_error)?);
    let mut params = RunParams::new(&scenario, &opts);
    params.warnings = validity_warnings(kind, &scenario)
        .iter()
        .map(ToString::to_string)
        .collect();
    let out = common(py, kind, params, &traj.stop)?;
    // The closed-form terminal velocity where one exists, as the CLI's JSON `stop` has it.
    let v_terminal = (kind == ModelKind::Snowless)
        .then(|| snowroll::losses::terminal_velocity(&scenario, &opts.losses))
        .flatten();
    if let (Some(vt), Some(stop)) = (v_terminal, out.get_item("stop")?) {
        stop.set_item("v_terminal_m_s", vt)?;
    }
    trajectory_columns(py, &traj)?.into_result(&out)?;
    Ok(out)
}

/// Runs a turn model for a number of turns (`snowroll turns`); returns a
/// dict with `columns` (one row per turn), `summary`, `stop`, `params`,
/// `version`, `model`, `equation`, `warnings`.
#[pyfunction]
#[pyo3(signature = (model = "turns", *, max_memory = guard::MAX_MEMORY_DEFAULT, **params))]
fn turns<'py>(
    py: Python<'py>,
    model: &str,
    max_memory: u64,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let mut given = given("turns", &[Scope::Shared, Scope::Turns], params)?;
    let kind: ModelKind = model.parse().map_err(value_error)?;
    if !kind.is_turn_model() {
        return Err(PyValueError::new_err(format!(
            "turns() needs a turn model, one of turns, turns-exact (aliases eq73, eq88), not {}",
            kind.id()
        )));
    }
    let wanted = match given.take(param("turns")?) {
        Some(Value::Count(n)) => n,
        _ => TURNS_DEFAULT,
    };
    // Only the turn ends are recorded, as by the CLI.
    let mut base = Settings::default();
    base.options.t_end = TURNS_T_END_S;
    base.options.sampling = Sampling::Ends;
    base.options.turns = Some(wanted);
    let (scenario, opts) = inputs(&given, base)?;
    let guard = guard::Guard::new(max_memory, guard::turn_bytes())
        .with_clock_every(guard::TURN_ROWS_PER_CLOCK);
    guard.check_up_front(wanted as f64, "turns()")?;
    let mut sink = guard::GuardedTurns {
        // The turns' room at once, fallibly (no doubling to pay for).
        rows: guard::try_vec(usize::try_from(wanted).unwrap_or(usize::MAX), "turns()")?,
        ledger: Vec::new(),
        guard,
    };
    let end = py.detach(|| run_turns_into(kind, &scenario, &opts, &mut sink));
    let guard::GuardedTurns {
        rows,
        ledger,
        guard,
    } = sink;
    let end = guard.outcome(end, sim_error)?;
    let table = TurnTable {
        model: end.model,
        rows,
        ledger,
        stop: end.stop,
        summary: end.summary,
        stats: end.stats,
        hop_doubt: end.hop_doubt,
    };
    let mut params = RunParams::new(&scenario, &opts).per_turn();
    params.warnings = validity_warnings(kind, &scenario)
        .iter()
        .map(ToString::to_string)
        .collect();
    let out = common(py, kind, params, &table.stop)?;
    turn_columns(py, &table)?.into_result(&out)?;
    out.set_item("summary", Bound::new(py, SummaryRecord(table.summary))?)?;
    Ok(out)
}

/// The native module `snowroll._snowroll`.
#[pymodule]
fn _snowroll(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", snowroll_io::VERSION)?;
    m.add("PARAMS", param_table(m.py())?)?;
    m.add("MAX_MEMORY", guard::MAX_MEMORY_DEFAULT)?;
    m.add(
        "SWEEP_AXES",
        snowroll::sweep::AxisParam::ALL
            .map(snowroll::sweep::AxisParam::key)
            .to_vec(),
    )?;
    m.add("SWEEP_ROW_BYTES", sweep::SWEEP_ROW_BYTES)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(turns, m)?)?;
    m.add_function(wrap_pyfunction!(models::models, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::grid_len, m)?)?;
    Ok(())
}
