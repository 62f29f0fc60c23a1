//! `snowroll.sweep`: the library's sweep ([`snowroll::sweep`]) over a grid
//! given as a Python dict, rows as numpy columns named as in the CLI's
//! `snowroll sweep` CSV.

use numpy::IntoPyArray;
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use snowroll::sweep::{
    run_chunks, shard_range, Axis, AxisParam, Choices, Grid, GridError, Method, SweepRow, Values,
    DEFAULT_CHUNK,
};
use snowroll::trajectory::StopReason;
use snowroll::{CollisionModel, ModelKind, OnHop, ParamError};

use crate::guard::{grow, try_vec, Guard};
use crate::{record, value_error, value_error_text};

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
/// axis in `AxisParam` order varies fastest), rows computed in parallel with the
/// GIL released. `shard = (i, n)` runs only shard i of n, as `--shard i/n`.
/// Returns `{"columns": {name: ndarray}, "len": int, "shard": (i, n),
/// "rows": (start, end), "settings": [(name, text)], "version": str}`:
/// numbers as numpy arrays, the text columns (`model`, `on_hop`,
/// `collision`, `stop`, `error`, `warnings`) as numpy object arrays of `str`
/// or `None`, each distinct value one shared string. A result that cannot
/// fit in `max_memory` ([`SWEEP_ROW_BYTES`] a row), or in the memory the
/// machine has, raises `MemoryError`, before any row is computed.
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
    let rows = (range.end - range.start) as usize;
    let mut guard = Guard::new(max_memory, SWEEP_ROW_BYTES);
    guard.check_up_front(rows as f64, "sweep()")?;
    // Every column's room at once, fallibly: a grid too large for the
    // machine is a MemoryError here, before any row is computed.
    let mut cols = Columns::with_room(rows)?;
    // Chunks small enough that Ctrl-C is seen within about a second even
    // for the slowest models, large enough to keep both cores busy.
    let chunk = DEFAULT_CHUNK / 8;
    let done = py.detach(|| {
        run_chunks(&grid, range.clone(), chunk, method, |part| {
            guard
                .rows(part.len() as u64, "sweep()")
                .map_err(|_| Stop::Guard)?;
            // A failed row's message: its text twice (Rust's, then Python's
            // string) and the string object's header.
            let errors: u64 = (part.iter().filter_map(|r| r.error.as_ref()))
                .map(|e| 2 * e.len() as u64 + ERROR_OBJECT_BYTES)
                .sum();
            if errors > 0 {
                guard.bytes(errors, "sweep()").map_err(|_| Stop::Guard)?;
            }
            cols.push(part).map_err(Stop::Memory)
        })
    });
    guard.outcome(done, |e| match e {
        Stop::Param(p) => value_error(p),
        Stop::Guard => PyRuntimeError::new_err("sweep stopped"),
        Stop::Memory(e) => e,
    })?;
    let out = PyDict::new(py);
    out.set_item("columns", cols.into_py(py)?)?;
    out.set_item("len", grid.len())?;
    out.set_item("shard", (i, n))?;
    out.set_item("rows", (range.start, range.end))?;
    out.set_item("settings", settings(&grid, method))?;
    out.set_item("version", snowroll_io::VERSION)?;
    Ok(out)
}

/// The number of points of a Python grid dict (models × every axis × the
/// settings), without running any.
#[pyfunction]
pub(crate) fn grid_len(grid: &Bound<'_, PyDict>) -> PyResult<u64> {
    Ok(parse_grid(grid)?.len())
}

/// Why a sweep's rows stopped coming: a bad grid point, the guard, or an
/// allocation that failed.
enum Stop {
    Param(ParamError),
    /// The guard stopped the run; its error is the guard's.
    Guard,
    Memory(PyErr),
}

impl From<ParamError> for Stop {
    fn from(e: ParamError) -> Self {
        Stop::Param(e)
    }
}

/// Bytes a sweep row holds until the call returns, measured (issue 33,
/// item 3; docs/reliability.md): the 18 numeric columns of 8 bytes (index,
/// the 12 parameters, t_s, x_m, v_m_s, a_over_g_sin_alpha, turns), the codes
/// of its 5 text cells that repeat (model, on_hop, collision, stop,
/// warnings; 4 bytes each, while the call runs) and the 6 pointers of the
/// object columns (8 bytes each). Every buffer is reserved at its final
/// size before the run, so there is no doubling to pay for. The rows were
/// 448 bytes by an estimate and 737 measured, when each text cell was a
/// string object of its own and the library's rows were kept whole.
pub(crate) const SWEEP_ROW_BYTES: u64 = (8 * (6 + AxisParam::ALL.len()) + 4 * 5 + 8 * 6) as u64;

/// Bytes of a failed row's message besides its text: a Python string's
/// header (49 bytes on CPython) and the allocator's rounding. Counted as
/// the rows come, since which rows fail is not known before.
const ERROR_OBJECT_BYTES: u64 = 64;

/// The values a text column takes, each kept once: a row holds the code of
/// its value, and the Python column one shared string object per value.
struct Interned<T> {
    values: Vec<T>,
    codes: Vec<u32>,
}

impl<T: PartialEq> Interned<T> {
    fn with_room(n: usize) -> PyResult<Self> {
        Ok(Self {
            values: Vec::new(),
            codes: try_vec(n, "sweep()")?,
        })
    }

    fn push(&mut self, value: T) -> PyResult<()> {
        let code = match self.values.iter().position(|v| *v == value) {
            Some(k) => k,
            None => {
                grow(&mut self.values, "sweep()")?;
                self.values.push(value);
                self.values.len() - 1
            }
        };
        self.codes.push(code as u32);
        Ok(())
    }

    /// The column as a numpy object array: each value made a Python object
    /// once by `object`, every cell a reference to it.
    fn into_py<'py>(
        self,
        py: Python<'py>,
        object: impl Fn(&T) -> PyResult<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let objects = self
            .values
            .iter()
            .map(|v| object(v).map(Bound::unbind))
            .collect::<PyResult<Vec<Py<PyAny>>>>()?;
        let mut cells: Vec<Py<PyAny>> = try_vec(self.codes.len(), "sweep()")?;
        cells.extend(
            self.codes
                .iter()
                .map(|&k| objects[k as usize].clone_ref(py)),
        );
        Ok(cells.into_pyarray(py).into_any())
    }
}

/// The rows of a sweep as the columns the call returns, filled a chunk at
/// a time while the rows are computed (the library's rows are not kept).
struct Columns {
    index: Vec<u64>,
    /// One per parameter, in [`AxisParam::ALL`] order.
    params: Vec<Vec<f64>>,
    /// t_s, x_m, v_m_s, a_over_g_sin_alpha, turns.
    results: [Vec<f64>; 5],
    model: Interned<ModelKind>,
    on_hop: Interned<OnHop>,
    collision: Interned<CollisionModel>,
    stop: Interned<Option<StopReason>>,
    warnings: Interned<Option<String>>,
    /// The failed rows' messages, by position in the shard.
    errors: Vec<(usize, String)>,
}

impl Columns {
    fn with_room(n: usize) -> PyResult<Self> {
        let f = || try_vec::<f64>(n, "sweep()");
        Ok(Self {
            index: try_vec(n, "sweep()")?,
            params: AxisParam::ALL
                .iter()
                .map(|_| f())
                .collect::<PyResult<_>>()?,
            results: [f()?, f()?, f()?, f()?, f()?],
            model: Interned::with_room(n)?,
            on_hop: Interned::with_room(n)?,
            collision: Interned::with_room(n)?,
            stop: Interned::with_room(n)?,
            warnings: Interned::with_room(n)?,
            errors: Vec::new(),
        })
    }

    fn push(&mut self, rows: &[SweepRow]) -> PyResult<()> {
        let opt = |x: Option<f64>| x.unwrap_or(f64::NAN);
        for r in rows {
            let at = self.index.len();
            self.index.push(r.index);
            for (col, p) in self.params.iter_mut().zip(AxisParam::ALL) {
                col.push(r.param(p));
            }
            let results = [
                opt(r.t_s),
                opt(r.x_m),
                opt(r.v_m_s),
                opt(r.a_over_g_sin_alpha),
                r.turns.map_or(f64::NAN, |k| k as f64),
            ];
            for (col, x) in self.results.iter_mut().zip(results) {
                col.push(x);
            }
            self.model.push(r.model)?;
            self.on_hop.push(r.on_hop)?;
            self.collision.push(r.collision)?;
            self.stop.push(r.stop)?;
            self.warnings.push(r.warnings.clone())?;
            if let Some(e) = &r.error {
                grow(&mut self.errors, "sweep()")?;
                self.errors.push((at, e.clone()));
            }
        }
        Ok(())
    }

    /// The columns named as the CLI's CSV header, in its order: numbers as
    /// numpy arrays (NaN where the cell is empty), text as numpy object
    /// arrays of `str` or `None`.
    fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let c = PyDict::new(py);
        let text = |s: &str| Ok(PyString::new(py, s).into_any());
        let rows = self.index.len();
        c.set_item("index", self.index.into_pyarray(py))?;
        c.set_item("model", self.model.into_py(py, |m| text(m.id()))?)?;
        for (p, col) in AxisParam::ALL.into_iter().zip(self.params) {
            c.set_item(p.key(), col.into_pyarray(py))?;
        }
        c.set_item("on_hop", self.on_hop.into_py(py, |h| text(h.id()))?)?;
        c.set_item("collision", self.collision.into_py(py, |m| text(m.id()))?)?;
        let stop = |s: &Option<StopReason>| match s {
            Some(s) => record(py, s),
            None => Ok(py.None().into_bound(py)),
        };
        c.set_item("stop", self.stop.into_py(py, stop)?)?;
        let names = ["t_s", "x_m", "v_m_s", "a_over_g_sin_alpha", "turns"];
        for (name, col) in names.into_iter().zip(self.results) {
            c.set_item(name, col.into_pyarray(py))?;
        }
        let mut errors: Vec<Py<PyAny>> = try_vec(rows, "sweep()")?;
        errors.extend((0..rows).map(|_| py.None()));
        for (at, e) in self.errors {
            errors[at] = PyString::new(py, &e).into_any().unbind();
        }
        c.set_item("error", errors.into_pyarray(py))?;
        let warnings = |w: &Option<String>| match w {
            Some(w) => text(w),
            None => Ok(py.None().into_bound(py)),
        };
        c.set_item("warnings", self.warnings.into_py(py, warnings)?)?;
        Ok(c)
    }
}

/// Every setting of a sweep, by name, as text, as `merge` compares two
/// shards' headers: the models, each sweep parameter (its values, or its
/// default when the grid does not vary it), the collision laws and hop
/// settings, and the method. `SweepResult.concat` refuses parts whose
/// settings differ, naming each difference.
fn settings(grid: &Grid, method: Method) -> Vec<(String, String)> {
    let ids = |v: Vec<&str>| v.join(",");
    let mut out = vec![(
        "model".to_string(),
        ids(grid.models().iter().map(|m| m.id()).collect()),
    )];
    for p in AxisParam::ALL {
        let text = match grid.axes().iter().find(|a| a.param == p) {
            Some(a) => match &a.values {
                Values::Range {
                    start, count: 1, ..
                } => Values::List(vec![*start]).to_string(),
                v => v.to_string(),
            },
            None => match snowroll::Param::of_key(p.key()).map(|t| t.default_value()) {
                Some(snowroll::Value::Real(x)) => Values::List(vec![x]).to_string(),
                _ => "none".to_string(),
            },
        };
        out.push((p.key().to_string(), text));
    }
    let choices = grid.choices();
    out.push((
        "collision".to_string(),
        ids(choices.collision.iter().map(|c| c.id()).collect()),
    ));
    out.push((
        "on_hop".to_string(),
        ids(choices.on_hop.iter().map(|c| c.id()).collect()),
    ));
    let method = match method {
        Method::Auto => "auto",
        Method::Ode => "ode",
    };
    out.push(("method".to_string(), method.to_string()));
    out
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
        let param = AxisParam::from_key(&key).ok_or_else(|| {
            PyValueError::new_err(format!(
                "unknown axis {key:?}: expected model, collision, on_hop or one of {}",
                AxisParam::ALL.map(AxisParam::key).join(", ")
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
