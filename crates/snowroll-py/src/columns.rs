//! The results as Python objects: records, numpy columns (with a mask
//! where a value is missing), the stop, and the columns of a trajectory, a
//! turn table and an energy ledger.

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
    name: &str,
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

/// Adds column `name` built from `items` to `columns` as a
/// `numpy.ma.MaskedArray`: masked where `f` is `None` (a quantity that is
/// undefined there, e.g. |F|/N where N ≤ 0), with 0.0 under the mask, so the
/// array holds no NaN or infinity.
pub(crate) fn masked_column<'py, T>(
    py: Python<'py>,
    columns: &Bound<'py, PyDict>,
    name: &str,
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
    let kwargs = PyDict::new(py);
    kwargs.set_item("mask", mask.into_pyarray(py))?;
    let array = py.import("numpy.ma")?.call_method(
        "masked_array",
        (data.into_pyarray(py),),
        Some(&kwargs),
    )?;
    columns.set_item(name, array)
}

/// The stop as a dict: reason (kebab-case id), description, t_s, x_m, v_m_s
/// and, for the turn models, turn, theta_rad, omega_rad_s.
pub(crate) fn stop<'py>(py: Python<'py>, s: &Stop) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("reason", record(py, &s.reason)?)?;
    d.set_item("description", s.reason.describe())?;
    d.set_item("t_s", s.t_s)?;
    d.set_item("x_m", s.x_m)?;
    d.set_item("v_m_s", s.v_m_s)?;
    if let Some(k) = s.turn {
        d.set_item("turn", k.turn)?;
        d.set_item("theta_rad", k.theta_rad)?;
        d.set_item("omega_rad_s", k.omega_rad_s)?;
    }
    Ok(d)
}

/// What both runs return besides their columns: version, model, params, stop, warnings.
pub(crate) fn common<'py>(
    py: Python<'py>,
    model: ModelKind,
    params: &RunParams,
    s: &Stop,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("version", snowroll_io::VERSION)?;
    out.set_item("model", model.id())?;
    out.set_item("equation", model.equation())?;
    out.set_item("params", record(py, params)?)?;
    out.set_item("stop", stop(py, s)?)?;
    out.set_item("warnings", params.warnings.clone())?;
    Ok(out)
}

/// The columns of a trajectory, named as in the CLI's CSV header.
pub(crate) fn trajectory_columns<'py>(
    py: Python<'py>,
    traj: &Trajectory,
) -> PyResult<Bound<'py, PyDict>> {
    let c = PyDict::new(py);
    let s = &traj.samples;
    column(py, &c, "t_s", s, |s| s.t_s)?;
    column(py, &c, "x_m", s, |s| s.x_m)?;
    column(py, &c, "v_m_s", s, |s| s.v_m_s)?;
    column(py, &c, "a_m_s2", s, |s| s.a_m_s2)?;
    column(py, &c, "r_m", s, |s| s.r_m)?;
    column(py, &c, "mass_kg", s, |s| s.mass_kg)?;
    column(py, &c, "normal_n", s, |s| s.normal_n)?;
    column(py, &c, "friction_n", s, |s| s.friction_n)?;
    masked_column(py, &c, "friction_ratio", s, |s| s.friction_ratio)?;
    let k = &traj.turn_states;
    if !k.is_empty() && k.len() == s.len() {
        column(py, &c, "turn", k, |k| k.turn)?;
        column(py, &c, "theta_rad", k, |k| k.theta_rad)?;
        column(py, &c, "omega_rad_s", k, |k| k.omega_rad_s)?;
    }
    ledger_columns(py, &c, &traj.ledger, s.len())?;
    Ok(c)
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
    column(py, c, "kinetic_j", l, |l| l.kinetic_j)?;
    column(py, c, "released_j", l, |l| l.released_j)?;
    column(py, c, "drag_j", l, |l| l.drag_j)?;
    column(py, c, "rolling_j", l, |l| l.rolling_j)?;
    column(py, c, "compaction_j", l, |l| l.compaction_j)?;
    column(py, c, "model_j", l, |l| l.model_j)?;
    column(py, c, "collision_j", l, |l| l.collision_j)?;
    column(py, c, "created_j", l, |l| l.created_j)?;
    column(py, c, "residual_j", l, |l| l.residual_j)
}

/// One row per turn, named as in the CLI's `snowroll turns` CSV header.
pub(crate) fn turn_columns<'py>(
    py: Python<'py>,
    table: &TurnTable,
) -> PyResult<Bound<'py, PyDict>> {
    let c = PyDict::new(py);
    let r = &table.rows;
    column(py, &c, "turn", r, |r| r.turn)?;
    column(py, &c, "t_start_s", r, |r| r.t_start_s)?;
    column(py, &c, "x_start_m", r, |r| r.x_start_m)?;
    column(py, &c, "v_start_m_s", r, |r| r.v_start_m_s)?;
    column(py, &c, "t_end_s", r, |r| r.t_end_s)?;
    column(py, &c, "v_end_m_s", r, |r| r.v_end_m_s)?;
    column(py, &c, "v_after_m_s", r, |r| r.v_after_m_s)?;
    column(py, &c, "collision_loss_j", r, |r| r.collision_loss_j)?;
    column(py, &c, "mean_a_turn_m_s2", r, |r| r.mean_a_turn_m_s2)?;
    column(py, &c, "min_a_m_s2", r, |r| r.min_a_m_s2)?;
    column(py, &c, "max_a_m_s2", r, |r| r.max_a_m_s2)?;
    column(py, &c, "mean_a_with_collision_m_s2", r, |r| {
        r.mean_a_with_collision_m_s2
    })?;
    column(py, &c, "min_normal_n", r, |r| r.min_normal_n)?;
    column(py, &c, "min_normal_over_mg", r, |r| r.min_normal_over_mg)?;
    masked_column(py, &c, "max_friction_ratio", r, |r| r.max_friction_ratio)?;
    ledger_columns(py, &c, &table.ledger, r.len())?;
    Ok(c)
}
