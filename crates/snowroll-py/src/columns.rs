//! The results as Python objects: records, numpy columns (with a mask
//! where a value is missing), the stop, and the columns of a trajectory, a
//! turn table and an energy ledger.

use pyo3::intern;
use pyo3::sync::PyOnceLock;

use super::*;

/// A serde record as a Python object.
pub(crate) fn record<'py>(
    py: Python<'py>,
    value: &impl serde::Serialize,
) -> PyResult<Bound<'py, PyAny>> {
    let json = serde_json::to_value(value).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    to_py(py, &json)
}

/// Adds column `name` built from `items` to `columns`, as a numpy array.
pub(crate) fn column<'py, T, E>(
    py: Python<'py>,
    columns: &Bound<'py, PyDict>,
    name: &Bound<'py, PyString>,
    items: &[T],
    f: impl Fn(&T) -> E,
) -> PyResult<()>
where
    E: numpy::Element,
{
    let mut values: Vec<E> = guard::try_vec(items.len(), "building a column")?;
    values.extend(items.iter().map(f));
    columns.set_item(name, values.into_pyarray(py))
}

/// Adds column `name` built from `items` to `columns` with its mask in
/// `masks`: masked where `f` is `None` (a quantity that is undefined there,
/// e.g. |F|/N where N ≤ 0), with 0.0 under the mask, so the array holds no
/// NaN or infinity. The Python layer makes the pair a
/// `numpy.ma.MaskedArray` when a column is first read (`_Columns`): the
/// constructor is Python code in numpy.ma, a few microseconds a column that a
/// call which reads no column should not pay.
pub(crate) fn masked_column<'py, T>(
    py: Python<'py>,
    columns: &Columns<'py>,
    name: &Bound<'py, PyString>,
    items: &[T],
    f: impl Fn(&T) -> Option<f64>,
) -> PyResult<()> {
    let mut data: Vec<f64> = guard::try_vec(items.len(), "building a column")?;
    let mut mask: Vec<bool> = guard::try_vec(items.len(), "building a column")?;
    for item in items {
        let v = f(item);
        data.push(v.unwrap_or(0.0));
        mask.push(v.is_none());
    }
    columns.masks.set_item(name, mask.into_pyarray(py))?;
    columns.values.set_item(name, data.into_pyarray(py))
}

/// The columns of a result: the arrays by name, and the masks of the
/// columns that have one ([`masked_column`]).
pub(crate) struct Columns<'py> {
    pub(crate) values: Bound<'py, PyDict>,
    pub(crate) masks: Bound<'py, PyDict>,
}

impl<'py> Columns<'py> {
    fn new(py: Python<'py>) -> Self {
        Self {
            values: PyDict::new(py),
            masks: PyDict::new(py),
        }
    }

    /// Puts the columns into the call's result `out`: `columns` and `masks`.
    pub(crate) fn into_result(self, out: &Bound<'py, PyDict>) -> PyResult<()> {
        let py = out.py();
        out.set_item(intern!(py, "columns"), self.values)?;
        out.set_item(intern!(py, "masks"), self.masks)
    }
}

/// The stop as a dict: reason (kebab-case id), description, t_s, x_m, v_m_s
/// and, for the turn models, turn, theta_rad, omega_rad_s.
pub(crate) fn stop<'py>(py: Python<'py>, s: &Stop) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item(intern!(py, "reason"), record(py, &s.reason)?)?;
    d.set_item(intern!(py, "description"), s.reason.describe())?;
    d.set_item(intern!(py, "t_s"), s.t_s)?;
    d.set_item(intern!(py, "x_m"), s.x_m)?;
    d.set_item(intern!(py, "v_m_s"), s.v_m_s)?;
    if let Some(k) = s.turn {
        d.set_item(intern!(py, "turn"), k.turn)?;
        d.set_item(intern!(py, "theta_rad"), k.theta_rad)?;
        d.set_item(intern!(py, "omega_rad_s"), k.omega_rad_s)?;
    }
    Ok(d)
}

/// A parameter's value as Python's `None`, `float`, `int`, `bool`, `str`
/// or list of floats, as its serde record gives it (a number that is not
/// finite is `None`, as in serde_json).
fn value_to_py<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::None => py.None().into_bound(py),
        Value::Real(x) => real(py, *x)?,
        Value::Count(n) => n.into_pyobject(py)?.into_any(),
        Value::Flag(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Word(w) => PyString::new(py, w).into_any(),
        Value::Reals(xs) => {
            let list = PyList::empty(py);
            for x in xs {
                list.append(real(py, *x)?)?;
            }
            list.into_any()
        }
    })
}

/// The keys a run's `params` record may hold (the parameter table's, then
/// `method` and `warnings`), each with its Python string made once, and
/// each one's place in the record's key order (sorted, as serde_json's map
/// sorts them).
struct RecordKeys {
    /// The Python strings of the keys, sorted.
    strings: Vec<Py<PyString>>,
    /// The sorted place of each table parameter's key, in table order.
    table_rank: Vec<usize>,
    /// The sorted places of `method` and `warnings`.
    method_rank: usize,
    warnings_rank: usize,
}

static RECORD_KEYS: PyOnceLock<RecordKeys> = PyOnceLock::new();

fn record_keys(py: Python<'_>) -> &RecordKeys {
    RECORD_KEYS.get_or_init(py, || {
        let mut names: Vec<&'static str> = PARAMS.iter().map(|p| p.key).collect();
        names.extend(["method", "warnings"]);
        names.sort_unstable();
        let rank = |key: &str| names.iter().position(|n| *n == key).unwrap_or(0);
        RecordKeys {
            strings: names
                .iter()
                .map(|n| PyString::intern(py, n).unbind())
                .collect(),
            table_rank: PARAMS.iter().map(|p| rank(p.key)).collect(),
            method_rank: rank("method"),
            warnings_rank: rank("warnings"),
        }
    })
}

/// The run's parameters as a dict: the entries of `RunParams`'s serde
/// record (the parameter table's JSON entries, `method`, `warnings`) in the
/// record's key order, built directly rather than through a
/// `serde_json::Value`, with key strings made once ([`record_keys`]):
/// through serde_json and back it was about a fifth of a call's overhead.
pub(crate) fn params_dict<'py>(
    py: Python<'py>,
    params: &RunParams,
) -> PyResult<Bound<'py, PyDict>> {
    let keys = record_keys(py);
    let mut slots: Vec<Option<Bound<'py, PyAny>>> = vec![None; keys.strings.len()];
    // The entries come in table order: each one's parameter is found by
    // walking the table alongside.
    let mut table = PARAMS.iter().zip(&keys.table_rank);
    for (key, value) in params.settings.json_entries() {
        let (_, &at) = table.find(|(p, _)| p.key == key).ok_or_else(|| {
            PyRuntimeError::new_err(format!("record key {key} out of the table's order"))
        })?;
        slots[at] = Some(value_to_py(py, &value)?);
    }
    if let Some(m) = params.method {
        slots[keys.method_rank] = Some(PyString::new(py, m.id()).into_any());
    }
    if !params.warnings.is_empty() {
        slots[keys.warnings_rank] = Some(PyList::new(py, &params.warnings)?.into_any());
    }
    let d = PyDict::new(py);
    for (key, value) in keys.strings.iter().zip(slots) {
        if let Some(value) = value {
            d.set_item(key.bind(py), value)?;
        }
    }
    Ok(d)
}

/// A float as its serde record gives it: `None` where it is not finite
/// (serde_json's null).
fn real<'py>(py: Python<'py>, x: f64) -> PyResult<Bound<'py, PyAny>> {
    Ok(if x.is_finite() {
        x.into_pyobject(py)?.into_any()
    } else {
        py.None().into_bound(py)
    })
}

/// A turn run's summary as the library computed it, for
/// `TurnResult.summary`: the dict ([`summary_dict`]) is made when Python
/// first reads it (`to_dict()`), not by every call.
#[pyclass(frozen, name = "SummaryRecord", module = "snowroll._snowroll")]
pub(crate) struct SummaryRecord(pub(crate) TurnSummary);

#[pymethods]
impl SummaryRecord {
    /// The summary as a dict: the `summary` object of the CLI's JSON
    /// output, key for key.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        summary_dict(py, &self.0)
    }
}

/// A turn run's summary as a dict: the keys and values of its serde record
/// (what `record` gave, keys sorted as serde_json's map sorts them), built
/// directly with key strings made once; through serde_json and back it was
/// about half of a `turns` call's overhead. The Python tests compare it
/// with the CLI's JSON `summary`, key for key.
pub(crate) fn summary_dict<'py>(py: Python<'py>, s: &TurnSummary) -> PyResult<Bound<'py, PyDict>> {
    let checkpoints = PyList::empty(py);
    for c in &s.checkpoints {
        let d = PyDict::new(py);
        d.set_item(
            intern!(py, "mean_a_turn_over_g"),
            real(py, c.mean_a_turn_over_g)?,
        )?;
        d.set_item(
            intern!(py, "mean_a_with_collision_over_g"),
            real(py, c.mean_a_with_collision_over_g)?,
        )?;
        d.set_item(intern!(py, "turns"), c.turns)?;
        d.set_item(intern!(py, "window_first_turn"), c.window_first_turn)?;
        d.set_item(
            intern!(py, "window_max_a_over_g"),
            real(py, c.window_max_a_over_g)?,
        )?;
        d.set_item(
            intern!(py, "window_mean_a_turn_over_g"),
            real(py, c.window_mean_a_turn_over_g)?,
        )?;
        d.set_item(
            intern!(py, "window_mean_a_with_collision_over_g"),
            real(py, c.window_mean_a_with_collision_over_g)?,
        )?;
        d.set_item(
            intern!(py, "window_min_a_over_g"),
            real(py, c.window_min_a_over_g)?,
        )?;
        checkpoints.append(d)?;
    }
    let d = PyDict::new(py);
    d.set_item(intern!(py, "checkpoints"), checkpoints)?;
    d.set_item(intern!(py, "g_along_m_s2"), real(py, s.g_along_m_s2)?)?;
    d.set_item(intern!(py, "turns"), s.turns)?;
    Ok(d)
}

/// A run's parameters as the library recorded them, for `Result.params`:
/// the dict ([`params_dict`]) is made when Python first reads it
/// (`to_dict()`), not by every call (a fifth of what a call added to the
/// library's own time when it was).
#[pyclass(frozen, name = "ParamsRecord", module = "snowroll._snowroll")]
pub(crate) struct ParamsRecord(RunParams);

#[pymethods]
impl ParamsRecord {
    /// The parameters as a dict: the `params` object of the CLI's JSON
    /// output, key for key.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        params_dict(py, &self.0)
    }
}

/// What both runs return besides their columns: version, model, params (a
/// [`ParamsRecord`]), stop, warnings.
pub(crate) fn common<'py>(
    py: Python<'py>,
    model: ModelKind,
    params: RunParams,
    s: &Stop,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item(intern!(py, "version"), snowroll_io::VERSION)?;
    out.set_item(intern!(py, "model"), model.id())?;
    out.set_item(intern!(py, "equation"), model.equation())?;
    out.set_item(intern!(py, "stop"), stop(py, s)?)?;
    out.set_item(intern!(py, "warnings"), params.warnings.clone())?;
    out.set_item(intern!(py, "params"), Bound::new(py, ParamsRecord(params))?)?;
    Ok(out)
}

/// The columns of a trajectory, named as in the CLI's CSV header.
pub(crate) fn trajectory_columns<'py>(
    py: Python<'py>,
    traj: &Trajectory,
) -> PyResult<Columns<'py>> {
    let cols = Columns::new(py);
    let c = &cols.values;
    let s = &traj.samples;
    column(py, c, intern!(py, "t_s"), s, |s| s.t_s)?;
    column(py, c, intern!(py, "x_m"), s, |s| s.x_m)?;
    column(py, c, intern!(py, "v_m_s"), s, |s| s.v_m_s)?;
    column(py, c, intern!(py, "a_m_s2"), s, |s| s.a_m_s2)?;
    column(py, c, intern!(py, "r_m"), s, |s| s.r_m)?;
    column(py, c, intern!(py, "mass_kg"), s, |s| s.mass_kg)?;
    column(py, c, intern!(py, "normal_n"), s, |s| s.normal_n)?;
    column(py, c, intern!(py, "friction_n"), s, |s| s.friction_n)?;
    masked_column(py, &cols, intern!(py, "friction_ratio"), s, |s| {
        s.friction_ratio
    })?;
    let k = &traj.turn_states;
    if !k.is_empty() && k.len() == s.len() {
        column(py, c, intern!(py, "turn"), k, |k| k.turn)?;
        column(py, c, intern!(py, "theta_rad"), k, |k| k.theta_rad)?;
        column(py, c, intern!(py, "omega_rad_s"), k, |k| k.omega_rad_s)?;
    }
    ledger_columns(py, c, &traj.ledger, s.len())?;
    Ok(cols)
}

/// The ledger's columns (`docs/snowball-and-losses.md` §3), when there is
/// one row per row of the table (`rows`).
pub(crate) fn ledger_columns(
    py: Python<'_>,
    c: &Bound<'_, PyDict>,
    l: &[LedgerRow],
    rows: usize,
) -> PyResult<()> {
    if l.is_empty() || l.len() != rows {
        return Ok(());
    }
    column(py, c, intern!(py, "kinetic_j"), l, |l| l.kinetic_j)?;
    column(py, c, intern!(py, "released_j"), l, |l| l.released_j)?;
    column(py, c, intern!(py, "drag_j"), l, |l| l.drag_j)?;
    column(py, c, intern!(py, "rolling_j"), l, |l| l.rolling_j)?;
    column(py, c, intern!(py, "compaction_j"), l, |l| l.compaction_j)?;
    column(py, c, intern!(py, "model_j"), l, |l| l.model_j)?;
    column(py, c, intern!(py, "collision_j"), l, |l| l.collision_j)?;
    column(py, c, intern!(py, "created_j"), l, |l| l.created_j)?;
    column(py, c, intern!(py, "residual_j"), l, |l| l.residual_j)
}

/// One row per turn, named as in the CLI's `snowroll turns` CSV header.
pub(crate) fn turn_columns<'py>(py: Python<'py>, table: &TurnTable) -> PyResult<Columns<'py>> {
    let cols = Columns::new(py);
    let c = &cols.values;
    let r = &table.rows;
    column(py, c, intern!(py, "turn"), r, |r| r.turn)?;
    column(py, c, intern!(py, "t_start_s"), r, |r| r.t_start_s)?;
    column(py, c, intern!(py, "x_start_m"), r, |r| r.x_start_m)?;
    column(py, c, intern!(py, "v_start_m_s"), r, |r| r.v_start_m_s)?;
    column(py, c, intern!(py, "t_end_s"), r, |r| r.t_end_s)?;
    column(py, c, intern!(py, "v_end_m_s"), r, |r| r.v_end_m_s)?;
    column(py, c, intern!(py, "v_after_m_s"), r, |r| r.v_after_m_s)?;
    column(py, c, intern!(py, "collision_loss_j"), r, |r| {
        r.collision_loss_j
    })?;
    column(py, c, intern!(py, "mean_a_turn_m_s2"), r, |r| {
        r.mean_a_turn_m_s2
    })?;
    column(py, c, intern!(py, "min_a_m_s2"), r, |r| r.min_a_m_s2)?;
    column(py, c, intern!(py, "max_a_m_s2"), r, |r| r.max_a_m_s2)?;
    column(py, c, intern!(py, "mean_a_with_collision_m_s2"), r, |r| {
        r.mean_a_with_collision_m_s2
    })?;
    column(py, c, intern!(py, "min_normal_n"), r, |r| r.min_normal_n)?;
    column(py, c, intern!(py, "min_normal_over_mg"), r, |r| {
        r.min_normal_over_mg
    })?;
    masked_column(py, &cols, intern!(py, "max_friction_ratio"), r, |r| {
        r.max_friction_ratio
    })?;
    ledger_columns(py, c, &table.ledger, r.len())?;
    Ok(cols)
}
