//! `snowroll.sweep`: the library's sweep ([`snowroll::sweep`]) over a grid
//! given as a Python dict, rows as numpy columns named as in the CLI's
//! `snowroll sweep` CSV.

use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use snowroll::sweep::{
    run_chunks, shard_range, Axis, Choices, Grid, GridError, Method, Param, SweepRow, Values,
    DEFAULT_CHUNK,
};
use snowroll::{CollisionModel, ModelKind, OnHop, ParamError};

use crate::guard::Guard;
use crate::{column, record, value_error, value_error_text};

/// The values of one sweep axis: a string as the CLI reads it (`a,b,c` or
/// `start:end:count`), one number, or a sequence of numbers.
fn axis_values(key: &str, value: &Bound<'_, PyAny>) -> PyResult<Values> {
    if let Ok(text) = value.cast::<PyString>() {
        return Values::parse(key, &text.to_cow()?).map_err(|e| value_error_text(&e.to_string()));
    }
    if let Ok(x) = value.extract::<f64>() {
        return Ok(Values::List(vec![x]));
    }
    let list: Vec<f64> = value.extract().map_err(|_| {
        PyValueError::new_err(format!(
            "{key}: expected a number, a sequence of numbers or a string \"a,b,c\" / \"start:end:count\""
        ))
    })?;
    Ok(Values::List(list))
}

/// The `TypeError` of a list setting given neither as a string nor as a
/// sequence of strings, naming its key.
fn ids_expected(key: &str) -> PyErr {
    PyTypeError::new_err(format!(
        "{key}: expected a string \"a,b\" or a sequence of ids (str)"
    ))
}

/// The models of a sweep: `"a,b"` or a sequence of ids.
fn sweep_models(value: &Bound<'_, PyAny>) -> PyResult<Vec<ModelKind>> {
    let names: Vec<String> = match value.cast::<PyString>() {
        Ok(text) => text.to_cow()?.split(',').map(str::to_string).collect(),
        Err(_) => value.extract().map_err(|_| ids_expected("model"))?,
    };
    names
        .iter()
        .map(|n| n.parse().map_err(value_error))
        .collect()
}

/// The ids of a list setting: `"a,b"` or a sequence of ids, each one of
/// `ids` (the kebab-case names of `all`).
fn choice_list<T: Copy>(
    key: &str,
    value: &Bound<'_, PyAny>,
    all: &[T],
    id: fn(T) -> &'static str,
) -> PyResult<Vec<T>> {
    let names: Vec<String> = match value.cast::<PyString>() {
        Ok(text) => text
            .to_cow()?
            .split(',')
            .map(|s| s.trim().to_string())
            .collect(),
        Err(_) => value.extract().map_err(|_| ids_expected(key))?,
    };
    names
        .iter()
        .map(|n| {
            all.iter().copied().find(|v| id(*v) == n).ok_or_else(|| {
                let ids: Vec<&str> = all.iter().map(|v| id(*v)).collect();
                PyValueError::new_err(format!(
                    "{key}: unknown value {n:?}; expected one of {}",
                    ids.join(", ")
                ))
            })
        })
        .collect()
}

/// Runs a sweep (`snowroll sweep`): every model in `grid["model"]` at every
/// point of the other axes, one summary row each, in grid order (the last
/// axis in `Param` order varies fastest), rows computed in parallel with the
/// GIL released. `shard = (i, n)` runs only shard i of n, as `--shard i/n`.
/// Returns `{"columns": {name: ndarray or list}, "len": int, "shard": (i, n)}`:
/// numbers as numpy arrays, the text columns (`model`, `on_hop`,
/// `collision`, `stop`, `error`) as lists of `str` or `None`, which the
/// Python layer turns into numpy object arrays.
#[pyfunction]
#[pyo3(signature = (grid, *, shard = None, method = "auto", max_memory = crate::guard::MAX_MEMORY_DEFAULT))]
pub(crate) fn sweep<'py>(
    py: Python<'py>,
    grid: &Bound<'py, PyDict>,
    shard: Option<(u64, u64)>,
    method: &str,
    max_memory: u64,
) -> PyResult<Bound<'py, PyDict>> {
    let method = match method {
        "auto" => Method::Auto,
        "ode" => Method::Ode,
        other => {
            return Err(PyValueError::new_err(format!(
                "unknown method {other:?}: expected auto or ode"
            )))
        }
    };
    let grid = parse_grid(grid)?;
    let (i, n) = shard.unwrap_or((0, 1));
    let range = shard_range(grid.len(), i, n).map_err(|e| value_error_text(&e))?;
    let mut guard = Guard::new(max_memory, sweep_row_bytes());
    guard.check_up_front((range.end - range.start) as f64, "sweep()")?;
    // Chunks small enough that Ctrl-C is seen within about a second even
    // for the slowest models, large enough to keep both cores busy.
    let chunk = DEFAULT_CHUNK / 8;
    let (rows, done) = py.detach(|| {
        let mut rows: Vec<SweepRow> = Vec::new();
        let done = run_chunks(&grid, range, chunk, method, |part| {
            guard
                .rows(part.len() as u64, "sweep()")
                .map_err(|_| Stop::Guard)?;
            rows.extend_from_slice(part);
            Ok::<(), Stop>(())
        });
        (rows, done)
    });
    guard.outcome(done, |e| match e {
        Stop::Param(p) => value_error(p),
        Stop::Guard => PyRuntimeError::new_err("sweep stopped"),
    })?;
    let c = columns(py, &rows)?;
    let out = PyDict::new(py);
    out.set_item("columns", c)?;
    out.set_item("len", grid.len())?;
    out.set_item("shard", (i, n))?;
    out.set_item("version", snowroll_io::VERSION)?;
    Ok(out)
}

/// The number of points of a Python grid dict (models × every axis × the
/// settings), without running any.
#[pyfunction]
pub(crate) fn grid_len(grid: &Bound<'_, PyDict>) -> PyResult<u64> {
    Ok(parse_grid(grid)?.len())
}

/// Why a sweep's rows stopped coming: a bad grid point, or the guard.
enum Stop {
    Param(ParamError),
    /// The guard stopped the run; its error is the guard's.
    Guard,
}

impl From<ParamError> for Stop {
    fn from(e: ParamError) -> Self {
        Stop::Param(e)
    }
}

/// Bytes a sweep row holds until the call returns: the library's row and
/// one float (or object pointer) per column made from it.
fn sweep_row_bytes() -> u64 {
    (std::mem::size_of::<SweepRow>() + 8 * SweepRow::COLUMNS.len()) as u64
}

/// The grid of a Python grid dict: `model`, the numeric axes and the two
/// lists of words (`collision`, `on_hop`).
fn parse_grid(grid: &Bound<'_, PyDict>) -> PyResult<Grid> {
    let mut models = Vec::new();
    let mut axes = Vec::new();
    let mut choices = Choices::default();
    for (key, value) in grid.iter() {
        let key: String = key.extract()?;
        match key.as_str() {
            "model" => {
                models = sweep_models(&value)?;
                continue;
            }
            "collision" => {
                choices.collision =
                    choice_list(&key, &value, &CollisionModel::ALL, CollisionModel::id)?;
                continue;
            }
            "on_hop" => {
                choices.on_hop = choice_list(&key, &value, &OnHop::ALL, OnHop::id)?;
                continue;
            }
            _ => {}
        }
        let param = Param::from_key(&key).ok_or_else(|| {
            PyValueError::new_err(format!(
                "unknown axis {key:?}: expected model, collision, on_hop or one of {}",
                Param::ALL.map(Param::key).join(", ")
            ))
        })?;
        axes.push(Axis {
            param,
            values: axis_values(param.key(), &value)?,
        });
    }
    Grid::new(models, axes)
        .and_then(|g| g.with_choices(choices))
        .map_err(|e| match e {
            // The CLI's wording names its flag; a Python caller writes a grid key.
            GridError::NoModel => PyValueError::new_err(
                "no model given: put \"model\": \"ID[,ID...]\" (or a list of ids) in the grid \
                 (snowroll.models() lists them)",
            ),
            other => value_error_text(&other.to_string()),
        })
}

/// The rows as columns named as the CLI's CSV header, in its order: numbers
/// as numpy arrays, text as lists of `str` or `None`.
fn columns<'py>(py: Python<'py>, rows: &[SweepRow]) -> PyResult<Bound<'py, PyDict>> {
    let c = PyDict::new(py);
    let opt = |x: Option<f64>| x.unwrap_or(f64::NAN);
    column(py, &c, "index", rows, |r| r.index)?;
    c.set_item(
        "model",
        rows.iter().map(|r| r.model.id()).collect::<Vec<_>>(),
    )?;
    // The numeric axes, in grid order (NaN where x_end or mu is not set).
    for p in Param::ALL {
        column(py, &c, p.key(), rows, |r| r.param(p))?;
    }
    c.set_item(
        "on_hop",
        rows.iter().map(|r| r.on_hop.id()).collect::<Vec<_>>(),
    )?;
    c.set_item(
        "collision",
        rows.iter().map(|r| r.collision.id()).collect::<Vec<_>>(),
    )?;
    let stops = rows
        .iter()
        .map(|r| r.stop.map(|s| record(py, &s)).transpose())
        .collect::<PyResult<Vec<_>>>()?;
    c.set_item("stop", stops)?;
    column(py, &c, "t_s", rows, |r| opt(r.t_s))?;
    column(py, &c, "x_m", rows, |r| opt(r.x_m))?;
    column(py, &c, "v_m_s", rows, |r| opt(r.v_m_s))?;
    column(py, &c, "a_over_g_sin_alpha", rows, |r| {
        opt(r.a_over_g_sin_alpha)
    })?;
    column(py, &c, "turns", rows, |r| {
        r.turns.map_or(f64::NAN, |k| k as f64)
    })?;
    c.set_item(
        "error",
        rows.iter().map(|r| r.error.clone()).collect::<Vec<_>>(),
    )?;
    c.set_item(
        "warnings",
        rows.iter().map(|r| r.warnings.clone()).collect::<Vec<_>>(),
    )?;
    Ok(c)
}
