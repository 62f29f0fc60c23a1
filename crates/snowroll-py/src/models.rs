//! `snowroll.models()`: every model with its terminal fraction, stall slope
//! and range of validity, from the library.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use snowroll::params::{Group, Scope};
use snowroll::{Given, ModelKind, Scenario, Settings};

use crate::{given, record, value_error};

/// The keywords of `models()`: the table's shared parameters of the
/// scenario and the losses (`snowroll models`' flags); any other is a
/// `TypeError`, as Python raises for an unknown keyword.
fn body_given(params: Option<&Bound<'_, PyDict>>) -> PyResult<Given> {
    let all = given("models", &[Scope::Shared], params)?;
    let mut out = Given::new();
    for (p, v) in all.iter() {
        if !matches!(p.group, Group::Scenario | Group::Losses) {
            return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                "models() got an unexpected keyword argument '{}'",
                p.key
            )));
        }
        out.insert(p, v.clone());
    }
    Ok(out)
}

/// Every model: id, alias, equation, description, terminal fraction
/// a_inf/(g sin alpha), stall slope (degrees) and stall kind for the body,
/// slope and losses of the keywords (the scenario and loss parameters of the
/// table, as `snowroll models` takes them; the defaults where none is
/// given: the log without losses), validity.
#[pyfunction]
#[pyo3(signature = (**params))]
pub(crate) fn models<'py>(
    py: Python<'py>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyList>> {
    let given = body_given(params)?;
    let settings = given.apply(Settings::default()).map_err(value_error)?;
    let (file, losses) = (settings.scenario, settings.options.losses);
    losses.validate().map_err(value_error)?;
    let scenario = Scenario::new(file).map_err(value_error)?;
    let list = PyList::empty(py);
    for kind in ModelKind::ALL {
        let row = PyDict::new(py);
        row.set_item("id", kind.id())?;
        row.set_item("alias", kind.alias())?;
        row.set_item("equation", kind.equation())?;
        row.set_item("description", kind.description())?;
        row.set_item("terminal_fraction", kind.terminal_fraction())?;
        let shapes: Vec<&str> = kind.shapes().iter().map(|s| s.id()).collect();
        row.set_item("shapes", shapes)?;
        let stall = kind.stall_threshold_listed(&scenario, &losses);
        row.set_item("stall_slope_deg", stall.map(|t| t.slope.to_degrees()))?;
        let stall_kind = match stall {
            Some(t) => Some(record(py, &t.kind)?),
            None => None,
        };
        row.set_item("stall_kind", stall_kind)?;
        row.set_item("validity", record(py, &kind.validity())?)?;
        list.append(row)?;
    }
    Ok(list)
}
