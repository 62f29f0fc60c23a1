//! `snowroll.models()`: every model with its terminal fraction, stall slope
//! and range of validity, from the library.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use snowroll::{ModelKind, Scenario, ScenarioFile};

use crate::{record, value_error};

/// Every model: id, alias, equation, description, terminal fraction
/// a_inf/(g sin alpha), stall slope (degrees) and stall kind for the given
/// snow depth and radius (default: the default scenario's), validity.
#[pyfunction]
#[pyo3(signature = (*, snow_depth = None, r0 = None))]
pub(crate) fn models<'py>(
    py: Python<'py>,
    snow_depth: Option<f64>,
    r0: Option<f64>,
) -> PyResult<Bound<'py, PyList>> {
    let d = ScenarioFile::default();
    // Validates b and r0 as a scenario does.
    let scenario = Scenario::new(ScenarioFile {
        snow_depth: snow_depth.unwrap_or(d.snow_depth),
        r0: r0.unwrap_or(d.r0),
        ..d
    })
    .map_err(value_error)?;
    let (b, r0) = (scenario.snow_depth(), scenario.initial_radius());
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
        let stall = kind.stall_threshold(b, r0);
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
